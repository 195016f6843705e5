/*
 * inputs.h - the files a run reads (the scene, its parts, the template,
 * a mesh, a points file), which -o must never name, by any path or
 * link: whoever reads one says so here, and output.c asks.
 */
#ifndef INPUTS_H
#define INPUTS_H

struct sys_id;

/* path is read, as what ("the scene file"); remembered until exit. */
void	 input_add(const char *path, const char *what);
/*
 * Whether the file id (compat.h) is an input: 1 with the path it was
 * given as and what it is, else 0.
 */
int	 input_find(const struct sys_id *id, const char **path,
	    const char **what);

#endif
