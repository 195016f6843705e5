/*
 * test_planar.c - the planar model's geometry against Vogel's formula:
 * r = c sqrt(n), the angle n alpha, outer and inner radii, the dome's
 * paraboloid, and orthonormal frames.  Each check prints "ok - what" or
 * "not ok - what"; tests/run.sh counts them.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "models/model.h"
#include "scene/scene.h"
#include "check.h"
#include "scene_text.h"
#include "base/vec.h"

static double
angle_diff(double a, double b)
{
	double d = fmod(fabs(a - b), 360);

	return fmin(d, 360 - d);
}

static void
test_planar_vogel(void)
{
	struct scene sc;
	struct result res;
	double er = 0, ea = 0, ef = 0, eu = 0;
	const double c = 0.7, alpha = 137.3;

	if (scene_text_run("model = \"planar\"; count = 5000; divergence = 137.3;\n"
	    "planar = { scale = 0.7; };", &sc, &res) != 0) {
		check(0, "planar: scene loads");
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const struct organ *o = &res.organs[n];
		double rho = hypot(o->pos[0], o->pos[1]);
		double ang = atan2(o->pos[1], o->pos[0]) * 180 / M_PI;
		double want = fmod((double)n * alpha, 360);

		er = fmax(er, fabs(rho - c * sqrt((double)n)));
		if (n > 0)
			ea = fmax(ea, angle_diff(ang, want));
		ef = fmax(ef, frame_error(o));
		/* u radially outward, w = +Z. */
		if (n > 0)
			eu = fmax(eu, fabs(o->u[0] - o->pos[0] / rho) +
			    fabs(o->u[1] - o->pos[1] / rho) + fabs(o->u[2]));
		eu = fmax(eu, fabs(o->w[2] - 1) + fabs(o->pos[2]));
	}
	check(er < 1e-12, "planar: r = c sqrt(n) (worst %.2g)", er);
	check(ea < 1e-9, "planar: angle = n alpha (worst %.2g degree)", ea);
	check(ef < 1e-12, "planar: frames orthonormal, right-handed "
	    "(worst %.2g)", ef);
	check(eu < 1e-12, "planar: u radial, w = +Z on a flat disk");
	check(res.organs[0].u[0] == 1 && res.organs[0].pos[0] == 0,
	    "planar: organ 0 at the centre facing +X");
	check(fabs(res.organs[7].radius - c * sqrt(M_PI / (2 * sqrt(3)))) <
	    1e-12, "planar: packing radius c sqrt(pi / (2 sqrt 3))");
	result_free(&res);
	scene_free(&sc);
}

static void
test_planar_variants(void)
{
	struct scene sc;
	struct result res;
	double ez = 0, en = 0, ef = 0;

	if (scene_text_run("model = \"planar\"; count = 300;\n"
	    "planar = { outer = 2.5; inner = 0.5; exponent = 0.6; };",
	    &sc, &res) == 0) {
		const struct organ *o = res.organs;
		double c = 2.0 / pow(299, 0.6);

		check(fabs(hypot(o[299].pos[0], o[299].pos[1]) - 2.5) < 1e-12,
		    "planar: outer puts the last organ at the outer radius");
		check(fabs(hypot(o[0].pos[0], o[0].pos[1]) - 0.5) < 1e-12,
		    "planar: inner puts organ 0 at the inner radius");
		check(fabs(hypot(o[77].pos[0], o[77].pos[1]) -
		    (0.5 + c * pow(77, 0.6))) < 1e-12,
		    "planar: r = inner + c n^exponent");
	} else
		check(0, "planar: variants scene loads");
	result_free(&res);
	scene_free(&sc);

	if (scene_text_run("model = \"planar\"; count = 800;\n"
	    "planar = { scale = 0.1; dome = 0.6; };", &sc, &res) == 0) {
		double rim = 0.1 * sqrt(799.0);

		for (size_t n = 0; n < res.count; n++) {
			const struct organ *o = &res.organs[n];
			double rho = hypot(o->pos[0], o->pos[1]);
			/* Gradient of f = z - dome (1 - rho^2/rim^2). */
			double g[3] = { 1.2 * o->pos[0] / (rim * rim),
			    1.2 * o->pos[1] / (rim * rim), 1 }, cr[3];

			ez = fmax(ez, fabs(o->pos[2] -
			    0.6 * (1 - rho * rho / (rim * rim))));
			vec_normalize(g);
			vec_cross(cr, g, o->w);
			en = fmax(en, sqrt(vec_dot(cr, cr)) +
			    fabs(vec_dot(o->u, g)));
			ef = fmax(ef, frame_error(o));
			if (n > 0 && (o->u[2] > 0 ||
			    o->u[0] * o->pos[0] + o->u[1] * o->pos[1] <= 0))
				en = 1;
		}
		check(ez < 1e-12, "planar: dome centres on the paraboloid");
		check(en < 1e-12, "planar: dome w normal, u tangent pointing "
		    "outward and down");
		check(ef < 1e-12, "planar: dome frames orthonormal");
	} else
		check(0, "planar: dome scene loads");
	result_free(&res);
	scene_free(&sc);
}

int
main(void)
{
	test_planar_vogel();
	test_planar_variants();
	return check_failures != 0;
}
