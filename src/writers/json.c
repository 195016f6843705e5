/* json.c - JSON strings and numbers, for --settings and --gltf. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "writers/json.h"

/* The length of the UTF-8 sequence at p, or 0 if it is not one. */
static size_t
utf8_len(const unsigned char *p)
{
	/* Bounded above too: f5-ff lead nothing, and taken as 3-byte
	 * leads they let raw non-UTF-8 through (ff a1 a1 was copied). */
	size_t n = p[0] >= 0xf0 && p[0] <= 0xf4 ? 4 :
	    p[0] >= 0xe0 && p[0] < 0xf0 ? 3 :
	    p[0] >= 0xc2 && p[0] < 0xe0 ? 2 : 0;

	for (size_t i = 1; i < n; i++)
		if ((p[i] & 0xc0) != 0x80)
			return 0;
	/* Overlong, surrogate and past U+10FFFF forms are not UTF-8. */
	if ((n == 3 && ((p[0] == 0xe0 && p[1] < 0xa0) ||
	    (p[0] == 0xed && p[1] >= 0xa0))) ||
	    (n == 4 && ((p[0] == 0xf0 && p[1] < 0x90) ||
	    (p[0] == 0xf4 && p[1] >= 0x90))))
		return 0;
	return n;
}

void
json_string(struct sink *s, const char *str)
{
	static const char hex[] = "0123456789abcdef";
	const unsigned char *p = (const unsigned char *)str;

	sink_putc(s, '"');
	while (*p != '\0') {
		size_t n;

		if (*p == '"' || *p == '\\') {
			sink_putc(s, '\\');
			sink_putc(s, (char)*p++);
		} else if (*p == '\n') {
			sink_puts(s, "\\n");
			p++;
		} else if (*p < 0x20 || *p == 0x7f) {
			sink_puts(s, "\\u00");
			sink_putc(s, hex[*p >> 4]);
			sink_putc(s, hex[*p & 15]);
			p++;
		} else if (*p < 0x80) {
			sink_putc(s, (char)*p++);
		} else if ((n = utf8_len(p)) > 0) {
			sink_write(s, (const char *)p, n);
			p += n;
		} else {
			sink_puts(s, "\\ufffd");
			p++;
		}
	}
	sink_putc(s, '"');
}

void
json_number(struct sink *s, double x)
{
	char buf[40];

	if (!isfinite(x)) {
		sink_puts(s, "null");
		return;
	}
	for (int digits = 15; digits <= 17; digits++) {
		snprintf(buf, sizeof(buf), "%.*g", digits, x);
		if (strtod(buf, NULL) == x)
			break;
	}
	sink_puts(s, buf);
}
