/*
 * flatten.h - a compound structure's leaf organs carried through the
 * organs that place its parts, into the structure's own frame.
 */
#ifndef FLATTEN_H
#define FLATTEN_H

#include <stddef.h>

#include "result/organ.h"

/*
 * Where a part's organs land: x -> s R x + t, R's columns the placing
 * organ's u, v, w (orthonormal, so frames stay frames).
 */
struct xform {
	double	 R[3][3];	/* R[i][k]: row i of column k */
	double	 s;
	double	 t[3];
};

extern const struct xform xform_identity;

/* Called for each leaf: o of r (an organ whose object is no part) at P. */
typedef void leaf_fn(void *ctx, const struct result *r,
    const struct organ *o, const struct xform *P);

/* Every leaf of r, depth first in organ order. */
void	flatten_walk(const struct result *r, const struct xform *P,
	    leaf_fn *fn, void *ctx);
/* o carried to P: position, frame, scale and radius. */
void	place_organ(const struct xform *P, const struct organ *o,
	    struct organ *out);

/*
 * A view: r with every part opened, without making its leaves, so that
 * memory follows the parts, not the leaves (three levels of 1,000 are a
 * billion leaves).  out is a result whose organs are NULL: its count is
 * r's leaves, its objects the leaves' objects in the order a walk meets
 * them, its other facts r's; result_each() hands the leaves out.
 */
void	flatten_view(const struct result *r, struct result *out);
/* Free a view (result_free() leaves its walk, which it does not know). */
void	flatten_free(struct result *view);
/* How many leaves r has, from each part's tally: no walk. */
double	flatten_leaves(const struct result *r);

#define RESULT_ALL	((size_t)-1)

/* Called for each organ: placed in the result's frame, its object the
 * index into that result's objects. */
typedef void organ_fn(void *ctx, const struct organ *o);
/*
 * Each organ of r, in order (a view's leaves), of object k alone
 * unless k is RESULT_ALL.
 */
void	result_each(const struct result *r, size_t k, organ_fn *fn,
	    void *ctx);
/*
 * Up to m organs spread evenly over r, each placed as result_each()
 * gives them: a view's by descending its tree, so that estimating a
 * size never walks its leaves.  A sample's weight is how many organs it
 * stands for (a descent picks each organ of a level alike, so a leaf
 * under many levels of many organs stands for more): a mean over the
 * samples is sum(weight x) / sum(weight).
 */
typedef void sample_fn(void *ctx, const struct organ *o, double weight);
void	result_sample(const struct result *r, size_t m, sample_fn *fn,
	    void *ctx);
/* How many organs of r are object k (a view: its tally). */
double	result_object_organs(const struct result *r, size_t k);

#endif
