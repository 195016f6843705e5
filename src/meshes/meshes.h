/*
 * meshes.h - the organ meshes a compound's scenes name (organs.mesh):
 * one per object name across the tree, as every name is one thing, and
 * each file read once a run however many frames read it.
 */
#ifndef MESHES_H
#define MESHES_H

#include <stddef.h>

#include "meshes/mesh.h"

struct compound;

struct object_mesh {
	const char	*name;		/* the object's, in its scene */
	const struct mesh *mesh;	/* read once a run (meshes.c) */
};

/* A frame's table; its meshes belong to the run. */
struct meshes {
	struct object_mesh *m;
	size_t		 n;
	int		 missing;	/* MESH_SIZES: a file not there */
};

#define MESH_WARN	0x1	/* say which plain objects have none */
#define MESH_SIZES	0x2	/* only for sizes: a file not there is a
				   warning, and M->missing says so */

/*
 * Read the meshes C's scenes name into M and point every result of C
 * at M (result.meshes), as flags (MESH_*) say.  0, or -1 after a
 * diagnostic.
 */
int	meshes_load(struct meshes *M, struct compound *C, unsigned flags);
/* Object name's mesh, or NULL: it has none (a placeholder stands in). */
const struct mesh *meshes_find(const struct meshes *, const char *name);
void	meshes_free(struct meshes *);
/* Tell input_add() each OBJ file C's scenes name: -o may not. */
void	meshes_inputs(const struct compound *C);
/* Forget every mesh read: the run is over. */
void	meshes_forget(void);

#endif
