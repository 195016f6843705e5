/*
 * collision_impl.h - what the collision model's files share: the
 * primordia placed so far, the spatial hash grid over them and its
 * lookups (collision_grid.c keeps it up to date), and the walks that
 * place the next one (collision_walk.c, exact; collision_brute.c, the
 * tests' reference).
 */
#ifndef COLLISION_IMPL_H
#define COLLISION_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "geometry/curve.h"
#include "models/collision_cover.h"

struct collision;
struct model_ctx;

struct prim {
	double	 x, y, z, r, t;
};

/* A hash of grid cells to lists of primordia: neighbours in O(1). */
struct slot {
	int32_t	 key[3];
	int32_t	 head;		/* -1: empty slot */
};

struct coll {
	const struct model_ctx *ctx;
	const struct collision *p;
	double		 rconst;	/* > 0: the radius, not P->radius */
	struct curve	 cv;
	struct prim	*pr;
	size_t		 n, cap;
	double		 rmax;		/* largest radius placed */
	double		 g, inv_g;	/* grid cell size, its inverse */
	double		 reach;		/* the area placing may cover */
	struct slot	*slot;
	uint32_t	 mask;
	size_t		 used;
	int32_t		*next;		/* per primordium: next in its cell */
	struct cover	 cover;
	int		 nocover;	/* walk without the cover map */
	int		 check;		/* test what refine() proves */
	int		 finer;		/* the map's cells doubled (a falling
					   radius up a tall band) */
	long long	 refined, refine_misses;
	long long	 starts, start_misses;	/* check: start_row()'s */
	double		*law;		/* the radius law sampled, or NULL */
	double		*law_min;	/* the least of law[i ..], each i */
	long long	 law_step;	/* every law_step primordia */
	size_t		 nlaw;
};

/*
 * The grid's lookups, inline: the walk asks them for every stop
 * (collision_walk.c), the grid's upkeep for every primordium.
 */

static inline uint32_t
hash3(const int32_t k[3])
{
	uint32_t h = (uint32_t)k[0] * 0x9E3779B1u ^
	    (uint32_t)k[1] * 0x85EBCA77u ^ (uint32_t)k[2] * 0xC2B2AE3Du;

	return h ^ h >> 15;
}

/* Cell k's slot, or the empty one it would take, from slot i on. */
static inline struct slot *
slot_from(const struct coll *C, const int32_t k[3], uint32_t i)
{
	for (;; i = (i + 1) & C->mask) {
		struct slot *s = &C->slot[i];

		if (s->head < 0 || (s->key[0] == k[0] && s->key[1] == k[1] &&
		    s->key[2] == k[2]))
			return s;
	}
}

static inline struct slot *
slot_find(const struct coll *C, const int32_t k[3])
{
	return slot_from(C, k, hash3(k) & C->mask);
}

/* Far-flung cells share a key: slower, never wrong, and no overflow. */
static inline int32_t
cell1(double v)
{
	int32_t i;

	if (!(v >= -1e9))
		return -1000000000;
	if (v > 1e9)
		return 1000000000;
	/* floor() without the call: truncation, one down below zero. */
	i = (int32_t)v;
	return i - (v < i);
}

static inline void
cell_of(const struct coll *C, double x, double y, double z, int32_t k[3])
{
	/*
	 * A product, not a division: monotone all the same, so a box's
	 * cells still hold every point inside it.
	 */
	k[0] = cell1(x * C->inv_g);
	k[1] = cell1(y * C->inv_g);
	k[2] = cell1(z * C->inv_g);
}

/*
 * How many grid cells a box of half-size q about (x, y, z) spans, and
 * which: when radii grow far beyond the first one the cells are small
 * beside the box, and a plain pass over every primordium is cheaper
 * than a pass over the cells (and cannot hang).
 */
static inline double
box_cells(const struct coll *C, double x, double y, double z, double q,
    int32_t lo[3], int32_t hi[3])
{
	cell_of(C, x - q, y - q, z - q, lo);
	cell_of(C, x + q, y + q, z + q, hi);
	return ((double)hi[0] - lo[0] + 1) * ((double)hi[1] - lo[1] + 1) *
	    ((double)hi[2] - lo[2] + 1);
}

/* The grid's upkeep (collision_grid.c). */
void	coll_grid_insert(struct coll *, int32_t i);
void	coll_grid_fit(struct coll *, double r);

/*
 * The smallest free t >= t0 on meridian (c, s) at angle phi, for
 * primordium n of radius r, exactly; HUGE_VAL: none.  With s0 >= 0,
 * t0 is curve_t(s0), worked out only if the walk must look there.
 * *row is t's row of the cover map, if the walk found it, else -1, and
 * p the curve's point at t (collision_walk.c).
 */
double	coll_place_exact(struct coll *, long long n, double t0, double s0,
	    double phi, double c, double s, double r, int32_t *row,
	    double p[2]);
/* For cover_check: a primordium's surface within U of p? */
int	coll_near_point(void *, const double p[3], double U);

/* The same by brute force, the tests' reference (collision_brute.c). */
double	coll_place_brute(const struct coll *, double t0, double c, double s,
	    double r);

#endif
