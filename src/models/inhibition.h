/* inhibition.h - the inhibition model's hooks for the tests and benchmarks. */
#ifndef INHIBITION_H
#define INHIBITION_H

#include <stddef.h>

struct model_ctx;
struct result;

/*
 * how: 0, or INHIB_ALL_PAIRS: the power law summed one by one, no far
 * field, and the Gaussian kernel's weights summed exactly however many
 * primordia (the references); and/or INHIB_CHECK_BOUNDS: every gap
 * searched too, and --info's "bound misses" counts the gap bounds above
 * the least E found in their gap (the tests': it must be 0).
 */
enum { INHIB_ALL_PAIRS = 1, INHIB_CHECK_BOUNDS = 2 };

/*
 * The weights a run of count primordia with the Gaussian kernel gives
 * the ages k[0 .. n - 1] (each over GAUSS_NEAR, 32), into w.
 */
void	inhibition_gauss_weights(size_t count, const double *k, double *w,
	    size_t n);

/* Place as how says, an inhibition scene's ctx (model.h); count given. */
int	inhibition_place(const struct model_ctx *, struct result *, int how);

#endif
