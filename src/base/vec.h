/* vec.h - the few 3-vector operations the models need, inline. */
#ifndef VEC_H
#define VEC_H

#include <math.h>

static inline void
vec_set(double r[3], double x, double y, double z)
{
	r[0] = x;
	r[1] = y;
	r[2] = z;
}

static inline double
vec_dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void
vec_cross(double r[3], const double a[3], const double b[3])
{
	double x = a[1] * b[2] - a[2] * b[1];
	double y = a[2] * b[0] - a[0] * b[2];
	double z = a[0] * b[1] - a[1] * b[0];

	vec_set(r, x, y, z);
}

static inline void
vec_normalize(double a[3])
{
	double len = sqrt(vec_dot(a, a));

	if (len > 0) {
		a[0] /= len;
		a[1] /= len;
		a[2] /= len;
	}
}

#endif
