/* path.h - a file named relative to the file that names it. */
#ifndef PATH_H
#define PATH_H

/*
 * rel taken relative to the directory of the file from, which names it
 * (a scene naming a part's scene, a mesh, a points file); rel itself
 * when it is absolute or from is "<stdin>".  Allocated.
 */
char	*path_resolve(const char *from, const char *rel);

#endif
