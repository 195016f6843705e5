/*
 * test_numfmt.c - the number formatter against printf's %.9g: nine
 * significant digits, the same text but for rare rounding ties.  Each
 * check prints "ok - what" or "not ok - what"; tests/run.sh counts them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/numfmt.h"
#include "check.h"

/* A deterministic stream of doubles for the formatter checks. */
static unsigned long long rng = 0x9e3779b97f4a7c15ull;

static double
uniform(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return (double)(rng >> 11) / 9007199254740992.0;
}

static void
test_numfmt(void)
{
	char ours[NUMFMT_MAX], ref[NUMFMT_MAX];
	double worst = 0;
	long differ = 0, n = 300000;

	for (long i = 0; i < n; i++) {
		double x = (uniform() - 0.5) * pow(10, floor(uniform() * 30) - 15);
		double back;

		num_format(ours, x);
		snprintf(ref, sizeof(ref), "%.9g", x);
		back = strtod(ours, NULL);
		if (x != 0)
			worst = fmax(worst, fabs(back - x) / fabs(x));
		differ += strcmp(ours, ref) != 0;
	}
	check(worst <= 5.0000001e-9, "numfmt: 9 significant digits "
	    "(worst relative error %.3g over %ld numbers)", worst, n);
	/* Only rounding ties may differ from printf, and they are rare. */
	check(differ * 10000 < n, "numfmt: same text as %%.9g "
	    "(%ld of %ld differ)", differ, n);
	num_format(ours, 0.0);
	check(strcmp(ours, "0") == 0, "numfmt: zero is \"0\"");
	num_format(ours, -0.0);
	check(strcmp(ours, "0") == 0, "numfmt: negative zero is \"0\"");
	num_format(ours, 1e-5);
	check(strcmp(ours, "1e-05") == 0, "numfmt: 1e-5 as %%g writes it");
	num_format(ours, 123456789.0);
	check(strcmp(ours, "123456789") == 0, "numfmt: 9-digit integer");
	num_format(ours, 0.1 + 0.2);
	check(strcmp(ours, "0.3") == 0, "numfmt: 0.1 + 0.2 is 0.3");
}

int
main(void)
{
	test_numfmt();
	return check_failures != 0;
}
