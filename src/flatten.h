/*
 * flatten.h - a compound structure's leaf organs carried through the
 * organs that place its parts, into the structure's own frame.
 */
#ifndef FLATTEN_H
#define FLATTEN_H

#include <stddef.h>

#include "organ.h"

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
/* How many leaves r has. */
size_t	flatten_count(const struct result *r);
/*
 * out: r with every part opened, each leaf an organ in r's frame and
 * its objects the leaves' (NULL sub); the rest of r's facts kept.
 */
void	flatten_result(const struct result *r, struct result *out);

#endif
