/* collision_cover.h - where the receptacle is provably covered. */
#ifndef COVER_H
#define COVER_H

#include <stdint.h>

#include "geometry/curve.h"

#define COVER_SUB	4	/* sub-cells a side, for a closer look */
#define COVER_Z		32	/* column halvings, at most */
#define COVER_E		8	/* row heights: a times 1, 2, .. 2^(COVER_E - 1) */

/*
 * The receptacle cut into cells: rows of arc length up the curve,
 * columns of equal angle about the axis.  Each cell keeps an upper
 * bound U of the clearance min_i (|p - Q_i| - r_i) over all its points
 * p, so a new primordium of radius r > U overlaps something wherever
 * it is put in the cell.  Each column keeps how many of its rows, from
 * the base up, are so covered (for every radius above f).
 *
 * Rows come in runs of 8, each run's rows a 2^e high (its level e),
 * and a bound is kept in steps of q_e = a 2^e / 64: with a falling
 * radius the rows the front passes early are as high as the radius
 * there wants (cover_init()), not as the least radius does.
 */
struct cover {
	double		 a;		/* the lowest rows' height, arc length */
	double		 tight;		/* bounds above this get a closer look;
					   under it a cell is covered for
					   every radius, for good */
	uint8_t		 final[COVER_E];	/* per level: steps 0 ..
					   final - 1 are bounds under most of
					   every radius to come
					   (cover_floor()) */
	double		 q[COVER_E], inv_q[COVER_E];	/* per level: a
					   bound's step, and its inverse */
	int		 levels;	/* the levels in use: 0 .. levels - 1 */
	int32_t		 rows, cols;
	uint8_t		*be;		/* per 8 rows: their level */
	double		*s_row;		/* rows + 1: arc length at each row's
					   start, then the band's end */
	double		*t_row;		/* rows + 1: t at each row's start,
					   then the band's end */
	double		(*start)[4];	/* rows: the curve's point and dp/dt
					   at t_row, as curve_eval() gives
					   them */
	int		 band;		/* the rows end below the tip */
	double		*rho_c, *z_c;	/* rows: the row's middle point */
	double		*d;		/* rows: cell points lie this near */
	double		*h;		/* rows: half the row's arc length */
	double		*kappa;		/* rows: distances to a point are
					   convex along the row within it */
	/*
	 * Rows nearer the axis than the widest have fewer columns, so
	 * that cells are not slivers there: each run of 8 rows has
	 * cols >> z, and a walk up column j meets cell j >> z there.
	 */
	uint8_t		*bz;		/* per 8 rows: their z */
	size_t		*bbase;		/* per 8 rows: the tile of their first
					   8 columns */
	int32_t		*bstride;	/* per 8 rows: tiles to their next 8 */
	double		*mid[COVER_Z];	/* per z: cos, sin of each column's
					   middle angle */
	double		*edge[COVER_Z];	/* per z: of its edges' (cols + 1) */
	double		 sub_turn[COVER_Z][COVER_SUB][2];	/* per z:
					   cos, sin of each sub-column's
					   middle less the column's */
	uint8_t		*u;		/* U in steps of its row's q, in 8 x 8
					   tiles */
	double		(*sub)[3];	/* rows * COVER_SUB: sub-row middles
					   (rho, z) and their cells' d */
	int32_t		*head;		/* cols: rows covered from the base */
	uint8_t		*f;		/* cols: the largest U among them, in
					   steps of q[0] (255: more, or as
					   many) */
	int32_t		*first, *last;	/* cols: their exceptions, or -1 */
	struct except	*ex;		/* the pool of exceptions */
	size_t		 nex, exmax;
	double		 lim_r;		/* the radius of the last walk, */
	uint8_t		 lim[COVER_E];	/* and per level the least bound it
					   is not covered by */
};

/*
 * A cell below a column's head that is not covered everywhere (a gap
 * between primordia too small for the primordium that came by, but not
 * provably too small for every other): walks look at it exactly.
 */
struct except {
	int32_t		 row;
	int32_t		 next;		/* in the column's list, or -1 */
};

/*
 * Map the band from the base up to arc length s_band (the whole curve
 * if it is longer) in cells sized for primordia of radius r_min, at
 * most cells_most of them (fewer, coarser cells past that).  With
 * r_est, no walk of a radius under r_est[i] is expected to look at arc
 * lengths i / n_est to (i + 1) / n_est of the band (a radius that only
 * rises), and cells there may be as wide as that radius wants.  With
 * r_front, the primordia placed while the front crosses those arc
 * lengths are expected to have radii of r_front[i] or more (a radius
 * that falls), and rows there may be as high as that radius wants.
 */
void	cover_init(struct cover *, const struct curve *, double r_min,
	    double s_band, double cells_most, const double *r_est,
	    const double *r_front, int n_est);
/* How many rows cover_init() would cut the band into. */
double	cover_rows(const struct curve *, double r_min, double s_band,
	    double cells_most);
void	cover_free(struct cover *);

/*
 * No primordium to come has a radius under r_floor (at least r_min,
 * and never less than the last call's): bounds under about it cover a
 * cell for good, and cover_add() need not lower them further.
 */
void	cover_floor(struct cover *, double r_floor);

/* The column of angle phi (radians, [0, 2 pi)), in the widest rows. */
int32_t	cover_col(const struct cover *, double phi);

/* Cell (k, j)'s first angle about the axis, *phi0; returns its width. */
double	cover_angles(const struct cover *, int32_t k, int32_t j,
	    double *phi0);

/*
 * The directions (cosine, sine) of cell (k, j)'s middle meridian and
 * of its COVER_SUB sub-columns' middles, in order of angle.
 */
void	cover_dirs(const struct cover *, int32_t k, int32_t j, double mid[2],
	    double sub[COVER_SUB][2]);

/*
 * A walk at angle phi comes next: ask for its column's cells at the
 * head of its prefix, where it will look first, ahead of time.  Each
 * walk's column is far from the last one's, and its cells are seldom
 * in the cache (the dome's map is 17 MB).
 */
void	cover_ahead(const struct cover *, double phi);

/* The row holding t. */
int32_t	cover_row(const struct cover *, double t);

/*
 * Record primordium (x, y, z) of radius r at curve parameter t, in row
 * row (-1: not known), at angle phi about the axis (radians, [0, 2 pi)).
 */
void	cover_add(struct cover *, double t, int32_t row, double phi, double x,
	    double y, double z, double r);

/* Lower cell (k, j)'s bound to U if that is lower. */
void	cover_lower(struct cover *, int32_t k, int32_t j, double U);

/*
 * If t lies in covered cells of column j for radius r, move it past
 * them and return 1; else return 0.  Either way t is then where the
 * walk must look: a cell not covered, an exception, the tip or past
 * the band.  *row is the row of t after, and a guess of it before
 * (-1: none).  Past the band, never.
 */
int	cover_skip(struct cover *, double *t, int32_t j, double r,
	    int32_t *row);

/*
 * For the tests: at 3 x 3 points of every every-th cell whose bound U
 * is below r (its corners, edges' middles and middle), near(ctx, p, U)
 * says whether a primordium comes within U of point p.  Returns the
 * points where none does: 0, or the bounds would let a walk of radius
 * up to r skip room it should have looked at.
 */
long long cover_check(const struct cover *, const struct curve *,
	    double r, int every,
	    int (*near)(void *, const double p[3], double U), void *ctx);

/*
 * A walk found column j's head cell k blocked all along its meridian.
 * If the cell cannot now be proven covered everywhere, it becomes an
 * exception; either way the head moves on.
 */
void	cover_passed(struct cover *, int32_t j, int32_t k);

#endif
