/*
 * lattice.h - the lattice of one band of unordered points: two vectors
 * that step from organ to neighbouring organ, and how many organs of
 * the spiral each step skips (its parastichy number), found by
 * counting that family's spirals across the band.
 */
#ifndef LATTICE_H
#define LATTICE_H

#include <stddef.h>
#include <stdint.h>

#include "analysis/axis.h"
#include "analysis/kdtree.h"

/* The points as the analysis reads them. */
struct point_field {
	const struct axis *A;
	const struct axis_point *ap;
	size_t		 n;
	const double	*area;		/* each point's area per organ */
	const uint32_t	(*nn)[KD_K];	/* its neighbours, nearest first */
	const uint8_t	*nnn;		/* how many */
	const struct kd	*T;		/* over ap[].p */
	const size_t	*order;		/* the points by s */
	const double	*sorted_s;	/* s in that order */
	long		*claim;		/* n of -1: lattice_count()'s room */
};

/*
 * A band's lattice, in unrolled coordinates at the band's reference
 * radius: along the curve (outward) and across it (counter-clockwise),
 * the first scaled so that the lattice of a constant divergence is the
 * same at every radius (by rho and by the area per organ).
 */
struct band_lattice {
	double		 rho, area, s;	/* the reference: the band's medians */
	double		 a[2], b[2];	/* a reduced basis, both outward */
	double		 sigma_t[2];	/* the error of a's and b's across */
	double		 sigma_s[2];	/* and along */
	double		 on;		/* share of neighbour steps on it */
	int		 ok;
	long long	 ka, kb;	/* organs a step of a, of b skips */
	double		 ka_est, kb_est;	/* the same from a's and b's
					   shape alone, continuous */
	double		 ka_err, kb_err;	/* their errors */
	double		 coverage;	/* of the ring at s, 0 .. 1 */
	int		 counted;	/* ka, kb counted on a whole ring */
	int		 clamped;	/* counted at the outermost (1) or
					   innermost (-1) ring the spirals
					   cross whole, not its own */
};

/* The step from point i to point j in the band's coordinates. */
void	lattice_step(const struct point_field *,
	    const struct band_lattice *, size_t i, size_t j, double l[2]);
/*
 * Step l as whole steps x a + y b, if it lies within tol (a share of
 * |a|) of one: 1, else 0.
 */
int	lattice_round(const struct band_lattice *, const double l[2],
	    double tol, long long *x, long long *y);
/* The basis of the band pts[0 .. n); 0, or -1 where none shows. */
int	lattice_basis(const struct point_field *, const size_t *pts,
	    size_t n, struct band_lattice *);
/*
 * ka and kb: the spirals of each family counted across the ring at the
 * band's s (if count_them), counted set where the ring is whole and the
 * counts agree with the basis's shape (ka_est, kb_est, set either way);
 * -1 where the basis has none.
 */
int	lattice_count(const struct point_field *, struct band_lattice *,
	    int count_them);
/*
 * ka and kb from the turn of a and b and the divergence alpha (radians,
 * to alpha_err) of a band next to this one: 0, or -1 where no one
 * number fits.
 */
int	lattice_by_angle(struct band_lattice *, double alpha,
	    double alpha_err);

#endif
