/*
 * inhibition_min.c - the angle of least inhibition: Newton on E' in a
 * gap, and the search over the gaps between the newest primordia's
 * angles, passing over those whose lower bound is above the least E
 * found.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/inhibition_impl.h"

/*
 * The minimum of E inside gap g, from x, to 1e-12 rad: Newton on E'
 * where E'' > 0 and its step stays inside the bracket of E''s signs,
 * else the bracket's chord or half; or an end, if that is lower: where
 * a lower bound at an end (inhib_end_least()) is above the minimum
 * inside, as it mostly is, E is not summed there.
 */
double
inhib_minimise(const struct field *F, const struct cut *cuts, size_t k,
    size_t g, double x, double *emin)
{
	double a = cuts[g].th, b = gap_end(cuts, k, g);
	double e[3], ends[2] = { a, b }, last = 0;	/* Newton's step */
	double d[2] = { 0, 0 };		/* E' at a and b, once known */
	int done = 0, tried[2] = { 0, 0 }, moved, kept = -1;

	for (int it = 0; it < 100 && !done; it++) {
		double nx, step;
		int newton;

		inhib_energy(F, x, e);
		moved = e[1] > 0;
		if (moved) {
			b = x;
			d[1] = e[1];
		} else {
			a = x;
			d[0] = e[1];
		}
		/* Illinois: an end kept twice has its slope halved. */
		if (moved == kept)
			d[!moved] /= 2;
		kept = moved;
		nx = e[2] > 0 ? x - e[1] / e[2] : (a + b) / 2;
		newton = e[2] > 0 && nx > a && nx < b;
		/*
		 * Where Newton cannot go: to the gap's end that E falls
		 * towards, once, where E still falling outwards ends the
		 * search (E is mostly monotone in a gap whose ends are far
		 * ones: halving took 40 sums to reach it); then between the
		 * ends where E' changes sign, by its chord (regula falsi).
		 */
		if (!newton) {
			if (e[1] < 0 && b == ends[1] && !tried[1]) {
				nx = b;
				tried[1] = 1;
			} else if (e[1] > 0 && a == ends[0] && !tried[0]) {
				nx = a;
				tried[0] = 1;
			} else {
				nx = (a * d[1] - b * d[0]) / (d[1] - d[0]);
				if (!(d[0] < 0 && d[1] > 0 && nx > a && nx < b))
					nx = (a + b) / 2;
			}
		}
		step = nx - x;
		/*
		 * Converged: the step under 1e-12; or a Newton step after
		 * another, whose error (step / last^2) step^2 by Newton's
		 * quadratic convergence is under 1e-13, the step under 1e-7.
		 * E there from E and its derivatives here, exact to E'''
		 * times the step cubed: a whole sum less.
		 */
		if (fabs(step) < 1e-12 || b - a < 1e-12 || (newton && last !=
		    0 && fabs(step) < 1e-7 && fabs(step) * step * step <
		    1e-13 * last * last)) {
			e[0] += (e[1] + e[2] * step / 2) * step;
			done = 1;
		}
		last = newton ? step : 0;
		x = nx;
	}
	*emin = done ? e[0] : inhib_energy_only(F, x);
	for (int side = 0; side < 2; side++) {
		double ee;

		if (inhib_end_least(F, cuts, k, g, side) > *emin * (1 + 1e-12))
			continue;
		ee = inhib_energy_only(F, ends[side]);

		if (ee < *emin) {
			*emin = ee;
			x = ends[side];
		}
	}
	return x;
}

static int
cutcmp(const void *a, const void *b)
{
	double x = ((const struct cut *)a)->th, y = ((const struct cut *)b)->th;

	return x < y ? -1 : x > y;
}

/*
 * The circle's cuts, the k newest primordia's angles, in order (newest
 * first among equal angles, as a stable sort of them newest first).
 * From one step to the next the newest joins and, with k the same, the
 * oldest leaves: one removal and one insertion keep the order, where a
 * sort of them all took 8% of the time; where k grows by one a step
 * (the first steps, and wherever near_count() rises with the growth)
 * the insertion alone.  Otherwise they are sorted afresh.
 */
static void
cuts_update(struct field *F, struct cut *cuts, size_t k)
{
	size_t n = F->n, p, lo = 0, hi;
	struct cut nw;
	int keep = F->ncut == k && n > k, grow = F->ncut + 1 == k;

	if (!((keep || grow) && F->cut_n + 1 == n && F->ncut > 0)) {
		for (size_t i = 0; i < k; i++) {
			cuts[i].i = n - 1 - i;
			cuts[i].th = remainder(F->phi[cuts[i].i], 2 * M_PI);
			cuts[i].c = F->c[cuts[i].i];
			cuts[i].s = F->s[cuts[i].i];
		}
		qsort(cuts, k, sizeof(*cuts), cutcmp);
		F->ncut = k;
		F->cut_n = n;
		return;
	}
	if (keep) {	/* the oldest leaves */
		for (p = 0; cuts[p].i != n - 1 - k; p++)
			;
		memmove(cuts + p, cuts + p + 1, (k - 1 - p) * sizeof(*cuts));
	}
	nw.i = n - 1;
	nw.th = remainder(F->phi[n - 1], 2 * M_PI);
	nw.c = F->c[n - 1];
	nw.s = F->s[n - 1];
	for (hi = k - 1; lo < hi; ) {	/* the first at or past nw.th */
		size_t mid = (lo + hi) / 2;

		if (cuts[mid].th < nw.th)
			lo = mid + 1;
		else
			hi = mid;
	}
	memmove(cuts + lo + 1, cuts + lo, (k - 1 - lo) * sizeof(*cuts));
	cuts[lo] = nw;
	F->ncut = k;
	F->cut_n = n;
}

/*
 * Gap g, while its bound is below the least E found: its bound made
 * closer, tier by tier, and at the last searched.  Of equal minima the
 * first gap's is taken, whatever order the gaps are searched in.
 */
static void
search_gap(const struct field *F, const struct cut *cuts, size_t k,
    size_t g, struct gap *gp, double *emin, double *th, size_t *gmin)
{
	double a = cuts[g].th, b = gap_end(cuts, k, g), e, x;

	while (gp->lb < *emin && gp->tier + 1 < TIERS) {
		double to = gp->at, bound = inhib_gap_bound(F, cuts, k, g, a, b,
		    ++gp->tier, *emin, &gp->live, &to);

		if (bound > gp->lb) {
			gp->lb = bound;
			gp->at = to;
		}
	}
	if (!(gp->lb < *emin))
		return;
	x = inhib_minimise(F, cuts, k, g, gp->at, &e);
	if (e < *emin || (e == *emin && g < *gmin)) {
		*emin = e;
		*th = x;
		*gmin = g;
	}
}

/*
 * Opposite each primordium its pull is least: with s = 3 (a sqrt and a
 * division each) the first n / LANES * LANES of them in lanes, into fl,
 * and their sum.  Its own function: GCC vectorises the loop only with
 * the arrays as restrict parameters.
 */
static HOT double
floor_lanes(const double *restrict r, double *restrict fl, size_t n)
{
	double acc[LANES] = { 0 }, sum = 0;

	for (size_t a = 0; a + LANES <= n; a += LANES)
		for (int l = 0; l < LANES; l++) {
			double q = (R0 + r[a + l]) * (R0 + r[a + l]);
			double f = 1 / (q * sqrt(q));

			fl[a + l] = f;
			acc[l] += f;
		}
	for (int l = 0; l < LANES; l++)
		sum += acc[l];
	return sum;
}

/*
 * Each near one's least pull into F->fl, and their sum, the floor of
 * E, returned: one at a time, they were a third of the step's set-up at
 * G = 0.002.  Summed in lanes, the floor is rounded otherwise than one
 * by one, oldest first, as before; it feeds only the lower bounds,
 * never E, and the angles were the same bytes (108 cases compared).
 */
static double
floors(struct field *F)
{
	size_t n = F->n - F->from, a = 0;
	double sum = 0;

	if (F->hs == 1.5) {
		sum = floor_lanes(F->r, F->fl, n);
		a = n / LANES * LANES;
	}
	for (; a < n; a++) {
		F->fl[a] = pull_at(F, (R0 + F->r[a]) * (R0 + F->r[a]));
		sum += F->fl[a];
	}
	return sum;
}

/*
 * The angle of least inhibition on the edge.  The circle is cut at the
 * angles of the near newest primordia, so that each gap holds one
 * minimum.  A gap whose lower bound is above the least E found cannot
 * hold the minimum: each gap's bound is made closer while it is below,
 * and the gap searched if its closest bound still is.  As exact as a
 * search of every gap, and most gaps are passed on their first bounds.
 *
 * Tried and dropped: keeping a gap's bound for later steps.  In Delta
 * of growth a pull falls at most by (1 + u (e^Delta - 1))^-s, u = |P| /
 * d, so a bound made q steps before, shrunk so, still holds; at G =
 * 0.0005 it ruled out 205 of 317 gaps a step, but spared only 8% of the
 * instructions: what the bounds cost is in the five or six gaps a step
 * within 1-3% of the least E, whose margins do not last a step, and
 * working u out for each gap kept cost about what a first bound does.
 *
 * What better bounds could win at most, measured by a replay: a run's
 * angles recorded, then the run again with no bound at all and one
 * search a step, in the gap the angle is in.  G = 0.001: 29 -> 10.5 us a
 * primordium, G = 0.0005: 42 -> 15 (20,000 and 12,000; one core, best
 * of 3).  So the bounds and the extra searches they let through (2 and
 * 2.9 a step, 1 needed) are two thirds of a step at slow growth.  Timed
 * call by call at G = 0.001 (rdtsc, so a little high): the first bounds
 * of all 232 gaps 6.2 us a step, the tiers above them 7.3, 3.0 and 1.9
 * (56, 13 and 3 gaps a step), the searches 3.3 (2 a step).  The
 * replay's own 15 us at G = 0.0005 is two thirds the far field (its
 * moments alone 5.4 us).  Counted on the gaps the first bounds let
 * through (55 and 63 a step at G = 0.001 and 0.0005): a bound from all
 * the near cuts, each at its least over each of 4 parts, would rule out
 * 50 and 54 of them (8 parts: 52 and 59; the whole gap: 30 and 19);
 * the two cuts at the gap's ends taken part by part, 0.8 and 0.1.  It
 * is the many cuts beyond the nearest 8 or 16 that the gaps lack, not
 * closer parts; summed one by one they cost more than the tiers do.
 */
double
inhib_next_angle(struct field *F, struct cut *cuts, struct gap *gaps)
{
	size_t k = F->near < F->n ? F->near : F->n, best = 0, gmin = k;
	double th = 0, emin = HUGE_VAL;

	cuts_update(F, cuts, k);
	F->floor = floors(F);
	F->nmid = 0;
	for (size_t i = F->from; i + k < F->n; i++) {
		size_t a = F->n - 1 - i;

		cutv_set(&F->mid, F->nmid++, F->c[i], F->s[i], F->r[a],
		    F->fl[a]);
	}
	/* The near cuts, in order; the far ones' pulls are the far field's. */
	F->ncp = 0;
	for (size_t c = 0; c < k; c++) {
		size_t i = cuts[c].i;
		double r = F->r[F->n - 1 - i];

		if (i >= F->from) {
			F->cpi[F->ncp] = i;
			cutv_set(&F->cp, F->ncp++, F->c[i], F->s[i], r,
			    F->fl[F->n - 1 - i]);
		}
		F->gpos[c] = F->ncp;	/* cut c itself is before gap c */
	}
	for (size_t c = 0; c < F->ncp; c++) {
		size_t d = F->ncp + c;

		F->cp.c[d] = F->cp.c[c];
		F->cp.s[d] = F->cp.s[c];
		F->cp.q0[d] = F->cp.q0[c];
		F->cp.r2[d] = F->cp.r2[c];
		F->cp.fl[d] = F->cp.fl[c];
		F->cpi[F->ncp + c] = F->cpi[c];
	}
	inhib_first_near(F, cuts, k);
	/*
	 * First the gap where the last divergence would put it: its minimum
	 * is mostly the least, and rules out the most gaps soonest.  Then
	 * every other in turn.
	 */
	if (F->n >= 2) {
		double want = remainder(2 * F->phi[F->n - 1] - F->phi[F->n - 2],
		    2 * M_PI);

		best = k - 1;	/* before the first cut: the last gap's */
		for (size_t lo = 0, hi = k; lo < hi; ) {
			size_t mid = (lo + hi) / 2;

			if (cuts[mid].th <= want) {
				best = mid;
				lo = mid + 1;
			} else
				hi = mid;
		}
	}
	for (size_t j = 0; j < k; j++) {
		size_t g = (best + j) % k;
		double a = cuts[g].th, b = gap_end(cuts, k, g);
		struct gap *gp = &gaps[g];

		gp->tier = 0;
		gp->live = (1u << SUBPARTS) - 1;
		gp->lb = b - a >= 1e-12 ? inhib_first_bound(F, cuts, k, g, a, b,
		    emin, &gp->at) : HUGE_VAL;	/* no room */
		if (gp->lb < emin)
			search_gap(F, cuts, k, g, gp, &emin, &th, &gmin);
	}
	if (F->check)
		inhib_check_bounds(F, cuts, k);
	return th;
}
