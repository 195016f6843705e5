/*
 * kdtree.c - the nearest organs to a point, from a k-d tree over the
 * organs' positions: the neighbours the parastichy analysis measures
 * contacts by (parastichy.c), the inhibition model's spacing, and
 * the neighbours of measured points (unordered.c).
 *
 * A tree, because organ sizes may differ by orders of magnitude (the
 * inhibition model's grown radii) where a grid of one cell size would
 * not do.  Written here: Debian has no small C library for it, and it
 * is a few hundred lines.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "analysis/kdtree.h"

/*
 * The organs' positions are copied into one array, so that a search
 * reads them in order and not through 120-byte organs, and the tree
 * is built over it: a node splits its range [lo, hi) at m on one axis,
 * every point before m at or below its split value and every point
 * from m on at or above; a range of LEAF points or fewer is a leaf,
 * read through.
 */
struct kd_node {
	double		 split;
	size_t		 m;	/* 0: a leaf */
	size_t		 right;	/* the node of [m, hi); [lo, m)'s is next */
	int		 axis;
};

#define LEAF	16

static void
pt_swap(struct kd_pt *a, struct kd_pt *b)
{
	struct kd_pt t = *a;

	*a = *b;
	*b = t;
}

/*
 * Split pt[lo..hi) on axis about the median of nine points spread over
 * it, in one pass (Hoare's: points equal to it go to either side, so
 * a range of equal values still halves); where the halves start.  A
 * sample's median, not the exact one: a quickselect's passes made the
 * build cost more than all the searches, and a split a little off the
 * middle costs a search a little depth.
 */
static size_t
split(struct kd_pt *pt, size_t lo, size_t hi, int axis, double *value)
{
	double s[9], v;
	size_t i = lo, j = hi - 1;

	/* Sorted as they are read in: nine, not worth qsort()'s calls. */
	for (int k = 0; k < 9; k++) {
		double x = pt[lo + (hi - lo - 1) * (size_t)k / 8].p[axis];
		int at = k;

		for (; at > 0 && s[at - 1] > x; at--)
			s[at] = s[at - 1];
		s[at] = x;
	}
	v = *value = s[4];
	for (;;) {
		while (pt[i].p[axis] < v)
			i++;
		while (pt[j].p[axis] > v)
			j--;
		if (i >= j)
			break;
		pt_swap(&pt[i], &pt[j]);
		i++;
		j--;
	}
	/* pt[lo..i) <= v <= pt[j + 1..hi), and j < i. */
	return j + 1;
}

/*
 * Build over pt[lo..hi), inside the box bmin..bmax: split on the box's
 * widest axis (a flat head has no spread in z: splitting there would
 * make every search look on both sides).  The halves' boxes are this
 * one cut at the split, not measured again.
 */
static void
build(struct kd *T, size_t lo, size_t hi, const double bmin[3],
    const double bmax[3])
{
	size_t at = T->nnode++, m = 0;
	double cut[3], v = 0;
	int axis = 0;

	if (T->nnode > T->cap) {
		T->cap = 2 * T->cap + 64;
		T->node = xreallocarray(T->node, T->cap, sizeof(*T->node));
	}
	for (int a = 1; a < 3; a++)
		if (bmax[a] - bmin[a] > bmax[axis] - bmin[axis])
			axis = a;
	if (hi - lo > LEAF) {
		m = split(T->pt, lo, hi, axis, &v);
		/*
		 * Both halves hold points: the scan from lo stops at or
		 * before the last of the nine (which is at hi - 1), and m
		 * = hi would need v at hi - 1 alone, the most of five of
		 * the nine.  Were it not so, a leaf, not a loop.
		 */
		if (m <= lo || m >= hi)
			m = 0;
	}
	T->node[at] = (struct kd_node){ v, m, 0, axis };
	if (m == 0)
		return;
	memcpy(cut, bmax, sizeof(cut));
	cut[axis] = v;
	build(T, lo, m, bmin, cut);
	T->node[at].right = T->nnode;
	memcpy(cut, bmin, sizeof(cut));
	cut[axis] = v;
	build(T, m, hi, cut, bmax);
}

/*
 * Equal distances (a lattice on a cylinder has them) go by index, so
 * the neighbours found do not hang on the order the tree is read in.
 */
static inline int
nearer(double d2, size_t j, double e2, size_t k)
{
	return d2 < e2 || (d2 == e2 && j < k);
}

static void
near_add(struct kd_near *nb, size_t j, double d2)
{
	int k;

	if (nb->n == KD_K) {
		if (!nearer(d2, j, nb->d2[KD_K - 1], nb->j[KD_K - 1]))
			return;
		k = KD_K - 1;
	} else
		k = nb->n++;
	while (k > 0 && nearer(d2, j, nb->d2[k - 1], nb->j[k - 1])) {
		nb->d2[k] = nb->d2[k - 1];
		nb->j[k] = nb->j[k - 1];
		k--;
	}
	nb->d2[k] = d2;
	nb->j[k] = j;
}

/*
 * A search from p: the KD_K nearest but organ self, or of those before
 * self if earlier; distances in units of scale, a power of two near
 * p's size, so that their squares neither overflow nor underflow where
 * the organs span e^700 (the inhibition model's grown radii): unscaled,
 * every square past 1e154 was infinite, every side of every node then
 * as near as the KD_K-th, and the search read the whole tree.
 */
struct look {
	double		 p[3];
	double		 inv;		/* 1 / scale, exact */
	size_t		 self;
	int		 earlier;
};

static void
look_init(struct look *lk, const double p[3], size_t self, int earlier)
{
	double m = fmax(fabs(p[0]), fmax(fabs(p[1]), fabs(p[2])));
	int e = 0;

	if (m > 0 && isfinite(m))
		frexp(m, &e);
	memcpy(lk->p, p, sizeof(lk->p));
	lk->inv = ldexp(1, -e);
	lk->self = self;
	lk->earlier = earlier;
}

/* Point pt's distance to the look's, added to nb if it may be one. */
static inline void
consider(const struct kd_pt *pt, const struct look *lk, struct kd_near *nb)
{
	double dx = (pt->p[0] - lk->p[0]) * lk->inv;
	double dy = (pt->p[1] - lk->p[1]) * lk->inv;
	double dz = (pt->p[2] - lk->p[2]) * lk->inv;
	size_t self = lk->self;
	int earlier = lk->earlier;

	if (earlier ? pt->i < self : pt->i != self)
		near_add(nb, pt->i, dx * dx + dy * dy + dz * dz);
}

/*
 * The look's KD_K nearest in the subtree at node at, over [lo, hi), whose
 * box is rd (squared, in the look's units) from the look's point: off
 * holds, per axis, how far the point lies outside the box (Arya and
 * Mount's incremental distance), so a far side is passed when its box,
 * not only its splitting plane, is farther than the KD_K-th found.
 */
static void
query(const struct kd *T, size_t at, size_t lo, size_t hi,
    const struct look *lk, struct kd_near *nb, double rd, double off[3])
{
	const struct kd_node *nd = &T->node[at];
	double diff, old, far;
	int a;

	if (nd->m == 0) {
		for (size_t k = lo; k < hi; k++)
			consider(&T->pt[k], lk, nb);
		return;
	}
	a = nd->axis;
	diff = (lk->p[a] - nd->split) * lk->inv;
	old = off[a];
	far = rd - old * old + diff * diff;
	if (diff < 0) {
		query(T, at + 1, lo, nd->m, lk, nb, rd, off);
		if (nb->n < KD_K || far <= nb->d2[nb->n - 1]) {
			off[a] = diff;
			query(T, nd->right, nd->m, hi, lk, nb, far, off);
			off[a] = old;
		}
	} else {
		query(T, nd->right, nd->m, hi, lk, nb, rd, off);
		if (nb->n < KD_K || far <= nb->d2[nb->n - 1]) {
			off[a] = diff;
			query(T, at + 1, lo, nd->m, lk, nb, far, off);
			off[a] = old;
		}
	}
}

void
kd_nearest(const struct kd *T, const double p[3], size_t self, int earlier,
    struct kd_near *nb)
{
	struct look lk;

	look_init(&lk, p, self, earlier);
	nb->n = 0;
	nb->inv = lk.inv;
	query(T, 0, 0, T->n, &lk, nb, 0, (double [3]){ 0, 0, 0 });
}

/* The tree over pt[0 .. T->n), filled in. */
static void
kd_build(struct kd *T)
{
	double bmin[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
	double bmax[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };

	for (size_t i = 0; i < T->n; i++)
		for (int a = 0; a < 3; a++) {
			double v = T->pt[i].p[a];

			/* Not fmin(): a call each, 6 M of them for 1 M organs. */
			bmin[a] = v < bmin[a] ? v : bmin[a];
			bmax[a] = v > bmax[a] ? v : bmax[a];
		}
	build(T, 0, T->n, bmin, bmax);
}

void
kd_init(struct kd *T, const struct result *r)
{
	*T = (struct kd){ .n = r->count };
	T->pt = xcalloc(r->count ? r->count : 1, sizeof(*T->pt));
	for (size_t i = 0; i < r->count; i++) {
		memcpy(T->pt[i].p, r->organs[i].pos, sizeof(T->pt[i].p));
		T->pt[i].i = i;
	}
	kd_build(T);
}

void
kd_init_points(struct kd *T, const double (*p)[3], size_t n)
{
	*T = (struct kd){ .n = n };
	T->pt = xcalloc(n ? n : 1, sizeof(*T->pt));
	for (size_t i = 0; i < n; i++) {
		memcpy(T->pt[i].p, p[i], sizeof(T->pt[i].p));
		T->pt[i].i = i;
	}
	kd_build(T);
}

void
kd_free(struct kd *T)
{
	free(T->pt);
	free(T->node);
}
