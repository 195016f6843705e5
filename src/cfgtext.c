/*
 * cfgtext.c - prepare a scene file's text for libconfig.
 *
 * libconfig 1.5 (Debian 12) has two blind spots we must cover before it
 * parses: it silently truncates a string at a NUL byte, and it keeps an
 * integer literal without an L suffix in 32 bits, wrapping larger ones
 * (count = 20000000000 arrives as -1474836480).  We reject NULs with
 * their line, and append the L suffix to every integer literal that does
 * not fit in 32 bits, so the range checks see the number as written.
 * Line numbers are unchanged.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "cfgtext.h"
#include "mem.h"

/* Length of the comment or string at p, or 0 if none starts there. */
static size_t
skip_inert(const char *p, const char *end)
{
	const char *q = p;

	if (*p == '#' || (*p == '/' && p + 1 < end && p[1] == '/')) {
		while (q < end && *q != '\n')
			q++;
	} else if (*p == '/' && p + 1 < end && p[1] == '*') {
		for (q = p + 2; q < end; q++)
			if (*q == '*' && q + 1 < end && q[1] == '/') {
				q += 2;
				break;
			}
		if (q > end)
			q = end;
	} else if (*p == '"') {
		for (q = p + 1; q < end && *q != '"'; q++)
			if (*q == '\\' && q + 1 < end)
				q++;
		if (q < end)
			q++;
	}
	return (size_t)(q - p);
}

/* How many of the characters in [p, end) are in set, from the start. */
static size_t
span(const char *p, const char *end, const char *set)
{
	const char *q = p;

	while (q < end && strchr(set, *q) != NULL)
		q++;
	return (size_t)(q - p);
}

/* Does the integer literal of n characters at p fit in a C int? */
static int
fits_int(const char *p, size_t n)
{
	char buf[64];
	long long v;

	if (n >= sizeof(buf))
		return 0;
	memcpy(buf, p, n);
	buf[n] = '\0';
	errno = 0;
	v = strtoll(buf, NULL, 0);
	return errno == 0 && v <= INT_MAX;
}

char *
cfgtext_prepare(const char *text, size_t len, int *nul_line)
{
	const char *p = text, *end = text + len;
	char *out = xmalloc(len + len / 2 + 2), *o = out;
	int line = 1;

	*nul_line = 0;
	for (const char *q = text; q < end; q++) {
		if (*q == '\0') {
			*nul_line = line;
			free(out);
			return NULL;
		}
		line += *q == '\n';
	}
	while (p < end) {
		size_t n = skip_inert(p, end);

		if (n > 0) {
			memcpy(o, p, n);
			o += n;
			p += n;
			continue;
		}
		/* A number starts at a digit not inside a word. */
		if (isdigit((unsigned char)*p) && (p == text ||
		    !(isalnum((unsigned char)p[-1]) || p[-1] == '_' ||
		    p[-1] == '.'))) {
			const char *q = p;

			int hex = end - p > 1 && p[0] == '0' &&
			    (p[1] == 'x' || p[1] == 'X');

			while (q < end && (isalnum((unsigned char)*q) ||
			    *q == '_' || *q == '.' || ((*q == '-' ||
			    *q == '+') && (q[-1] == 'e' || q[-1] == 'E') &&
			    !hex)))
				q++;
			memcpy(o, p, (size_t)(q - p));
			o += q - p;
			/* Only plain digits, or 0x and hex digits, are integers. */
			if (span(p, q, "0123456789") == (size_t)(q - p) ||
			    (hex && q - p > 2 && span(p + 2, q,
			    "0123456789abcdefABCDEF") == (size_t)(q - p - 2)))
				if (!fits_int(p, (size_t)(q - p)))
					*o++ = 'L';
			p = q;
			continue;
		}
		*o++ = *p++;
	}
	*o = '\0';
	return out;
}

/* A setting's string value fit for a one-line message. */
void
cfgtext_quote(char *dst, size_t sz, const char *s)
{
	static const char hex[] = "0123456789abcdef";
	size_t i = 0;

	for (; *s != '\0' && i + 5 < sz; s++) {
		unsigned char c = (unsigned char)*s;

		if (c >= 0x20 && c < 0x7f && c != '\\')
			dst[i++] = (char)c;
		else {
			dst[i++] = '\\';
			dst[i++] = 'x';
			dst[i++] = hex[c >> 4];
			dst[i++] = hex[c & 15];
		}
	}
	if (*s != '\0' && i + 3 < sz) {
		memcpy(dst + i, "...", 3);
		i += 3;
	}
	dst[i] = '\0';
}
