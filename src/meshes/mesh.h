/*
 * mesh.h - an organ object's mesh, as --gltf writes it: indexed
 * triangles over one array of vertices, in primitives of one material
 * each.  Read from a Wavefront OBJ file (obj.c), or a placeholder.
 */
#ifndef MESH_H
#define MESH_H

#include <stddef.h>
#include <stdint.h>

#define MESH_MATERIAL_LEN	64	/* bytes of a material's name kept */

/* The triangles of one material. */
struct mesh_prim {
	uint32_t	*index;		/* 3 per triangle, into the vertices */
	size_t		 nindex;
	float		 color[4];	/* base colour: linear RGB, alpha */
	int		 colored;	/* color was given (.mtl Kd), not the
					   object's hue */
	char		 material[MESH_MATERIAL_LEN];	/* "" none; raw bytes */
};

/*
 * The mesh in the organ's own frame: outward along +X, up along +Y (as
 * Blender's OBJ export writes a model built outward +X, up +Z), so
 * glTF's local axes.  Normals are unit length.
 */
struct mesh {
	float		(*pos)[3];
	float		(*normal)[3];
	size_t		 nvert;
	float		 min[3], max[3];	/* of pos */
	struct mesh_prim *prim;
	size_t		 nprim;
};

/*
 * A unit icosphere (one subdivision: 42 vertices, 80 triangles), as the
 * Blender script's placeholders are, for an object without a mesh.
 */
void	mesh_placeholder(struct mesh *);
/* Organ object k's colour in the previews (the SVG's hsl(hue, 70%, 45%)),
 * as linear RGB. */
void	mesh_hue_color(size_t k, float rgb[3]);
void	mesh_free(struct mesh *);

#endif
