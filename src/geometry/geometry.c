/* geometry.c - small geometric facts shared by the models. */
#include <math.h>
#include <stdlib.h>

#include "geometry/geometry.h"
#include "base/vec.h"

/*
 * n*deg mod 360.  For a million organs n*deg is near 1e8 and its
 * rounding would cost seven digits of the angle; fma() recovers the
 * product's rounding error exactly, and p - 360k is exact too (the
 * result needs no more bits than p has below 360).
 */
double
angle_mod360(double n, double deg)
{
	double p = n * deg, err = fma(n, deg, -p);
	double a = fma(-360.0, floor(p / 360.0), p) + err;

	if (a >= 360.0)
		a -= 360.0;
	else if (a < 0)
		a += 360.0;
	return a;
}

void
frame_revolution(struct organ *o, double phi, double rho, double z,
    double t_rho, double t_z)
{
	frame_revolution_cs(o, phi, cos(phi * (M_PI / 180)),
	    sin(phi * (M_PI / 180)), rho, z, t_rho, t_z);
}

void
frame_revolution_cs(struct organ *o, double phi, double c, double s,
    double rho, double z, double t_rho, double t_z)
{
	double n2 = t_rho * t_rho + t_z * t_z;
	/* hypot() only where the squares could overflow or underflow. */
	double k = n2 > 1e-280 && n2 < 1e280 ? 1 / sqrt(n2) :
	    1 / hypot(t_rho, t_z);

	t_rho *= k;
	t_z *= k;
	o->phi = phi;
	o->height = z;
	o->pos[0] = rho * c;
	o->pos[1] = rho * s;
	o->pos[2] = z;
	o->u[0] = t_rho * c;
	o->u[1] = t_rho * s;
	o->u[2] = t_z;
	o->w[0] = -t_z * c;
	o->w[1] = -t_z * s;
	o->w[2] = t_rho;
}

void
frame_dome(struct organ *o, double phi, double rho, double rim, double dome)
{
	/* dz/drho = -kdome rho: away from the tip is outward, (1, dz/drho). */
	double kdome = rim > 0 ? 2 * dome / (rim * rim) : 0;
	double z = rim > 0 ? dome * (1 - (rho / rim) * (rho / rim)) : dome;

	frame_revolution(o, phi, rho, z, 1, -kdome * rho);
}

/*
 * Does a divergence of deg degrees line count organs up on rays?  It
 * does when deg/360 is so near a fraction p/q, with at least three
 * organs to a ray (3q <= count), that organ n + q lands beside organ n
 * and the drift along the whole ray stays below the gap between rays:
 * count |q x - p| < 1, x = deg/360.  The continued fraction of x gives
 * the only q worth trying.  137.5 degrees is 55/144 of a turn exactly;
 * the golden angle is never near enough (q |q x - p| tends to 1/sqrt 5).
 */
int
divergence_rays(double deg, size_t count, long long *p, long long *q)
{
	double x = fabs(deg) / 360, f = x - floor(x);
	long long h0 = 1, h1 = (long long)floor(x), k0 = 0, k1 = 1;

	for (int i = 0; i < 64 && 3 * (double)k1 <= (double)count; i++) {
		double a;

		if (fabs((double)k1 * x - (double)h1) * (double)count < 1 &&
		    k1 > 1) {
			*p = h1;
			*q = k1;
			return 1;
		}
		if (f < 1e-15)
			break;
		f = 1 / f;
		a = floor(f);
		f -= a;
		if (a > 1e15)
			break;
		{
			long long h = (long long)a * h1 + h0;
			long long k = (long long)a * k1 + k0;

			h0 = h1;
			h1 = h;
			k0 = k1;
			k1 = k;
		}
	}
	return 0;
}

/*
 * Stretch placed organs by the diagonal matrix S = diag(k): positions
 * by S, tangents (u) by S, normals (w) by S's inverse transpose, both
 * made unit again.  They stay orthogonal, (S u).(S^-1 w) = u.w = 0, and
 * w stays normal to the stretched surface.  The angle about the axis is
 * read again from the position when x and y stretch differently.
 */
void
stretch_apply(struct result *res, const double k[3])
{
	if (k[0] == 1 && k[1] == 1 && k[2] == 1)
		return;
	for (size_t i = 0; i < res->count; i++) {
		struct organ *o = &res->organs[i];
		double lu = 0, lw = 0;

		for (int j = 0; j < 3; j++) {
			o->pos[j] *= k[j];
			o->u[j] *= k[j];
			o->w[j] /= k[j];
			lu += o->u[j] * o->u[j];
			lw += o->w[j] * o->w[j];
		}
		lu = 1 / sqrt(lu);
		lw = 1 / sqrt(lw);
		for (int j = 0; j < 3; j++) {
			o->u[j] *= lu;
			o->w[j] *= lw;
		}
		o->height = o->pos[2];
		if (k[0] != k[1] && (o->pos[0] != 0 || o->pos[1] != 0)) {
			o->phi = atan2(o->pos[1], o->pos[0]) * (180 / M_PI);
			if (o->phi < 0)
				o->phi += 360;
		}
	}
}
