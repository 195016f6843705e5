/*
 * axis.h - where a pattern's axis is and what surface it lies on, found
 * from its points alone: the centre of a head, the axis of a cone, the
 * squash of an oblique photograph, and the generating curve.
 */
#ifndef AXIS_H
#define AXIS_H

#include <stddef.h>

/*
 * The fit.  Corrected coordinates are (M (x - centre, y - centre), z):
 * the axis is their Z axis, and the view's squash is undone (M only
 * stretches: a view foreshortens the one way).  The generating curve runs from the
 * tip (a head's centre, a cone's apex) outward, by arc length s.
 */
struct axis {
	double		 centre[2];	/* in the points' coordinates */
	double		 M[2][2];
	double		 squash;	/* short over long axis of the view */
	double		 squash_deg;	/* its short axis, in [0, 180) */
	double		 spacing;	/* median distance to the nearest */
	int		 has_z;
	int		 surface;	/* a surface of revolution, not a head */
	double		(*node)[3];	/* the curve: s, rho, z; owned */
	size_t		 nnode;
};

/* A point in the fit's terms. */
struct axis_point {
	double		 p[3];		/* corrected */
	double		 s;		/* along the curve from the tip */
	double		 rho, phi;	/* from the axis; angle in radians */
	double		 t[2];		/* the curve's unit tangent (drho,
					   dz) at it, away from the tip */
};

/*
 * Fit the axis to points p[0 .. n) (z used if has_z), starting at guess
 * (the centre in the points' coordinates) if not NULL.  Always succeeds
 * on n >= 3 points not all on one line.
 */
void	axis_find(struct axis *, const double (*p)[3], size_t n, int has_z,
	    const double *guess);
void	axis_points(const struct axis *, const double (*p)[3], size_t n,
	    struct axis_point *);
/* The corrected position at arc length s, angle phi, on the surface. */
void	axis_place(const struct axis *, double s, double phi, double X[3]);
/* The curve's rho and z at arc length s (past the ends, straight on). */
void	axis_curve(const struct axis *, double s, double *rho, double *z);
void	axis_free(struct axis *);

#endif
