/*
 * test_geometry.c - exact angles: angle_mod360 against a long double
 * reference up to n = 1e7.  Each check prints "ok - what" or
 * "not ok - what"; tests/run.sh counts them.
 */
#include <math.h>
#include <stdio.h>

#include "geometry/geometry.h"
#include "models/model.h"
#include "check.h"

/*
 * Whether fma() rounds once and long double has 64 bits, as on real
 * hardware; valgrind emulates neither, and the exactness check below
 * would then measure the emulator.
 */
static int
exact_arithmetic(void)
{
	volatile double a = 1 + 0x1p-30, p = a * a;
	volatile long double one = 1;

	return fma(a, a, -p) == 0x1p-60 && one + 0x1p-60L != one;
}

static void
test_angle(void)
{
	const double alpha = 137.50776405003785;
	double worst = 0;

	/*
	 * The long double product carries 64 bits, enough to show the
	 * 1e-7 degree error a plain double product would make.
	 */
	for (long n = 1; n <= 10000000; n += 9973) {
		long double ref = fmodl((long double)n * (long double)alpha,
		    360.0L);
		double got = angle_mod360((double)n, alpha);

		worst = fmax(worst, fabs((double)(ref - (long double)got)));
	}
	if (exact_arithmetic())
		check(worst < 2e-10, "angle_mod360 exact to %.2g degree up "
		    "to n = 1e7", worst);
	else
		printf("ok - # SKIP angle_mod360 exactness: fma() or long "
		    "double is emulated here (valgrind?)\n");
	check(angle_mod360(3, -90) == 90, "angle_mod360 of a negative "
	    "divergence lies in [0, 360)");
}

int
main(void)
{
	test_angle();
	return check_failures != 0;
}
