/*
 * collision.c - the collision-based model of Fowler, Prusinkiewicz and
 * Battjes (1992): primordia of radius r_n on a surface of revolution,
 * primordium n at angle n alpha and at the smallest curve parameter t
 * where it overlaps no earlier one.
 *
 * The walk up the generating curve is exact: starting at the lowest t
 * allowed, it asks the spatial grid which earlier primordia the new
 * one would overlap there, jumps to the furthest point where it leaves
 * them (curve_exit: the exact crossing, never a sample), and asks
 * again, until nothing overlaps or the tip is passed.  Each jump
 * clears at least one primordium, and every point jumped over is
 * covered, so the first free point found is the smallest.
 *
 * What keeps it fast without epsilon is the cover map (collision_cover.c): most
 * of the receptacle below the front is provably covered, and the walk
 * skips it a cell at a time.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/design.h"
#include "diag.h"
#include "geometry/curve.h"
#include "geometry/geometry.h"
#include "geometry/receptacle.h"
#include "mem.h"
#include "models/collision.h"
#include "models/collision_cover.h"
#include "models/model.h"

#define COUNT_DEFAULT	1000000	/* primordia when count is not given */
#define COUNT_MOST	5000000	/* 180 bytes each: under 1 GiB */
#define PROGRESS_EVERY	16384
#define CHECK_EVERY	31	/* cells the tests' check of the map takes */
#define LAW_SAMPLES	4096	/* of the radius law, to size the maps */
#define CELLS_PER_ORGAN	64	/* of the cover map, at most */
#define REFINE_FALL	0.03	/* of r: a proof for r lasts about so far */
#define R_SMALLEST	1e-12	/* of the receptacle's size: below it the
				   walk's steps vanish in double precision */

enum { CO_RECEPTACLE, CO_RADIUS, CO_EPSILON, CO_PARASTICHIES, CO__N };

struct collision {
	struct group_at	 at;
	int		 given[CO__N];
	struct receptacle receptacle;
	struct expr_setting radius;	/* of primordium n */
	struct expr_setting epsilon;	/* how far t may fall back */
	struct int_list	 parastichies;	/* instead of radius: the pair wanted */
};

#define CO(f)	offsetof(struct collision, f)

static const struct row collision_rows[] = {
	[CO_RECEPTACLE] = { .name = "receptacle", .type = T_GROUP,
	  .off = CO(receptacle), .sub = &receptacle_table,
	  .doc = "the surface of revolution the primordia sit on" },
	[CO_RADIUS] = { .name = "radius", .type = T_EXPR, .off = CO(radius),
	  .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .unit = "length",
	  .doc = "radius of primordium n" },
	[CO_EPSILON] = { .name = "epsilon", .type = T_EXPR,
	  .off = CO(epsilon), .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T) |
	  EXPR_VAR(V_R),
	  .unit = "length",
	  .doc = "arc length t may fall back below the last primordium; "
	  "\"r\": its radius" },
	[CO_PARASTICHIES] = { .name = "parastichies", .type = T_INTS,
	  .off = CO(parastichies), .lo = 1, .hi = 1000, .defstr = "none",
	  .doc = "instead of radius: the contact pair [m, n] wanted at the "
	  "base" },
};

static const struct table collision_table = TABLE(collision_rows,
    struct collision);

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
	long long	 refined, refine_misses;
	double		*law;		/* the radius law sampled, or NULL */
	double		*law_min;	/* the least of law[i ..], each i */
	long long	 law_step;	/* every law_step primordia */
	size_t		 nlaw;
};

static inline uint32_t
hash3(const int32_t k[3])
{
	uint32_t h = (uint32_t)k[0] * 0x9E3779B1u ^
	    (uint32_t)k[1] * 0x85EBCA77u ^ (uint32_t)k[2] * 0xC2B2AE3Du;

	return h ^ h >> 15;
}

/* Cell k's slot, or the empty one it would take, from slot i on. */
static struct slot *
slot_from(const struct coll *C, const int32_t k[3], uint32_t i)
{
	for (;; i = (i + 1) & C->mask) {
		struct slot *s = &C->slot[i];

		if (s->head < 0 || (s->key[0] == k[0] && s->key[1] == k[1] &&
		    s->key[2] == k[2]))
			return s;
	}
}

static struct slot *
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

static void
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

static void
grid_insert(struct coll *C, int32_t i)
{
	C->used += (size_t)slot_put(C, i);
	if (2 * C->used > (size_t)C->mask + 1)
		grid_build(C, 2 * ((size_t)C->mask + 1));
}

/*
 * How many grid cells a box of half-size q about (x, y, z) spans, and
 * which: when radii grow far beyond the first one the cells are small
 * beside the box, and a plain pass over every primordium is cheaper
 * than a pass over the cells (and cannot hang).
 */
static double
box_cells(const struct coll *C, double x, double y, double z, double q,
    int32_t lo[3], int32_t hi[3])
{
	cell_of(C, x - q, y - q, z - q, lo);
	cell_of(C, x + q, y + q, z + q, hi);
	return ((double)hi[0] - lo[0] + 1) * ((double)hi[1] - lo[1] + 1) *
	    ((double)hi[2] - lo[2] + 1);
}

/*
 * The earlier primordia that overlap the new one at a walk's stop, in
 * the meridian plane: each a disk of squared radius S2 about q, and
 * how far along the tangent the curve would leave it (not exact: only
 * which exit to work out first).
 */
struct hit {
	double	 q[2], S2, guess;
	int32_t	 m;		/* the primordium */
};

#define HITS	32

/*
 * The furthest exact exit from the disks hits[0..n), none below best.
 * Only one exit needs working out in most stops: once the curve has
 * reached e, a disk it is out of by then was left at or before e (its
 * exit is the first point out), so it cannot raise the furthest.
 * The guess picks the disk to start with; the answer never depends
 * on it.
 */
static double
furthest_exit(const struct coll *C, double t, const double pt[2],
    const double tan[2], struct hit *hits, int n, double best)
{
	double at = -1, p[2], tt = tan[0] * tan[0] + tan[1] * tan[1];
	int first = 0;

	/*
	 * Along the tangent (of any length: only the order counts), the
	 * point leaves disk i at pt + g tan, g the larger root of
	 * |pt + g tan - q|^2 = S2.
	 */
	for (int i = 0; i < (n > 1 ? n : 0); i++) {	/* one: no order */
		struct hit *h = &hits[i];
		double w[2] = { pt[0] - h->q[0], pt[1] - h->q[1] };
		double wt = w[0] * tan[0] + w[1] * tan[1];
		double disc = wt * wt - tt * (w[0] * w[0] + w[1] * w[1] - h->S2);

		h->guess = -wt + sqrt(disc > 0 ? disc : 0);
		if (h->guess > hits[first].guess)
			first = i;
	}
	for (int k = 0; k < n; k++) {
		const struct hit *h = &hits[k == 0 ? first : k == first ? 0 : k];
		double e, pe[2];

		if (best == HUGE_VAL)
			break;	/* past the tip: none goes further */
		if (best > t) {
			if (at != best)
				curve_eval(&C->cv, at = best, p, NULL);
			if ((p[0] - h->q[0]) * (p[0] - h->q[0]) + (p[1] -
			    h->q[1]) * (p[1] - h->q[1]) >= h->S2)
				continue;
		}
		e = curve_exit(&C->cv, t, h->q, h->S2, pe);
		/* e == t: touching, up to rounding. */
		if (e > t && e > best) {
			best = e;
			if (e != HUGE_VAL) {	/* the point there, known */
				at = e;
				p[0] = pe[0];
				p[1] = pe[1];
			}
		}
	}
	return best;
}

/*
 * If primordium m overlaps the new one of radius r at (x, y, z), on
 * the meridian (c, s) at curve parameter t, note the disk it leaves;
 * when the notes are full, raise *best to where the curve leaves it.
 */
static inline void
exit_from(const struct coll *C, int32_t m, double t, const double pt[2],
    const double tan[2], double x, double y, double z, double c, double s,
    double r, struct hit *hits, int *n, double *best)
{
	const struct prim *o = &C->pr[m];
	double dx = x - o->x, dy = y - o->y, dz = z - o->z, R = r + o->r;
	double perp;
	struct hit *h;

	if (dx * dx + dy * dy + dz * dz >= R * R)
		return;
	if (*n == HITS) {
		*best = furthest_exit(C, t, pt, tan, hits, *n, *best);
		*n = 0;
	}
	h = &hits[(*n)++];
	h->m = m;
	/* In the meridian plane: a disk. */
	h->q[0] = o->x * c + o->y * s;
	h->q[1] = o->z;
	perp = o->y * c - o->x * s;
	h->S2 = R * R - perp * perp;
}

/*
 * At curve parameter t on the meridian (c, s) = (cos, sin) of the new
 * primordium of radius r: 1 if nothing overlaps it, else 0 and *to the
 * furthest exit from the primordia that do (HUGE_VAL: past the tip).
 * pd, if not NULL, is the curve's point and dp/dt at t, known already;
 * p is the point, after.  hits[0..*nh) are the overlapping primordia,
 * for refine(): all of them, or of more than HITS the ones after the
 * last full set, which was worked out as it filled.
 */
static int
free_at(const struct coll *C, double t, double c, double s, double r,
    const double *pd, double p[2], double *to, struct hit hits[HITS],
    int *nh)
{
	double d[2], x, y, z, best = -1, cells;
	int32_t lo[3], hi[3];
	int n = 0;

	if (pd != NULL) {
		p[0] = pd[0];
		p[1] = pd[1];
		d[0] = pd[2];
		d[1] = pd[3];
	} else	/* d: the tangent, for the guesses */
		curve_eval(&C->cv, t, p, d);
	x = p[0] * c;
	y = p[0] * s;
	z = p[1];
	if ((cells = box_cells(C, x, y, z, r + C->rmax, lo, hi)) >
	    (double)C->n) {
		for (size_t m = 0; m < C->n; m++)
			exit_from(C, (int32_t)m, t, p, d, x, y, z, c, s, r, hits,
			    &n, &best);
	} else {
		/*
		 * The cells' slots first, each one's line asked for ahead:
		 * the table is megabytes, and a box's cells' slots lie far
		 * apart in it.  The grid's cells are at least half the box
		 * (grid_fit()), so it meets 27 at most; were it more, the
		 * slots are found as before.
		 */
		uint32_t at[27];
		int ahead = cells <= 27, nc = 0;

		for (int32_t i = lo[0]; ahead && i <= hi[0]; i++)
			for (int32_t j = lo[1]; j <= hi[1]; j++)
				for (int32_t k = lo[2]; k <= hi[2]; k++) {
					int32_t key[3] = { i, j, k };

					at[nc] = hash3(key) & C->mask;
					PREFETCH(&C->slot[at[nc++]]);
				}
		nc = 0;
		for (int32_t i = lo[0]; i <= hi[0]; i++)
			for (int32_t j = lo[1]; j <= hi[1]; j++)
				for (int32_t k = lo[2]; k <= hi[2]; k++) {
					int32_t key[3] = { i, j, k }, m;

					m = (ahead ? slot_from(C, key, at[nc++]) :
					    slot_find(C, key))->head;
					for (; m >= 0; m = C->next[m])
						exit_from(C, m, t, p, d, x, y, z, c,
						    s, r, hits, &n, &best);
				}
	}
	*nh = n;
	if ((best = furthest_exit(C, t, p, d, hits, n, best)) < 0)
		return 1;
	*to = best;
	return 0;
}

/* Is primordium o's surface within U of p? */
static int
surface_within(const struct prim *o, const double p[3], double U)
{
	double dx = p[0] - o->x, dy = p[1] - o->y, dz = p[2] - o->z;

	return sqrt(dx * dx + dy * dy + dz * dz) - o->r <= U * (1 + 1e-12) +
	    1e-15;
}

static int	near_point(void *, const double p[3], double U);

/*
 * For the tests: at 9 x 9 points over cell (k, j), its edges and
 * corners too, does a primordium come within U, the bound refine()
 * proved?  Returns the points where none does.
 */
static long long
refine_check(struct coll *C, int32_t k, int32_t j, double U)
{
	const struct cover *cv = &C->cover;
	double phi0, dphi = cover_angles(cv, k, j, &phi0);
	double t0 = cv->t_row[k], t1 = fmin(cv->t_row[k + 1], C->cv.tmax);
	long long misses = 0;

	for (int a = 0; a <= 8; a++) {
		double q[2];

		curve_eval(&C->cv, t0 + (t1 - t0) * a / 8, q, NULL);
		for (int b = 0; b <= 8; b++) {
			double phi = phi0 + dphi * b / 8;
			double p[3] = { q[0] * cos(phi), q[0] * sin(phi), q[1] };

			misses += !near_point(C, p, U);
		}
	}
	return misses;
}

/*
 * Try to prove cell (k, j) covered after all: a cell the walk found
 * blocked along its meridian but that cover_add's one bound per cell
 * left open.  The same bound on 4 x 4 sub-cells, from the primordia
 * over the cell, is four times tighter.
 *
 * Those primordia are the look's hits[0..nh): the ones over the point
 * where the walk found the cell blocked, which the walk has just left
 * by their furthest exit, past the row.  A bound from some of the
 * primordia near a point is still a bound (the least over all of them
 * can only be lower), so a proof from these holds; gathering every
 * primordium near the cell instead, a second search of the grid, cost
 * the dome 9% of its instructions and proved 2% more cells, with not
 * one look fewer (measured).
 */
static int
refine(struct coll *C, int32_t k, int32_t j, double r,
    const struct hit *hits, int nh)
{
	const struct cover *cv = &C->cover;
	double mid[2], cs[COVER_SUB][2], worst = 0;
	double mx, my, mz = cv->z_c[k];
	struct near {
		double	 x, y, z, r, d2;
	} near[HITS];
	int nn = 0;

	cover_dirs(cv, k, j, mid, cs);
	mx = cv->rho_c[k] * mid[0];
	my = cv->rho_c[k] * mid[1];
	for (int h = 0; h < nh; h++) {
		const struct prim *o = &C->pr[hits[h].m];
		double dx = mx - o->x, dy = my - o->y, dz = mz - o->z;
		double d2 = dx * dx + dy * dy + dz * dz;
		double qo = cv->d[k] + r + o->r;
		int i = nn;

		/*
		 * Farther than this, it leaves every point of the cell
		 * clear by r or more: it could only be the least where the
		 * cell fails.
		 */
		if (d2 >= qo * qo)
			continue;
		/* Nearest first: they settle most points. */
		for (; i > 0 && near[i - 1].d2 > d2; i--)
			near[i] = near[i - 1];
		near[i] = (struct near){ o->x, o->y, o->z, o->r, d2 };
		nn++;
	}
	/*
	 * Sub-rows from the top: the walk found the cell blocked from
	 * below, so what is open in it is mostly towards the front, and
	 * a proof that fails (half of them) fails there first.
	 */
	for (int sa = COVER_SUB - 1; sa >= 0; sa--) {
		const double *p = cv->sub[k * COVER_SUB + sa];

		for (int sb = 0; sb < COVER_SUB; sb++) {
			double x = p[0] * cs[sb][0], y = p[0] * cs[sb][1];
			double best = HUGE_VAL;

			for (int i = 0; i < nn; i++) {
				double dx = x - near[i].x, dy = y - near[i].y,
				    dz = p[1] - near[i].z;
				double d2 = dx * dx + dy * dy + dz * dz;
				double lim = worst + near[i].r - p[2], f;

				/* This point cannot raise the worst: next. */
				if (lim > 0 && d2 <= lim * lim) {
					best = -HUGE_VAL;
					break;
				}
				/* Not fmin() and fmax(): calls, here. */
				f = sqrt(d2) - near[i].r;
				best = f < best ? f : best;
			}
			worst = best + p[2] > worst ? best + p[2] : worst;
			if (worst >= r)
				return 0;
		}
	}
	if (C->check) {
		C->refined++;
		C->refine_misses += refine_check(C, k, j, worst);
	}
	cover_lower(&C->cover, k, j, worst);
	return 1;
}

/*
 * For cover_check: does some primordium come within U of p, its
 * surface that is (and a hair more, for rounding)?
 */
static int
near_point(void *ctx, const double p[3], double U)
{
	const struct coll *C = ctx;
	double q = U + C->rmax;
	int32_t lo[3], hi[3];

	if (box_cells(C, p[0], p[1], p[2], q, lo, hi) > (double)C->n) {
		for (size_t m = 0; m < C->n; m++)
			if (surface_within(&C->pr[m], p, U))
				return 1;
		return 0;
	}
	for (int32_t i = lo[0]; i <= hi[0]; i++)
		for (int32_t j = lo[1]; j <= hi[1]; j++)
			for (int32_t k = lo[2]; k <= hi[2]; k++) {
				int32_t key[3] = { i, j, k };

				for (int32_t m = slot_find(C, key)->head; m >= 0;
				    m = C->next[m])
					if (surface_within(&C->pr[m], p, U))
						return 1;
			}
	return 0;
}

/*
 * Is proving a cell covered worth it?  refine() proves it for radii
 * down to a bound a little under r.  If the law falls further than
 * that, by REFINE_FALL, before the walks come round to the cell again
 * (period primordia on), no walk uses the proof: on the falling
 * hemisphere refine() cost more than it saved, and still does from the
 * look's hits alone (2% more instructions; the disk 1%).
 */
static int
refine_pays(const struct coll *C, long long n, long long period, double r)
{
	size_t i;

	if (C->law == NULL)
		return 1;
	i = (size_t)((n + period) / C->law_step);
	return C->law[i < C->nlaw ? i : C->nlaw - 1] >= (1 - REFINE_FALL) * r;
}

/*
 * With one radius for all, a look at t in row k below column j's head
 * (an exception's: the rest of the prefix is covered) found the
 * meridian blocked up to to.  The new t, and two things that keep
 * later walks from looking there again:
 *
 * The exception is proved again, from this look's primordia: each walk
 * comes by on a meridian of its own, so over other primordia than the
 * one that made the exception, and a proof for the one radius holds
 * for good (prefix_next() drops the cell once its bound covers it).
 *
 * And if to lies past the head's row, the walk goes on from the head's
 * start instead: it lies between t and to, all of it inside the disk
 * that to is the first exit of (furthest_exit()), so nothing free is
 * passed, but the head gets its look, and cover_passed() or refine()
 * moves it on.  From to, the walk would go on above the head, which
 * only a look at the head moves.
 *
 * Without either, on the hemisphere with r = 0.00053 and count 4M (a
 * map of 2^26 cells, 0.73 r a side, where 2M get 0.6 r, so fewer cells
 * covered by their bounds alone): 0.1 to 0.4 walks a primordium jumped
 * past their head, the heads fell behind the front (400 rows by 4M),
 * and every walk looked at the open cells between, 2.5 looks a
 * primordium at 250k, 20 from 2.75M on, each a cache miss among old
 * primordia.  With the second only, the exceptions that hits-only
 * proofs left open piled up to 1.5 looks a primordium, and all of them
 * sampled were covered (1,470 of 1,470, 9 x 9 points each).  With
 * both: 2.0 to 2.3 throughout.
 */
static double
below_head(struct coll *C, int32_t k, int32_t j, double r, double t,
    double to, const struct hit *hits, int nh)
{
	const struct cover *cv = &C->cover;
	int32_t h = cv->head[j];

	(void)refine(C, k, j, r, hits, nh);
	if (h < cv->rows && to >= cv->t_row[h + 1] && to <= C->cv.tmax &&
	    cv->t_row[h] > t)
		return cv->t_row[h];
	return to;
}

/*
 * The smallest free t >= t0 on meridian (c, s), exactly; HUGE_VAL: none.
 * *row is t's row of the cover map, if the walk found it, else -1, and
 * p the curve's point at t.
 */
static double
place_exact(struct coll *C, long long n, double t0, double phi, double c,
    double s, double r, int32_t *row, double p[2])
{
	int32_t j = C->nocover ? 0 : cover_col(&C->cover, phi), k = -1;
	double t = t0, to;
	struct hit hits[HITS];

	while (t <= C->cv.tmax) {
		const double *pd = NULL;
		int nh;

		/* One call leaves t where the walk must look. */
		if (!C->nocover && cover_skip(&C->cover, &t, j, r, &k) &&
		    !(t <= C->cv.tmax))
			break;
		/* Moved to a row's start: the curve there is known. */
		if (k >= 0 && t == C->cover.t_row[k])
			pd = C->cover.start[k];
		if (free_at(C, t, c, s, r, pd, p, &to, hits, &nh)) {
			*row = k;	/* cover_skip() has just found it */
			return t;
		}
		/* Blocked across a cell that holds up the column's prefix. */
		if (!C->nocover && k == C->cover.head[j] &&
		    to >= C->cover.t_row[k + 1]) {
			if (!refine_pays(C, n, C->cover.cols >> C->cover.bz[k >>
			    3], r) || !refine(C, k, j, r, hits, nh))
				cover_passed(&C->cover, j, k);
		} else if (!C->nocover && C->rconst > 0 && k >= 0 &&
		    k < C->cover.head[j])
			to = below_head(C, k, j, r, t, to, hits, nh);
		t = to;		/* k, the row before, is where its row is sought from */
	}
	return HUGE_VAL;
}

/*
 * Does any earlier primordium overlap the point at t on meridian
 * (c, s)?  All of them are tried, the last one found first: along a
 * scan one primordium covers many samples in a row.
 */
static int
blocked_any(const struct coll *C, double t, double c, double s, double r,
    size_t *last)
{
	double p[2], x, y, z;

	curve_eval(&C->cv, t, p, NULL);
	x = p[0] * c;
	y = p[0] * s;
	z = p[1];
	for (size_t k = 0; k <= C->n; k++) {
		size_t i = k == 0 ? *last : k - 1;
		const struct prim *o = &C->pr[i];
		double dx = x - o->x, dy = y - o->y, dz = z - o->z,
		    R = r + o->r;

		if (i >= C->n)
			continue;
		if (dx * dx + dy * dy + dz * dz < R * R) {
			*last = i;
			return 1;
		}
	}
	return 0;
}

/*
 * The reference for the tests and the benchmark: every earlier
 * primordium at samples r / BRUTE_DIV apart along the curve, then
 * bisection between the last covered and the first free sample.  A gap
 * narrower than the spacing is missed: that is the point of having
 * the exact walk.
 */
#define BRUTE_DIV	1024

static double
place_brute(const struct coll *C, double t0, double c, double s, double r)
{
	double h = r / BRUTE_DIV / C->cv.speed, lo = t0;
	size_t last = 0;

	if (!blocked_any(C, t0, c, s, r, &last))
		return t0;
	for (double k = 1;; k++) {
		double t = fmin(t0 + k * h, C->cv.tmax);

		if (!blocked_any(C, t, c, s, r, &last)) {
			for (int i = 0; i < 200; i++) {
				double mid = lo + (t - lo) / 2;

				if (mid <= lo || mid >= t)
					break;
				if (blocked_any(C, mid, c, s, r, &last))
					lo = mid;
				else
					t = mid;
			}
			return t;
		}
		if (t >= C->cv.tmax)
			return HUGE_VAL;
		lo = t;
	}
}

/* Primordium n's radius and the fall-back limit; errors name n. */
static int
radius_at(const struct coll *C, struct expr_env *env, long long n,
    long long N, double *r, double *eps)
{
	const struct model_ctx *ctx = C->ctx;
	const struct collision *P = C->p;

	expr_env_organ(env, n, N);
	if (C->rconst > 0)
		*r = C->rconst;
	else if (model_eval(ctx, &P->radius, "collision.radius", "primordium",
	    env, r) != 0)
		return -1;
	if (!(*r > 0)) {
		diag(ST_SCENE, ctx->file, P->radius.line, 0,
		    "collision.radius is %.9g at primordium %lld; it must be "
		    "positive", *r, n);
		return -1;
	}
	*eps = -1;
	if (P->epsilon.e == NULL)
		return 0;
	env->var[V_R] = *r;
	if (model_eval(ctx, &P->epsilon, "collision.epsilon",
	    "primordium", env, eps) != 0)
		return -1;
	if (*eps < 0) {
		diag(ST_SCENE, ctx->file, P->epsilon.line, 0,
		    "collision.epsilon is %.9g at primordium %lld; it must be "
		    "at least 0", *eps, n);
		return -1;
	}
	return 0;
}

/*
 * Primordium n at t, row (-1: not known) of the cover map, angle phi;
 * at is the curve's point at t, if the walk has it (else NULL).
 */
static void
coll_add(struct coll *C, double t, int32_t row, double phi, double c,
    double s, double r, const double *at)
{
	double p[2];
	struct prim *o;

	if (C->n == C->cap) {
		C->cap = C->cap ? 2 * C->cap : 4096;
		C->pr = xreallocarray(C->pr, C->cap, sizeof(*C->pr));
		C->next = xreallocarray(C->next, C->cap, sizeof(*C->next));
	}
	if (at != NULL) {
		p[0] = at[0];
		p[1] = at[1];
	} else
		curve_eval(&C->cv, t, p, NULL);
	o = &C->pr[C->n];
	o->x = p[0] * c;
	o->y = p[0] * s;
	o->z = p[1];
	o->r = r;
	o->t = t;
	if (r > C->rmax)
		C->rmax = r;
	C->n++;
	grid_insert(C, (int32_t)(C->n - 1));
	if (!C->nocover)
		cover_add(&C->cover, t, row, phi, o->x, o->y, o->z, r);
}

/* The organs: frames on the receptacle, the tangent away from the tip. */
static void
fill_result(const struct coll *C, double alpha, struct result *res)
{
	double tiny = 1e-12 * (C->cv.length + 1);	/* a speed of 0 */

	result_init(res, C->n);
	res->divergence = alpha;
	res->svg = PROJ_TOP;
	for (size_t i = 0; i < C->n; i++) {
		const struct prim *o = &C->pr[i];
		struct organ *g = &res->organs[i];
		double p[2], d[2], rho, phi;

		curve_eval(&C->cv, o->t, p, d);
		if (d[0] * d[0] + d[1] * d[1] < tiny * tiny) {
			/* A cusp: the chord across it gives the direction. */
			double a[2], b[2], e = 1e-6 * C->cv.tmax;

			curve_eval(&C->cv, fmax(o->t - e, 0), a, NULL);
			curve_eval(&C->cv, fmin(o->t + e, C->cv.tmax), b, NULL);
			d[0] = b[0] - a[0];
			d[1] = b[1] - a[1];
		}
		rho = hypot(o->x, o->y);
		phi = angle_mod360((double)i, alpha);
		/* The angle is in the position already, but for on the axis. */
		if (rho > 0)
			frame_revolution_cs(g, phi, o->x / rho, o->y / rho, p[0],
			    p[1], -d[0], -d[1]);
		else
			frame_revolution(g, phi, p[0], p[1], -d[0], -d[1]);
		/* Exactly the position placed, not a second evaluation. */
		g->pos[0] = o->x;
		g->pos[1] = o->y;
		g->pos[2] = o->z;
		g->radius = o->r;
		g->scale = o->r;
	}
}

/*
 * What the maps need before placement starts: the smallest radius the
 * law gives up to the bound N, and the area N primordia can cover
 * (2 sqrt 3 r^2 each, hexagonally packed).  Sampled; a sample the law
 * cannot give is left out here and reported when placement gets there.
 */
static void
law_extent(struct coll *C, long long N, double r0, double *rmin,
    double *area)
{
	struct expr_env env = { { 0 }, (uint64_t)C->ctx->seed, 0 };
	long long step = N / LAW_SAMPLES + 1, samples = 0;
	double sum = 0, r;

	*rmin = r0;
	if (C->rconst > 0 || expr_is_constant(C->p->radius.e, &r)) {
		*area = 2 * sqrt(3) * r0 * r0 * (double)N;
		return;
	}
	C->law_step = step;
	C->nlaw = (size_t)((N + step - 1) / step);
	C->law = xcalloc(C->nlaw, sizeof(*C->law));
	for (long long n = 0; n < N; n += step) {
		expr_env_organ(&env, n, N);
		/* A radius the law cannot give: no fall to plan for. */
		if (expr_eval(C->p->radius.e, &env, &r) != EXPR_OK ||
		    !(r > 0)) {
			C->law[n / step] = HUGE_VAL;
			continue;
		}
		C->law[n / step] = r;
		*rmin = fmin(*rmin, r);
		sum += r * r;
		samples++;
	}
	*area = samples ? 2 * sqrt(3) * sum / (double)samples * (double)N :
	    HUGE_VAL;
	/*
	 * The least radius from each sample on; a sample the law cannot
	 * give counts as 0, which promises nothing.
	 */
	C->law_min = xcalloc(C->nlaw, sizeof(*C->law_min));
	for (size_t i = C->nlaw; i-- > 0; ) {
		r = C->law[i] == HUGE_VAL ? 0 : C->law[i];
		C->law_min[i] = i + 1 < C->nlaw ? fmin(r, C->law_min[i + 1]) :
		    r;
	}
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
static void
grid_fit(struct coll *C, double r)
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

/* Placement with radius rconst if > 0, at most cap primordia if > 0. */
static int
place(const struct model_ctx *ctx, struct result *res, int how,
    double rconst, long long cap)
{
	int brute = how == PLACE_BRUTE;
	struct expr_env env = { { 0 }, (uint64_t)ctx->seed, 0 };
	const struct collision *P = ctx->params;
	struct coll C = { .ctx = ctx, .p = P, .nocover = how == PLACE_PLAIN ||
	    how == PLACE_BRUTE, .check = how == PLACE_CHECK,
	    .rconst = rconst };
	double alpha = ctx->divergence, r, eps, rmin, band, k;
	double a_next;
	long long N = ctx->count_line ? ctx->count : COUNT_DEFAULT;
	int rc = -1, full = 0;

	if (cap > 0 && cap < N)
		N = cap;

	if (N > COUNT_MOST) {
		model_error(ctx, ctx->count_line, "count %lld is more than "
		    "the collision model places, %d", N, COUNT_MOST);
		return -1;
	}
	if (P->radius.e == NULL && rconst <= 0) {
		model_error(ctx, GIVEN_AT(P, CO_RADIUS), "missing setting "
		    "'collision.radius' (the primordia's radius, or "
		    "collision.parastichies to have it found)");
		return -1;
	}
	if (receptacle_curve(ctx->file, &P->receptacle, &C.cv) != 0)
		return -1;
	if (radius_at(&C, &env, 0, N, &r, &eps) != 0)
		goto out;
	/* A constant radius is that for every primordium: no evaluating. */
	if (C.rconst <= 0 && expr_is_constant(P->radius.e, &k))
		C.rconst = r;
	law_extent(&C, N, r, &rmin, &band);
	if (rmin < R_SMALLEST * fmax(C.cv.length, C.cv.rho_max)) {
		model_error(ctx, GIVEN_AT(P, CO_RADIUS), "collision.radius "
		    "%.9g is too small for this receptacle: below %g of its "
		    "size, %.9g, the placement cannot be resolved", rmin,
		    R_SMALLEST, fmax(C.cv.length, C.cv.rho_max));
		goto out;
	}
	if (!C.nocover) {
		/*
		 * The band N primordia can cover, twice over for loose
		 * packing, and some rows more.
		 */
		double s = C.cv.length;

		if (2 * band < C.cv.area)
			s = curve_s(&C.cv, curve_t_area(&C.cv, 2 * band, NULL,
			    NULL, NULL)) + 16 * r;
		cover_init(&C.cover, &C.cv, rmin, s,
		    (double)N * CELLS_PER_ORGAN);
	}
	/*
	 * Room for as many as circles of radius r would pack hexagonally,
	 * and a little more: growing a million by doubling copies it all.
	 */
	C.cap = (size_t)fmin((double)N, C.cv.area / (2 * sqrt(3) * r * r) *
	    1.1 + 4096);
	C.pr = xcalloc_big(C.cap, sizeof(*C.pr));
	C.next = xcalloc_big(C.cap, sizeof(*C.next));
	C.reach = fmin(band, C.cv.area);
	grid_fit(&C, r);
	coll_add(&C, 0, -1, 0, 1, 0, r, NULL);
	a_next = angle_mod360(1, alpha) * (M_PI / 180);
	for (long long n = 1; n < N; n++) {
		double a = a_next, c = cos(a), s = sin(a), t0 = 0, t, at[2];
		int32_t row = -1;

		if (radius_at(&C, &env, n, N, &r, &eps) != 0)
			goto out;
		if (eps >= 0)
			t0 = curve_t(&C.cv, curve_s(&C.cv, C.pr[n - 1].t) - eps);
		grid_fit(&C, r);
		/* The next walk's first cells on their way in meanwhile. */
		a_next = angle_mod360((double)(n + 1), alpha) * (M_PI / 180);
		if (!C.nocover)
			cover_ahead(&C.cover, a_next);
		t = brute ? place_brute(&C, t0, c, s, r) :
		    place_exact(&C, n, t0, a, c, s, r, &row, at);
		if (t > C.cv.tmax)
			break;
		/*
		 * Bounds under the least radius still to come cover their
		 * cells for good.  With a rising radius that is far above
		 * r_min, the least of all, which the map was made for, and
		 * cover_add() went on lowering bounds that no walk to come
		 * could tell from lower ones.  The least from the sample at
		 * or before the next primordium on, which on a law that
		 * only rises is no more than any radius to come.
		 */
		if (C.law_min != NULL && !C.nocover) {
			size_t i = (size_t)((n + 1) / C.law_step);

			if (i < C.nlaw)
				cover_floor(&C.cover, fmin(r, C.law_min[i]));
		}
		coll_add(&C, t, row, a, c, s, r, brute ? NULL : at);
		if (ctx->progress != NULL && n % PROGRESS_EVERY == 0)
			ctx->progress(n + 1, 0);
	}
	full = (long long)C.n == N;
	if (ctx->progress != NULL)
		ctx->progress((long long)C.n, 1);
	if (full && !ctx->count_line && cap <= 0)
		diag(ST_OK, ctx->file, P->radius.line, 0, "stopped at %d "
		    "primordia, the default bound, with room left on the "
		    "receptacle; set count to place more", COUNT_DEFAULT);
	fill_result(&C, alpha, res);
	result_info(res, "primordia", 1, (double)C.n);
	result_info_labelled(res, "receptacle", "length radius", 2,
	    C.cv.length, C.cv.rho_max);
	if (how == PLACE_CHECK) {
		result_info(res, "refine misses", 2, (double)C.refine_misses,
		    (double)C.refined);
		result_info(res, "cover misses", 1, (double)cover_check(&C.cover,
		    &C.cv, C.rmax, CHECK_EVERY, near_point, &C));
	}
	rc = 0;
out:
	cover_free(&C.cover);
	curve_free(&C.cv);
	free(C.pr);
	free(C.next);
	free(C.law);
	free(C.law_min);
	free(C.slot);
	return rc;
}

const struct receptacle *
collision_receptacle(const struct model_ctx *ctx)
{
	return &((const struct collision *)ctx->params)->receptacle;
}

int
collision_place(const struct model_ctx *ctx, struct result *res, int how)
{
	return place(ctx, res, how, 0, 0);
}

static int
trial_place(void *arg, double r, long long cap, struct result *res)
{
	return place(arg, res, PLACE_EXACT, r, cap);
}

static int
collision_run(const struct model_ctx *ctx, struct result *res)
{
	const struct collision *P = ctx->params;
	int at = P->given[CO_PARASTICHIES];
	double r;

	if (!at)
		return collision_place(ctx, res, PLACE_EXACT);
	r = para_design_receptacle(ctx, "collision", at, P->given[CO_RADIUS],
	    &P->receptacle, &P->parastichies, 0, trial_place, (void *)ctx);
	if (r < 0 || place(ctx, res, PLACE_EXACT, r, 0) != 0)
		return -1;
	result_info(res, "radius", 1, r);
	return 0;
}

const struct model collision_model = {
	.name = "collision",
	.help = "Fowler, Prusinkiewicz & Battjes: primordia packed on a "
	    "receptacle",
	.settings = &collision_table,
	.size = sizeof(struct collision),
	.run = collision_run,
};
