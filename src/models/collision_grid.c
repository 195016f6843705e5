/*
 * collision_grid.c - the collision model's spatial hash grid: cells of
 * space to lists of the primordia in them, grown and rebuilt as the
 * primordia and their radii change.  The lookups are inline in
 * collision_impl.h.
 *
 * A look asks for the primordia within r + rmax, rmax the largest
 * radius placed, which with a radius falling 5x is six times the late
 * radius: a look reads 20 to 25 primordia for 1.5 that overlap (the
 * falling sphere and disk; 15 with one radius).  Kept instead by class
 * of radius (factors of two from the first), each class in a grid of
 * its own and asked for r + its own largest radius, a look read 23.4
 * instead of 25.0 (the falling disk, to the tip) and 17.7 instead of
 * 20.7 (the falling sphere, 100,000), from 8.2 cells, and took as long
 * or longer (7.1 against 6.7 us a primordium, 6.3 against 4.9, best of
 * three).  With each class's cells fixed at 8 of its first radius
 * (no rebuilds), 36 and 33: the early classes' cells grew far wider
 * than their looks.
 */
#include <math.h>
#include <string.h>

#include "base/mem.h"
#include "models/collision_impl.h"

/* Put primordium i in its cell's list; 1 if that took a new slot. */
static int
slot_put(struct coll *C, int32_t i)
{
	const struct prim *p = &C->pr[i];
	struct slot *s;
	int32_t k[3];
	int fresh;

	cell_of(C, p->x, p->y, p->z, k);
	s = slot_find(C, k);
	if ((fresh = s->head < 0))
		memcpy(s->key, k, sizeof(s->key));
	C->next[i] = s->head;
	s->head = i;
	return fresh;
}

/*
 * A table of at least nslots, kept at most half full, with every
 * primordium in it.  Cells hold many primordia each, so the table is
 * sized for the cells in use, not for the primordia.
 */
static void
grid_build(struct coll *C, size_t nslots)
{
	size_t n = 1024;

	while (n < nslots)
		n *= 2;
	for (;;) {
		C->slot = xreallocarray(C->slot, n, sizeof(*C->slot));
		for (size_t i = 0; i < n; i++)
			C->slot[i].head = -1;
		C->mask = (uint32_t)(n - 1);
		C->used = 0;
		for (size_t i = 0; i < C->n && 2 * C->used <= n; i++)
			C->used += (size_t)slot_put(C, (int32_t)i);
		if (2 * C->used <= n)
			return;
		n *= 2;		/* the cells outgrew it: again, larger */
	}
}

void
coll_grid_insert(struct coll *C, int32_t i)
{
	C->used += (size_t)slot_put(C, i);
	if (2 * C->used > (size_t)C->mask + 1)
		grid_build(C, 2 * ((size_t)C->mask + 1));
}

/*
 * The neighbour grid's cells: 8 radii of the primordium being placed,
 * and at least twice the reach of the largest placed, so that a look's
 * box (r + rmax either side) meets at most two cells along each axis
 * as built, three before radii have moved far enough for a rebuild:
 * with cells of one reach, when radii had fallen, the box met two to
 * three, some twenty cells a look, and finding them took more time
 * than the primordia in them (the falling hemisphere: 5% more).
 * Rebuilt when the size wanted has halved or doubled: a grid sized for
 * other radii makes each look at many more cells, or many more
 * primordia, than needed.
 */
void
coll_grid_fit(struct coll *C, double r)
{
	double g = fmax(8 * r, 2 * (r + C->rmax)), cells;

	if (C->slot != NULL && g <= 2 * C->g && g >= C->g / 2)
		return;
	C->g = g;
	C->inv_g = 1 / g;
	/*
	 * The first table has room for the cells that the area the
	 * primordia can cover will fill (a surface crosses about 1.5 cubes
	 * of side g per g^2), at most one a primordium: on the dome it
	 * otherwise doubled eight times, rehashing all it held each time.
	 * A table rebuilt for new radii starts from the cells in use, and
	 * grows as it must: sized for all the area at the new g, it held
	 * the falling laws' peak 10% higher.
	 */
	cells = C->slot == NULL ? fmin(1.5 * C->reach / (g * g),
	    (double)C->cap) : (double)C->used;
	grid_build(C, (size_t)(2 * cells));
}
