/*
 * obj.h - our own reader of Wavefront OBJ meshes and the base colours
 * (Kd) of their .mtl materials, for organ meshes (mesh.h).
 */
#ifndef OBJ_H
#define OBJ_H

#include <stddef.h>

#include "meshes/mesh.h"

#define OBJ_BYTES_MAX	(64L * 1024 * 1024)	/* an OBJ file, at most */

/* Told the path of each material library read, for -o's check. */
typedef void obj_read_fn(const char *path);

/*
 * Read the OBJ file at path into m, its mtllib files beside it; 0, or
 * -1 after a diagnostic at FILE:LINE of the OBJ or .mtl.  A material
 * library that cannot be read is a warning: the object's hue stands in.
 */
int	obj_load(struct mesh *m, const char *path, obj_read_fn *told);
/*
 * Tell told each material library the OBJ file at path names and that
 * exists, without reading the mesh: what -o must not name though the
 * format reads no meshes.  Quiet: a file that cannot be read has none.
 */
void	obj_libraries(const char *path, obj_read_fn *told);
/*
 * The same from len bytes of text (no NUL needed), messages naming
 * file; mtllib lines are only checked, not read, unless dir is given:
 * the directory (with its '/', or "") their files are relative to.
 */
int	obj_parse(struct mesh *m, const char *file, const char *text,
	    size_t len, const char *dir, obj_read_fn *told);

#endif
