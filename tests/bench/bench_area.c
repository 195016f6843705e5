/*
 * bench_area.c - the area model alone (make bench): a million organs on
 * a hemisphere, best of three, beside the collision model on the same
 * receptacle at the radius that places about as many; one core.
 */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "models/model.h"
#include "pipeline/pipeline.h"
#include "scene/scene.h"
#include "clock.h"

/* Best of three seconds to run the scene's model; count placed. */
static double
best(const char *text, size_t *count)
{
	double b = 1e9;

	for (int i = 0; i < 3; i++) {
		struct scene sc;
		struct result res = { 0 };
		double t0;

		if (scene_load_buffer(&sc, "bench.cfg", text, strlen(text)) != 0)
			return -1;
		t0 = now();
		if (scene_run(&sc, &res, NULL) != 0) {
			scene_free(&sc);
			return -1;
		}
		if (now() - t0 < b)
			b = now() - t0;
		*count = res.count;
		result_free(&res);
		scene_free(&sc);
	}
	return b;
}

int
main(void)
{
	size_t na, nc;
	double ta = best("model = \"area\"; count = 1000000; area = { "
	    "receptacle = { shape = \"hemisphere\"; }; };", &na);
	/* 0.93 of the area model's even radius: about a million fit. */
	double tc = best("model = \"collision\"; count = 1000000; collision = "
	    "{ receptacle = { shape = \"hemisphere\"; }; radius = 0.00125; };",
	    &nc);

	printf("area model alone: %zu organs in %.3f s = %.1f M/s; collision, "
	    "same receptacle: %zu in %.3f s = %.2f M/s; %.0fx per organ\n",
	    na, ta, na / ta / 1e6, nc, tc, nc / tc / 1e6,
	    (tc / nc) / (ta / na));
	return ta < 0 || tc < 0;
}
