/* parastichy.h - contact parastichies measured on placed organs. */
#ifndef PARASTICHY_H
#define PARASTICHY_H

#include <stddef.h>

#include "organ.h"

/* A stretch of the structure with one contact pair, from organ from on. */
struct para_zone {
	long long	 from;
	int		 m, n;
	double		 rho, z;	/* where organ from lies */
};

/*
 * The opposed pair of contact parastichies at each organ, smaller
 * first, from its nearest earlier neighbours turning either way about
 * the axis;
 * 0 0 where there is none (on the axis, or too few organs).
 */
void	para_pairs(const struct result *, int (*pair)[2]);

/*
 * The zones along the structure in index order; how many (<= zmax).
 * pair: every organ's, or NULL to measure an even sample of each run.
 */
size_t	para_zones(const struct result *, const int (*pair)[2],
	    struct para_zone *, size_t zmax);

#endif
