/* mem.c - allocation wrappers; the only place an allocation failure is handled. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "mem.h"

/*
 * Nothing useful can be written once memory is gone, and every caller
 * would have to unwind the same way, so we stop here with the system
 * status; -o's temporary file is removed by the atexit handler.
 */
static void
nomem(void)
{
	diag(ST_SYSTEM, NULL, 0, 0, "out of memory");
	exit(ST_SYSTEM);
}

void *
xmalloc(size_t sz)
{
	void *p = malloc(sz ? sz : 1);

	if (p == NULL)
		nomem();
	return p;
}

void *
xcalloc(size_t n, size_t sz)
{
	void *p = calloc(n ? n : 1, sz ? sz : 1);

	if (p == NULL)
		nomem();
	return p;
}

void *
xreallocarray(void *old, size_t n, size_t sz)
{
	void *p;

	if (sz != 0 && n > SIZE_MAX / sz)
		nomem();
	p = realloc(old, n * sz > 0 ? n * sz : 1);
	if (p == NULL)
		nomem();
	return p;
}

/* size bytes aligned to align (a power of two dividing size's multiple). */
void *
xaligned(size_t align, size_t sz)
{
	size_t whole = (sz + align - 1) / align * align;
	void *p = aligned_alloc(align, whole ? whole : align);

	if (p == NULL)
		nomem();
	return p;
}

char *
xstrdup(const char *s)
{
	size_t len = strlen(s) + 1;

	return memcpy(xmalloc(len), s, len);
}
