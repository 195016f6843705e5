/*
 * inhibition_bounds.c - lower bounds of E in a gap of the circle: each
 * pull at least its least over the gap, or over each part of it, in
 * tiers ever closer; what lets the search pass over most gaps unsearched.
 */
#include <math.h>

#include "models/inhibition_impl.h"

/* A part of a gap: its ends and their cosines and sines. */
struct gap_part {
	double		 lo, hi, cl, sl, ch, sh;
};

/*
 * The least cosine of the angle from (c, s) to a point of part p
 * narrower than pi: -1 if the opposite point is inside (the sines
 * say), else at the farther end.  No branch the compiler must keep:
 * selects only, which it can run on vectors (cuts_lanes()).
 */
static inline double
least_cos(double c, double s, const struct gap_part *p)
{
	double x = c * p->sl - s * p->cl, y = s * p->ch - c * p->sh;
	double a = p->cl * c + p->sl * s, b = p->ch * c + p->sh * s;
	double least = a < b ? a : b, opp = x >= 0 ? -1 : least;

	return y >= 0 ? opp : least;
}

/*
 * The least pull of primordium i anywhere in part p: where the part is
 * farthest from it, or opposite it.  For the power law from the ends'
 * cosines and sines alone: no call to the maths library a primordium.
 */
static double
least_pull(const struct field *F, size_t i, const struct gap_part *p)
{
	double cd, r = F->r[F->n - 1 - i];

	if (p->hi - p->lo >= M_PI) {	/* the first few steps' wide gaps */
		double opp = remainder(F->phi[i] + M_PI - p->lo, 2 * M_PI);

		if (opp < 0)
			opp += 2 * M_PI;
		cd = opp <= p->hi - p->lo ? -1 : cos(fmax(fabs(remainder(p->lo -
		    F->phi[i], 2 * M_PI)), fabs(remainder(p->hi - F->phi[i], 2 *
		    M_PI))));
	} else
		cd = least_cos(F->c[i], F->s[i], p);
	return pull_at(F, R0 * R0 + r * r - 2 * R0 * r * cd);
}

/*
 * Sums over near primordia: a side of a part (the cuts before it, or
 * after) is 4 to 8 cuts in the first three tiers, the last tier's whole
 * gap some hundreds.  Runs of LANES a side or more go to functions that
 * take LANES at once, built for AVX2 too (HOT), where a call costs less
 * than the lanes save; shorter ones inline, two at a time for s = 3
 * (1/x + 1/y = (x + y) / xy, one division).  A lone side of LONG or
 * more the same (the ends' bounds: 16).
 */
#define LONG		8

/* The lanes' partial sums added up, always in this order. */
static inline double
lanes_sum(const double acc[LANES])
{
	double sum = 0;

	for (int l = 0; l < LANES; l++)
		sum += acc[l];
	return sum;
}

/*
 * Entries a0 to a1 - 1 of v above their floors at (xa, ya), and b0 to
 * b1 - 1 at (xb, yb); s = 3.
 */
static inline double
sides_sum(const struct cutv *v, size_t a0, size_t a1, double xa,
    double ya, size_t b0, size_t b1, double xb, double yb)
{
	double acc[LANES] = { 0 }, sum = 0;

	for (int side = 0; side < 2; side++) {
		size_t d = side ? b0 : a0, to = side ? b1 : a1;
		double cx = side ? xb : xa, sx = side ? yb : ya;

		for (; d + LANES <= to; d += LANES)
			for (int l = 0; l < LANES; l++) {
				double q = v->q0[d + l] - v->r2[d + l] *
				    (v->c[d + l] * cx + v->s[d + l] * sx);

				acc[l] += 1 / (q * sqrt(q)) - v->fl[d + l];
			}
		for (; d < to; d++) {
			double q = v->q0[d] - v->r2[d] * (v->c[d] * cx +
			    v->s[d] * sx);

			sum += 1 / (q * sqrt(q)) - v->fl[d];
		}
	}
	return sum + lanes_sum(acc);
}

static HOT double
sides_lanes(const struct cutv *v, size_t a0, size_t a1, double xa,
    double ya, size_t b0, size_t b1, double xb, double yb)
{
	return sides_sum(v, a0, a1, xa, ya, b0, b1, xb, yb);
}

/*
 * sides_sum() of a0 .. a1 - 1 at each part's high end and a1 .. b1 - 1
 * at its low end, for the parts whose subparts live holds (sub a part),
 * part p from (x[p], y[p]) to (x[p + 1], y[p + 1]), into out[p].
 */
static HOT void
parts_lanes(const struct cutv *v, size_t a0, size_t a1, size_t b1,
    const double *x, const double *y, int parts, unsigned live, int sub,
    double *out)
{
	unsigned mask = (1u << sub) - 1;

	for (int p = 0; p < parts; p++)
		if (live & mask << p * sub)
			out[p] = sides_sum(v, a0, a1, x[p + 1], y[p + 1], a1,
			    b1, x[p], y[p]);
}

/* The same, each where it pulls least in part p; s = 3. */
static HOT double
cuts_lanes(const struct cutv *v, size_t from, size_t to,
    const struct gap_part *part)
{
	const struct gap_part pt = *part, *p = &pt;	/* in registers */
	double acc[LANES] = { 0 }, sum = 0;
	size_t d = from;

	for (; d + LANES <= to; d += LANES)
		for (int l = 0; l < LANES; l++) {
			double q = v->q0[d + l] - v->r2[d + l] *
			    least_cos(v->c[d + l], v->s[d + l], p);

			acc[l] += 1 / (q * sqrt(q)) - v->fl[d + l];
		}
	for (; d < to; d++) {
		double q = v->q0[d] - v->r2[d] * least_cos(v->c[d], v->s[d],
		    p);

		sum += 1 / (q * sqrt(q)) - v->fl[d];
	}
	return sum + lanes_sum(acc);
}

/*
 * The same as above_floor() summed over entries from to to - 1 of v,
 * in a part narrower than pi.
 */
static inline double
cuts_above(const struct field *F, const struct cutv *v, size_t from,
    size_t to, const struct gap_part *p)
{
	double sum = 0;

	if (F->hs == 1.5 && from + LONG <= to)
		return cuts_lanes(v, from, to, p);
	for (size_t d = from; d < to; d++)
		sum += pull_at(F, v->q0[d] - v->r2[d] * least_cos(v->c[d],
		    v->s[d], p)) - v->fl[d];
	return sum;
}

/*
 * Whether the near cuts from to to - 1 (in F->cp, in order round the
 * circle) are each less than pi from the far end of the gap: then the
 * ones before the gap pull least at its end, and at every part's high
 * end; the ones after, at its start and the parts' low ends.  The
 * outermost two say it for all.  Inline: first_near()'s AVX2 clone
 * called it as baseline code, a gap at a time, 5% of all the time at
 * G = 0.002 (18.8 -> 17.9 us a primordium).
 */
static inline int
straight_from(const struct field *F, size_t from, size_t to,
    const struct gap_part *gap)
{
	const struct cutv *v = &F->cp;

	if (!(from < to && gap->hi - gap->lo < M_PI))
		return 0;
	return gap->sh * v->c[from] - gap->ch * v->s[from] > 0 &&
	    /* sin(b - left) and sin(right - a) */
	    v->s[to - 1] * gap->cl - v->c[to - 1] * gap->sl > 0;
}

/*
 * The near cuts from to to - 1 above their floors, each pulling least
 * at the point (cx, sx) of the part, the farthest from it.  The loop
 * for s = 3 apart: the pull without a call, the exponent not tested
 * every cut (the bounds are most of the time).
 */
static inline double
side_above(const struct field *F, size_t from, size_t to, double cx,
    double sx)
{
	const struct cutv *v = &F->cp;
	double sum = 0;
	size_t d = from;

	if (F->hs != 1.5) {
		for (; d < to; d++)
			sum += pull_at(F, v->q0[d] - v->r2[d] * (v->c[d] * cx +
			    v->s[d] * sx)) - v->fl[d];
		return sum;
	}
	if (from + LONG <= to)
		return sides_lanes(v, from, to, cx, sx, to, to, cx, sx);
	for (; d + 1 < to; d += 2) {
		double q = v->q0[d] - v->r2[d] * (v->c[d] * cx + v->s[d] * sx);
		double p = v->q0[d + 1] - v->r2[d + 1] * (v->c[d + 1] * cx +
		    v->s[d + 1] * sx);
		double x = q * sqrt(q), y = p * sqrt(p);

		sum += (x + y) / (x * y) - v->fl[d] - v->fl[d + 1];
	}
	if (d < to) {
		double q = v->q0[d] - v->r2[d] * (v->c[d] * cx + v->s[d] * sx);

		sum += 1 / (q * sqrt(q)) - v->fl[d];
	}
	return sum;
}

/*
 * side_above() of a0 to a1 - 1 at (xa, ya) plus b0 to b1 - 1 at (xb,
 * yb): the cuts before a part at its high end and after it at its low
 * end, in one pass where they are LANES a side or more.
 */
static inline double
sides_above(const struct field *F, size_t a0, size_t a1, double xa,
    double ya, size_t b0, size_t b1, double xb, double yb)
{
	if (F->hs == 1.5 && a0 + LANES <= a1 && b0 + LANES <= b1)
		return sides_lanes(&F->cp, a0, a1, xa, ya, b0, b1, xb, yb);
	return side_above(F, a0, a1, xa, ya) + side_above(F, b0, b1, xb, yb);
}

/*
 * How much primordium i pulls in part p above its floor, the least it
 * pulls anywhere; 0 for one in the far field, which is bounded apart.
 */
static double
above_floor(const struct field *F, size_t i, const struct gap_part *p)
{
	return i >= F->from ? least_pull(F, i, p) - F->fl[F->n - 1 - i] : 0;
}

/*
 * The same summed over the near ones that are not cuts, older than the
 * k newest: from F->mid, in one tight loop, where the part is narrower
 * than pi (a quarter of the time at the slowest growth went to reading
 * them one by one from four arrays).
 */
static double
mid_above(const struct field *F, size_t k, const struct gap_part *p)
{
	double sum = 0;

	if (p->hi - p->lo < M_PI)
		sum = cuts_above(F, &F->mid, 0, F->nmid, p);
	else
		for (size_t i = F->from; i + k < F->n; i++)
			sum += above_floor(F, i, p);
	return sum;
}

/*
 * Per tier: how many cuts nearest the gap, 0 for all; in how many parts
 * (chosen by measurement: most gaps go at the first, most of the rest
 * at the second and third); and of those cuts, how many nearest are
 * taken part by part (0: all), the others once over the whole gap: far
 * from the gap a pull hardly changes across it.  The third at 64 cuts
 * in 8 parts, not 48 in 4, spares the last tier enough gaps at slow
 * growth to cost 15% less at G = 0.0005 (the same angles).  With the
 * sums on vectors, closer first tiers pay: the first 8 cuts, not 6
 * (four a side, a vector each), and the second all its 16 part by
 * part, not 6 of them: G = 0.0005 0.37 -> 0.30 s for 6,000, G = 0.002
 * 0.52 -> 0.44 s for 20,000 (best of 9 and 5).  No better, within 8%:
 * 16 cuts for the first; the second in 2 parts; the third of 48 or 96
 * cuts, in 4 parts, or 32 of its 64 part by part; 32 of the last's.
 */
static const struct {
	size_t		 cuts;
	int		 parts;
	size_t		 fine;
} tiers[TIERS] = { { 8, 1, 0 }, { 16, 4, 16 }, { 64, 8, 16 }, { 0, 16, 16 } };

/*
 * A lower bound of E in gap g, [a, b]: every pull is positive and
 * falls with the angle from its primordium, so it is at least its
 * least over the gap, and at least its least anywhere (opposite it):
 * F->floor sums those.  The closer tiers take the least over each of
 * several parts of the gap (the bound is the least of the parts'), for
 * more of the primordia nearest in angle; the far field is at least
 * Taylor's bound over the gap, and at least its least on the circle,
 * or, where it has a grid, at least its bound from that over the gap
 * or the part (inhib_far_least()).
 * *at: the middle of the part of least bound, where a search should
 * start.
 *
 * A part whose bound reaches stop (the least E found) cannot hold the
 * minimum.  A closer tier's parts split a coarser tier's and take every
 * term it took, closer: where the coarser part reached stop, theirs
 * would too.  *live, if not NULL, holds which of the last tier's parts
 * have not; the others are passed over, and the bound returned is the
 * least of the rest, or at least stop.
 */
double
inhib_gap_bound(const struct field *F, const struct cut *cuts, size_t k,
    size_t g, double a, double b, int tier, double stop, unsigned *live,
    double *at)
{
	int parts = tiers[tier].parts, sub = SUBPARTS / parts;
	unsigned mask = (1u << sub) - 1;	/* part 0's subparts */
	size_t kn = F->ncp, nc = tiers[tier].cuts ? tiers[tier].cuts : kn;
	size_t first, fine, skip, lo, hi, after;
	double h = (b - a) / parts, least = HUGE_VAL, far = 0, ch = 1, sh = 0;
	double coarse = 0;
	const struct cut *end = &cuts[g + 1 < k ? g + 1 : 0];
	struct gap_part pt, whole = { a, b, cuts[g].c, cuts[g].s, end->c,
	    end->s };
	double xs[SUBPARTS + 1], ys[SUBPARTS + 1], near[SUBPARTS];
	int straight, batch;

	if (nc > kn)
		nc = kn;
	/* The near cuts about the gap: nc/2 before it, nc/2 after. */
	first = kn > 0 ? (F->gpos[g] + kn - nc / 2) % kn : 0;
	fine = tiers[tier].fine && tiers[tier].fine < nc && b - a < M_PI ?
	    tiers[tier].fine : nc;
	skip = nc / 2 - fine / 2;
	lo = first + skip;		/* the fine ones */
	hi = lo + fine;
	after = first + nc / 2;		/* the first after the gap */
	if (fine < nc) {
		/* The others, and the near ones that are not cuts, once. */
		if (straight_from(F, first, first + nc, &whole))
			coarse = sides_above(F, first, lo, whole.ch, whole.sh,
			    hi, first + nc, whole.cl, whole.sl);
		else
			coarse = cuts_above(F, &F->cp, first, lo, &whole) +
			    cuts_above(F, &F->cp, hi, first + nc, &whole);
		if (tiers[tier].cuts == 0)
			coarse += mid_above(F, k, &whole);
	}
	if (F->moments)
		far = inhib_far_least(F, a, b);
	if (F->floor + coarse + far >= stop)
		return F->floor + coarse + far;
	if (F->grid > 0)
		;	/* each part's from the grid, below */
	else if (F->moments && tier >= 2) {
		/*
		 * Smooth beside the near ones: Taylor's, over the whole gap,
		 * from the first modes and what the others add at most.
		 */
		double e[3] = { 0, 0, 0 };
		int modes = F->nmodes < BOUND_MODES ? F->nmodes : BOUND_MODES;

		inhib_far_energy(F, cos((a + b) / 2), sin((a + b) / 2), modes,
		    e);
		far = fmax(F->far_least, e[0] - F->tail[0] - (fabs(e[1]) +
		    F->tail[1]) * (b - a) / 2 - F->far_curv * (b - a) *
		    (b - a) / 8);
	}
	straight = fine > 0 && straight_from(F, lo, hi, &whole);
	/* The parts' ends: the cuts' own cosines, turned by h between. */
	pt.lo = a;
	if (parts > 1) {
		ch = cos(h);
		sh = sin(h);
	}
	xs[0] = cuts[g].c;
	ys[0] = cuts[g].s;
	for (int p = 1; p < parts; p++) {
		xs[p] = xs[p - 1] * ch - ys[p - 1] * sh;
		ys[p] = ys[p - 1] * ch + xs[p - 1] * sh;
	}
	xs[parts] = end->c;
	ys[parts] = end->s;
	/*
	 * Every live part's sides in one call, where each would be one of
	 * sides_lanes(): the same sums, without a call through the CPU's
	 * choice a part.
	 */
	batch = straight && F->hs == 1.5 && lo + LANES <= after &&
	    after + LANES <= hi;
	if (batch)
		parts_lanes(&F->cp, lo, after, hi, xs, ys, parts, live != NULL ?
		    *live : ~0u, sub, near);
	for (int p = 0; p < parts; p++) {
		double sum = F->floor + coarse;
		unsigned bits = mask << p * sub;

		pt.hi = p + 1 < parts ? pt.lo + h : b;
		pt.cl = xs[p];
		pt.sl = ys[p];
		pt.ch = xs[p + 1];
		pt.sh = ys[p + 1];
		if (live != NULL && !(*live & bits))
			;	/* ruled out by a coarser tier's part */
		else if (batch)
			sum += near[p];
		else if (straight)	/* the ones before at hi, after at lo */
			sum += sides_above(F, lo, after, pt.ch, pt.sh, after,
			    hi, pt.cl, pt.sl);
		else if (pt.hi - pt.lo < M_PI)
			sum += cuts_above(F, &F->cp, lo, hi, &pt);
		else
			for (size_t d = first; d < first + nc; d++)
				sum += above_floor(F, F->cpi[d], &pt);
		/* And the near ones that are not cuts. */
		if (tiers[tier].cuts == 0 && fine == nc)
			sum += mid_above(F, k, &pt);
		/*
		 * The far field from the grid over the part, where its
		 * bound over the whole gap does not already reach stop.
		 */
		if (F->grid > 0 && parts > 1 && (live == NULL || (*live &
		    bits)) && sum + far < stop)
			sum += fmax(far, inhib_far_least(F, pt.lo, pt.hi));
		else
			sum += far;
		if (live != NULL && (!(*live & bits) || sum >= stop))
			*live &= ~bits;
		else if (sum < least) {
			least = sum;
			*at = (pt.lo + pt.hi) / 2;
		}
		pt.lo = pt.hi;
	}
	return least;
}

/*
 * The first tier's near part for every gap into F->fnear, in one pass
 * at the start of a step (a call a gap: 0.49 -> 0.45 s for 20,000 at G
 * = 0.002): the nearest near cuts, each at the end of the gap farther
 * from it; NAN where those ends are not the farthest points.
 */
static HOT void
first_near(const struct field *F, const struct cut *cuts, size_t k,
    double *out)
{
	size_t kn = F->ncp, nc = tiers[0].cuts < kn ? tiers[0].cuts : kn;

	for (size_t g = 0; g < k; g++) {
		size_t first = kn > 0 ? (F->gpos[g] + kn - nc / 2) % kn : 0;
		size_t mid = first + nc / 2;
		const struct cut *end = &cuts[g + 1 < k ? g + 1 : 0];
		struct gap_part whole = { cuts[g].th, gap_end(cuts, k, g),
		    cuts[g].c, cuts[g].s, end->c, end->s };

		if (!straight_from(F, first, first + nc, &whole))
			out[g] = NAN;
		else if (F->hs == 1.5)
			out[g] = sides_sum(&F->cp, first, mid, end->c, end->s,
			    mid, first + nc, cuts[g].c, cuts[g].s);
		else
			out[g] = side_above(F, first, mid, end->c, end->s) +
			    side_above(F, mid, first + nc, cuts[g].c,
			    cuts[g].s);
	}
}

void
inhib_first_near(struct field *F, const struct cut *cuts, size_t k)
{
	first_near(F, cuts, k, F->fnear);
}

/*
 * The first tier's bound, the only one most gaps get: the floor, the
 * far field's least, and the near part inhib_first_near() found;
 * inhib_gap_bound() itself where that is NAN.
 */
double
inhib_first_bound(const struct field *F, const struct cut *cuts, size_t k,
    size_t g, double a, double b, double stop, double *at)
{
	double near = F->floor + F->fnear[g];

	if (isnan(near))
		return inhib_gap_bound(F, cuts, k, g, a, b, 0, HUGE_VAL, NULL,
		    at);
	*at = (a + b) / 2;
	if (!F->moments)
		return near;
	/* The grid's bound only where the far field's least falls short. */
	return near + F->far_least >= stop ? near + F->far_least : near +
	    inhib_far_least(F, a, b);
}

/*
 * A lower bound of E at an end of gap g (side 0: its start, 1: its
 * end), where a cut sits: as gap_bound() takes it, the floor and the
 * far field's least, with the pulls of the 16 near cuts about the gap
 * at that point, the cut's own among them.  Half the minimised gaps'
 * ends are ruled out by it at G = 0.0005 (one sum of E less each).
 */
double
inhib_end_least(const struct field *F, const struct cut *cuts, size_t k,
    size_t g, int side)
{
	size_t kn = F->ncp, nc = tiers[1].cuts < kn ? tiers[1].cuts : kn;
	size_t first = kn > 0 ? (F->gpos[g] + kn - nc / 2) % kn : 0;
	const struct cut *at = &cuts[side == 0 ? g : g + 1 < k ? g + 1 : 0];

	return F->floor + (F->moments ? inhib_far_least(F, at->th, at->th) :
	    0) + side_above(F, first, first + nc, at->c, at->s);
}

/*
 * For the tests: every tier's bound of every gap, inhib_first_bound()'s too,
 * against the least E the search finds in it.  A bound above it is
 * wrong, and would have let the search pass over the gap holding the
 * minimum.
 */
void
inhib_check_bounds(struct field *F, const struct cut *cuts, size_t k)
{
	for (size_t g = 0; g < k; g++) {
		double a = cuts[g].th, b = gap_end(cuts, k, g), at, e;

		if (!(b - a >= 1e-12))
			continue;
		inhib_minimise(F, cuts, k, g, (a + b) / 2, &e);
		for (int t = 0; t < TIERS; t++)
			if (inhib_gap_bound(F, cuts, k, g, a, b, t, HUGE_VAL,
			    NULL, &at) > e * (1 + 1e-12))
				F->misses++;
		if (inhib_first_bound(F, cuts, k, g, a, b, HUGE_VAL, &at) >
		    e * (1 + 1e-12))
			F->misses++;
	}
}
