/* bench_numfmt.c - our number formatter against printf's "%.9g", timed side by side. */
#include <stdio.h>
#include <time.h>

#include "base/numfmt.h"

static double
now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

int
main(void)
{
	enum { N = 4000000 };
	char buf[NUMFMT_MAX];
	double t0, t1, t2, x = 0.123456789, sum = 0;

	t0 = now();
	for (int i = 0; i < N; i++)
		sum += (double)snprintf(buf, sizeof(buf), "%.9g", x * i);
	t1 = now();
	for (int i = 0; i < N; i++)
		sum += (double)num_format(buf, x * i);
	t2 = now();
	printf("format %d numbers: printf %.0f ns each, num_format %.0f ns "
	    "each, ratio %.1fx (checksum %.0f)\n", N, (t1 - t0) / N * 1e9,
	    (t2 - t1) / N * 1e9, (t1 - t0) / (t2 - t1), sum);
	return 0;
}
