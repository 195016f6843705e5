/*
 * collision_walk.c - the collision model's exact walk up the generating
 * curve: at each stop the grid names the earlier primordia the new one
 * would overlap, and the walk jumps to the furthest point where the
 * curve leaves them (curve_exit), skipping what the cover map
 * (collision_cover.c) proves covered, and proving more of it (refine).
 *
 * Tried for the falling radius's looks far below the front, and not
 * kept (the sphere's band of 100,000, radius falling 5x):
 *
 * A proof at each look above the column's head that left the cell
 * blocked, closer than refine()'s: every primordium that can reach the
 * cell (a second search of the grid, not the look's hits), the cell's
 * 4 x 4 sub-cells and, where one was not under 0.7 r, 4 x 4 finer ones
 * in it, each bounded by its middle's clearance and its half diagonal.
 * Sampled at 9 x 9 points, 83% of the cells looked at there fitted
 * nothing, and the proofs held: 1.85 of 2.14 a walk proved the cell,
 * at 0.65 r to r.  But looks fell only from 6.6 to 5.1 a walk, for 70%
 * more instructions and 38% more time: late in the run the radius
 * falls 12% to 25% between one walk up a column and the next, past
 * most bounds proved, and about half the looks are a cell's first
 * (its bound covered the column's last walk).
 * Proofs aimed at the radius of the column's next walk proved 1.42 a
 * walk, and the looks stayed 5.1.
 *
 * In free_at(), each cell's first primordium asked for (prefetched)
 * before any was read, and each next one while the last was tried: the
 * reads of the primordia are a fifth of the time there (perf), but the
 * lists are short (2 or 3 a cell) and the time was the same within the
 * noise (best of five, side by side).  And the primordium's t kept
 * apart, so that one is 32 bytes on a 32-byte boundary, a cache line:
 * 11% fewer D1 misses (cachegrind), no faster beyond the noise.
 */
#include <math.h>

#include "base/mem.h"
#include "models/collision_impl.h"

#define REFINE_FALL	0.03	/* of r: a proof for r lasts about so far */

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
		 * (coll_grid_fit()), so it meets 27 at most; were it more, the
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

			misses += !coll_near_point(C, p, U);
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
int
coll_near_point(void *ctx, const double p[3], double U)
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
 * The row of the cover map that holds t0 = curve_t(s0), without
 * working t0 out; -1 where that is not sure.
 *
 * With epsilon each walk starts at t0 = curve_t(s0), s0 = the last
 * primordium's arc length less epsilon, and curve_t() inverts the arc
 * length by Newton's method: some seven arc lengths of a piece, each
 * eight points of Gauss-Legendre, a fifth of the walk's time (disk,
 * falling, epsilon r, 300,000).  But most walks (70-85% there) start
 * in covered rows that cover_skip() moves them past, and what it does
 * there depends on t only through its row: t0 itself is needed only
 * for a look at it.
 *
 * Row k starts at t_row[k] = curve_t(s_row[k]) (cover_init()), so t0
 * lies in the row whose arc lengths hold s0 (floor(s0 / a) when all
 * rows are a high) when curve_t() keeps the order of s0 and the rows'
 * ends.  It is the same function at both (the piece found by
 * its start's arc length, then the same Newton iteration on the same
 * Gauss-Legendre sum), and it lands within about 1e-15 of the piece's
 * parameter span of that sum's root (its iteration stops on a step
 * under 1e-16 or a bracket under 1e-15), so the order holds wherever s0
 * lies further than that, in arc length, from a row's end: kept here
 * at least 1e-6 of a row and 1e-12 of the whole curve's length away,
 * some thousand times that even were the curve one piece.  The tests'
 * check (PLACE_CHECK) works t0 out at every such start and counts the
 * rows that do not hold it.
 */
static int32_t
start_row(const struct coll *C, double s0)
{
	const struct cover *cv = &C->cover;
	double x = s0 / cv->a, m = fmax(1e-6 * cv->a, 1e-12 * C->cv.length);
	int32_t k;

	if (C->nocover || !(s0 > 0 && s0 < C->cv.length))
		return -1;
	if (cv->levels == 1) {
		if (!(x < cv->rows))
			return -1;
		k = (int32_t)x;
		if (s0 - k * cv->a < m || fmin((k + 1) * cv->a,
		    C->cv.length) - s0 < m)
			return -1;
		return k;
	}
	if (!(s0 < cv->s_row[cv->rows]))
		return -1;
	for (int32_t lo = 0, hi = cv->rows - 1; ; ) {	/* s_row[lo] <= s0 */
		k = (lo + hi + 1) / 2;
		if (lo == hi)
			break;
		if (cv->s_row[k] <= s0)
			lo = k;
		else
			hi = k - 1;
	}
	if (s0 - cv->s_row[k] < m || fmin(cv->s_row[k + 1], C->cv.length) -
	    s0 < m)
		return -1;
	return k;
}

/*
 * The smallest free t >= t0 on meridian (c, s), exactly; HUGE_VAL: none.
 * With s0 >= 0, t0 is curve_t(s0), worked out only if the walk must
 * look there.  *row is t's row of the cover map, if the walk found it,
 * else -1, and p the curve's point at t.
 */
double
coll_place_exact(struct coll *C, long long n, double t0, double s0,
    double phi, double c, double s, double r, int32_t *row, double p[2])
{
	int32_t j = C->nocover ? 0 : cover_col(&C->cover, phi), k = -1;
	double t = t0, to, below = -1;
	struct hit hits[HITS];
	int skipped = 0;

	if (s0 >= 0) {
		/*
		 * From row k's start, cover_skip() does what it would do
		 * from t0 in the row: it moves the walk past the row, or
		 * leaves it in the row, at t0 then.
		 */
		if ((k = start_row(C, s0)) >= 0) {
			t = C->cover.t_row[k];
			skipped = 1;
			if (C->check) {
				double e = curve_t(&C->cv, s0);

				C->starts++;
				C->start_misses += !(C->cover.t_row[k] <= e &&
				    e < C->cover.t_row[k + 1]);
			}
			/*
			 * Row k is not covered for the walk.  With rows of
			 * many heights (collision_cover.c) that is often so, a
			 * row too coarse to be covered where t0 is, and
			 * curve_t() would be a fifth of the walk: look at the
			 * row's start first, whose point is known (below).
			 */
			if (!cover_skip(&C->cover, &t, j, r, &k)) {
				if (C->cover.levels > 1)
					below = s0;
				else
					t = curve_t(&C->cv, s0);
			}
		} else
			t = curve_t(&C->cv, s0);
	}
	while (t <= C->cv.tmax) {
		const double *pd = NULL;
		int nh, fr;

		/* One call leaves t where the walk must look. */
		if (!C->nocover && !skipped && cover_skip(&C->cover, &t, j, r,
		    &k) && !(t <= C->cv.tmax))
			break;
		skipped = 0;
		/* Moved to a row's start: the curve there is known. */
		if (k >= 0 && t == C->cover.t_row[k])
			pd = C->cover.start[k];
		fr = free_at(C, t, c, s, r, pd, p, &to, hits, &nh);
		if (below >= 0) {
			/*
			 * That was row k's start, below t0 = curve_t(below):
			 * blocked past the row, everything from it to the exit
			 * is covered, t0 too; else t0 is worked out after all,
			 * and the walk goes on from it or the exit, beyond.
			 */
			if (fr || !(to >= C->cover.t_row[k + 1])) {
				double tt = curve_t(&C->cv, below);

				t = !fr && to > tt ? to : tt;
			} else
				t = to;
			/* At t0, row k is known not to be covered. */
			skipped = t < C->cover.t_row[k + 1];
			below = -1;
			continue;
		}
		if (fr) {
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
