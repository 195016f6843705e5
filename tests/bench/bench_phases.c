/*
 * bench_phases.c - a run's three costs, each timed on its own (make
 * bench): the model placing the organs, the parastichy analysis that
 * --info and --svg make of them, and the CSV written of them to
 * /dev/null.  Best of three, one core.  With "pairs", the analysis of
 * every organ's pair as the SVG's colours take it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "models/model.h"
#include "analysis/parastichy.h"
#include "pipeline/pipeline.h"
#include "scene/scene.h"
#include "base/sink.h"
#include "writers/writer.h"

#define ROUNDS	3

int
main(int argc, char **argv)
{
	double best[4] = { 1e9, 1e9, 1e9, 1e9 };
	size_t count = 0, nz = 0;
	struct para_zone z[64];
	FILE *null = fopen("/dev/null", "w");
	int pairs = argc > 2 && strcmp(argv[2], "pairs") == 0;

	if (argc < 2 || null == NULL) {
		fprintf(stderr, "usage: bench_phases 'scene text' [pairs]\n");
		return 2;
	}
	for (int k = 0; k < ROUNDS; k++) {
		struct scene sc;
		struct result res = { 0 };
		struct sink s;
		double t0, t1, t2, t3, t4;
		int (*pair)[2];

		if (scene_load_buffer(&sc, "bench.cfg", argv[1],
		    strlen(argv[1])) != 0)
			return 1;
		t0 = now();
		if (scene_run(&sc, &res, NULL) != 0)
			return 1;
		t1 = now();
		nz = para_zones(&res, NULL, z, 64);
		t2 = now();
		sink_init(&s, null);
		csv_write(&s, &res, 0);
		if (sink_finish(&s) != 0)
			return 1;
		sink_free(&s);
		t3 = now();
		if (pairs) {
			pair = calloc(res.count ? res.count : 1, sizeof(*pair));
			if (pair == NULL)
				return 1;
			para_pairs(&res, pair);
			free(pair);
		}
		t4 = now();
		best[0] = t1 - t0 < best[0] ? t1 - t0 : best[0];
		best[1] = t2 - t1 < best[1] ? t2 - t1 : best[1];
		best[2] = t3 - t2 < best[2] ? t3 - t2 : best[2];
		best[3] = t4 - t3 < best[3] ? t4 - t3 : best[3];
		count = res.count;
		result_free(&res);
		scene_free(&sc);
	}
	printf("%zu organs: model %.3f s, analysis %.3f s (%zu zones), CSV "
	    "writing %.3f s", count, best[0], best[1], nz, best[2]);
	if (pairs)
		printf(", every organ's pair %.3f s", best[3]);
	printf("\n");
	return 0;
}
