/*
 * numfmt.c - format a double with 9 significant digits, like "%.9g".
 *
 * Why not printf: writing a million organs means fourteen million
 * numbers, and glibc's "%.9g" takes about 150 ns each, which alone caps
 * CSV output near 0.5 M organs/s.  Nine digits are far more than the
 * geometry needs (tests check 1e-6) and fewer than a double holds, so
 * we scale by an exact power of ten, round to a 9-digit integer and
 * print its digits.  The result can differ from printf's in the last
 * digit when the scaled value lies within an ulp of a rounding tie; it
 * always parses back to within one unit of the ninth digit.  Anything
 * outside the range where the powers of ten are exact falls back to
 * snprintf.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/numfmt.h"

static const double p10[] = {
	1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
	1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
};

/* round(a * 10^k) for |k| <= 22; the power itself is exact. */
static uint64_t
scaled(double a, int k)
{
	return (uint64_t)((k >= 0 ? a * p10[k] : a / p10[-k]) + 0.5);
}

/* "00" to "99", for writing two digits at a time. */
static const char pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233"
    "34353637383940414243444546474849505152535455565758596061626364656667"
    "6869707172737475767778798081828384858687888990919293949596979899";

size_t
num_format(char *out, double x)
{
	char digits[9], *p = out;
	double a = fabs(x);
	uint64_t bits, m;
	uint32_t v;
	int e, nd;

	if (a == 0.0) {
		out[0] = '0';
		out[1] = '\0';
		return 1;
	}
	if (!isfinite(x) || a < 1e-13 || a >= 1e13)
		return (size_t)snprintf(out, NUMFMT_MAX, "%.9g", x);

	/*
	 * The decimal exponent from the binary one, which log10() would
	 * give at twice the cost: 2^b <= a < 2^(b+1) puts floor(log10 a)
	 * within one of b log10(2), and the checks on m settle it.
	 */
	memcpy(&bits, &a, sizeof(bits));
	e = (int)(((int)(bits >> 52) - 1023) * 0.30102999566398120);
	m = scaled(a, 8 - e);
	if (m >= 1000000000u) {
		e++;
		m = scaled(a, 8 - e);
	}
	if (m < 100000000u) {
		e--;
		m = scaled(a, 8 - e);
	}
	/* Rounding up 999999999.5 gives 1e9: one digit more. */
	if (m >= 1000000000u) {
		e++;
		m = scaled(a, 8 - e);
	}
	v = (uint32_t)m;
	for (int i = 7; i > 0; i -= 2, v /= 100)
		memcpy(digits + i, pairs + 2 * (v % 100), 2);
	digits[0] = (char)('0' + v);
	for (nd = 9; nd > 1 && digits[nd - 1] == '0'; nd--)
		continue;

	if (x < 0)
		*p++ = '-';
	if (e >= 9 || e < -4) {
		/* Exponent form, where %.9g uses it: d.ddde+XX. */
		*p++ = digits[0];
		if (nd > 1) {
			*p++ = '.';
			memcpy(p, digits + 1, (size_t)nd - 1);
			p += nd - 1;
		}
		p += sprintf(p, "e%c%02d", e < 0 ? '-' : '+', e < 0 ? -e : e);
		return (size_t)(p - out);
	}
	if (e >= 0) {
		/* e + 1 integer digits; 9 digits cover e <= 8. */
		memcpy(p, digits, (size_t)e + 1);
		p += e + 1;
		if (nd > e + 1) {
			*p++ = '.';
			memcpy(p, digits + e + 1, (size_t)(nd - e - 1));
			p += nd - e - 1;
		}
	} else {
		*p++ = '0';
		*p++ = '.';
		for (int i = -1; i > e; i--)
			*p++ = '0';
		memcpy(p, digits, (size_t)nd);
		p += nd;
	}
	*p = '\0';
	return (size_t)(p - out);
}
