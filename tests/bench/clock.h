/* clock.h - the benchmarks' one clock: monotonic seconds. */
#ifndef CLOCK_H
#define CLOCK_H

#include <time.h>

static double
now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

#endif
