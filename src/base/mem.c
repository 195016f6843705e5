/* mem.c - allocation wrappers; the only place an allocation failure is handled. */
#define _DEFAULT_SOURCE		/* madvise() and MADV_HUGEPAGE, on Linux */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* configure's test-madv_hugepage.c: Linux's, in its own words. */
#if HAVE_MADV_HUGEPAGE
#include <sys/mman.h>
#endif

#include "base/diag.h"
#include "base/mem.h"

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

/*
 * n zeroed items of sz bytes for an array of a million or more organs:
 * on Linux in huge pages where the kernel gives them on request, which
 * spares it a page fault every 4 KiB (a tenth of the time of placing a
 * million primordia went to those).  calloc() of that size maps fresh
 * zero pages, so nothing is cleared twice.
 */
#define HUGE_PAGE	(2u << 20)

void *
xcalloc_big(size_t n, size_t sz)
{
	void *p = xcalloc(n, sz);

#if HAVE_MADV_HUGEPAGE
	/* The whole huge pages inside, before anything touches them. */
	if (sz != 0 && n >= 8 * HUGE_PAGE / sz) {
		uintptr_t a = ((uintptr_t)p + HUGE_PAGE - 1) & ~(uintptr_t)
		    (HUGE_PAGE - 1);
		uintptr_t b = ((uintptr_t)p + n * sz) & ~(uintptr_t)
		    (HUGE_PAGE - 1);

		if (b > a)
			madvise((void *)a, b - a, MADV_HUGEPAGE);
	}
#endif
	return p;
}

char *
xstrdup(const char *s)
{
	size_t len = strlen(s) + 1;

	return memcpy(xmalloc(len), s, len);
}
