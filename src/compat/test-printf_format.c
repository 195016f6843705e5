/*
 * test-printf_format.c - configure: whether the compiler checks a
 * printf-like function's %zu as C99 says, with -DPRINTF_FORMAT=NAME
 * as the format attribute's archetype (mingw's gcc takes "printf" as
 * Microsoft's formats).
 */
#include <stddef.h>
#include <stdio.h>

void	say(const char *, ...) __attribute__((format(PRINTF_FORMAT, 1, 2)));

void
say(const char *fmt, ...)
{
	(void)fmt;
}

int
main(void)
{
	size_t n = sizeof(n);

	say("%zu %lld", n, (long long)n);
	return 0;
}
