/*
 * organs.c - a scene's structure at full precision, to hold one build
 * against another (tests/windows.sh: the Windows program's numbers
 * against the native one's, where 9 printed digits would hide a
 * difference or make one of a last digit rounded the other way):
 *	organs SCENE.cfg
 * prints the model's facts, then every organ's position, u, w, scale,
 * radius, angle and height, each number with 17 digits.
 */
#include <stdio.h>

#include "result/organ.h"
#include "pipeline/pipeline.h"
#include "scene/scene.h"

int
main(int argc, char *argv[])
{
	struct scene sc;
	struct result res = { 0 };

	if (argc != 2) {
		fprintf(stderr, "usage: organs SCENE.cfg\n");
		return 2;
	}
	if (scene_load(&sc, argv[1]) != 0 || scene_run(&sc, &res, NULL) != 0)
		return 1;
	printf("divergence %.17g\n", res.divergence);
	for (int i = 0; i < res.ninfo; i++) {
		printf("%s", res.info[i].key);
		for (int k = 0; k < res.info[i].nval; k++)
			printf(" %.17g", res.info[i].val[k]);
		printf("\n");
	}
	for (size_t n = 0; n < res.count; n++) {
		const struct organ *o = &res.organs[n];

		printf("%zu %u", n, o->object);
		for (int k = 0; k < 3; k++)
			printf(" %.17g", o->pos[k]);
		for (int k = 0; k < 3; k++)
			printf(" %.17g", o->u[k]);
		for (int k = 0; k < 3; k++)
			printf(" %.17g", o->w[k]);
		printf(" %.17g %.17g %.17g %.17g\n", o->scale, o->radius, o->phi,
		    o->height);
	}
	result_free(&res);
	scene_free(&sc);
	return fflush(stdout) != 0;
}
