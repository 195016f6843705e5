/* test-madv_hugepage.c - configure: asking Linux for huge pages. */
#define _DEFAULT_SOURCE
#include <stdlib.h>
#include <sys/mman.h>

int
main(void)
{
	size_t sz = 4u << 20;
	char *p = malloc(sz);

	if (p != NULL)
		(void)madvise(p + (2u << 20) - ((size_t)p & ((2u << 20) - 1)),
		    2u << 20, MADV_HUGEPAGE);
	free(p);
	return 0;
}
