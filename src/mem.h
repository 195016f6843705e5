/* mem.h - allocation wrappers: running out of memory ends the program here. */
#ifndef MEM_H
#define MEM_H

#include <stddef.h>

void	*xmalloc(size_t);
void	*xcalloc(size_t, size_t);
void	*xreallocarray(void *, size_t, size_t);
void	*xcalloc_big(size_t, size_t);
char	*xstrdup(const char *);

#endif
