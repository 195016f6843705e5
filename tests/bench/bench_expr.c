/*
 * bench_expr.c - evaluations per second of a 10-operator expression,
 * side by side with the same formula compiled by the C compiler.
 */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "base/expr.h"

#define SRC "0.05 - 0.02 * t + sin(phi * pi / 180) * r ^ 2 / (1 + n)"

static double
now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* The same formula in C; volatile inputs keep it from being hoisted. */
static double
native(const volatile double *v)
{
	return 0.05 - 0.02 * v[V_T] + sin(v[V_PHI] * M_PI / 180) *
	    pow(v[V_R], 2) / (1 + v[V_N]);
}

int
main(void)
{
	enum { N = 20000000 };
	struct expr_error err;
	struct expr *e = expr_compile(SRC, EXPR_ALL, &err);
	struct expr_env env = { { 0 }, 1, 0 };
	volatile double vin[V__MAX];
	double t0, t1, t2, sum = 0, x;

	if (e == NULL)
		return 1;
	env.var[V_R] = 0.3;
	t0 = now();
	for (long i = 0; i < N; i++) {
		env.var[V_N] = (double)i;
		env.var[V_T] = (double)i / N;
		env.var[V_PHI] = (double)(i % 360);
		expr_eval(e, &env, &x);
		sum += x;
	}
	t1 = now();
	vin[V_R] = 0.3;
	for (long i = 0; i < N; i++) {
		vin[V_N] = (double)i;
		vin[V_T] = (double)i / N;
		vin[V_PHI] = (double)(i % 360);
		sum -= native(vin);
	}
	t2 = now();
	printf("expression \"%s\" (10 operators):\n  ours %.1f M evaluations/s, "
	    "compiled C %.1f M/s, ratio %.1fx (residual %.2g)\n", SRC,
	    N / (t1 - t0) / 1e6, N / (t2 - t1) / 1e6, (t1 - t0) / (t2 - t1),
	    sum);
	expr_free(e);
	return 0;
}
