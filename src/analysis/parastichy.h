/* parastichy.h - contact parastichies measured on placed organs. */
#ifndef PARASTICHY_H
#define PARASTICHY_H

#include <stddef.h>

#include "result/organ.h"

/* Most pairs a transition lists, in the order its runs showed them. */
#define PARA_SEEN	3

/*
 * A stretch of the structure from organ from on: one family pair m/n
 * (coprime, held by at least half its organs), or, where m is 0, a
 * transition, whose runs' most common pairs were seen[0..nseen) (not
 * pairs: they may share a factor, 34/68, or hold few organs).
 */
struct para_zone {
	long long	 from;
	int		 m, n;
	int		 seen[PARA_SEEN][2];
	int		 nseen;
	double		 rho, z;	/* where organ from lies */
};

/*
 * The opposed pair of contact parastichies at each organ, smaller
 * first, from its nearest earlier neighbours turning either way about
 * the axis;
 * 0 0 where there is none (on the axis, or too few organs).
 */
void	para_pairs(const struct result *, int (*pair)[2]);

/* Each organ's distance to its nearest other organ (HUGE_VAL if alone). */
void	para_nearest(const struct result *, double *d);

/*
 * The zones along the structure in index order, pairs and transitions;
 * how many (<= zmax).  pair: every organ's, or NULL to measure an even
 * sample of each run.
 */
size_t	para_zones(const struct result *, const int (*pair)[2],
	    struct para_zone *, size_t zmax);

/* Writes "transition 47/60 21/42" for a transition's zone; its length. */
int	para_seen_text(const struct para_zone *, char *, size_t);

/* The greatest common divisor of a, b >= 0: pairs are coprime. */
int	para_gcd(int a, int b);

#endif
