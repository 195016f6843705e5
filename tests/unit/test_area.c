/*
 * test_area.c - the area-based model against closed forms computed
 * here, not against its own numbers:
 *  - the sphere preset gives the Fibonacci sphere lattice, z_n =
 *    2R(n + 1/2)/N, and the cylinder z_n = H(n + 1/2)/N;
 *  - on every preset the area between consecutive organs is their
 *    share, measured by each preset's own area formula (Archimedes'
 *    zones, the cone's frustums, the disk's rings; for the ellipsoid a
 *    fine Simpson sum over the exact ellipse);
 *  - with a radius expression each organ sits in the middle of its
 *    hexagonal cell, the cells adding up from the base, as many as fit;
 *  - frames: w the outward normal, u down the meridian, orthonormal;
 *  - stretch: centres on the stretched surface, w its normal (the
 *    gradient of its equation), frames orthonormal and right-handed.
 * Prints "ok"/"not ok" lines.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/model.h"
#include "scene/scene.h"
#include "check.h"
#include "scene_text.h"

#define R	1.3
#define H	1.7

static int
run(const char *cfg, struct scene *sc, struct result *res)
{
	char text[1024];

	snprintf(text, sizeof(text), "model = \"area\";\n%s\n", cfg);
	return scene_text_run(text, sc, res);
}

static double
rho_of(const struct organ *o)
{
	return hypot(o->pos[0], o->pos[1]);
}

/* Fibonacci sphere and cylinder: positions and angles by formula. */
static void
lattices(void)
{
	static const struct {
		const char	*what, *cfg;
		int		 sphere;
	} c[] = {
		{ "sphere", "count = 500; area = { receptacle = { shape = "
		  "\"sphere\"; radius = 1.3; }; };", 1 },
		{ "cylinder", "count = 500; area = { receptacle = { shape = "
		  "\"cylinder\"; radius = 1.3; height = 1.7; }; };", 0 },
	};

	for (size_t k = 0; k < 2; k++) {
		struct scene sc;
		struct result res;
		double wz = 0, wr = 0, wa = 0, wf = 0;
		size_t N;

		if (run(c[k].cfg, &sc, &res) != 0) {
			check(0, "%s: runs", c[k].what);
			scene_free(&sc);
			continue;
		}
		N = res.count;
		for (size_t n = 0; n < N; n++) {
			const struct organ *o = &res.organs[n];
			double z = (c[k].sphere ? 2 * R : H) * (n + 0.5) / N;
			double rho = c[k].sphere ? sqrt(R * R - (z - R) *
			    (z - R)) : R;
			double a = fmod(n * GOLDEN_ANGLE, 360) * M_PI / 180;
			double w[3], u[3];

			wz = fmax(wz, fabs(o->pos[2] - z));
			wr = fmax(wr, fabs(rho_of(o) - rho));
			wa = fmax(wa, hypot(o->pos[0] - rho * cos(a),
			    o->pos[1] - rho * sin(a)));
			/* w outward from the axis point (sphere: centre). */
			w[0] = o->pos[0];
			w[1] = o->pos[1];
			w[2] = c[k].sphere ? o->pos[2] - R : 0;
			/* u down the meridian, towards the base. */
			u[0] = c[k].sphere ? o->pos[2] - R : 0;
			u[1] = 0;
			u[2] = c[k].sphere ? -rho : -1;
			for (int j = 0; j < 3; j++)
				w[j] /= c[k].sphere ? R : (j < 2 ? R : 1);
			wf = fmax(wf, fabs(o->w[0] - w[0]) + fabs(o->w[1] -
			    w[1]) + fabs(o->w[2] - w[2]));
			/* u's meridian component and its z. */
			wf = fmax(wf, fabs(o->u[0] * cos(a) + o->u[1] *
			    sin(a) - u[0] / (c[k].sphere ? R : 1)) +
			    fabs(o->u[2] - u[2] / (c[k].sphere ? R : 1)));
		}
		check(N == 500 && wz < 1e-9 * R && wr < 1e-9 * R && wa <
		    1e-9 * R, "%s: organ n at z = %s (n + 1/2)/N, on the "
		    "surface, at angle n alpha (worst %.2g, %.2g, %.2g)",
		    c[k].what, c[k].sphere ? "2R" : "H", wz, wr, wa);
		/* The arcs' tangents are within 1e-8 of the circle's. */
		check(wf < 1e-8, "%s: w the outward normal, u down the "
		    "meridian (worst %.2g)", c[k].what, wf);
		result_free(&res);
		scene_free(&sc);
	}
}

/* Area swept from the base of each preset up to the organ at o. */
static double
swept(const char *shape, const struct organ *o)
{
	double rho = rho_of(o), z = o->pos[2];

	if (strcmp(shape, "disk") == 0)		/* from the rim inward */
		return M_PI * (R * R - rho * rho);
	if (strcmp(shape, "cylinder") == 0)
		return 2 * M_PI * R * z;
	if (strcmp(shape, "cone") == 0) {	/* frustum's lateral area */
		double L = hypot(R, H);

		return M_PI * (R + rho) * (z / H * L);
	}
	if (strcmp(shape, "sphere") == 0)	/* Archimedes: 2 pi Rs dz */
		return 2 * M_PI * R * z;
	if (strcmp(shape, "hemisphere") == 0)
		return 2 * M_PI * R * z;
	if (strcmp(shape, "cap") == 0) {
		double rs = (R * R + H * H) / (2 * H);

		return 2 * M_PI * rs * z;
	}
	{
		/*
		 * The ellipsoid (rho, z) = (R sin th, c (1 - cos th)), c =
		 * H/2, from the base pole to the organ's th: Simpson's rule
		 * on the exact curve, fine enough for 1e-12.
		 */
		double c = H / 2, th = acos(fmax(-1, fmin(1, 1 - z / c)));
		int n = 20000;
		double h = th / n, sum = 0;

		for (int i = 0; i <= n; i++) {
			double t = i * h, f = 2 * M_PI * R * sin(t) *
			    hypot(R * cos(t), c * sin(t));

			sum += f * (i == 0 || i == n ? 1 : i % 2 ? 4 : 2);
		}
		return sum * h / 3;
	}
}

static double
total_area(const char *shape)
{
	struct organ top = { .pos = { 0, 0, 0 } };

	if (strcmp(shape, "disk") == 0)
		return M_PI * R * R;
	top.pos[2] = strcmp(shape, "sphere") == 0 ? 2 * R :
	    strcmp(shape, "hemisphere") == 0 ? R : H;
	if (strcmp(shape, "cylinder") == 0)
		top.pos[0] = R;
	return swept(shape, &top);
}

static void
shares(void)
{
	static const char *const shapes[] = { "disk", "cone", "hemisphere",
	    "sphere", "cylinder", "ellipsoid", "cap" };

	for (size_t k = 0; k < sizeof(shapes) / sizeof(shapes[0]); k++) {
		const char *sh = shapes[k];
		int height = strcmp(sh, "cone") == 0 ||
		    strcmp(sh, "cylinder") == 0 || strcmp(sh, "ellipsoid") == 0 ||
		    strcmp(sh, "cap") == 0;
		char cfg[256];
		struct scene sc;
		struct result res;
		double worst = 0, A;

		snprintf(cfg, sizeof(cfg), "count = 300; area = { receptacle "
		    "= { shape = \"%s\"; radius = %.17g; %s%.17g%s }; };", sh,
		    R, height ? "height = " : "/* ", H, height ? ";" : " */");
		if (run(cfg, &sc, &res) != 0) {
			check(0, "%s: runs", sh);
			scene_free(&sc);
			continue;
		}
		A = total_area(sh);
		for (size_t n = 0; n < res.count; n++) {
			double want = A * (n + 0.5) / res.count;

			worst = fmax(worst, fabs(swept(sh, &res.organs[n]) -
			    want) / A);
		}
		check(res.count == 300 && worst < 1e-9, "%s: organ n at (n + "
		    "1/2)/N of the area by the shape's own formula (worst "
		    "%.2g of the whole)", sh, worst);
		result_free(&res);
		scene_free(&sc);
	}
}

/* A radius growing towards the base of a cone: cells add up. */
static void
cells(void)
{
	struct scene sc;
	struct result res;
	double used = 0, worst = 0, A = total_area("cone");
	size_t fit = 0;

	if (run("area = { receptacle = { shape = \"cone\"; radius = 1.3; "
	    "height = 1.7; }; radius = \"0.06 - 0.00002 * n\"; };", &sc,
	    &res) != 0) {
		check(0, "cone with a radius expression: runs");
		scene_free(&sc);
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		double r = 0.06 - 0.00002 * (double)n, cell = 2 * sqrt(3) *
		    r * r;

		worst = fmax(worst, fabs(swept("cone", &res.organs[n]) -
		    (used + cell / 2)) / A);
		worst = fmax(worst, fabs(res.organs[n].radius - r));
		used += cell;
	}
	/* As many as fit: the next cell would not. */
	for (double u = 0;; fit++) {
		double r = 0.06 - 0.00002 * (double)fit;

		if (u + 2 * sqrt(3) * r * r > A)
			break;
		u += 2 * sqrt(3) * r * r;
	}
	check(res.count == fit && worst < 1e-9, "cone, radius falling with "
	    "n: each organ in the middle of its cell, cells summed from the "
	    "base, %zu organs as %zu fit (worst %.2g)", res.count, fit,
	    worst);
	result_free(&res);
	scene_free(&sc);
}

/* A sphere stretched into an ellipsoid of three radii. */
static void
stretched(void)
{
	static const double k[3] = { 1.5, 0.6, 2.0 };
	struct scene sc;
	struct result res;
	double won = 0, wnorm = 0, wframe = 0;

	if (run("count = 400; stretch = [1.5, 0.6, 2.0]; area = { "
	    "receptacle = { shape = \"sphere\"; radius = 1.3; }; };", &sc,
	    &res) != 0) {
		check(0, "stretch: runs");
		scene_free(&sc);
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const struct organ *o = &res.organs[n];
		double a = R * k[0], b = R * k[1], c = R * k[2], zc = R * k[2];
		double x = o->pos[0], y = o->pos[1], z = o->pos[2] - zc;
		double g[3] = { x / (a * a), y / (b * b), z / (c * c) };
		double lg = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
		double v[3], d[6];

		won = fmax(won, fabs(x * x / (a * a) + y * y / (b * b) + z * z /
		    (c * c) - 1));
		for (int j = 0; j < 3; j++)
			wnorm = fmax(wnorm, fabs(o->w[j] - g[j] / lg));
		organ_v(o, v);
		d[0] = o->u[0] * o->u[0] + o->u[1] * o->u[1] + o->u[2] * o->u[2];
		d[1] = o->w[0] * o->w[0] + o->w[1] * o->w[1] + o->w[2] * o->w[2];
		d[2] = o->u[0] * o->w[0] + o->u[1] * o->w[1] + o->u[2] * o->w[2];
		/* Right-handed: u x v = w. */
		d[3] = o->u[1] * v[2] - o->u[2] * v[1] - o->w[0];
		d[4] = o->u[2] * v[0] - o->u[0] * v[2] - o->w[1];
		d[5] = o->u[0] * v[1] - o->u[1] * v[0] - o->w[2];
		wframe = fmax(wframe, fmax(fabs(d[0] - 1), fabs(d[1] - 1)));
		for (int j = 2; j < 6; j++)
			wframe = fmax(wframe, fabs(d[j]));
	}
	check(won < 1e-9 && wnorm < 1e-8 && wframe < 1e-12, "stretch [1.5, "
	    "0.6, 2]: centres on the ellipsoid (%.2g), w its normal (%.2g), "
	    "frames orthonormal and right-handed (%.2g)", won, wnorm, wframe);
	result_free(&res);
	scene_free(&sc);
}

int
main(void)
{
	check_topic = "area: ";
	lattices();
	shares();
	cells();
	stretched();
	return check_failures != 0;
}
