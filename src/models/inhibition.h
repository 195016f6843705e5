/* inhibition.h - the inhibition model's hooks for the tests and benchmarks. */
#ifndef INHIBITION_H
#define INHIBITION_H

struct model_ctx;
struct result;

/*
 * how: 0, or INHIB_ALL_PAIRS: the power law summed one by one, no far
 * field (the bench's reference); and/or INHIB_CHECK_BOUNDS: every gap
 * searched too, and --info's "bound misses" counts the gap bounds above
 * the least E found in their gap (the tests': it must be 0).
 */
enum { INHIB_ALL_PAIRS = 1, INHIB_CHECK_BOUNDS = 2 };

/* Place as how says, an inhibition scene's ctx (model.h); count given. */
int	inhibition_place(const struct model_ctx *, struct result *, int how);

#endif
