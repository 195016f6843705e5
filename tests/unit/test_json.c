/*
 * test_json.c - JSON strings and numbers: escapes, UTF-8 kept, every
 * byte that is no part of UTF-8 made U+FFFD (against RFC 3629's table,
 * not json.c's own test), and numbers that read back the same.
 * Prints "ok - what" / "not ok - what" lines for tests/run.sh.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "writers/json.h"
#include "check.h"

/* json_string(in) as a C string; the caller frees it. */
static char *
jstr(const char *in)
{
	struct sink s;
	char *out;

	sink_init(&s, NULL);
	json_string(&s, in);
	out = malloc(s.len + 1);
	if (out == NULL)
		abort();
	memcpy(out, s.buf, s.len);
	out[s.len] = '\0';
	sink_free(&s);
	return out;
}

static void
string(const char *in, const char *want, const char *what)
{
	char *got = jstr(in);

	check(strcmp(got, want) == 0, "json_string: %s (got %s)", what, got);
	free(got);
}

/*
 * RFC 3629's table: the length of the UTF-8 sequence that starts with
 * lead byte b and second byte c, or 0 if there is none.  The bytes
 * after the second are 0x80 in the test below, always continuations.
 */
static int
rfc3629_len(unsigned b, unsigned c)
{
	int cont = c >= 0x80 && c <= 0xbf;

	if (b >= 0xc2 && b <= 0xdf)
		return cont ? 2 : 0;
	if (b == 0xe0)
		return c >= 0xa0 && c <= 0xbf ? 3 : 0;
	if ((b >= 0xe1 && b <= 0xec) || b == 0xee || b == 0xef)
		return cont ? 3 : 0;
	if (b == 0xed)
		return c >= 0x80 && c <= 0x9f ? 3 : 0;
	if (b == 0xf0)
		return c >= 0x90 && c <= 0xbf ? 4 : 0;
	if (b >= 0xf1 && b <= 0xf3)
		return cont ? 4 : 0;
	if (b == 0xf4)
		return c >= 0x80 && c <= 0x8f ? 4 : 0;
	return 0;	/* 80-c1 and f5-ff lead nothing */
}

/* Every lead byte before every continuation byte, then two more. */
static void
test_every_lead(void)
{
	int bad = 0, kept = 0;

	for (unsigned b = 0x80; b <= 0xff; b++)
		for (unsigned c = 0x80; c <= 0xbf; c++) {
			char in[5] = { (char)b, (char)c, (char)0x80,
			    (char)0x80, '\0' };
			char want[32] = "\"", *got;
			int n = rfc3629_len(b, c);

			/* The sequence kept, or its lead byte made U+FFFD;
			 * each continuation byte left over is stray. */
			if (n > 0) {
				memcpy(want + 1, in, (size_t)n);
				want[n + 1] = '\0';
			}
			for (int i = n > 0 ? n : 0; i < 4; i++)
				strcat(want, "\\ufffd");
			strcat(want, "\"");
			got = jstr(in);
			if (strcmp(got, want) != 0) {
				if (bad++ < 5)
					printf("# %02x %02x 80 80: got %s\n",
					    b, c, got);
			}
			kept += n > 0;
			free(got);
		}
	check(bad == 0, "json_string: every lead byte 80-ff before every "
	    "continuation byte, as RFC 3629's table says (%d of %d wrong, "
	    "%d sequences kept)", bad, 128 * 64, kept);
}

static void
test_string(void)
{
	string("", "\"\"", "empty");
	string("a\"b\\c\001d\n\x7f" "e", "\"a\\\"b\\\\c\\u0001d\\n\\u007fe\"",
	    "quote, backslash, control characters escaped");
	string("Bl\303\274te \342\202\254 \360\237\214\273 \364\217\277\277",
	    "\"Bl\303\274te \342\202\254 \360\237\214\273 \364\217\277\277\"",
	    "UTF-8 of 2, 3 and 4 bytes and U+10FFFF kept");
	string("x\377y", "\"x\\ufffdy\"", "a stray byte is U+FFFD");
	/* The fuzz_json input: ff before two continuation bytes was
	 * taken for a 3-byte sequence and written out raw. */
	string("\241p\377\241\241\241",
	    "\"\\ufffdp\\ufffd\\ufffd\\ufffd\\ufffd\"",
	    "ff a1 a1 is three stray bytes, not a sequence (fuzz_json)");
	string("\370\210\200\200\200", "\"\\ufffd\\ufffd\\ufffd\\ufffd\\ufffd\"",
	    "a 5-byte form is five stray bytes");
	string("\300\200 \340\200\200 \355\240\200 \360\200\200\200 "
	    "\364\220\200\200", "\"\\ufffd\\ufffd \\ufffd\\ufffd\\ufffd "
	    "\\ufffd\\ufffd\\ufffd \\ufffd\\ufffd\\ufffd\\ufffd "
	    "\\ufffd\\ufffd\\ufffd\\ufffd\"",
	    "overlong, surrogate and past U+10FFFF forms are stray bytes");
	string("\342\202", "\"\\ufffd\\ufffd\"",
	    "a sequence cut short by the end is stray bytes");
	test_every_lead();
}

static void
number(double x, const char *want)
{
	struct sink s;

	sink_init(&s, NULL);
	json_number(&s, x);
	check(s.len == strlen(want) && memcmp(s.buf, want, s.len) == 0,
	    "json_number: %s (got %.*s)", want, (int)s.len, s.buf);
	sink_free(&s);
}

static void
test_number(void)
{
	number(0, "0");
	number(0.1, "0.1");
	number(1.0 / 3, "0.3333333333333333");
	number(-2.5e-300, "-2.5e-300");
	number(NAN, "null");
	number(INFINITY, "null");
	number(-INFINITY, "null");
}

int
main(void)
{
	test_string();
	test_number();
	return check_failures != 0;
}
