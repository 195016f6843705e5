/*
 * test_collision.c - the collision model against its definition, on
 * receptacles of every kind, with and without epsilon, with constant
 * and varying radii:
 *  - no two primordia overlap;
 *  - every centre lies on the receptacle (measured against the Bezier
 *    control points directly, not through the model's own curve code);
 *  - primordium n sits at angle n alpha;
 *  - without epsilon, every primordium above the base touches an
 *    earlier one;
 *  - every primordium is at the smallest feasible t: the exact walk
 *    agrees with the brute-force reference, which tries every earlier
 *    primordium at finely spaced t.
 * Prints "ok"/"not ok" lines.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/geometry.h"
#include "models/collision.h"
#include "models/model.h"
#include "geometry/receptacle.h"
#include "pipeline/pipeline.h"
#include "scene/scene.h"
#include "check.h"

#define TOL	1e-9


static const struct {
	const char	*what;
	const char	*cfg;
	int		 touching;	/* no epsilon: each touches one */
} cases[] = {
	{ "disk", "collision = { receptacle = { shape = \"disk\"; }; "
	  "radius = 0.07; };", 1 },
	{ "cone", "collision = { receptacle = { shape = \"cone\"; radius = 1; "
	  "height = 1.5; }; radius = 0.08; };", 1 },
	{ "hemisphere, varying radius", "collision = { receptacle = { shape = "
	  "\"hemisphere\"; }; radius = \"0.09 - 0.04*t\"; }; count = 300;", 1 },
	{ "sphere", "collision = { receptacle = { shape = \"sphere\"; "
	  "radius = 0.6; }; radius = 0.07; };", 1 },
	{ "cylinder", "collision = { receptacle = { shape = \"cylinder\"; "
	  "radius = 0.5; height = 1.2; }; radius = 0.09; };", 1 },
	{ "ellipsoid, epsilon r", "collision = { receptacle = { shape = "
	  "\"ellipsoid\"; radius = 0.5; height = 1.6; }; radius = \"0.08 - "
	  "0.05*t\"; epsilon = \"r\"; }; count = 250;", 0 },
	{ "cap", "collision = { receptacle = { shape = \"cap\"; radius = 1; "
	  "height = 0.3; }; radius = 0.075; };", 1 },
	{ "two-segment profile, epsilon 0.05", "collision = { receptacle = { "
	  "profile = ((0.8, 0), (0.9, 0.3), (0.7, 0.6), (0.5, 0.8), "
	  "(0.3, 1.0), (0.1, 1.3), (0, 1.4)); }; radius = 0.06; "
	  "epsilon = 0.05; };", 0 },
	{ "spruce profile, decreasing radius", "collision = { receptacle = { "
	  "profile = ((0.3, 0), (0.5, 0.2), (0.5, 0.8), (0.4, 1.2), "
	  "(0.3, 1.6), (0.15, 2.0), (0, 2.1)); }; radius = \"0.07 - "
	  "0.00005*n\"; }; count = 400;", 1 },
	{ "disk, wide divergence", "divergence = 99.5; collision = { "
	  "receptacle = { shape = \"disk\"; }; radius = 0.08; };", 1 },
	/* A count that covers only a band at the base: a band-sized map. */
	{ "hemisphere, a band at the base", "collision = { receptacle = { "
	  "shape = \"hemisphere\"; }; radius = 0.03; }; count = 300;", 1 },
	{ "disk, a band, radius falling", "collision = { receptacle = { "
	  "shape = \"disk\"; }; radius = \"0.03 * (1 - 0.8 * t)\"; }; "
	  "count = 300;", 1 },
	{ "sphere, a band, radius rising", "collision = { receptacle = { "
	  "shape = \"sphere\"; }; radius = \"0.02 * (0.5 + t)\"; }; "
	  "count = 300;", 1 },
};

static double
bez_dist(const double (*p)[2], double u, double rho, double z)
{
	double v = 1 - u, x, y;

	x = v * v * v * p[0][0] + 3 * v * v * u * p[1][0] +
	    3 * v * u * u * p[2][0] + u * u * u * p[3][0];
	y = v * v * v * p[0][1] + 3 * v * v * u * p[1][1] +
	    3 * v * u * u * p[2][1] + u * u * u * p[3][1];
	return hypot(x - rho, y - z);
}

/*
 * Distance from (rho, z) to the Bezier curve of the control points:
 * the nearest of 4000 samples per segment, then a ternary search on
 * the samples either side.
 */
static double
curve_dist(const double (*b)[2], int npts, double rho, double z)
{
	double best = HUGE_VAL, h = 1.0 / 4000;

	for (int k = 0; k + 3 < npts; k += 3) {
		const double (*p)[2] = b + k;
		double bu = 0, bd = HUGE_VAL, lo, hi;

		for (int i = 0; i <= 4000; i++) {
			double d = bez_dist(p, i * h, rho, z);

			if (d < bd) {
				bd = d;
				bu = i * h;
			}
		}
		lo = fmax(bu - h, 0);
		hi = fmin(bu + h, 1);
		for (int i = 0; i < 200; i++) {
			double a = lo + (hi - lo) / 3, c = hi - (hi - lo) / 3;

			if (bez_dist(p, a, rho, z) < bez_dist(p, c, rho, z))
				hi = c;
			else
				lo = a;
		}
		best = fmin(best, fmin(bd, bez_dist(p, (lo + hi) / 2, rho, z)));
	}
	return best;
}

/* The model's hooks take what the model sees of sc. */
static int
place(const struct scene *sc, struct result *res, int how)
{
	struct model_ctx ctx;

	scene_model_ctx(sc, &ctx, NULL);
	return collision_place(&ctx, res, how);
}

/* The receptacle's control points. */
static double (*points(const struct scene *sc, int *n))[2]
{
	struct model_ctx ctx;

	scene_model_ctx(sc, &ctx, NULL);
	return receptacle_points(sc->file, collision_receptacle(&ctx), n);
}

static void
properties(const char *what, const struct scene *sc, const struct result *res,
    int touching)
{
	const struct organ *o = res->organs;
	double worst_overlap = 0, worst_surface = 0, worst_angle = 0;
	double worst_touch = 0, (*b)[2];
	int npts;

	b = points(sc, &npts);
	for (size_t i = 0; i < res->count; i++) {
		double rho = hypot(o[i].pos[0], o[i].pos[1]), nearest = HUGE_VAL;

		for (size_t j = 0; j < i; j++) {
			double dx = o[i].pos[0] - o[j].pos[0];
			double dy = o[i].pos[1] - o[j].pos[1];
			double dz = o[i].pos[2] - o[j].pos[2];
			double gap = sqrt(dx * dx + dy * dy + dz * dz) -
			    o[i].radius - o[j].radius;

			worst_overlap = fmax(worst_overlap, -gap);
			nearest = fmin(nearest, gap);
		}
		worst_surface = fmax(worst_surface,
		    curve_dist((const double (*)[2])b, npts, rho,
		    o[i].pos[2]));
		if (rho > 1e-6) {
			double a = atan2(o[i].pos[1], o[i].pos[0]) * 180 / M_PI;
			double want = angle_mod360((double)i, res->divergence);
			double d = fmod(fabs(a - want), 360);

			worst_angle = fmax(worst_angle, fmin(d, 360 - d));
		}
		/* Above the base: resting on an earlier primordium. */
		if (touching && i > 0 && fabs(o[i].pos[2] - o[0].pos[2]) +
		    fabs(rho - hypot(o[0].pos[0], o[0].pos[1])) > 1e-12)
			worst_touch = fmax(worst_touch, nearest);
	}
	free(b);
	check(res->count > 50, "%s: %zu primordia placed", what, res->count);
	check(worst_overlap < TOL, "%s: no overlap (worst %.3g)", what,
	    worst_overlap);
	check(worst_surface < TOL, "%s: centres on the receptacle (worst "
	    "%.3g)", what, worst_surface);
	check(worst_angle < 1e-9, "%s: angle n alpha (worst %.3g degrees)",
	    what, worst_angle);
	if (touching)
		check(worst_touch < TOL, "%s: each touches an earlier one "
		    "(worst gap %.3g)", what, worst_touch);
}

/* The exact walk and the brute-force reference place the same. */
static void
agreement(const char *what, const struct scene *sc, const struct result *x)
{
	struct result br = { 0 };
	double worst = 0;
	size_t first = 0;

	if (place(sc, &br, PLACE_BRUTE) != 0) {
		check(0, "%s: brute-force reference runs", what);
		return;
	}
	check(br.count == x->count, "%s: same count, exact %zu, reference %zu",
	    what, x->count, br.count);
	for (size_t i = 0; i < x->count && i < br.count; i++) {
		double d = 0;

		for (int k = 0; k < 3; k++)
			d = fmax(d, fabs(x->organs[i].pos[k] -
			    br.organs[i].pos[k]));
		if (d > worst) {
			worst = d;
			if (d > TOL && first == 0)
				first = i;
		}
	}
	if (first > 0)
		check(0, "%s: exact walk and reference differ from primordium "
		    "%zu on", what, first);
	check(worst < TOL, "%s: exact walk places every primordium where the "
	    "reference does (worst %.3g)", what, worst);
	result_free(&br);
}

/* A collision scene from the settings after its model line. */
static int
load(struct scene *sc, const char *cfg)
{
	char text[1024];

	snprintf(text, sizeof(text), "model = \"collision\";\n%s\n", cfg);
	return scene_load_buffer(sc, "test.cfg", text, strlen(text));
}

/*
 * The cover map only ever skips covered receptacle: with it and
 * without it, the walk places the same (and the map's own check finds
 * no cell with room beyond its bound), on structures large enough
 * for the map to matter (tens of rows, holes, exceptions, radii
 * falling below what a column's prefix proved).
 */
static const struct {
	const char	*what;
	const char	*cfg;
} large[] = {
	{ "disk, 9000 primordia", "collision = { receptacle = { shape = "
	  "\"disk\"; }; radius = 0.0095; };" },
	{ "hemisphere, radius falling 2x", "collision = { receptacle = { "
	  "shape = \"hemisphere\"; }; radius = \"0.02 - 0.01*t\"; }; "
	  "count = 12000;" },
	{ "cone, epsilon r, radius falling", "collision = { receptacle = { "
	  "shape = \"cone\"; height = 2; }; radius = \"0.02 - 0.000001*n\"; "
	  "epsilon = \"r\"; };" },
	{ "sphere, radius rising", "collision = { receptacle = { shape = "
	  "\"sphere\"; }; radius = \"0.012 + 0.000001*n\"; };" },
	/* Bands at the base: maps of the band alone, walks beyond it. */
	{ "hemisphere, a band of 8000", "collision = { receptacle = { "
	  "shape = \"hemisphere\"; }; radius = 0.004; }; count = 8000;" },
	{ "sphere, a band, radius falling 5x", "collision = { receptacle = "
	  "{ shape = \"sphere\"; }; radius = \"0.005 * (1 - 0.8 * t)\"; }; "
	  "count = 8000;" },
	{ "disk, a band, radius rising 3x", "collision = { receptacle = { "
	  "shape = \"disk\"; }; radius = \"0.002 * (0.5 + t)\"; }; "
	  "count = 8000;" },
	/*
	 * A narrow cylinder, a radius falling 10x: a map of over 1,024
	 * rows, whose cells are doubled (collision.c).
	 */
	{ "cylinder, radius falling 10x, a tall band", "collision = { "
	  "receptacle = { shape = \"cylinder\"; radius = 0.05; height = 4; "
	  "}; radius = \"0.01 * (1 - 0.9 * t)\"; }; count = 6000;" },
	/*
	 * Epsilon and a radius falling 5x, enough primordia for rows as
	 * high as the radius where the front crosses them (collision.c):
	 * a thin band at the rim, where rows of every height meet the
	 * walks (a row's bound read in the lowest rows' steps moved 2,308
	 * of these placements).
	 */
	{ "disk, epsilon r, radius falling 5x, rows of many heights",
	  "collision = { receptacle = { shape = \"disk\"; }; radius = "
	  "\"0.0006 * (1 - 0.8 * t)\"; epsilon = \"r\"; }; count = 30000;" },
	/*
	 * And epsilon 0: walks start at the last primordium's height, in
	 * rows often not covered, whose start the walk looks at before t0
	 * (collision_walk.c); going on from an exit short of the row's end
	 * without t0 moved 27,404 of these placements.
	 */
	{ "disk, epsilon 0, radius falling 5x, rows of many heights",
	  "collision = { receptacle = { shape = \"disk\"; }; radius = "
	  "\"0.0006 * (1 - 0.8 * t)\"; epsilon = 0; }; count = 30000;" },
};

static void
cover_agrees(void)
{
	for (size_t i = 0; i < sizeof(large) / sizeof(large[0]); i++) {
		struct scene sc;
		struct result a = { 0 }, b = { 0 };
		double worst = 0;

		if (load(&sc, large[i].cfg) != 0 ||
		    place(&sc, &a, PLACE_CHECK) != 0 ||
		    place(&sc, &b, PLACE_PLAIN) != 0) {
			check(0, "%s: scene loads and runs", large[i].what);
			scene_free(&sc);
			continue;
		}
		for (size_t k = 0; k < a.count && k < b.count; k++)
			for (int x = 0; x < 3; x++)
				worst = fmax(worst, fabs(a.organs[k].pos[x] -
				    b.organs[k].pos[x]));
		check(a.count == b.count && a.count > 2000 && worst < TOL,
		    "%s: the cover map changes nothing (%zu and %zu "
		    "primordia, worst %.3g)", large[i].what, a.count, b.count,
		    worst);
		/*
		 * And directly: no point of a cell is clear of every
		 * primordium by more than the cell's bound.  (A bound too
		 * low need not change a placement here, and did not when
		 * it was made so on purpose.)
		 */
		check(info(&a, "cover misses", 0) == 0, "%s: every cell's "
		    "bound holds at 3 x 3 points of it (%g points beyond)",
		    large[i].what, info(&a, "cover misses", 0));
		/* The doubled cells, where the case is there for them. */
		if (strstr(large[i].what, "tall band") != NULL)
			check(info(&a, "cover doubled", 0) == 1, "%s: the "
			    "map's cells doubled", large[i].what);
		/* And the rows of many heights. */
		if (strstr(large[i].what, "many heights") != NULL)
			check(info(&a, "cover levels", 0) >= 2, "%s: the map's "
			    "rows of %g heights", large[i].what,
			    info(&a, "cover levels", 0));
		/*
		 * And what refine() proved, closely: 9 x 9 points of every
		 * cell it lowered (the check above samples every 31st cell
		 * and missed sub-columns shifted a quarter of a column).
		 */
		check(info(&a, "refine misses", 0) == 0, "%s: every refined "
		    "cell's bound holds at 9 x 9 points of it (%g points "
		    "beyond, %g cells)", large[i].what,
		    info(&a, "refine misses", 0), info(&a, "refine misses", 1));
		/*
		 * With epsilon, each walk that starts in a row known from
		 * the arc length alone (start_row()): t0, worked out, lies
		 * in that row.
		 */
		check(info(&a, "start misses", 0) == 0, "%s: every start "
		    "row found without t0 holds it (%g of %g starts outside it)",
		    large[i].what, info(&a, "start misses", 0),
		    info(&a, "start misses", 1));
		result_free(&a);
		result_free(&b);
		scene_free(&sc);
	}
}

/*
 * The presets against their closed forms, computed here and not from
 * receptacle.c: every point of the generating curve (sampled from the
 * control points by the test's own Bezier evaluation) and every placed
 * centre must satisfy the shape's equation, and the curve must run
 * from the base named in the man page to the tip.  R = 0.7, H = 1.3.
 */
#define PR	0.7
#define PH	1.3

/* How far (rho, z) is from the preset's surface, in units of length. */
static double
off_preset(const char *shape, double rho, double z)
{
	double rs = (PR * PR + PH * PH) / (2 * PH);	/* the cap's sphere */

	if (strcmp(shape, "disk") == 0)
		return fabs(z) + fmax(rho - PR, 0);
	if (strcmp(shape, "cone") == 0)		/* rho/R + z/H = 1 */
		return fabs(rho / PR + z / PH - 1) / hypot(1 / PR, 1 / PH);
	if (strcmp(shape, "cylinder") == 0)
		return fabs(rho - PR) + fmax(-z, 0) + fmax(z - PH, 0);
	if (strcmp(shape, "hemisphere") == 0)
		return fabs(hypot(rho, z) - PR) + fmax(-z, 0);
	if (strcmp(shape, "sphere") == 0)	/* centre (0, R) */
		return fabs(hypot(rho, z - PR) - PR);
	if (strcmp(shape, "cap") == 0)		/* centre (0, H - rs) */
		return fabs(hypot(rho, z - (PH - rs)) - rs) + fmax(-z, 0);
	/* ellipsoid: semi-axes R across and H/2 along, centre (0, H/2) */
	return fabs(hypot(rho / PR, (z - PH / 2) / (PH / 2)) - 1) *
	    fmin(PR, PH / 2);
}

static void
presets(void)
{
	static const struct {
		const char	*shape;
		double		 base[2], tip[2];
		int		 height;	/* takes receptacle.height */
	} shapes[] = {
		{ "disk", { PR, 0 }, { 0, 0 }, 0 },
		{ "cone", { PR, 0 }, { 0, PH }, 1 },
		{ "cylinder", { PR, 0 }, { PR, PH }, 1 },
		{ "hemisphere", { PR, 0 }, { 0, PR }, 0 },
		{ "sphere", { 0, 0 }, { 0, 2 * PR }, 0 },
		{ "cap", { PR, 0 }, { 0, PH }, 1 },
		{ "ellipsoid", { 0, 0 }, { 0, PH }, 1 },
	};

	for (size_t i = 0; i < sizeof(shapes) / sizeof(shapes[0]); i++) {
		const char *shape = shapes[i].shape;
		char cfg[256];
		struct scene sc;
		struct result res = { 0 };
		double (*b)[2], worst = 0, worst_c = 0, ends;
		int n;

		snprintf(cfg, sizeof(cfg), "collision = { receptacle = { "
		    "shape = \"%s\"; radius = %.17g; %s%.17g%s }; radius = "
		    "0.05; }; count = 200;", shape, PR, shapes[i].height ?
		    "height = " : "/* ", PH, shapes[i].height ? ";" : " */");
		if (load(&sc, cfg) != 0 || place(&sc, &res, PLACE_EXACT) != 0 ||
		    (b = points(&sc, &n)) == NULL) {
			check(0, "preset %s: loads and runs", shape);
			scene_free(&sc);
			continue;
		}
		for (int k = 0; k + 3 < n; k += 3)
			for (int j = 0; j <= 1000; j++) {
				double u = j / 1000.0, v = 1 - u, p[2];

				for (int c = 0; c < 2; c++)
					p[c] = v * v * v * b[k][c] +
					    3 * v * v * u * b[k + 1][c] +
					    3 * v * u * u * b[k + 2][c] +
					    u * u * u * b[k + 3][c];
				worst = fmax(worst, off_preset(shape, p[0],
				    p[1]));
			}
		for (size_t k = 0; k < res.count; k++)
			worst_c = fmax(worst_c, off_preset(shape,
			    hypot(res.organs[k].pos[0], res.organs[k].pos[1]),
			    res.organs[k].pos[2]));
		ends = fmax(hypot(b[0][0] - shapes[i].base[0], b[0][1] -
		    shapes[i].base[1]), hypot(b[n - 1][0] - shapes[i].tip[0],
		    b[n - 1][1] - shapes[i].tip[1]));
		/* Circular arcs as cubic Beziers are within 2e-11 of radius. */
		check(worst < 2e-11 && worst_c < 2e-11 && ends < 1e-12 &&
		    res.count > 20, "preset %s: the curve and %zu centres lie "
		    "on its closed form (worst %.2g, %.2g), base and tip "
		    "where the manual says (%.2g)", shape, res.count, worst,
		    worst_c, ends);
		free(b);
		result_free(&res);
		scene_free(&sc);
	}
}

int
main(void)
{
	check_topic = "collision: ";
	presets();
	cover_agrees();
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		struct scene sc;
		struct result res = { 0 };

		if (load(&sc, cases[i].cfg) != 0 ||
		    place(&sc, &res, PLACE_EXACT) != 0) {
			check(0, "%s: scene loads and runs", cases[i].what);
			scene_free(&sc);
			continue;
		}
		properties(cases[i].what, &sc, &res, cases[i].touching);
		agreement(cases[i].what, &sc, &res);
		result_free(&res);
		scene_free(&sc);
	}
	return check_failures != 0;
}
