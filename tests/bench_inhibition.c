/*
 * bench_inhibition.c - the inhibition model's speed (make bench): 100,000
 * primordia with the far field, and side by side with the plain all-pairs
 * sum at 5,000, one core.
 */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "model.h"
#include "scene.h"
#include "clock.h"

/* Seconds to place count primordia at growth G; -1 on error. */
static double
run(long count, double G, int all_pairs, double *settled)
{
	char text[256];
	struct scene sc;
	struct result res = { 0 };
	double t0, t;

	snprintf(text, sizeof(text), "model = \"inhibition\";\ncount = %ld;\n"
	    "inhibition = { growth = %.9g; };\n", count, G);
	if (scene_load_buffer(&sc, "bench.cfg", text, strlen(text)) != 0)
		return -1;
	t0 = now();
	if (inhibition_place(&sc, &res, all_pairs ? INHIB_ALL_PAIRS : 0) != 0) {
		scene_free(&sc);
		return -1;
	}
	t = now() - t0;
	*settled = res.divergence;
	result_free(&res);
	scene_free(&sc);
	return t;
}

/* Enough primordia at each G for a tenth of a second or so. */
static const struct {
	long		 count;
	double		 G;
} sweep[] = { { 2000, 0.3 }, { 6000, 0.1 }, { 30000, 0.02 },
    { 20000, 0.002 }, { 5000, 0.001 } };

int
main(void)
{
	double s1, s2, s3, t1, t2, t3;

	t1 = run(100000, 0.005, 0, &s1);
	printf("power law, G = 0.005, 100000 primordia with the far field: "
	    "%.2f s = %.1f us each (settled at %.4f degrees)\n", t1,
	    t1 / 100000 * 1e6, s1);
	t2 = run(5000, 0.005, 0, &s2);
	t3 = run(5000, 0.005, 1, &s3);
	printf("side by side, 5000 primordia: far field %.3f s, all pairs %.3f "
	    "s: %.1fx (settled %.6f and %.6f)\n", t2, t3, t3 / t2, s2, s3);
	/*
	 * The cost a primordium against G: the slower the growth, the more
	 * primordia are near and the more gaps the circle has.
	 */
	for (size_t i = 0; i < sizeof(sweep) / sizeof(sweep[0]); i++) {
		double s, t = run(sweep[i].count, sweep[i].G, 0, &s);

		if (t < 0)
			return 1;
		printf("G = %g, %ld primordia: %.1f us each (settled at %.4f "
		    "degrees)\n", sweep[i].G, sweep[i].count, t /
		    (double)sweep[i].count * 1e6, s);
	}
	return t1 < 0 || t2 < 0 || t3 < 0;
}
