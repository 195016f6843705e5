/*
 * test_cylindrical.c - the cylindrical model against ABOP's Table 4.1
 * and the properties that define it: organ 0 touches organs m and n at
 * exactly d, nothing is nearer, and at the ends of the admissible range
 * a third parastichy touches.  Prints "ok"/"not ok" lines.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "models/cylindrical_lattice.h"
#include "models/model.h"
#include "scene/scene.h"
#include "check.h"
#include "scene_text.h"
#include "base/vec.h"


/* ABOP Table 4.1, the 15 rows with a diameter. */
static const struct {
	int	 m, n;
	double	 alpha, h, d;
} table[] = {
	{ 1, 2, 128.571426, 0.777343, 2.374821 },
	{ 1, 3, 96.923073, 0.418569, 1.742642 },
	{ 2, 3, 142.105270, 0.286389, 1.441462 },
	{ 1, 4, 77.142860, 0.259114, 1.371104 },
	{ 3, 4, 102.162163, 0.147065, 1.032949 },
	{ 3, 5, 135.918365, 0.111049, 0.897598 },
	{ 2, 5, 152.307693, 0.139523, 1.006115 },
	{ 1, 5, 63.870968, 0.175529, 1.128493 },
	{ 4, 5, 79.672134, 0.089203, 0.804479 },
	{ 4, 7, 98.709671, 0.058510, 0.651536 },
	{ 3, 7, 107.088600, 0.068878, 0.706914 },
	{ 3, 8, 131.752579, 0.056097, 0.637961 },
	{ 5, 8, 138.139542, 0.042181, 0.553204 },
	{ 5, 7, 150.275223, 0.049921, 0.601820 },
	{ 2, 7, 158.507462, 0.081215, 0.767613 },
};

static void
test_table(void)
{
	for (size_t i = 0; i < sizeof(table) / sizeof(table[0]); i++) {
		double a, h, d;

		cyl_triple(table[i].m, table[i].n, &a, &h, &d);
		check(fabs(a - table[i].alpha) / 360 < 2e-5 &&
		    fabs(h - table[i].h) < 2e-5 && fabs(d - table[i].d) < 2e-5,
		    "Table 4.1 (%d, %d, %d): alpha %.6f h %.6f d %.6f",
		    table[i].m, table[i].n, table[i].m + table[i].n, a, h, d);
	}
}

/* Distance from organ 0 to organ k on the unrolled unit cylinder. */
static double
unrolled(double alpha, double h, int k)
{
	double a = remainder(k * alpha * (M_PI / 180), 2 * M_PI);

	return hypot(a, k * h);
}

static int
gcd(int a, int b)
{
	return b == 0 ? a : gcd(b, a % b);
}

/*
 * Every coprime m < n up to (21, 34): at five divergences across the
 * admissible range organ 0 touches m and n at d and nothing nearer;
 * at the range's ends a third organ (m + n or n - m) touches as well.
 */
static void
test_pairs(void)
{
	int pairs = 0, bad_touch = 0, bad_near = 0, bad_end = 0, bad_dn = 0;
	char first[128] = "";

	/* Every coprime pair with n <= 34, so (21, 34) and all below. */
	for (int n = 2; n <= 34; n++)
		for (int m = 1; m < n; m++) {
			double lo, hi, h, d;

			if (gcd(m, n) != 1)
				continue;
			pairs++;
			cyl_range(m, n, &lo, &hi);
			for (int i = 0; i <= 4; i++) {
				double a = lo + (hi - lo) * (0.001 + 0.998 *
				    i / 4.0);
				double nearest = HUGE_VAL;
				int dm, dn;

				if (cyl_pair(m, n, a, &h, &d) != 0) {
					bad_touch++;
					continue;
				}
				if (fabs(unrolled(a, h, m) - d) > 1e-9 ||
				    fabs(unrolled(a, h, n) - d) > 1e-9) {
					bad_touch++;
					if (!*first)
						snprintf(first, sizeof(first),
						    "(%d, %d) at %.6f", m, n,
						    a);
				}
				for (int k = 1; k * h < 2 * d + 1; k++)
					nearest = fmin(nearest,
					    unrolled(a, h, k));
				if (nearest < d - 1e-9)
					bad_near++;
				if (cyl_contacts(a, h, &dm, &dn, &d) != 0 ||
				    dm != m || dn != n)
					bad_dn++;
			}
			/* At the ends: a third parastichy in contact. */
			for (int e = 0; e < 2; e++) {
				double a = e ? hi : lo;
				int third = 0;

				if (cyl_pair(m, n, a, &h, &d) != 0)
					continue;	/* (1, 2) at 180 */
				if (fabs(unrolled(a, h, m + n) - d) < 1e-7 ||
				    fabs(unrolled(a, h, n - m) - d) < 1e-7)
					third = 1;
				bad_end += !third;
			}
		}
	check(bad_touch == 0, "organ 0 touches organs m and n at exactly d "
	    "(%d coprime pairs up to (21, 34), 5 divergences each) %s",
	    pairs, first);
	check(bad_near == 0, "no organ is nearer than d (%d failures)",
	    bad_near);
	check(bad_dn == 0, "the contact parastichies found from (alpha, h) "
	    "are (m, n) again (%d failures)", bad_dn);
	check(bad_end == 0, "at both ends of the range a third parastichy "
	    "touches (%d failures)", bad_end);
}

static void
test_encyclic(void)
{
	int dm, dn, s = cyl_encyclic(5, 8, &dm, &dn);

	check(dm == 2 && dn == 3 && s == 1 && 8 * dm - 5 * dn == 1,
	    "encyclic numbers of (5, 8) are (2, 3)");
	s = cyl_encyclic(8, 13, &dm, &dn);
	check(dm == 3 && dn == 5 && 13 * dm - 8 * dn == s,
	    "encyclic numbers of (8, 13) are (3, 5)");
}

static void
test_model(void)
{
	struct scene sc;
	struct result r;
	double h, d, e = 0, ef = 0;

	if (scene_text_run("model = \"cylindrical\"; count = 300;\n"
	    "cylindrical = { radius = 2.5; parastichies = [5, 8]; };",
	    &sc, &r) != 0) {
		check(0, "the (5, 8) scene loads");
		return;
	}
	cyl_pair(5, 8, 137.50776405003785, &h, &d);
	for (size_t k = 0; k < r.count; k++) {
		const struct organ *o = &r.organs[k];
		double ang = atan2(o->pos[1], o->pos[0]) * 180 / M_PI;
		double want = fmod(k * 137.50776405003785, 360), c[3];

		e = fmax(e, fabs(hypot(o->pos[0], o->pos[1]) - 2.5));
		e = fmax(e, fabs(o->pos[2] - k * h * 2.5));
		e = fmax(e, fabs(remainder(ang - want, 360)));
		e = fmax(e, fabs(o->radius - d / 2 * 2.5));
		/* w outward, u down the axis, v = w x u, orthonormal. */
		ef = fmax(ef, fabs(o->w[0] - o->pos[0] / 2.5) +
		    fabs(o->w[1] - o->pos[1] / 2.5) + fabs(o->w[2]));
		ef = fmax(ef, fabs(o->u[2] + 1));
		/* v = w x u turns counter-clockwise: along (-y, x). */
		organ_v(o, c);
		ef = fmax(ef, fabs(c[0] + o->pos[1] / 2.5) +
		    fabs(c[1] - o->pos[0] / 2.5) + fabs(c[2]));
	}
	check(e < 1e-9, "organ k at angle k alpha, height k h R on radius R, "
	    "packing radius d/2 R (worst %.2g)", e);
	check(ef < 1e-12, "frames: w outward, u down the axis, v = w x u");
	result_free(&r);
	scene_free(&sc);

	/* A taper: the rise and size follow the local radius. */
	if (scene_text_run("model = \"cylindrical\"; count = 400;\n"
	    "cylindrical = { radius = \"1.5 - t\"; parastichies = [8, 13]; };",
	    &sc, &r) == 0) {
		double worst = 0, wn = 0;

		cyl_pair(8, 13, 137.50776405003785, &h, &d);
		for (size_t k = 1; k < r.count; k++) {
			const struct organ *o = &r.organs[k], *p = o - 1;
			double rk = hypot(o->pos[0], o->pos[1]);
			double rp = hypot(p->pos[0], p->pos[1]);
			double dr = rk - rp, dz = o->pos[2] - p->pos[2], g[3];

			worst = fmax(worst, fabs(dz - h * (rk + rp) / 2));
			worst = fmax(worst, fabs(o->radius - d / 2 * rk));
			/* w is normal to the cone's generating line. */
			g[0] = dr * o->pos[0] / rk;
			g[1] = dr * o->pos[1] / rk;
			g[2] = dz;
			vec_normalize(g);
			wn = fmax(wn, fabs(vec_dot(g, o->w)));
		}
		check(worst < 1e-12, "taper: rise and size follow the local "
		    "radius");
		check(wn < 1e-3, "taper: w is normal to the surface (%.2g)",
		    wn);
	} else
		check(0, "the taper scene loads");
	result_free(&r);
	scene_free(&sc);
}

int
main(void)
{
	check_topic = "cylinder: ";
	test_table();
	test_encyclic();
	test_pairs();
	test_model();
	return check_failures != 0;
}
