/* collision.h - the collision model's hooks for the tests and benchmarks. */
#ifndef COLLISION_H
#define COLLISION_H

struct model_ctx;
struct receptacle;
struct result;

/* How the collision model places, as the tests and benchmarks choose. */
enum place {
	PLACE_EXACT,	/* the exact walk with the cover map: the model */
	PLACE_PLAIN,	/* the exact walk alone */
	PLACE_BRUTE,	/* every earlier primordium at finely spaced t */
	PLACE_CHECK	/* PLACE_EXACT, and --info's "cover misses" counts
			   points of the cover map's cells further from
			   every primordium than their cell's bound (the
			   tests': it must be 0) */
};

/* Place as how says, a collision scene's ctx (model.h); 0 or -1. */
int	collision_place(const struct model_ctx *, struct result *, int how);

/* The receptacle a collision scene's ctx gave. */
const struct receptacle *collision_receptacle(const struct model_ctx *);

#endif
