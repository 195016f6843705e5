/*
 * unordered.c - contact parastichies measured without an organ order,
 * zone by zone, as parastichy.c measures them with one.
 *
 * The points, in their axis's terms (axis.c), are cut into bands from
 * the tip outward, each a ring or two of organs.  In each band the
 * lattice of neighbour steps and the number of spirals each of its two
 * steps traces are found (lattice.c); then every step between
 * neighbours is a whole number of organs along the spiral, so each
 * organ's contacts are read as parastichy.c reads them from an order:
 * its nearest earlier neighbour turning either way about the axis
 * (earlier: nearer the tip), the organs between giving the pair.  A
 * band's most common pair, held by at least half its organs and
 * spanning its lattice, is its pair; bands join into zones as runs do
 * there.  A band with no lattice to read is said to be unclear.
 *
 * From the same lattices: the divergence (each step of a family of n
 * spirals turns n divergences less whole turns, and the turns are known
 * from the pair), and the area per organ, which gives Vogel's c on a
 * head and the rise on a cylinder.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "analysis/parastichy.h"
#include "analysis/lattice.h"
#include "analysis/unordered.h"

#define BANDS_MAX	48	/* bands a structure is cut into at most */
#define BAND_MIN	8	/* points in a band at least */
#define BASIS_MIN	64	/* points a band's lattice is read from */
#define BASIS_MAX	500	/* and at most */
#define COUNTED_MAX	16	/* bands whose spirals are counted */
#define SMOOTH		32	/* points either side an area is averaged */
#define CONTACT_ON	0.45	/* a contact step: within this of |a| */

struct band {
	size_t		 from, to;	/* in the order by s */
	enum uzone_kind	 kind;
	int		 m, n;		/* its most common pair */
	size_t		 organs, held;
	struct band_lattice L;
	int		 basis;		/* L holds a basis */
	int		 lattice;	/* and its numbers */
	double		 alpha, alpha_sigma;	/* radians; NAN: none */
	double		 alpha_local;	/* its own, or the nearest band's */
	double		 noise;		/* of a step's turn (turn_noise()) */
};

static const double *sort_key;

static int
by_key(const void *a, const void *b)
{
	double x = sort_key[*(const size_t *)a];
	double y = sort_key[*(const size_t *)b];

	if (x != y)
		return x < y ? -1 : 1;
	return *(const size_t *)a < *(const size_t *)b ? -1 : 1;
}

static int
by_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

static struct unordered *
unordered_new(const struct axis *A, size_t n)
{
	struct unordered *U = xcalloc(1, sizeof(*U) + n * sizeof(U->c[0]));

	U->centre[0] = A->centre[0];
	U->centre[1] = A->centre[1];
	U->squash = A->squash;
	U->squash_deg = A->squash_deg;
	U->spacing = A->spacing;
	U->surface = A->surface;
	U->divergence = U->divergence_err = NAN;
	U->vogel_c = U->vogel_c_err = U->exponent = U->exponent_err = NAN;
	U->rise = U->rise_err = U->contact = NAN;
	U->count = n;
	U->unit = 1;
	for (size_t i = 0; i < n; i++)
		U->c[i] = (struct uorgan){ { -1, -1 }, { 0, 0 }, 0 };
	return U;
}

/*
 * The organs step l skips, counted outward, and the whole turns q it
 * makes less than k divergences; 0 where it cannot be told.  With a
 * divergence alpha at hand, the k of the few a step's length allows
 * (from the lattice's numbers, or from the area per organ where the
 * lattice has none there) whose k alpha is the step's turn: that holds
 * for every step, where the rounding to a lattice step fails at the
 * lattice's flaws (the collision model's, where its radius changes).
 * Without one, the lattice's numbers.
 */
static int
step_k(const struct band_lattice *L, const double l[2], double alpha,
    double noise, long long *k, long long *q)
{
	double cross = fabs(L->a[0] * L->b[1] - L->a[1] * L->b[0]);
	double phi = l[1] / L->rho, kc = 2 * M_PI * L->rho * l[0] / cross;
	double best = HUGE_VAL, second = HUGE_VAL;
	long long x, y, kr = 0, from[2], w[2];
	int have = L->ka != 0 && lattice_round(L, l, CONTACT_ON, &x, &y);

	if (have)
		kr = x * L->ka + y * L->kb;
	*k = kr;
	*q = 0;
	if (isnan(alpha))
		return have;
	/* The lattice's number, its turn agreeing: two checks in one. */
	if (have && fabs(remainder((double)kr * alpha - phi, 2 * M_PI)) <=
	    5 * noise) {
		*q = llround(((double)kr * alpha - phi) / (2 * M_PI));
		return 1;
	}
	from[0] = kr;
	w[0] = have ? 2 : -1;
	/* A step no lattice numbers: nothing to try from its length. */
	from[1] = fabs(kc) < 1e6 ? llround(kc) : 0;
	w[1] = fabs(kc) < 1e6 ? llround(0.35 * fabs(kc) + 3) : -1;
	for (int c = 0; c < 2; c++) {
		/* t alpha - phi, a turn at a time: one wrap a step. */
		double turn = remainder((double)(from[c] - w[c]) * alpha - phi,
		    2 * M_PI), by = remainder(alpha, 2 * M_PI);

		for (long long t = from[c] - w[c]; t <= from[c] + w[c]; t++,
		    turn += by) {
			double r;

			if (turn > M_PI)
				turn -= 2 * M_PI;
			else if (turn <= -M_PI)
				turn += 2 * M_PI;
			if (t == 0 || (c == 1 && have && llabs(t - kr) <= 2))
				continue;
			r = fabs(turn);
			if (r < best) {
				second = best;
				best = r;
				*k = t;
			} else if (r < second)
				second = r;
		}
	}
	/*
	 * Within the turns' noise, and the next candidate clear of it: the
	 * golden angle's k and k + 89 turn 1.8 degrees apart, and a step
	 * of a photograph's florets is off by some tenths of one.
	 */
	if (!(best <= 5 * noise && second >= best + 8 * noise)) {
		if (!have)
			return 0;
		*k = kr;
	}
	*q = llround(((double)*k * alpha - phi) / (2 * M_PI));
	return 1;
}

/*
 * Each point's contacts in band lattice L: the nearest neighbour a
 * whole number of organs earlier on each side; its pair (0 0: none)
 * and whether the two contacts span the lattice of the organs (k q' -
 * k' q = +-1, q the turns: parastichy.c's test).
 */
static void
contacts_of(const struct point_field *F, const struct band_lattice *L,
    double alpha, double noise, size_t i, int older_out, struct uorgan *c,
    int pair[2], int *spans)
{
	long long at[2][2] = { { 0, 0 }, { 0, 0 } };

	c->prev[0] = c->prev[1] = -1;
	c->dk[0] = c->dk[1] = 0;
	pair[0] = pair[1] = 0;
	*spans = 0;
	for (int m = 0; m < F->nnn[i]; m++) {
		double l[2];
		long long dk, q;
		int side;

		/*
		 * One on the line through the axis turns neither way (a
		 * rank of a whorl); a side found is found (the nearest first).
		 */
		lattice_step(F, L, i, F->nn[i][m], l);
		side = l[1] > 0;
		if (!(fabs(l[1]) > 1e-9 * fabs(L->a[1]) + 1e-300) ||
		    c->prev[side] >= 0)
			continue;
		if (!step_k(L, l, alpha, noise, &dk, &q))
			continue;
		/* Counted outward; earlier is toward the older organs. */
		if (older_out)
			dk = -dk, q = -q;
		if (dk >= 0 || -dk > INT32_MAX)
			continue;
		c->prev[side] = (int32_t)F->nn[i][m];
		c->dk[side] = (int32_t)-dk;
		at[side][0] = dk;
		at[side][1] = q;
	}
	if (c->prev[0] < 0 || c->prev[1] < 0)
		return;
	pair[0] = c->dk[0] < c->dk[1] ? c->dk[0] : c->dk[1];
	pair[1] = c->dk[0] < c->dk[1] ? c->dk[1] : c->dk[0];
	/* Without the turns (no divergence), the pair's numbers alone. */
	*spans = isnan(alpha) ? para_gcd(pair[0], pair[1]) == 1 :
	    llabs(at[0][0] * at[1][1] - at[0][1] * at[1][0]) == 1;
}

struct tally {
	int		 m, n;
	int		 spans;
};

static int
tally_cmp(const void *a, const void *b)
{
	const struct tally *x = a, *y = b;

	if (x->m != y->m)
		return x->m < y->m ? -1 : 1;
	return x->n < y->n ? -1 : x->n > y->n;
}

/*
 * The band's pairs: every point's contacts into U, the most common pair
 * and how many hold it; a family pair if at least half hold it and it
 * spans the lattice.
 */
static void
band_pairs(const struct point_field *F, struct band *B, const size_t *pts,
    size_t np, int older_out, double noise, struct unordered *U)
{
	double alpha = B->alpha_local;

	struct tally *t = xcalloc(np + 1, sizeof(*t));
	size_t nt = 0, best = 0, spans = 0;

	for (size_t k = 0; k < np; k++) {
		int pair[2], sp;

		contacts_of(F, &B->L, alpha, noise, pts[k], older_out,
		    &U->c[pts[k]], pair, &sp);
		if (pair[0] > 0)
			t[nt++] = (struct tally){ pair[0], pair[1], sp };
	}
	qsort(t, nt, sizeof(*t), tally_cmp);
	B->m = B->n = 0;
	for (size_t i = 0, j; i < nt; i = j) {
		size_t sp = 0;

		for (j = i; j < nt && t[j].m == t[i].m && t[j].n == t[i].n; j++)
			sp += (size_t)t[j].spans;
		if (j - i > best) {
			best = j - i;
			spans = sp;
			B->m = t[i].m;
			B->n = t[i].n;
		}
	}
	free(t);
	B->held = best;
	B->kind = B->m > 0 && 2 * best >= B->organs && 2 * spans >= best &&
	    para_gcd(B->m, B->n) == 1 ? UZ_PAIR : UZ_TRANSITION;
	if (B->m == 0)
		B->kind = UZ_UNCLEAR;
}

/* x, y with x a + y b = gcd(a, b). */
static long long
euclid(long long a, long long b, long long *x, long long *y)
{
	long long x0 = 1, y0 = 0, x1 = 0, y1 = 1;

	while (b != 0) {
		long long q = a / b, t;

		t = a - q * b, a = b, b = t;
		t = x0 - q * x1, x0 = x1, x1 = t;
		t = y0 - q * y1, y0 = y1, y1 = t;
	}
	*x = x0;
	*y = y0;
	return a;
}

/*
 * The divergence a band's lattice shows: a step of a turns ka
 * divergences less some whole turns pa, so alpha is one of the ka
 * values (a's turn + 2 pi pa) / ka, and one of the kb from b; with ka
 * and kb coprime exactly one of each pair coincide (the others lie
 * 2 pi / (ka kb) apart at least), and the two must agree to their
 * errors.  Each to the error of its step's turn over ka or kb organs.
 */
static int
band_alpha(struct band *B)
{
	const struct band_lattice *L = &B->L;
	double phi[2] = { L->a[1] / L->rho, L->b[1] / L->rho };
	double al[2] = { 0, 0 }, sg[2], w[2], best = HUGE_VAL;
	long long x, y, k[2] = { L->ka, L->kb };

	B->alpha = B->alpha_sigma = NAN;
	if (euclid(L->ka, L->kb, &x, &y) != 1)
		return -1;
	for (long long p = 0; p < k[0]; p++) {
		double a = (phi[0] + 2 * M_PI * (double)p) / (double)k[0];
		double q = round(((double)k[1] * a - phi[1]) / (2 * M_PI));
		double b = (phi[1] + 2 * M_PI * q) / (double)k[1];

		if (fabs(a - b) < best) {
			best = fabs(a - b);
			al[0] = a;
			al[1] = b;
		}
	}
	for (int f = 0; f < 2; f++) {
		sg[f] = fmax(L->sigma_t[f] / L->rho / (double)k[f], 1e-12);
		w[f] = 1 / (sg[f] * sg[f]);
	}
	if (!(best <= 6 * hypot(sg[0], sg[1]) + 1e-9))
		return -1;
	B->alpha = (w[0] * al[0] + w[1] * al[1]) / (w[0] + w[1]);
	B->alpha_sigma = 1 / sqrt(w[0] + w[1]);
	return 0;
}

/* Forget band B's numbers: it is to be labelled from its neighbours. */
static void
unlabel(struct band *B)
{
	B->L.ka = B->L.kb = 0;
	B->L.counted = 0;
	B->alpha = B->alpha_sigma = NAN;
}

/* The median of the counted bands' divergences from b - w to b + w. */
static double
median_alpha(const struct band *B, size_t nb, size_t b, size_t w)
{
	double *v = xcalloc(2 * w + 2, sizeof(*v)), ref = B[b].alpha, m;
	size_t n = 0;

	for (size_t c = b > w ? b - w : 0; c < nb && c <= b + w; c++)
		if (!isnan(B[c].alpha))
			v[n++] = ref + remainder(B[c].alpha - ref, 2 * M_PI);
	qsort(v, n, sizeof(*v), by_double);
	m = n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
	free(v);
	return m;
}

/*
 * A counted band whose divergence is not its neighbours' miscounted:
 * one spiral too few turns a family's step ka divergences less a few
 * degrees.  Against the median of the counted bands within three of it,
 * to a quarter degree (the divergence may drift, not jump), and of all
 * of them, to a degree: counts are wrong together where a run of
 * missing organs breaks a spiral in the rings that bands next to each
 * other share.
 */
static void
outliers(struct band *B, size_t nb)
{
	double *local = xcalloc(nb + 1, sizeof(*local));
	double *all = xcalloc(nb + 1, sizeof(*all));

	for (size_t b = 0; b < nb; b++) {
		local[b] = all[b] = NAN;
		if (isnan(B[b].alpha))
			continue;
		local[b] = median_alpha(B, nb, b, 3);
		all[b] = median_alpha(B, nb, b, nb);
	}
	for (size_t b = 0; b < nb; b++)
		if (!isnan(local[b]) && (fabs(remainder(B[b].alpha - local[b],
		    2 * M_PI)) > 0.25 * M_PI / 180 + 5 * B[b].alpha_sigma ||
		    fabs(remainder(B[b].alpha - all[b], 2 * M_PI)) > M_PI /
		    180 + 5 * B[b].alpha_sigma))
			unlabel(&B[b]);
	free(local);
	free(all);
}

/*
 * How far labels by divergence alpha stray from what the bands' shapes
 * say, in their errors squared, on average; how many bands it labels
 * into *n.
 */
static double
stray(const struct band *B, size_t nb, double alpha, double err, size_t *n)
{
	double chi = 0;

	*n = 0;
	for (size_t b = 0; b < nb; b++) {
		struct band_lattice L = B[b].L;
		double da, db;

		if (!B[b].basis || L.ka_err == 0 || lattice_by_angle(&L,
		    alpha, err) != 0)
			continue;
		da = ((double)L.ka - L.ka_est) / fmax(L.ka_err, 0.2);
		db = ((double)L.kb - L.kb_est) / fmax(L.kb_err, 0.2);
		chi += da * da + db * db;
		(*n)++;
	}
	return *n > 0 ? chi / (2 * (double)*n) : HUGE_VAL;
}

/*
 * The counted bands' divergences may be an alias: where a family is
 * miscounted by the same number all along, its count and the true
 * count's divergence differ, yet each labels every band consistently
 * in angle (at the golden angle, 32 and 78.6 degrees stand for 34 and
 * 137.5 everywhere).  Only along the curve do they differ: labels by
 * an alias stray from the bands' shapes, by one in most bands.  So of
 * the divergences the counted bands give, their counts and those up to
 * two off each way, the one whose labels stray least (of those that
 * label a third of the bands at least); every band is labelled by it, a
 * counted band whose count gave another too.
 */
static void
alias(struct band *B, size_t nb)
{
	double (*h)[2] = xcalloc(25 * nb + 1, sizeof(*h)), best = HUGE_VAL;
	double at = NAN, at_err = 0;
	size_t nh = 0, bases = 0, counted = 0;

	for (size_t b = 0; b < nb; b++)
		counted += !isnan(B[b].alpha);
	for (size_t b = 0; b < nb; b++) {
		struct band u = B[b];

		bases += B[b].basis;
		/*
		 * With no count at all (a photograph that keeps few whole
		 * rings, and those jittered), the numbers each whole ring's
		 * shape gives, as counts: the turns and the fit along the
		 * curve choose among them as among counts.
		 */
		if (counted == 0 && u.basis && u.L.ka_err > 0 && u.L.ka_err <
		    1 && u.L.kb_err < 1 && u.L.coverage > 0.97) {
			u.L.ka = llround(u.L.ka_est);
			u.L.kb = llround(u.L.kb_est);
		} else if (isnan(u.alpha))
			continue;
		for (int da = -2; da <= 2; da++)
			for (int db = -2; db <= 2; db++) {
				struct band v = u;
				size_t k = 0;

				v.L.ka += da;
				v.L.kb += db;
				if (v.L.ka <= 0 || v.L.kb == 0 ||
				    band_alpha(&v) != 0)
					continue;
				/* The same, to the sharper of the two. */
				while (k < nh && fabs(remainder(h[k][0] -
				    v.alpha, 2 * M_PI)) >= 0.05 * M_PI / 180)
					k++;
				if (k == nh || v.alpha_sigma < h[k][1]) {
					h[k][0] = v.alpha;
					h[k][1] = v.alpha_sigma;
					nh += k == nh;
				}
			}
	}
	/* The best fit of those that label a third of the bands at least. */
	for (size_t k = 0; k < nh; k++) {
		size_t n;
		double chi = stray(B, nb, h[k][0], h[k][1], &n);

		if (3 * n >= bases && chi < best) {
			best = chi;
			at = h[k][0];
			at_err = h[k][1];
		}
	}
	free(h);
	if (isnan(at))
		return;
	for (size_t b = 0; b < nb; b++) {
		if (!B[b].lattice || (!isnan(B[b].alpha) &&
		    fabs(remainder(B[b].alpha - at, 2 * M_PI)) <= M_PI / 180))
			continue;
		unlabel(&B[b]);
		if (lattice_by_angle(&B[b].L, at, at_err) != 0 ||
		    band_alpha(&B[b]) != 0)
			unlabel(&B[b]);
	}
}

/*
 * Labels for the bands whose ring was cut or whose counts did not hold:
 * from the divergence of a labelled band next to them, band by band
 * out from the counted ones (the divergence may drift along a plant,
 * so the nearest band's, not one for all).
 */
static void
label(struct band *B, size_t nb)
{
	size_t keep_in = SIZE_MAX, keep_out = SIZE_MAX;
	int changed = 1;

	for (size_t b = 0; b < nb; b++)
		if (B[b].lattice && (!B[b].L.counted || isnan(B[b].alpha)))
			unlabel(&B[b]);
	/*
	 * Bands past the outermost ring the spirals cross whole were all
	 * counted at that ring: one count, not as many votes.  The one
	 * nearest the bands counted where they are keeps it, of those whose
	 * count held (under a click's jitter, maybe one of several).
	 */
	for (size_t b = 0; b < nb; b++) {
		if (B[b].L.clamped < 0 && !isnan(B[b].alpha))
			keep_in = b;
		if (B[nb - 1 - b].L.clamped > 0 && !isnan(B[nb - 1 - b].alpha))
			keep_out = nb - 1 - b;
	}
	for (size_t b = 0; b < nb; b++)
		if ((B[b].L.clamped > 0 && b != keep_out) ||
		    (B[b].L.clamped < 0 && b != keep_in))
			unlabel(&B[b]);
	alias(B, nb);
	outliers(B, nb);
	while (changed) {
		changed = 0;
		for (size_t b = 0; b < nb; b++) {
			struct band *bd = &B[b];
			const struct band *by = NULL;

			if (!bd->lattice || bd->L.ka != 0)
				continue;
			/* The nearest labelled band, the inner on a tie. */
			for (size_t d = 1; d < nb && by == NULL; d++)
				if (b >= d && !isnan(B[b - d].alpha))
					by = &B[b - d];
				else if (b + d < nb && !isnan(B[b + d].alpha))
					by = &B[b + d];
			if (by == NULL)
				break;
			if (lattice_by_angle(&bd->L, by->alpha,
			    by->alpha_sigma) != 0 ||
			    band_alpha(bd) != 0) {
				/* Tried once: unclear. */
				unlabel(bd);
				bd->lattice = 0;
				continue;
			}
			changed = 1;
		}
	}
}

/*
 * Each band's divergence for reading its steps: its own, or the
 * nearest band's that has one (the inner on a tie).
 */
static void
local_alpha(struct band *B, size_t nb)
{
	for (size_t b = 0; b < nb; b++) {
		B[b].alpha_local = B[b].alpha;
		for (size_t d = 1; d < nb && isnan(B[b].alpha_local); d++)
			if (b >= d && !isnan(B[b - d].alpha))
				B[b].alpha_local = B[b - d].alpha;
			else if (b + d < nb && !isnan(B[b + d].alpha))
				B[b].alpha_local = B[b + d].alpha;
	}
}

/*
 * How far a step's turn is from k divergences, as it goes: the median
 * over the steps a labelled band rounds to its lattice, as a standard
 * deviation, each band its own (a turn's error falls as the radius
 * grows), or all of them together where a band has too few.  A model's
 * organs are exactly k divergences apart; a photograph's are not.
 */
static void
turn_noise(const struct point_field *F, struct band *B, size_t nb)
{
	double *r = xcalloc(3 * F->n + 1, sizeof(*r)), all;
	size_t nr = 0, *from = xcalloc(nb + 1, sizeof(*from));

	for (size_t b = 0; b < nb; b++) {
		const struct band_lattice *L = &B[b].L;

		from[b] = nr;
		if (!B[b].basis || L->ka == 0 || isnan(B[b].alpha_local))
			continue;
		/* A few hundred points a band are enough for a median. */
		for (size_t k = B[b].from; k < B[b].to; k += 1 + (B[b].to -
		    B[b].from) / 300) {
			size_t i = F->order[k];

			for (int m = 0; m < F->nnn[i] && m < 3; m++) {
				double l[2];
				long long x, y;

				lattice_step(F, L, i, F->nn[i][m], l);
				if (!lattice_round(L, l, 0.3, &x, &y))
					continue;
				r[nr++] = fabs(remainder((double)(x * L->ka + y *
				    L->kb) * B[b].alpha_local - l[1] / L->rho,
				    2 * M_PI));
			}
		}
	}
	from[nb] = nr;
	for (size_t b = 0; b < nb; b++) {
		size_t n = from[b + 1] - from[b];

		qsort(r + from[b], n, sizeof(*r), by_double);
		B[b].noise = n >= 20 ? fmax(1.4826 * r[from[b] + n / 2],
		    1e-12) : NAN;
	}
	qsort(r, nr, sizeof(*r), by_double);
	all = nr > 0 ? fmax(1.4826 * r[nr / 2], 1e-12) : HUGE_VAL;
	for (size_t b = 0; b < nb; b++)
		if (isnan(B[b].noise))
			B[b].noise = all;
	free(r);
	free(from);
}

/* Band B into the zones: as parastichy.c joins its runs. */
static void
zone_add(struct unordered *U, const struct band *B,
    const struct axis_point *ap, const size_t *order)
{
	struct uzone *z = U->nzones > 0 ? &U->zone[U->nzones - 1] : NULL;
	size_t first = order[B->from];
	double end = ap[order[B->to - 1]].s;

	if (z != NULL && B->kind == UZ_PAIR && z->kind == UZ_TRANSITION &&
	    z->nseen == 1 && z->seen[0][0] == B->m && z->seen[0][1] == B->n) {
		/* A transition of one pair at the ends is that pair's. */
		z->kind = UZ_PAIR;
		z->m = B->m;
		z->n = B->n;
		z->nseen = 0;
	}
	if (z != NULL && ((B->kind == UZ_PAIR || B->kind == UZ_TRANSITION) &&
	    z->kind == UZ_PAIR ? z->m == B->m && z->n == B->n :
	    z->kind == B->kind && B->kind != UZ_PAIR)) {
		z->organs += B->organs;
		z->s_end = end;
		z->agree += z->kind == UZ_PAIR ? B->held : 0;
		z->cut |= B->lattice && B->L.coverage < 0.97;
		if (z->kind == UZ_TRANSITION) {
			int k = 0;

			while (k < z->nseen && (z->seen[k][0] != B->m ||
			    z->seen[k][1] != B->n))
				k++;
			if (k == z->nseen && k < UZ_SEEN) {
				z->seen[k][0] = B->m;
				z->seen[k][1] = B->n;
				z->nseen++;
			}
		}
		return;
	}
	if (U->nzones == UZONES_MAX)
		return;
	z = &U->zone[U->nzones++];
	*z = (struct uzone){ .kind = B->kind, .from = first,
	    .s = ap[first].s, .s_end = end, .rho = ap[first].rho,
	    .z = ap[first].p[2],
	    .organs = B->organs, .cut = B->lattice &&
	    B->L.coverage < 0.97 };
	if (B->kind == UZ_PAIR) {
		z->m = B->m;
		z->n = B->n;
		z->agree = B->held;
	} else if (B->kind == UZ_TRANSITION) {
		z->seen[0][0] = B->m;
		z->seen[0][1] = B->n;
		z->nseen = 1;
	}
}

/* The larger number a zone names: its pair's, or its transition's. */
static int
zone_n(const struct uzone *z)
{
	int n = z->n;

	for (int k = 0; k < z->nseen; k++)
		if (z->seen[k][1] > n)
			n = z->seen[k][1];
	return n;
}

/*
 * The oldest organs (at the rim or base if older_out, else at the tip)
 * have too few earlier ones to show their true contacts: zones there
 * holding fewer than about 1.5 n organs of the next zone's pair are
 * their artefact, as parastichy.c drops them.
 */
static void
boundary(struct unordered *U, int older_out)
{
	size_t gone = 0;

	while (U->nzones > 1) {
		size_t end = older_out ? U->nzones - 1 : 0;
		size_t in = older_out ? end - 1 : 1;

		gone += U->zone[end].organs;
		if ((double)gone > 1.5 * zone_n(&U->zone[in]))
			break;
		if (!older_out)
			memmove(U->zone, U->zone + 1, (U->nzones - 1) *
			    sizeof(*U->zone));
		U->nzones--;
	}
}

/*
 * A pair is clear where most of its zone's organs hold it, by more than
 * chance would give a few of them (half, and one and a half standard
 * deviations of a count of coin tosses: 7 of 13 organs are no clearer
 * than a toss, 10 of 13 are); not one of a zone between two others of
 * fewer organs than its smaller number, a wisp of a ring (at either
 * end, where the rings run out, a zone may be less than a ring).  What
 * is not clear is a transition, and transitions side by side are one:
 * under a click's jitter a rim where two pairs meet flickers between
 * them, ring by ring, and says so once.
 */
static void
clear_pairs(struct unordered *U)
{
	size_t k, j;

	for (k = 0; k < U->nzones; k++) {
		struct uzone *z = &U->zone[k];

		if (z->kind != UZ_PAIR || ((double)z->agree >= 0.5 *
		    (double)z->organs + 0.75 * sqrt((double)z->organs) &&
		    !(k > 0 && k + 1 < U->nzones && z->organs < (size_t)z->m)))
			continue;
		z->kind = UZ_TRANSITION;
		z->seen[0][0] = z->m;
		z->seen[0][1] = z->n;
		z->nseen = 1;
		z->m = z->n = 0;
	}
	for (k = 0, j = 0; k < U->nzones; k++) {
		struct uzone *z = &U->zone[k], *w = j > 0 ? &U->zone[j - 1] :
		    NULL;

		if (w == NULL || z->kind == UZ_PAIR || w->kind == UZ_PAIR) {
			U->zone[j++] = *z;
			continue;
		}
		w->kind = UZ_TRANSITION;
		w->organs += z->organs;
		w->s_end = z->s_end;
		w->cut |= z->cut;
		for (int q = 0; q < z->nseen; q++) {
			int r = 0;

			while (r < w->nseen && (w->seen[r][0] != z->seen[q][0] ||
			    w->seen[r][1] != z->seen[q][1]))
				r++;
			if (r == w->nseen && r < UZ_SEEN) {
				memcpy(w->seen[r], z->seen[q], sizeof(w->seen[r]));
				w->nseen++;
			}
		}
	}
	U->nzones = j;
}

/* The divergence over the bands: weighted, its error widened by scatter. */
static int
alpha_of(const struct band *B, int whole)
{
	return B->kind == UZ_PAIR && !isnan(B->alpha) && (!whole ||
	    B->L.coverage > 0.97);
}

static void
divergence(struct unordered *U, const struct band *B, size_t nb)
{
	double sw = 0, mean = 0, chi = 0, ref = NAN;
	int used = 0, whole = 0;

	/*
	 * Whole rings' bands if two at least: on a ring the photograph
	 * cut, a centre a little off turns the lattice one way more than
	 * the other, where round a whole ring it cancels.
	 */
	for (size_t b = 0; b < nb; b++)
		whole += alpha_of(&B[b], 1);
	whole = whole >= 2;
	for (size_t b = 0; b < nb; b++) {
		double w, a;

		if (!alpha_of(&B[b], whole))
			continue;
		w = 1 / (B[b].alpha_sigma * B[b].alpha_sigma);
		if (isnan(ref))
			ref = B[b].alpha;
		a = ref + remainder(B[b].alpha - ref, 2 * M_PI);
		mean += w * a;
		sw += w;
		used++;
	}
	if (used == 0)
		return;
	mean /= sw;
	for (size_t b = 0; b < nb; b++)
		if (alpha_of(&B[b], whole)) {
			double d = remainder(B[b].alpha - mean, 2 * M_PI);

			chi += d * d / (B[b].alpha_sigma * B[b].alpha_sigma);
		}
	U->divergence = fmod(mean * 180 / M_PI + 720, 360);
	U->divergence_err = 180 / M_PI / sqrt(sw) *
	    (used > 1 && chi / (used - 1) > 1 ? sqrt(chi / (used - 1)) : 1);
	U->divergence_bands = used;
	/*
	 * What the bands share their errors do not show (a centre a
	 * little off, a squash a little wrong, bear on every band alike,
	 * more on the inner): half the difference of the inner and outer
	 * halves' means, if larger.
	 */
	if (used >= 4) {
		double m[2] = { 0, 0 }, w[2] = { 0, 0 };
		int seen = 0;

		for (size_t b = 0; b < nb; b++) {
			double wb, a;
			int half;

			if (!alpha_of(&B[b], whole))
				continue;
			half = 2 * seen++ >= used;
			wb = 1 / (B[b].alpha_sigma * B[b].alpha_sigma);
			a = mean + remainder(B[b].alpha - mean, 2 * M_PI);
			m[half] += wb * a;
			w[half] += wb;
		}
		U->divergence_err = fmax(U->divergence_err, 180 / M_PI *
		    fabs(m[0] / w[0] - m[1] / w[1]) / 2);
	}
}

/* Mean and its standard error of v[0 .. n). */
static void
mean_err(const double *v, size_t n, double *mean, double *err)
{
	double s = 0, ss = 0;

	for (size_t i = 0; i < n; i++)
		s += v[i];
	*mean = n ? s / (double)n : NAN;
	for (size_t i = 0; i < n; i++)
		ss += (v[i] - *mean) * (v[i] - *mean);
	*err = n > 1 ? sqrt(ss / (double)(n - 1) / (double)n) : NAN;
}

/*
 * The area per organ, band by band: Vogel's c = sqrt(area / pi) on a
 * head (his exponent 1/2), the exponent from how the area grows with
 * the radius (area ~ rho^(2 - 1/e)), and the rise area / (2 pi rho).
 */
static void
spacing(struct unordered *U, const struct band *B, size_t nb)
{
	double *c = xcalloc(nb + 1, sizeof(*c)), *h = xcalloc(nb + 1,
	    sizeof(*h)), *d = xcalloc(nb + 1, sizeof(*d));
	double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
	size_t n = 0;

	for (size_t b = 0; b < nb; b++) {
		const struct band_lattice *L = &B[b].L;
		double area;

		if (!B[b].lattice || B[b].kind == UZ_UNCLEAR)
			continue;
		area = fabs(L->a[0] * L->b[1] - L->a[1] * L->b[0]);
		c[n] = sqrt(area / M_PI);
		h[n] = area / (2 * M_PI * L->rho);
		d[n] = hypot(L->a[0], L->a[1]);
		sx += log(L->rho);
		sy += log(area);
		sxx += log(L->rho) * log(L->rho);
		sxy += log(L->rho) * log(area);
		syy += log(area) * log(area);
		n++;
	}
	if (n > 0) {
		double e;

		mean_err(h, n, &U->rise, &U->rise_err);
		qsort(d, n, sizeof(*d), by_double);
		U->contact = d[n / 2];
		if (!U->surface)
			mean_err(c, n, &U->vogel_c, &U->vogel_c_err);
		if (!U->surface && n > 2 && n * sxx - sx * sx > 0) {
			double k = (double)n, beta = (k * sxy - sx * sy) /
			    (k * sxx - sx * sx), alpha0 = (sy - beta * sx) / k;
			double res = (syy - 2 * alpha0 * sy - 2 * beta * sxy +
			    alpha0 * alpha0 * k + 2 * alpha0 * beta * sx +
			    beta * beta * sxx) / (k - 2);
			double sb = sqrt(fmax(res, 0) * k / (k * sxx - sx * sx));

			e = 1 / (2 - beta);
			U->exponent = e;
			U->exponent_err = sb * e * e;
		}
	}
	free(c);
	free(h);
	free(d);
}

/*
 * Each point's area per organ, for the band's scale: its nearest
 * neighbour's distance squared (the lattice's shape being near one
 * everywhere), averaged over the points nearest it along the curve.
 */
static void
areas(const struct point_field *F, double *area)
{
	double *d2 = xcalloc(F->n, sizeof(*d2)), sum = 0;
	size_t n = F->n, lo = 0, hi = 0;

	for (size_t k = 0; k < n; k++) {
		size_t i = F->order[k];
		const double *p = F->ap[i].p, *q;

		q = F->nnn[i] > 0 ? F->ap[F->nn[i][0]].p : p;
		d2[k] = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) *
		    (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
	}
	/* A running mean over [k - SMOOTH, k + SMOOTH]. */
	for (size_t k = 0; k < n; k++) {
		size_t want_lo = k > SMOOTH ? k - SMOOTH : 0;
		size_t want_hi = k + SMOOTH + 1 < n ? k + SMOOTH + 1 : n;

		while (hi < want_hi)
			sum += d2[hi++];
		while (lo < want_lo)
			sum -= d2[lo++];
		area[F->order[k]] = fmax(sum / (double)(hi - lo), 1e-300);
	}
	free(d2);
}

struct unordered *
unordered_measure(const struct axis *A, const struct axis_point *ap,
    const double (*raw)[3], size_t n, int older_out)
{
	struct unordered *U = unordered_new(A, n);
	struct point_field F = { A, ap, n, NULL, NULL, NULL, NULL, NULL, NULL,
	    NULL };
	double (*p)[3], *s, *area;
	uint32_t (*nn)[KD_K];
	uint8_t *nnn;
	size_t *order, *pts, nb;
	struct band *B;
	struct kd T;

	for (size_t i = 0; i < n; i++)
		U->c[i].s = ap[i].s;
	if (n < 10)
		return U;
	p = xcalloc(n, sizeof(*p));
	for (size_t i = 0; i < n; i++)
		memcpy(p[i], ap[i].p, sizeof(p[i]));
	kd_init_points(&T, (const double (*)[3])p, n);
	free(p);
	/*
	 * Neighbours as near as they are: on a head the view's squash
	 * undone, on a surface as scanned (its sections may be ellipses
	 * of the thing itself, which the unrolling only straightens).
	 */
	{
		struct kd W;
		const struct kd *by = &T;

		if (A->surface && raw != NULL) {
			kd_init_points(&W, raw, n);
			by = &W;
		}
		nn = xcalloc(n, sizeof(*nn));
		nnn = xcalloc(n, sizeof(*nnn));
		for (size_t i = 0; i < n; i++) {
			struct kd_near nb8;

			kd_nearest(by, by == &T ? ap[i].p : raw[i], i, 0, &nb8);
			for (int k = 0; k < nb8.n; k++)
				nn[i][k] = (uint32_t)nb8.j[k];
			nnn[i] = (uint8_t)nb8.n;
		}
		if (by != &T)
			kd_free(&W);
	}
	order = xcalloc(n, sizeof(*order));
	s = xcalloc(n, sizeof(*s));
	for (size_t i = 0; i < n; i++) {
		order[i] = i;
		s[i] = ap[i].s;
	}
	sort_key = s;
	qsort(order, n, sizeof(*order), by_key);
	sort_key = NULL;
	for (size_t k = 0; k < n; k++)
		s[k] = ap[order[k]].s;
	area = xcalloc(n, sizeof(*area));
	F.nn = (const uint32_t (*)[KD_K])nn;
	F.nnn = nnn;
	F.T = &T;
	F.order = order;
	F.sorted_s = s;
	F.claim = xcalloc(n, sizeof(*F.claim));
	for (size_t i = 0; i < n; i++)
		F.claim[i] = -1;
	areas(&F, area);
	F.area = area;
	nb = n / BAND_MIN < 1 ? 1 : n / BAND_MIN > BANDS_MAX ? BANDS_MAX :
	    n / BAND_MIN;
	B = xcalloc(nb, sizeof(*B));
	pts = xcalloc(n, sizeof(*pts));
	for (size_t b = 0; b < nb; b++) {
		struct band *bd = &B[b];
		size_t np = 0, lo, hi;

		bd->from = n * b / nb;
		bd->to = n * (b + 1) / nb;
		bd->organs = bd->to - bd->from;
		bd->kind = UZ_UNCLEAR;
		bd->alpha = NAN;
		/*
		 * The lattice about the band, half as much again either side
		 * and BASIS_MIN points at least: a band at the rim holds the
		 * last ring's organs, whose steps go inward and along it only.
		 */
		lo = bd->from > bd->organs / 2 ? bd->from - bd->organs / 2 : 0;
		hi = bd->to + bd->organs / 2 < n ? bd->to + bd->organs / 2 : n;
		while (hi - lo < BASIS_MIN && (lo > 0 || hi < n)) {
			lo -= lo > 0;
			hi += hi < n;
		}
		/*
		 * Near the axis the unrolled steps mean nothing; of a large
		 * band, BASIS_MAX points are as good as all.
		 */
		for (size_t k = lo; k < hi; k += 1 + (hi - lo) / BASIS_MAX)
			if (ap[order[k]].rho > 0.25 * A->spacing)
				pts[np++] = order[k];
		if (np < 8 || lattice_basis(&F, pts, np, &bd->L) != 0)
			continue;
		bd->basis = 1;
		/*
		 * Counting reads a few rings of organs: COUNTED_MAX bands
		 * count, spread out; the others are labelled by the angle.
		 */
		if (lattice_count(&F, &bd->L, nb <= COUNTED_MAX || b %
		    ((nb + COUNTED_MAX - 1) / COUNTED_MAX) == 0) != 0)
			continue;
		bd->lattice = 1;
		if (bd->L.counted && band_alpha(bd) == 0)
			U->counted++;
	}
	label(B, nb);
	local_alpha(B, nb);
	turn_noise(&F, B, nb);
	for (size_t b = 0; b < nb; b++) {
		struct band *bd = &B[b];
		size_t np = 0;

		if (!bd->basis || (bd->L.ka == 0 && isnan(bd->alpha_local)))
			continue;
		for (size_t k = bd->from; k < bd->to; k++)
			if (ap[order[k]].rho > 0.25 * A->spacing)
				pts[np++] = order[k];
		band_pairs(&F, bd, pts, np, older_out, bd->noise, U);
	}
	for (size_t b = 0; b < nb; b++)
		zone_add(U, &B[b], ap, order);
	boundary(U, older_out);
	clear_pairs(U);
	divergence(U, B, nb);
	/* Counted the other way, the spiral turns back. */
	if (older_out && !isnan(U->divergence))
		U->divergence = fmod(360 - U->divergence, 360);
	U->older_out = older_out;
	spacing(U, B, nb);
	free(pts);
	free(B);
	free(area);
	free(s);
	free(order);
	free(F.claim);
	free(nn);
	free(nnn);
	kd_free(&T);
	return U;
}

struct unordered *
unordered_of_result(const struct result *r)
{
	double (*p)[3] = xcalloc(r->count ? r->count : 1, sizeof(*p));
	struct axis_point *ap = xcalloc(r->count ? r->count : 1, sizeof(*ap));
	struct unordered *U;
	struct axis A;
	int has_z = 0;

	for (size_t i = 0; i < r->count; i++) {
		memcpy(p[i], r->organs[i].pos, sizeof(p[i]));
		has_z |= p[i][2] != p[0][2];
	}
	axis_find(&A, (const double (*)[3])p, r->count, has_z, NULL);
	axis_points(&A, (const double (*)[3])p, r->count, ap);
	U = unordered_measure(&A, ap, (const double (*)[3])p, r->count,
	    !r->rim_last);
	axis_free(&A);
	free(ap);
	free(p);
	return U;
}

size_t
unordered_para_zones(const struct unordered *U, struct para_zone *z,
    size_t zmax)
{
	size_t nz = 0;

	for (size_t k = 0; k < U->nzones && nz < zmax; k++) {
		const struct uzone *u = &U->zone[k];

		/* An unclear zone as a transition that saw nothing. */
		z[nz] = (struct para_zone){ .from = (long long)u->from,
		    .m = u->kind == UZ_PAIR ? u->m : 0,
		    .n = u->kind == UZ_PAIR ? u->n : 0, .rho = u->rho,
		    .z = u->z };
		for (int s = 0; s < u->nseen && s < PARA_SEEN; s++) {
			z[nz].seen[s][0] = u->seen[s][0];
			z[nz].seen[s][1] = u->seen[s][1];
			z[nz].nseen = s + 1;
		}
		nz++;
	}
	return nz;
}

const struct uzone *
unordered_rim(const struct unordered *U)
{
	return U->nzones > 0 ? &U->zone[U->nzones - 1] : NULL;
}
