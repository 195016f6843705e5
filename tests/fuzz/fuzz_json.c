/*
 * fuzz_json.c - libFuzzer harness for json_string(): any bytes make a
 * JSON string that a strict reader takes (quotes, escapes, no control
 * characters, valid UTF-8) and that reads back as the input, each byte
 * that was no part of valid UTF-8 made U+FFFD.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "writers/json.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The code point of the UTF-8 sequence at s (n bytes left), or -1. */
static long
decode(const unsigned char *s, size_t n, size_t *len)
{
	static const unsigned char lead[] = { 0, 0xc0, 0xe0, 0xf0 };
	static const long least[] = { 0, 0x80, 0x800, 0x10000 };
	long c;
	size_t k;

	if (s[0] < 0x80) {
		*len = 1;
		return s[0];
	}
	for (k = 3; k > 0; k--)
		if ((s[0] & (0xff << (6 - k))) == (lead[k] & (0xff << (6 - k))) &&
		    (s[0] & (0x40 >> k)) == 0)
			break;
	if (k == 0 || k + 1 > n)
		return -1;
	c = s[0] & (0x3f >> k);
	for (size_t i = 1; i <= k; i++) {
		if ((s[i] & 0xc0) != 0x80)
			return -1;
		c = c << 6 | (s[i] & 0x3f);
	}
	if (c < least[k] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff))
		return -1;
	*len = k + 1;
	return c;
}

static int
hex(int c)
{
	return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ?
	    c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *in = malloc(size + 1);
	const unsigned char *p, *q, *end;
	struct sink s;
	size_t len, n;

	if (in == NULL)
		return 0;
	memcpy(in, data, size);
	in[size] = '\0';
	n = strlen(in);		/* a C string ends at its first NUL */
	sink_init(&s, NULL);
	json_string(&s, in);
	if (s.len < 2 || s.buf[0] != '"' || s.buf[s.len - 1] != '"')
		abort();
	/* Read the string back, holding it to the input as it goes. */
	p = (const unsigned char *)s.buf + 1;
	end = (const unsigned char *)s.buf + s.len - 1;
	q = (const unsigned char *)in;
	while (p < end) {
		long c, want;
		size_t wl;

		if (*p < 0x20 || *p == '"')
			abort();
		if (*p == '\\') {
			if (p + 1 >= end)
				abort();
			switch (p[1]) {
			case '"': case '\\': case '/':
				c = p[1];
				p += 2;
				break;
			case 'b': c = '\b'; p += 2; break;
			case 'f': c = '\f'; p += 2; break;
			case 'n': c = '\n'; p += 2; break;
			case 'r': c = '\r'; p += 2; break;
			case 't': c = '\t'; p += 2; break;
			case 'u':
				if (end - p < 6)
					abort();
				c = 0;
				for (int i = 2; i < 6; i++) {
					if (hex(p[i]) < 0)
						abort();
					c = c * 16 + hex(p[i]);
				}
				if (c >= 0xd800 && c <= 0xdfff)
					abort();	/* no surrogate pairs made */
				p += 6;
				break;
			default:
				abort();
			}
		} else if ((c = decode(p, (size_t)(end - p), &len)) < 0)
			abort();	/* the output must be UTF-8 */
		else
			p += len;
		/* The input's next character, or U+FFFD for a stray byte. */
		if (q >= (const unsigned char *)in + n)
			abort();
		want = decode(q, (size_t)((const unsigned char *)in + n - q),
		    &wl);
		if (want < 0) {
			want = 0xfffd;
			wl = 1;
		}
		if (c != want)
			abort();
		q += wl;
	}
	if (q != (const unsigned char *)in + n)
		abort();
	sink_free(&s);
	free(in);
	return 0;
}
