/*
 * planar.c - Vogel's model (ABOP ch. 4): organ n at angle n*alpha and
 * radius inner + c*n^e on a disk facing +Z, optionally lifted onto a
 * paraboloid dome.  The packing radius is that of a hexagonal packing
 * with the same area per organ, which is pi*c^2 for Vogel's formula.
 */
#include <math.h>

#include "model.h"

/* n^e; pow() is the model's costliest call, and e is mostly 1/2. */
static double
power(double n, double e)
{
	return e == 0.5 ? sqrt(n) : pow(n, e);
}

static int
planar_check(const struct scene *sc)
{
	const struct planar_params *p = &sc->planar;

	if (!scene_given(sc, "count")) {
		scene_error(sc, "count", "missing setting 'count'");
		return -1;
	}
	if (scene_given(sc, "planar.outer") && scene_given(sc, "planar.scale")) {
		scene_error(sc, "planar.outer", "give planar.scale or "
		    "planar.outer, not both");
		return -1;
	}
	if (scene_given(sc, "planar.outer") && p->outer <= p->inner) {
		scene_error(sc, "planar.outer", "planar.outer %.9g must be "
		    "greater than planar.inner %.9g", p->outer, p->inner);
		return -1;
	}
	return 0;
}

int
planar_run(const struct scene *sc, struct result *res)
{
	const struct planar_params *p = &sc->planar;
	size_t count = (size_t)sc->count;
	double c = p->scale, rim, kdome;

	if (planar_check(sc) < 0)
		return -1;
	if (scene_given(sc, "planar.outer"))
		c = count > 1 ? (p->outer - p->inner) /
		    pow((double)(count - 1), p->exponent) :
		    p->outer - p->inner;
	rim = p->inner + c * power((double)(count - 1), p->exponent);
	/* z = dome * (1 - (rho/rim)^2), so dz/drho = -kdome * rho. */
	kdome = rim > 0 ? 2 * p->dome / (rim * rim) : 0;

	result_init(res, count);
	res->divergence = sc->divergence;
	res->objects = sc->objects;
	res->nobjects = sc->nobjects;
	for (size_t n = 0; n < count; n++) {
		struct organ *o = &res->organs[n];
		double phi = angle_mod360((double)n, sc->divergence);
		/* m: organ 0 takes its area per organ from n = 1. */
		double m = n > 1 ? (double)n : 1, pm = power(m, p->exponent);
		double rho = p->inner + (n > 0 ? c * pm : 0);
		double z = rim > 0 ? p->dome * (1 - (rho / rim) * (rho / rim)) :
		    p->dome;

		/* The tip is the centre: away from it is outward, (1, dz/drho). */
		frame_revolution(o, phi, rho, z, 1, -kdome * rho);
		/* Area per organ d(pi rho^2)/dn shared as hexagons. */
		o->radius = sqrt(M_PI * (p->inner + c * pm) *
		    (c * p->exponent * pm / m) / sqrt(3.0));
		o->scale = o->radius;
		o->object = 0;
	}
	result_info(res, "scale", 1, c);
	result_info(res, "outer", 1, rim);
	if (count >= 3) {
		int pair[2];

		parastichies(res, count - 1, pair);
		if (pair[0] > 0)
			result_info(res, "parastichies", 2, (double)pair[0],
			    (double)pair[1]);
	}
	return 0;
}
