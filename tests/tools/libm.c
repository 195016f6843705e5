/*
 * libm.c - the C library's maths functions that the program calls, on
 * the same arguments in every build, to say which of them a build's C
 * library computes differently (tests/windows.sh: mingw-w64's and
 * wine's msvcrt against glibc):
 *	libm		each function's results, as hexadecimal floats
 *	libm FILE	each function's results held against FILE's (the
 *			other build's output): how many differ, by how
 *			many units in the last place at most
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ARGS	2000

/* Arguments spread over lo .. hi by the golden ratio's fractions. */
static double
arg(int k, double lo, double hi)
{
	double f = fmod(0.5 + k * 0.61803398874989485, 1.0);

	return lo + (hi - lo) * f;
}

static double f_sin(double x, double y) { (void)y; return sin(x); }
static double f_cos(double x, double y) { (void)y; return cos(x); }
static double f_tan(double x, double y) { (void)y; return tan(x); }
static double f_asin(double x, double y) { (void)y; return asin(x); }
static double f_acos(double x, double y) { (void)y; return acos(x); }
static double f_atan(double x, double y) { (void)y; return atan(x); }
static double f_atan2(double x, double y) { return atan2(y, x); }
static double f_exp(double x, double y) { (void)y; return exp(x); }
static double f_expm1(double x, double y) { (void)y; return expm1(x); }
static double f_log(double x, double y) { (void)y; return log(x); }
static double f_log10(double x, double y) { (void)y; return log10(x); }
static double f_log1p(double x, double y) { (void)y; return log1p(x); }
static double f_pow(double x, double y) { return pow(x, y); }
static double f_hypot(double x, double y) { return hypot(x, y); }
static double f_sqrt(double x, double y) { (void)y; return sqrt(x); }
static double f_fmod(double x, double y) { return fmod(x, y); }
static double f_remainder(double x, double y) { return remainder(x, y); }

static const struct fn {
	const char	*name;
	double		(*f)(double, double);
	double		 lo, hi, ylo, yhi;
} fns[] = {
	{ "sin", f_sin, -20, 20, 0, 0 },
	{ "cos", f_cos, -20, 20, 0, 0 },
	{ "tan", f_tan, -1.5, 1.5, 0, 0 },
	{ "asin", f_asin, -1, 1, 0, 0 },
	{ "acos", f_acos, -1, 1, 0, 0 },
	{ "atan", f_atan, -50, 50, 0, 0 },
	{ "atan2", f_atan2, -3, 3, -3, 3 },
	{ "exp", f_exp, -40, 40, 0, 0 },
	{ "expm1", f_expm1, -2, 2, 0, 0 },
	{ "log", f_log, 1e-6, 1e6, 0, 0 },
	{ "log10", f_log10, 1e-6, 1e6, 0, 0 },
	{ "log1p", f_log1p, -0.9, 10, 0, 0 },
	{ "pow", f_pow, 1e-3, 20, -4, 4 },
	{ "hypot", f_hypot, -10, 10, -10, 10 },
	{ "sqrt", f_sqrt, 0, 1e4, 0, 0 },
	{ "fmod", f_fmod, -1e4, 1e4, 0.1, 7 },
	{ "remainder", f_remainder, -1e4, 1e4, 0.1, 7 },
};
#define NFNS	(sizeof(fns) / sizeof(fns[0]))

/* Units in the last place between two doubles of one sign. */
static uint64_t
ulps(double a, double b)
{
	int64_t x, y;

	memcpy(&x, &a, sizeof(x));
	memcpy(&y, &b, sizeof(y));
	if (x < 0)
		x = INT64_MIN - x;
	if (y < 0)
		y = INT64_MIN - y;
	return x > y ? (uint64_t)x - (uint64_t)y : (uint64_t)y - (uint64_t)x;
}

int
main(int argc, char *argv[])
{
	FILE *other = NULL;

	if (argc > 2 || (argc == 2 && (other = fopen(argv[1], "r")) == NULL)) {
		fprintf(stderr, "usage: libm [FILE]\n");
		return 2;
	}
	for (size_t i = 0; i < NFNS; i++) {
		const struct fn *f = &fns[i];
		uint64_t worst = 0;
		int differ = 0;

		for (int k = 0; k < ARGS; k++) {
			double x = arg(k, f->lo, f->hi);
			double y = arg(k + 7919, f->ylo, f->yhi);
			double r = f->f(x, y), theirs;
			char name[32];

			if (other == NULL) {
				printf("%s %a\n", f->name, r);
				continue;
			}
			if (fscanf(other, "%31s %la", name, &theirs) != 2 ||
			    strcmp(name, f->name) != 0) {
				fprintf(stderr, "libm: %s: not libm's output\n",
				    argv[1]);
				return 1;
			}
			if (memcmp(&r, &theirs, sizeof(r)) != 0) {
				uint64_t u = ulps(r, theirs);

				differ++;
				worst = u > worst ? u : worst;
			}
		}
		if (other != NULL && differ > 0)
			printf("%-10s %4d of %d differ, by %llu ulp at most\n",
			    f->name, differ, ARGS, (unsigned long long)worst);
		else if (other != NULL)
			printf("%-10s the same\n", f->name);
	}
	if (other != NULL)
		fclose(other);
	return fflush(stdout) != 0;
}
