/* mtl.h - the base colours (Kd, d) of a Wavefront .mtl's materials. */
#ifndef MTL_H
#define MTL_H

#include <stddef.h>

#include "meshes/mesh.h"

#define MTL_BYTES_MAX	(4L * 1024 * 1024)	/* a .mtl file, at most */

struct mtl_material {
	char		 name[MESH_MATERIAL_LEN];
	float		 color[4];	/* Kd, and d as alpha */
	int		 has_kd;
};

/*
 * The materials of a .mtl file's text (len bytes, no NUL needed),
 * appended to *mats (*n of them); 0, or -1 after a diagnostic at
 * file's line.
 */
int	mtl_parse(struct mtl_material **mats, size_t *n, const char *file,
	    const char *text, size_t len);

#endif
