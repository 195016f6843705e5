/*
 * test_organs.c - the organ vocabulary: each organs entry's range gets
 * its object, variants follow their weights and the seed, and altitude,
 * tilt, roll and scale transform the model's frames as documented.
 * Each check prints "ok - what" or "not ok - what"; tests/run.sh counts
 * them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/geometry.h"
#include "models/model.h"
#include "scene/scene.h"
#include "check.h"
#include "scene_text.h"

static void
done(struct scene *sc, struct result *res)
{
	result_free(res);
	scene_free(sc);
}

static const char *
object_of(const struct result *r, size_t n)
{
	return r->objects[r->organs[n].object];
}

static void
test_organ_ranges(void)
{
	struct scene sc;
	struct result res;
	int wrong = 0;

	if (scene_text_run("model = \"planar\"; count = 630;\n"
	    "organs = ( { object = \"Seed\"; to = 440; },\n"
	    "  { object = \"Ray\"; from = 441; to = 565; },\n"
	    "  { object = \"Petal\"; from = 566; } );", &sc, &res) != 0) {
		check(0, "organs: ranges scene loads");
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const char *want = n <= 440 ? "Seed" : n <= 565 ? "Ray" :
		    "Petal";

		wrong += strcmp(object_of(&res, n), want) != 0;
	}
	check(wrong == 0 && res.nobjects == 3, "organs: each range gets its "
	    "object (%d wrong)", wrong);
	done(&sc, &res);

	/* Entries past the last organ are dropped, to is clipped. */
	check(scene_text_run("model = \"planar\"; count = 100;\n"
	    "organs = ( { object = \"A\"; to = 440; },\n"
	    "  { object = \"B\"; from = 441; } );", &sc, &res) == 0 &&
	    strcmp(object_of(&res, 99), "A") == 0,
	    "organs: entries beyond the count are ignored");
	done(&sc, &res);
}

/* Count how often each of the objects A, B, C is chosen. */
static void
tally(const char *text, long counts[3], unsigned *choices)
{
	struct scene sc;
	struct result res;

	counts[0] = counts[1] = counts[2] = 0;
	if (scene_text_run(text, &sc, &res) != 0)
		return;
	for (size_t n = 0; n < res.count; n++) {
		const char *o = object_of(&res, n);

		if (o[0] >= 'A' && o[0] <= 'C' && o[1] == '\0')
			counts[o[0] - 'A']++;
		if (choices != NULL)
			choices[n] = (unsigned)o[0];
	}
	done(&sc, &res);
}

static void
test_variants(void)
{
	static unsigned a[3000], b[3000], c[3000];
	long k[3];
	int same = 1, differ = 0, kept = 1;

	tally("model = \"planar\"; count = 3000; seed = 7;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 2, 1]; } );", k, a);
	/* 3000 draws: 4 standard deviations is about 95. */
	check(labs(k[0] - 750) < 100 && labs(k[1] - 1500) < 110 &&
	    labs(k[2] - 750) < 100, "organs: variants follow their weights "
	    "1:2:1 over 3000 organs (%ld %ld %ld)", k[0], k[1], k[2]);
	tally("model = \"planar\"; count = 3000; seed = 7;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 2, 1]; } );", k, b);
	tally("model = \"planar\"; count = 3000; seed = 8;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 2, 1]; } );", k, c);
	for (int n = 0; n < 3000; n++) {
		same &= a[n] == b[n];
		differ += a[n] != c[n];
	}
	check(same, "organs: the same seed gives the same choices");
	check(differ > 1000, "organs: another seed gives other choices "
	    "(%d of 3000 differ)", differ);
	tally("model = \"planar\"; count = 3000;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; } );", k, NULL);
	check(labs(k[0] - 1000) < 110 && labs(k[1] - 1000) < 110 &&
	    labs(k[2] - 1000) < 110, "organs: without weights variants are "
	    "equally likely (%ld %ld %ld)", k[0], k[1], k[2]);
	tally("model = \"planar\"; count = 3000;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 0, 1]; } );", k, NULL);
	check(k[1] == 0 && k[0] > 0 && k[2] > 0, "organs: a zero weight is "
	    "never chosen");

	/* Changing the second range leaves the first range's choices. */
	tally("model = \"planar\"; count = 3000; seed = 3;\n"
	    "organs = ( { object = [\"A\", \"B\"]; to = 1499; },\n"
	    "  { object = \"C\"; from = 1500; } );", k, a);
	tally("model = \"planar\"; count = 3000; seed = 3;\n"
	    "organs = ( { object = [\"A\", \"B\"]; to = 1499; },\n"
	    "  { object = [\"C\", \"A\"]; weights = [3, 1]; "
	    "scale = \"rand(2)\"; from = 1500; } );", k, b);
	for (int n = 0; n < 1500; n++)
		kept &= a[n] == b[n];
	check(kept, "organs: editing one entry does not reshuffle another");
}

static void
test_transforms(void)
{
	struct scene sc, sc2;
	struct result base, res;
	double ep = 0, ef = 0, es = 0, eh = 0;

	if (scene_text_run("model = \"planar\"; count = 200; planar = { dome = 1; };",
	    &sc, &base) != 0 ||
	    scene_text_run("model = \"planar\"; count = 200; planar = { dome = 1; };\n"
	    "organs = ( { altitude = \"-0.1 * t\"; tilt = \"n % 90\";\n"
	    "  roll = 30; scale = \"2 * r + s\"; } );", &sc2, &res) != 0) {
		check(0, "organs: transform scenes load");
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const struct organ *b = &base.organs[n], *o = &res.organs[n];
		double alt = -0.1 * (double)n / 199;
		double th = fmod((double)n, 90) * M_PI / 180;
		double ro = 30 * M_PI / 180;
		double u1[3], w1[3], u2[3], v2[3], bv[3], ov[3];

		organ_v(b, bv);
		organ_v(o, ov);
		for (int i = 0; i < 3; i++) {
			/* Altitude along the model's w, then tilt, then roll. */
			ep = fmax(ep, fabs(o->pos[i] - (b->pos[i] +
			    alt * b->w[i])));
			u1[i] = b->u[i] * cos(th) + b->w[i] * sin(th);
			w1[i] = b->w[i] * cos(th) - b->u[i] * sin(th);
			u2[i] = u1[i] * cos(ro) + bv[i] * sin(ro);
			v2[i] = bv[i] * cos(ro) - u1[i] * sin(ro);
			ef = fmax(ef, fabs(o->u[i] - u2[i]) +
			    fabs(ov[i] - v2[i]) + fabs(o->w[i] - w1[i]));
		}
		es = fmax(es, fabs(o->scale - (2 * b->radius +
		    (double)n / 199)));
		eh = fmax(eh, frame_error(o));
	}
	check(ep < 1e-12, "organs: altitude moves the centre along w");
	check(ef < 1e-12, "organs: tilt turns u towards w about v, roll "
	    "turns u towards v about w");
	check(eh < 1e-12, "organs: transformed frames stay orthonormal and "
	    "right-handed");
	check(es < 1e-12, "organs: scale expression sees r and s");
	check(res.organs[5].radius == base.organs[5].radius,
	    "organs: the packing radius is the model's");
	done(&sc, &base);
	done(&sc2, &res);
}

int
main(void)
{
	test_organ_ranges();
	test_variants();
	test_transforms();
	return check_failures != 0;
}
