/* curve.h - a receptacle's generating curve: cubic Bezier segments in (radius, height). */
#ifndef CURVE_H
#define CURVE_H

#include <stddef.h>

/*
 * The curve is cut into short pieces, each a cubic Bezier of its own
 * over u in [0, 1], so that the distance from a point to a piece is
 * nearly always a convex function of u (see curve_exit).
 */
struct piece {
	double	 b[4][2];	/* control points, (radius, height) */
	double	 c[4][2];	/* the same polynomial in powers of u */
	double	 t0, t1;	/* the global parameter at its ends */
	double	 s0;		/* arc length from the base to its start */
	double	 a0;		/* area swept from the base to its start */
	double	 da[2];		/* d(area)/du at u = 0 and u = 1 */
	double	 kappa;		/* g(u) = |p(u) - q|^2 is convex on the
				   piece for |p - q| < kappa */
	double	 box[2][2];	/* its control points' least and largest
				   radius, then height */
};

/*
 * The global parameter t runs from 0 at the base to tmax at the tip,
 * segment k covering [k, k + 1].
 */
struct curve {
	struct piece	*pc;
	size_t		 npc;
	double		*t0;		/* npc + 1: each piece's start in t,
					   then the tip's, side by side */
	size_t		*first;		/* per segment, and past the last:
					   the index of its first piece */
	double		 tmax;		/* the number of segments */
	double		 length;	/* arc length, base to tip */
	double		 area;		/* of the surface it sweeps */
	double		 rho_max;	/* widest radius */
	double		 speed;		/* at least |dp/dt| everywhere */
};

/* From 3k+1 control points; -1 if the curve has no length. */
int	curve_init(struct curve *, const double (*pts)[2], int npts);
void	curve_free(struct curve *);

/* The point at t, and the derivative dp/dt (d may be NULL). */
void	curve_eval(const struct curve *, double t, double p[2], double d[2]);

/* Arc length from the base to t, and its inverse. */
double	curve_s(const struct curve *, double t);
double	curve_t(const struct curve *, double s);

/*
 * The area of the surface swept from the base to t, and its inverse:
 * the t where that area reaches a, with the point there and dp/dt (p
 * and d, unless p is NULL).  *hint, if not NULL, is a piece to start
 * looking from (0 at first), kept for the next call, so that increasing
 * areas cost O(1) each.
 */
double	curve_area(const struct curve *, double t);
double	curve_t_area(const struct curve *, double a, size_t *hint,
	    double p[2], double d[2]);

/*
 * The first t' >= t at which the curve is at least sqrt(S2) away from
 * the point q = (q0, q1): where a primordium leaves the disk in which
 * it would overlap an earlier one.  HUGE_VAL if it never does before
 * the tip.  Exact up to rounding: no sampling, so no gap is skipped.
 * at, if not NULL, gets the curve's point at t' (before the tip).
 */
double	curve_exit(const struct curve *, double t, const double q[2],
	    double S2, double at[2]);

#endif
