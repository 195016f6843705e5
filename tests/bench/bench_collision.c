/*
 * bench_collision.c - the collision model's speed and memory (make
 * bench): a million primordia on a hemisphere of radius 1 (best of
 * three runs), the same dome at a tenth of the count (same coverage,
 * larger primordia) for the scaling, and the exact walk beside the
 * brute-force reference at about 20,000.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "models/collision.h"
#include "models/model.h"
#include "pipeline/pipeline.h"
#include "scene/scene.h"
#include "clock.h"

/* Seconds to place a full dome of radius-r primordia; count placed. */
static double
run(double r, long long bound, int how, size_t *placed)
{
	char text[512];
	struct scene sc;
	struct model_ctx ctx;
	struct result res = { 0 };
	double t0, t1;

	snprintf(text, sizeof(text), "model = \"collision\";\ncount = %lld;\n"
	    "collision = { receptacle = { shape = \"hemisphere\"; }; "
	    "radius = %.9g; };\n", bound, r);
	if (scene_load_buffer(&sc, "bench.cfg", text, strlen(text)) != 0)
		return -1;
	scene_model_ctx(&sc, &ctx, NULL);
	t0 = now();
	if (collision_place(&ctx, &res, how) != 0)
		return -1;
	t1 = now();
	*placed = res.count;
	result_free(&res);
	scene_free(&sc);
	return t1 - t0;
}

static long
peak_kb(void)
{
	struct rusage ru;

	getrusage(RUSAGE_SELF, &ru);
	return ru.ru_maxrss;
}

int
main(void)
{
	/* Radius 0.0012 fills a unit hemisphere with about 1,000,000. */
	const double r1 = 0.0012;
	size_t n1, n2, n3, n4;
	long base = peak_kb();
	double t1, t2, t3, t4, beyond;

	if ((t1 = run(r1, 2000000, PLACE_EXACT, &n1)) < 0)
		return 1;
	/* Peak memory less what the result itself holds. */
	beyond = ((double)(peak_kb() - base) * 1024 -
	    (double)n1 * sizeof(struct organ)) / (double)n1;
	/* The best of three: this machine's neighbours come and go. */
	for (int i = 0; i < 2; i++) {
		double t = run(r1, 2000000, PLACE_EXACT, &n1);

		if (t < 0)
			return 1;
		t1 = fmin(t1, t);
	}
	printf("exact walk, full dome: %zu primordia in %.2f s = %.2f us "
	    "each, %.2f M/s\n", n1, t1, t1 / (double)n1 * 1e6,
	    (double)n1 / t1 / 1e6);
	printf("memory beyond the output: %.0f bytes per primordium\n",
	    beyond);
	fflush(stdout);
	if ((t2 = run(r1 * sqrt(10), 2000000, PLACE_EXACT, &n2)) < 0)
		return 1;
	for (int i = 0; i < 2; i++) {
		double t = run(r1 * sqrt(10), 2000000, PLACE_EXACT, &n2);

		if (t < 0)
			return 1;
		t2 = fmin(t2, t);
	}
	printf("exact walk, same dome at a tenth: %zu primordia in %.3f s "
	    "= %.2f us each\n", n2, t2, t2 / (double)n2 * 1e6);
	printf("scaling: time(%zu) / time(%zu) = %.1f for %.1fx the "
	    "primordia\n", n1, n2, t1 / t2, (double)n1 / (double)n2);

	if ((t3 = run(r1 * sqrt(50), 2000000, PLACE_EXACT, &n3)) < 0 ||
	    (t4 = run(r1 * sqrt(50), 2000000, PLACE_BRUTE, &n4)) < 0)
		return 1;
	printf("side by side, %zu primordia: exact walk %.3f s, brute-force "
	    "reference %.1f s (%zu placed): %.0fx\n", n3, t3, t4, n4,
	    t4 / t3);
	return 0;
}
