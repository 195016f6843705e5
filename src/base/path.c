/*
 * path.c - a file named relative to the file that names it: the loader,
 * the meshes and the models (the measured model's points) all resolve a
 * scene's names so, here below them all.
 */
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "base/path.h"
#include "compat/compat.h"

char *
path_resolve(const char *from, const char *rel)
{
	size_t dir = strcmp(from, "<stdin>") != 0 ?
	    (size_t)(sys_base(from) - from) : 0;
	char *p;

	if (sys_absolute(rel) || dir == 0)
		return xstrdup(rel);
	p = xmalloc(dir + strlen(rel) + 1);
	memcpy(p, from, dir);
	strcpy(p + dir, rel);
	return p;
}
