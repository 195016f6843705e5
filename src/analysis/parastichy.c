/*
 * parastichy.c - the contact parastichies measured on the organs as
 * placed, for every model: no formula of the model is used, so they hold
 * for the collision, area and inhibition models alike.
 *
 * At each organ the two nearest earlier neighbours turning either way
 * about the axis are its contacts; the index differences to them are the pair of
 * opposed parastichies through it (Vogel's 13 and 21, van Iterson's m
 * and n).  Along the structure the organs are taken in runs, each run's
 * most common pair is its pair, and runs with the same pair join into
 * zones: 34/55, then 21/34, then 13/21 up a coneflower.
 *
 * Neighbours come from a k-d tree (kdtree.c), because organ sizes may
 * differ by orders of magnitude (the inhibition model's grown radii)
 * where a grid of one cell size would not do.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "analysis/kdtree.h"
#include "analysis/parastichy.h"

#define RUNS	48	/* runs the structure is cut into for the zones */
#define SAMPLE	2048	/* organs measured in a run at most */

/* The nearest earlier neighbour of i in nb on each side, or -1. */
static void
sides(const struct result *r, size_t i, const struct kd_near *nb,
    long long side[2])
{
	const double *p = r->organs[i].pos;
	double ro = hypot(p[0], p[1]);

	/* Only the earlier ones count, the first either way. */
	for (int k = 0; k < nb->n && (side[0] < 0 || side[1] < 0); k++) {
		const double *q = r->organs[nb->j[k]].pos;
		double rq;

		if (nb->j[k] >= i)
			continue;
		rq = hypot(q[0], q[1]);
		/* Of unit vectors: radii may span e^700 (grown radii). */
		double turn = (p[0] / ro) * (q[1] / rq) - (p[1] / ro) *
		    (q[0] / rq);
		int s = turn > 0;

		/*
		 * On the same line through the axis (alternate leaves, a
		 * rank of a whorl) a neighbour turns neither way: rounding
		 * must not make it a parastichy.
		 */
		if (!(fabs(turn) > 1e-9))
			continue;
		if (side[s] < 0)
			side[s] = (long long)nb->j[k];
	}
}

/* Organ i's pair, from the tree. */
static void
pair_at(const struct kd *T, const struct result *r, size_t i, int pair[2])
{
	const struct organ *o = &r->organs[i];
	struct kd_near nb;
	long long side[2] = { -1, -1 };

	pair[0] = pair[1] = 0;
	/* On the axis no organ turns either way. */
	if (hypot(o->pos[0], o->pos[1]) < 1e-9 * (o->radius + 1e-300))
		return;
	kd_nearest(T, o->pos, i, 0, &nb);
	/*
	 * Earlier neighbours only: a parastichy through i has a neighbour
	 * on either side of it, i - m one way and i + m the other, so only
	 * the earlier ones tell the two families apart.  The side is the
	 * sign of the turn from i to the neighbour about the axis.
	 */
	sides(r, i, &nb, side);
	if (side[0] < 0 || side[1] < 0) {
		/*
		 * Where the radii grow fast (the inhibition model's grown
		 * radii) every later organ may be nearer than any earlier
		 * one: then the earlier ones alone, a slower search.
		 */
		kd_nearest(T, o->pos, i, 1, &nb);
		sides(r, i, &nb, side);
	}
	if (side[0] < 0 || side[1] < 0)
		return;
	for (int s = 0; s < 2; s++)
		pair[s] = (int)((long long)i - side[s]);
	if (pair[0] > pair[1]) {
		int t = pair[0];

		pair[0] = pair[1];
		pair[1] = t;
	}
}


int
para_gcd(int a, int b)
{
	while (b != 0) {
		int t = a % b;

		a = b;
		b = t;
	}
	return a;
}

void
para_nearest(const struct result *r, double *d)
{
	struct kd T;

	kd_init(&T, r);
	for (size_t t = 0; t < r->count; t++) {
		size_t i = T.pt[t].i;
		struct kd_near nb;

		kd_nearest(&T, T.pt[t].p, i, 0, &nb);
		/* In the search's units: scaled back, exactly. */
		d[i] = nb.n > 0 ? sqrt(nb.d2[0]) / nb.inv : HUGE_VAL;
	}
	kd_free(&T);
}

void
para_pairs(const struct result *r, int (*pair)[2])
{
	struct kd T;

	kd_init(&T, r);
	/* In tree order: neighbours in space are then neighbours in memory. */
	for (size_t t = 0; t < r->count; t++)
		pair_at(&T, r, T.pt[t].i, pair[T.pt[t].i]);
	kd_free(&T);
}

struct tally {
	int	 m, n;
	size_t	 first;		/* where it stood in the sample */
};

static int
tally_cmp(const void *a, const void *b)
{
	const struct tally *x = a, *y = b;

	if (x->m != y->m)
		return x->m < y->m ? -1 : 1;
	if (x->n != y->n)
		return x->n < y->n ? -1 : 1;
	return x->first < y->first ? -1 : x->first > y->first;
}

/*
 * The most common pair among the n of pair, or 0 0; of equally common
 * ones the one met first; how many organs hold it.  Sorted, so a sample
 * of thousands is cheap.
 */
static size_t
modal(const int (*pair)[2], size_t n, int out[2])
{
	struct tally *t = xcalloc(n ? n : 1, sizeof(*t));
	size_t nt = 0, best = 0, bestfirst = 0;

	out[0] = out[1] = 0;
	for (size_t i = 0; i < n; i++)
		if (pair[i][0] != 0)
			t[nt++] = (struct tally){ pair[i][0], pair[i][1], i };
	qsort(t, nt, sizeof(*t), tally_cmp);
	for (size_t i = 0, j; i < nt; i = j) {
		for (j = i; j < nt && t[j].m == t[i].m && t[j].n == t[i].n; j++)
			;
		/* t[i] is the group's first in the sample. */
		if (j - i > best || (j - i == best && t[i].first < bestfirst)) {
			best = j - i;
			bestfirst = t[i].first;
			out[0] = t[i].m;
			out[1] = t[i].n;
		}
	}
	free(t);
	return best;
}

/* Organ k's angle about the axis, in turns. */
static double
turns(const struct result *r, long long k)
{
	return atan2(r->organs[k].pos[1], r->organs[k].pos[0]) / (2 * M_PI);
}

/*
 * Whether m and n, the contacts of organ i, span the lattice the organs
 * make in index and turn, as the two families of a spiral do: going
 * back m organs winds p whole turns and n organs q turns, with m q - n p
 * = +-1.  Coprime m and n are not enough: 13 and 55 at the golden angle
 * wind 5 and 21 turns, 13 x 21 - 55 x 5 = -2, and are two halves of
 * different patterns, where the lattice's own pair is 21/34.  The turns
 * are the steps from organ to organ, each the shorter way round, summed.
 */
static int
spans(const struct result *r, long long i, int m, int n)
{
	double w = 0, wm = 0, prev;
	long long p, q;

	if (i < n)
		return 0;
	prev = turns(r, i - n);
	for (long long k = i - n + 1; k <= i; k++) {
		double t = turns(r, k);

		w += remainder(t - prev, 1.0);
		prev = t;
		if (k == i - m)
			wm = w;
	}
	/* Back from i: m organs wound w - wm turns, n organs w. */
	p = llround(w - wm);
	q = llround(w);
	return llabs((long long)m * q - (long long)n * p) == 1;
}

/*
 * A run shows one family pair when its most common pair is held by at
 * least half its organs and spans the lattice at an organ holding it:
 * two families of one spiral, which also share no factor, so 34/68 is
 * two pairs' contacts mixed (a transition), never a pattern of its own.
 */
static int
family_pair(const struct result *r, long long at, const int m[2],
    size_t held, size_t n)
{
	return m[0] > 0 && 2 * held >= n && para_gcd(m[0], m[1]) == 1 &&
	    spans(r, at, m[0], m[1]);
}

/* The larger number a zone names: its pair's, or a transition's largest. */
static int
zone_n(const struct para_zone *z)
{
	int n = z->n;

	for (int k = 0; k < z->nseen; k++)
		if (z->seen[k][1] > n)
			n = z->seen[k][1];
	return n;
}

int
para_seen_text(const struct para_zone *z, char *buf, size_t size)
{
	int len = snprintf(buf, size, "transition");

	for (int k = 0; k < z->nseen && len >= 0 && (size_t)len < size; k++)
		len += snprintf(buf + len, size - (size_t)len, " %d/%d",
		    z->seen[k][0], z->seen[k][1]);
	return len;
}

size_t
para_zones(const struct result *r, const int (*pair)[2], struct para_zone *z,
    size_t zmax)
{
	size_t N = r->count, runs = N < RUNS * 8 ? (N + 7) / 8 : RUNS, nz = 0;
	struct kd T = { 0 };
	int (*s)[2] = xcalloc(SAMPLE, sizeof(*s));

	if (pair == NULL)
		kd_init(&T, r);
	for (size_t k = 0; k < runs && N > 0; k++) {
		size_t from = N * k / runs, to = N * (k + 1) / runs;
		size_t step = to - from > SAMPLE ? (to - from) / SAMPLE : 1, n = 0;
		int m[2], fam;
		size_t held, at;

		/* The modal pair of an even sample of a long run is its own. */
		for (size_t i = from; i < to && n < SAMPLE; i += step, n++)
			if (pair != NULL)
				memcpy(s[n], pair[i], sizeof(s[0]));
			else
				pair_at(&T, r, i, s[n]);
		held = modal((const int (*)[2])s, n, m);
		if (m[0] == 0)
			continue;
		/* The last organ holding it: the most earlier ones to wind. */
		at = n - 1;
		while (s[at][0] != m[0] || s[at][1] != m[1])
			at--;
		fam = family_pair(r, (long long)(from + at * step), m, held, n);
		/*
		 * A run that holds a zone's pair less than half the time
		 * at its ends (the few organs at a pole or the first ones)
		 * belongs to it when that pair is still its most common.
		 */
		if (nz > 0 && z[nz - 1].m == 0 && z[nz - 1].nseen == 1 &&
		    fam && z[nz - 1].seen[0][0] == m[0] &&
		    z[nz - 1].seen[0][1] == m[1]) {
			z[nz - 1].m = m[0];
			z[nz - 1].n = m[1];
			z[nz - 1].nseen = 0;
			continue;
		}
		if (!fam && nz > 0 && z[nz - 1].m == m[0] && z[nz - 1].n ==
		    m[1])
			continue;
		if (nz > 0 && (fam ? z[nz - 1].m == m[0] && z[nz - 1].n ==
		    m[1] : z[nz - 1].m == 0)) {
			/* A transition goes on: note a pair it had not shown. */
			struct para_zone *t = &z[nz - 1];
			int k = 0;

			while (!fam && k < t->nseen && (t->seen[k][0] != m[0] ||
			    t->seen[k][1] != m[1]))
				k++;
			if (!fam && k == t->nseen && k < PARA_SEEN) {
				t->seen[k][0] = m[0];
				t->seen[k][1] = m[1];
				t->nseen++;
			}
			continue;
		}
		if (nz == zmax)
			break;
		z[nz] = (struct para_zone){ .from = (long long)from,
		    .m = fam ? m[0] : 0, .n = fam ? m[1] : 0,
		    .seen = { { m[0], m[1] } }, .nseen = fam ? 0 : 1,
		    .rho = hypot(r->organs[from].pos[0], r->organs[from].pos[1]),
		    .z = r->organs[from].pos[2] };
		nz++;
	}
	/*
	 * The first organs have too few earlier ones to show their true
	 * contacts: a zone that ends before about 1.5 n of the next zone's
	 * pair is their artefact, not a pattern.
	 */
	while (nz > 1 && (double)z[1].from <= 1.5 * zone_n(&z[1])) {
		memmove(z, z + 1, (nz - 1) * sizeof(*z));
		nz--;
	}
	free(s);
	if (pair == NULL)
		kd_free(&T);
	return nz;
}
