/*
 * mem.h - allocation wrappers: running out of memory ends the program
 * here.  And PREFETCH(): ask for memory's line ahead of its use, where
 * the compiler can (gcc, clang).
 */
#ifndef MEM_H
#define MEM_H

#include <stddef.h>

void	*xmalloc(size_t);
void	*xcalloc(size_t, size_t);
void	*xreallocarray(void *, size_t, size_t);
void	*xcalloc_big(size_t, size_t);
char	*xstrdup(const char *);

#if defined(__GNUC__)
#define PREFETCH(p)	__builtin_prefetch(p)
#else
#define PREFETCH(p)	((void)(p))
#endif

#endif
