/*
 * collision_brute.c - the reference for the collision model's tests
 * and benchmark: every earlier primordium tried at finely spaced points
 * along the curve.
 */
#include <math.h>

#include "models/collision_impl.h"

/*
 * Does any earlier primordium overlap the point at t on meridian
 * (c, s)?  All of them are tried, the last one found first: along a
 * scan one primordium covers many samples in a row.
 */
static int
blocked_any(const struct coll *C, double t, double c, double s, double r,
    size_t *last)
{
	double p[2], x, y, z;

	curve_eval(&C->cv, t, p, NULL);
	x = p[0] * c;
	y = p[0] * s;
	z = p[1];
	for (size_t k = 0; k <= C->n; k++) {
		size_t i = k == 0 ? *last : k - 1;
		const struct prim *o = &C->pr[i];
		double dx = x - o->x, dy = y - o->y, dz = z - o->z,
		    R = r + o->r;

		if (i >= C->n)
			continue;
		if (dx * dx + dy * dy + dz * dz < R * R) {
			*last = i;
			return 1;
		}
	}
	return 0;
}

/*
 * The reference for the tests and the benchmark: every earlier
 * primordium at samples r / BRUTE_DIV apart along the curve, then
 * bisection between the last covered and the first free sample.  A gap
 * narrower than the spacing is missed: that is the point of having
 * the exact walk.
 */
#define BRUTE_DIV	1024

double
coll_place_brute(const struct coll *C, double t0, double c, double s, double r)
{
	double h = r / BRUTE_DIV / C->cv.speed, lo = t0;
	size_t last = 0;

	if (!blocked_any(C, t0, c, s, r, &last))
		return t0;
	for (double k = 1;; k++) {
		double t = fmin(t0 + k * h, C->cv.tmax);

		if (!blocked_any(C, t, c, s, r, &last)) {
			for (int i = 0; i < 200; i++) {
				double mid = lo + (t - lo) / 2;

				if (mid <= lo || mid >= t)
					break;
				if (blocked_any(C, mid, c, s, r, &last))
					lo = mid;
				else
					t = mid;
			}
			return t;
		}
		if (t >= C->cv.tmax)
			return HUGE_VAL;
		lo = t;
	}
}
