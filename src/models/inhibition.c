/*
 * inhibition.c - the divergence angle emerges (seed 003; Douady and
 * Couder 1996): primordia are born on the meristem's edge, a circle of
 * radius R0, and move outward, r -> r e^G each plastochron; each new
 * one appears where the ones already there inhibit least.
 *
 * Kernels: Douady and Couder's power law, E(th) = sum 1/d^s over the
 * distances d from the edge point at th to every primordium; and seed
 * 003's parameter-free Gaussian sum in the angle alone, each primordium
 * a bell exp(-(th - phi)^2) weighted by 1/age, so the newest counts
 * most.  Primordium 0 is at angle 0, primordium 1 opposite; the rest
 * find their angle to 1e-9 rad: the circle is cut at the recent
 * primordia's angles, lower bounds of E rule out most gaps, and Newton
 * on E' searches the rest (inhibition_min.c): the least of all minima.
 *
 * With the power law, the primordia beyond a radius far_r are summed
 * as a Fourier series whose moments each plastochron rescales, so a
 * step costs the same however many came before.  The Gaussian kernel
 * weighs every primordium by 1/age, which changes every step: its
 * series' weights are sums of exponentials that a step multiplies
 * (inhibition_gauss.c), and each evaluation of E is then a few terms.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "analysis/parastichy.h"
#include "base/diag.h"
#include "geometry/geometry.h"
#include "base/mem.h"
#include "models/inhibition.h"
#include "models/inhibition_impl.h"
#include "models/model.h"

enum { IN_GROWTH, IN_START, IN_TRANSIENT, IN_KERNEL, IN_EXPONENT, IN_RADII,
	IN_OUTER, IN_DOME, IN__N };
enum { K_POWER, K_GAUSSIAN };
enum { RADII_GROWN, RADII_VOGEL };

struct inhibition {
	struct group_at	 at;
	int		 given[IN__N];
	struct expr_setting growth;	/* G_n: ln of r's growth before n */
	double		 start;		/* G of the young meristem */
	double		 transient;	/* primordia over which it fades */
	int		 kernel;	/* K_* */
	double		 exponent;	/* s of the power law */
	int		 radii;		/* RADII_*: how the output is laid out */
	double		 outer;		/* rescale: the oldest sits here */
	double		 dome;		/* height of the centre over the rim */
};

/*
 * The default transient, in primordia, where G is at least TRANSIENT_G;
 * slower growth passes more bifurcations on its way down and needs a
 * longer one (transient_for()).
 */
#define TRANSIENT	30
#define TRANSIENT_G	0.003

static const char *const kernel_names[] = { "power", "gaussian", NULL };
static const char *const radii_names[] = { "grown", "vogel", NULL };

#define I(f)	offsetof(struct inhibition, f)

static const struct row inhibition_rows[] = {
	[IN_GROWTH] = { .name = "growth", .type = T_EXPR, .off = I(growth),
	  .defstr = "0.02",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .doc = "G: radial growth a plastochron over the meristem radius" },
	[IN_START] = { .name = "start", .type = T_FLOAT, .off = I(start),
	  .lo = 0, .hi = 100, .flags = F_LO_OPEN, .def = 2, .defstr = "2",
	  .doc = "G of the young meristem, fading to growth" },
	[IN_TRANSIENT] = { .name = "transient", .type = T_FLOAT,
	  .off = I(transient), .lo = 0, .hi = HUGE_VAL, .def = TRANSIENT,
	  .defstr = "30, longer below G = 0.003", .unit = "primordia",
	  .doc = "primordia over which start fades; 0: none" },
	[IN_KERNEL] = { .name = "kernel", .type = T_CHOICE, .off = I(kernel),
	  .words = kernel_names, .defstr = "power",
	  .doc = "the inhibition: power (1/d^s) or gaussian (bells in the "
	  "angle, each by 1/age)" },
	[IN_EXPONENT] = { .name = "exponent", .type = T_FLOAT,
	  .off = I(exponent), .lo = 0, .hi = 64, .flags = F_LO_OPEN, .def = 3,
	  .defstr = "3", .doc = "s of the power law" },
	[IN_RADII] = { .name = "radii", .type = T_CHOICE, .off = I(radii),
	  .words = radii_names, .def = RADII_VOGEL, .defstr = "vogel",
	  .doc = "vogel: c sqrt(age); grown: where the growth took them" },
	[IN_OUTER] = { .name = "outer", .type = T_FLOAT, .off = I(outer),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .def = 1,
	  .defstr = "1 (vogel), none (grown)",
	  .unit = "length",
	  .doc = "radius of the oldest primordium; the head is scaled to it" },
	[IN_DOME] = { .name = "dome", .type = T_FLOAT, .off = I(dome),
	  .lo = -HUGE_VAL, .hi = HUGE_VAL, .defstr = "0",
	  .unit = "length",
	  .doc = "height of the centre above the rim (paraboloid)" },
};

static const struct table inhibition_table = TABLE(inhibition_rows,
    struct inhibition);

#define AGE_MAX		700	/* e^700: the largest radius a double holds */
#define GROWTH_MIN	0.0005	/* the slowest growth searched surely */

/* Room for n entries in v, one block. */
void
inhib_cutv_alloc(struct cutv *v, size_t n)
{
	v->c = xcalloc(5 * (n > 0 ? n : 1), sizeof(*v->c));
	v->s = v->c + n;
	v->q0 = v->s + n;
	v->r2 = v->q0 + n;
	v->fl = v->r2 + n;
}

void
inhib_cutv_free(struct cutv *v)
{
	free(v->c);
}

static void
field_add(struct field *F, double th)
{
	F->phi[F->n] = th;
	F->c[F->n] = cos(th);
	F->s[F->n] = sin(th);
	if (F->gt != NULL) {	/* the Gaussian's cos and sin (m th) */
		double *t = inhib_gauss_row(F, F->n);

		t[0] = 1;
		t[1] = 0;
		for (int m = 1; m <= GMODES; m++) {
			t[2 * m] = t[2 * m - 2] * F->c[F->n] - t[2 * m - 1] *
			    F->s[F->n];
			t[2 * m + 1] = t[2 * m - 1] * F->c[F->n] + t[2 * m - 2] *
			    F->s[F->n];
		}
	}
	F->n++;
}

/*
 * Each organ's radius: half the distance to its nearest neighbour, so
 * the discs touch as the primordia did.  Found in space (a k-d tree),
 * not among the organs near in index: laid out at Vogel's radii the
 * first primordia's neighbours may be many parastichy numbers apart.
 */
static void
contact_radii(struct result *res)
{
	double *d = xcalloc(res->count ? res->count : 1, sizeof(*d));

	para_nearest(res, d);
	for (size_t i = 0; i < res->count; i++) {
		struct organ *o = &res->organs[i];

		o->radius = isfinite(d[i]) ? d[i] / 2 : 1;
		o->scale = o->radius;
	}
	free(d);
}

/* How many recent primordia cut the circle at growth G: 3 sqrt(2 pi / G). */
static size_t
near_count(double G)
{
	double k = ceil(3 * sqrt(2 * M_PI / G));

	return k < 12 ? 12 : (size_t)k;
}

/*
 * The settled divergence: the mean and spread of the last two thirds.
 * The spread from the deviations, in a second pass: the mean square
 * less the squared mean loses eight of its sixteen digits to a spread
 * 10^4 times smaller than the mean (0.0133 of 137.5 degrees), and so
 * printed in its ninth digit the last bit of the angles (another C
 * library's sin(): the Windows program's).
 */
static double
step_deg(const double *phi, size_t i)
{
	return fabs(remainder(phi[i] - phi[i - 1], 2 * M_PI)) * (180 / M_PI);
}

static void
settled(const double *phi, size_t n, double *mean, double *spread)
{
	size_t from = n / 3 > 0 ? n / 3 : 1, k = n > from ? n - from : 0;
	double sum = 0, dev = 0;

	for (size_t i = from; i < n; i++)
		sum += step_deg(phi, i);
	*mean = k > 0 ? sum / (double)k : 0;
	for (size_t i = from; i < n; i++)
		dev += (step_deg(phi, i) - *mean) * (step_deg(phi, i) - *mean);
	*spread = k > 1 ? sqrt(dev / (double)k) : 0;
}

/*
 * The contact pair at the meristem when the last primordium is born:
 * the newest primordia where the growth put them, each one's nearest
 * older neighbours turning either way (para_pairs(), as --info measures
 * any structure), the pair most of the newest half hold; 0 0 where none
 * does (alternate leaves).  Whatever the layout written: it is the
 * pattern the model made, and names its branch.
 */
static void
meristem_pair(const double *phi, const double *S, size_t N, size_t near,
    int *m, int *n)
{
	size_t K = 2 * near + 32 < N ? 2 * near + 32 : N, best = 0;
	struct result tmp;
	int (*pair)[2];

	*m = *n = 0;
	if (K < 3)
		return;
	result_init(&tmp, K);
	for (size_t k = 0; k < K; k++) {
		size_t i = N - K + k;
		double r = R0 * exp(S[N - 1] - S[i]);

		tmp.organs[k].pos[0] = r * cos(phi[i]);
		tmp.organs[k].pos[1] = r * sin(phi[i]);
	}
	pair = xcalloc(K, sizeof(*pair));
	para_pairs(&tmp, pair);
	/* The most common among the newest half; few, so counted plainly. */
	for (size_t a = K / 2; a < K; a++) {
		size_t held = 0;

		if (pair[a][0] == 0)
			continue;
		for (size_t b = K / 2; b < K; b++)
			held += pair[b][0] == pair[a][0] &&
			    pair[b][1] == pair[a][1];
		if (held > best) {
			best = held;
			*m = pair[a][0];
			*n = pair[a][1];
		}
	}
	free(pair);
	result_free(&tmp);
}

/*
 * Whether m < n are neighbours in the series a, b, a + b, ..., or one
 * apart (m and the one after next, as at a triple contact between two
 * pairs, 5/13 between 5/8 and 8/13): 1; neighbours are 2.
 */
static int
in_series(int a, int b, int m, int n)
{
	int x = a, y = b;

	while (x < m && y < 1 << 29) {
		int z = x + y;

		x = y;
		y = z;
	}
	if (x != m)
		return 0;
	return y == n ? 2 : x + y == n ? 1 : 0;
}

/*
 * The branch a run followed, from what is sure of it: one divergence
 * (a spread of a few degrees at most over the last two thirds, as a
 * spiral settling; multijugate and disordered patterns have tens), and
 * the contact pair at the meristem, which the angle alone does not give
 * at fast growth (140.4 degrees at G = 0.2 is the Fibonacci branch's,
 * with 2/3; 101.2 the Lucas branch's, with 3/4).  A pair of both
 * series' numbers one apart (1/3) is the Lucas pair it neighbours.
 */
#define SPREAD_MAX	10	/* degrees: more, and no one divergence */

static const char *
regime(size_t N, double mean, double spread, int m, int n)
{
	int fib = in_series(1, 2, m, n), luc = in_series(1, 3, m, n);

	if (N < 2)
		return "none, one primordium";
	if (spread > SPREAD_MAX)
		return "none, no one divergence (spread over 10 degrees)";
	if (mean > 179.5 && m == 0)
		return "distichous";
	if (fib == 2 || (fib == 1 && luc != 2))
		return "fibonacci";
	if (luc > 0)
		return "lucas";
	return "other";
}

/*
 * The default transient for the slowest growth G of a run.  Each
 * bifurcation on the way down to G needs its own primordia to settle,
 * and there are more of them the slower the growth: measured, the
 * shortest transient that still reaches the Fibonacci branch is 30 at
 * G = 0.0015, 40 at 0.001, 50 at 0.0007 and 60 at 0.0005, about
 * G^-0.6; this gives half as much again, 30 (0.003 / G)^0.6.
 */
static double
transient_for(double G)
{
	return G >= TRANSIENT_G ? TRANSIENT :
	    TRANSIENT * pow(TRANSIENT_G / G, 0.6);
}

/*
 * The growth of primordia 1 .. N - 1 summed as start fades into it, the
 * oldest's radius being e^ of it, with every G_n (g[1 .. N], as given)
 * times k, a transient T (or, where T < 0, the default for the least G
 * of all N, as the run takes it).  Only for the advice of sum_check():
 * past 40 T the fade is below a double's last digit and not computed.
 */
static double
faded_sum(const double *g, size_t N, double start, double T, double k)
{
	double s = 0;

	if (T < 0) {
		double gmin = HUGE_VAL;

		for (size_t n = 1; n <= N; n++)
			gmin = fmin(gmin, k * g[n]);
		T = transient_for(gmin);
	}
	for (size_t n = 1; n < N; n++) {
		double x = k * g[n];

		if (T > 0 && (double)n < 40 * T)
			x *= pow(start / x, exp(-(double)n / T));
		s += x;
	}
	return s;
}

/* x rounded down to 3 significant digits, so that it is on the safe side. */
static double
down3(double x)
{
	double unit;

	if (!(x > 0))
		return 0;
	unit = pow(10, floor(log10(x)) - 2);
	return floor(x / unit * (1 + 1e-12)) * unit;
}

/*
 * The largest v in [lo, hi] (hi failing) whose sum stays within
 * AGE_MAX, v standing for what by says; to 1e-4 of it, as the advice
 * prints 3 digits.
 */
enum { BY_GROWTH, BY_TRANSIENT, BY_START };

static double
largest_within(const double *g, size_t N, double start, double T, int by,
    double lo, double hi)
{
	while (hi - lo > 1e-4 * hi) {
		double v = by == BY_TRANSIENT ? (lo + hi) / 2 : sqrt(lo * hi);
		double sum = by == BY_GROWTH ? faded_sum(g, N, start, T, v) :
		    by == BY_TRANSIENT ? faded_sum(g, N, start, v, 1) :
		    faded_sum(g, N, v, T, 1);

		if (sum <= AGE_MAX)
			lo = v;
		else
			hi = v;
	}
	return lo;
}

/*
 * The growth summed over the run, start fading into it, must stay
 * within AGE_MAX: e^700 is about the largest radius a double holds.
 * Past it, say what would do, where the cause is: where start or
 * transient was given and growth alone stays within, at them (the
 * longest transient, the largest start); else at count, which reaches
 * the limit, or at growth if a --set of it came last (the most
 * primordia this growth allows, and for a constant growth the fastest
 * this count allows).  Sums exactly as the run will, S[n] = S[n - 1]
 * + G_n faded, on g[1 .. N - 1] as given.
 */
static int
sum_check(const struct model_ctx *ctx, const struct inhibition *P,
    const double *g, size_t N, double T)
{
	double sum = 0, base = 0, T_arg = P->given[IN_TRANSIENT] ? T : -1;
	size_t most = N;
	int constant = 1, line;
	char advice[200], e[32];

	for (size_t n = 1; n < N; n++) {
		double x = g[n];

		base += x;
		constant &= x == g[1];
		if (T > 0)
			x *= pow(P->start / x, exp(-(double)n / T));
		sum += x;
		if (sum > AGE_MAX && most == N)
			most = n;
	}
	if (!(sum > AGE_MAX))
		return 0;
	/* Digits enough that it reads as past the limit. */
	snprintf(e, sizeof(e), sum >= AGE_MAX + 0.5 ? "%.0f" : "%.3f", sum);
	if (base <= AGE_MAX && (P->given[IN_TRANSIENT] ||
	    P->given[IN_START])) {
		double smax = largest_within(g, N, P->start, T_arg, BY_START,
		    g[1] * 1e-9, P->start);
		int n = 0;

		/*
		 * Past a million times N the transient fades nothing more
		 * that a sum to 1e-4 would see: the search starts there,
		 * not at a given 1e300 (a thousand halvings of O(N) each).
		 */
		if (P->given[IN_TRANSIENT]) {
			double hi = fmin(T, 1e6 * (double)N);

			n = snprintf(advice, sizeof(advice), "transient at most "
			    "%g, ", down3(faded_sum(g, N, P->start, hi, 1) <=
			    AGE_MAX ? hi : largest_within(g, N, P->start, T,
			    BY_TRANSIENT, 0, hi)));
		}
		/* Fewer primordia only where that leaves each G_n as it is. */
		if (constant)
			snprintf(advice + n, sizeof(advice) - (size_t)n, "start "
			    "at most %g, or at most %zu primordia", down3(smax),
			    most);
		else
			snprintf(advice + n, sizeof(advice) - (size_t)n, "start "
			    "at most %g", down3(smax));
		line = P->given[IN_TRANSIENT] ? P->given[IN_TRANSIENT] :
		    P->given[IN_START];
		model_error(ctx, line, "inhibition.start %.9g fading over %.9g "
		    "primordia adds %.0f to the growth's %.0f over %zu "
		    "primordia, past the %d the model holds (the oldest would "
		    "lie e^%s meristem radii out): %s", P->start, T,
		    sum - base, base, N, AGE_MAX, e, advice);
		return -1;
	}
	if (!constant)
		snprintf(advice, sizeof(advice), "it passes %d at primordium "
		    "%zu; fewer primordia or slower growth", AGE_MAX, most);
	else if (faded_sum(g, N, P->start, T_arg, GROWTH_MIN / g[1]) >
	    AGE_MAX)
		snprintf(advice, sizeof(advice), "at most %zu primordia at "
		    "this growth (no growth from %g up allows %zu)", most,
		    GROWTH_MIN, N);
	else
		snprintf(advice, sizeof(advice), "at most %zu primordia at "
		    "this growth, or growth at most %g for %zu", most,
		    down3(g[1] * largest_within(g, N, P->start, T_arg,
		    BY_GROWTH, GROWTH_MIN / g[1], 1)), N);
	if (P->given[IN_GROWTH] >= DIAG_LINE_SET && (ctx->count_line <
	    DIAG_LINE_SET || P->given[IN_GROWTH] > ctx->count_line)) {
		model_error(ctx, P->given[IN_GROWTH], "inhibition.growth adds "
		    "up to %s over %zu primordia, past the %d the model holds "
		    "(the oldest would lie e^%s meristem radii out): %s", e, N,
		    AGE_MAX, e, advice);
		return -1;
	}
	model_error(ctx, ctx->count_line ? ctx->count_line : GIVEN_AT(P,
	    IN_GROWTH), "count %zu is more than inhibition.growth allows: "
	    "it adds up to %s over them, past the %d the model holds (the "
	    "oldest would lie e^%s meristem radii out): %s", N, e, AGE_MAX,
	    e, advice);
	return -1;
}

int
inhibition_place(const struct model_ctx *ctx, struct result *res, int how)
{
	const struct inhibition *P = ctx->params;
	struct field F = { .hs = P->exponent / 2 };
	struct expr_env env = { { 0 }, (uint64_t)ctx->seed, 0 };
	size_t N;
	double mean, spread, flip = 1, rim, scale, gmin, *born, T;
	struct cut *cuts;
	size_t terms = 0;
	struct gap *gaps;
	int pm, pn;

	N = (size_t)ctx->count;
	F.S = xcalloc(N + 1, sizeof(*F.S));
	gmin = HUGE_VAL;
	for (size_t n = 1; n <= N; n++) {
		double g = 0.02;

		expr_env_organ(&env, (long long)n, (long long)N);
		if (P->growth.e != NULL && model_eval(ctx, &P->growth,
		    "inhibition.growth", "primordium", &env, &g) != 0) {
			free(F.S);
			return -1;
		}
		/*
		 * The search is exact at any G (its gaps' lower bounds are
		 * checked in the tests), but below 0.0005 a primordium
		 * looks at more than 330 recent ones and costs as much as a
		 * hundred at the usual G; the tests check down to 0.0005.
		 */
		if (!(g >= GROWTH_MIN) || g > 100) {
			diag(ST_SCENE, ctx->file, P->growth.line, 0,
			    "inhibition.growth is %.9g at primordium %zu; it "
			    "must be between %g and 100", g, n, GROWTH_MIN);
			free(F.S);
			return -1;
		}
		F.S[n] = g;
		gmin = fmin(gmin, g);
	}
	T = P->given[IN_TRANSIENT] ? P->transient : transient_for(gmin);
	if (sum_check(ctx, P, F.S, N, T) != 0) {
		free(F.S);
		return -1;
	}
	/* Now the least G as faded, which sizes the search's arrays. */
	gmin = HUGE_VAL;
	for (size_t n = 1; n <= N; n++) {
		double g = F.S[n];

		/*
		 * A young meristem is small, so it grows fast for its size:
		 * start fades into growth (geometrically, so that every
		 * scale of G gets its share), and the pattern follows the
		 * branch from alternate leaves down to the spirals, as in
		 * Douady and Couder's slowly falling G.  From the symmetric
		 * first two at a fixed small G it may lock into other modes.
		 */
		if (T > 0)
			g *= pow(P->start / g, exp(-(double)n / T));
		F.S[n] = F.S[n - 1] + g;
		gmin = fmin(gmin, g);
	}
	F.phi = xcalloc(N, sizeof(*F.phi));
	F.c = xcalloc(N, sizeof(*F.c));
	F.s = xcalloc(N, sizeof(*F.s));
	F.r = xcalloc(N + 1, sizeof(*F.r));
	born = xcalloc(N, sizeof(*born));
	for (size_t i = 0; i < N; i++)
		born[i] = exp(-F.S[i]);
	F.fl = xcalloc(N + 1, sizeof(*F.fl));
	/* Room for the most gaps any step looks at (near_count()). */
	cuts = xcalloc(near_count(gmin) + 1, sizeof(*cuts));
	gaps = xcalloc(near_count(gmin) + 1, sizeof(*gaps));
	inhib_cutv_alloc(&F.cp, 2 * near_count(gmin) + 2);
	F.cpi = xcalloc(2 * near_count(gmin) + 2, sizeof(*F.cpi));
	F.gpos = xcalloc(near_count(gmin) + 1, sizeof(*F.gpos));
	F.fnear = xcalloc(near_count(gmin) + 1, sizeof(*F.fnear));
	inhib_cutv_alloc(&F.mid, N);
	/*
	 * The far field, but for the power law's reference sum of all
	 * pairs; the Gaussian's is all of it.
	 */
	F.moments = P->kernel == K_GAUSSIAN || !(how & INHIB_ALL_PAIRS);
	F.check = how & INHIB_CHECK_BOUNDS;
	F.nmodes = P->kernel == K_GAUSSIAN ? GMODES : MODES;
	if (P->kernel == K_GAUSSIAN) {
		inhib_gauss_init(&F, N, how & INHIB_ALL_PAIRS);
		/*
		 * Its energy is its modes alone, bounded over a gap from
		 * their values on a grid: one gap in five searched further
		 * at G = 0.02, where the least of the modes on the whole
		 * circle let every gap through to the tiers.
		 */
		inhib_far_grid(&F, GMODES);
	} else if (F.moments)
		inhib_far_init(&F, R0 * exp(gmin * (double)near_count(gmin)));

	for (size_t n = 0; n < N; n++) {
		/*
		 * Enough recent ones that their gaps hold one minimum each,
		 * for the growth of this plastochron: finer gaps than the
		 * field's features would rank the wrong ones.
		 */
		F.near = near_count(n > 0 ? F.S[n] - F.S[n - 1] : F.S[1]);
		if (P->kernel == K_GAUSSIAN)
			inhib_gauss_step(&F);
		else if (F.moments && n > 0)
			inhib_far_step(&F);
		/*
		 * Moved out by the growth of every plastochron since birth,
		 * e^(S[n] - S[i]): a product, not an exp a primordium a step
		 * (S stays under AGE_MAX, e^S in a double's range).
		 */
		if (P->kernel == K_POWER) {
			double grown = R0 * exp(F.S[n]);

			for (size_t k = 0; k < n && (k < n - F.from ||
			    k < F.near); k++)
				F.r[k] = grown * born[n - 1 - k];
		}
		if (n - F.from > terms)
			terms = n - F.from;
		field_add(&F, n == 0 ? 0 : n == 1 ? M_PI : inhib_next_angle(&F,
		    cuts, gaps));
		if (ctx->progress != NULL && n % 16384 == 0 && n > 0)
			ctx->progress((long long)n, 0);
	}
	if (ctx->progress != NULL)
		ctx->progress((long long)N, 1);
	settled(F.phi, N, &mean, &spread);
	/* Turn the spiral counter-clockwise, as a positive divergence does. */
	if (N > 2) {
		double turn = 0;

		for (size_t i = N / 3 > 0 ? N / 3 : 1; i < N; i++)
			turn += remainder(F.phi[i] - F.phi[i - 1], 2 * M_PI);
		if (turn < 0)
			flip = -1;
	}
	/*
	 * Where each one is when the last is born, organ i at R0 e^(S[N-1] -
	 * S[i]); or, laid out as Vogel's, at sqrt(age + 1/2) with the angles
	 * that emerged: the growth's radii span e^(sum of G), too many
	 * orders of magnitude for a picture of a whole head.  Vogel's are
	 * scaled so that the oldest lies at outer (1 unless given), so a
	 * scene with only model and count frames like the planar head;
	 * grown radii keep the meristem's as the unit unless outer is
	 * given (scaled to 1 the newest of e^700 would be too small for
	 * their squares, which the parastichies measure).
	 */
	rim = P->radii == RADII_VOGEL ? sqrt((double)N - 0.5) :
	    R0 * exp(F.S[N - 1] - F.S[0]);
	scale = P->given[IN_OUTER] || P->radii == RADII_VOGEL ?
	    P->outer / rim : 1;
	rim *= scale;

	result_init(res, N);
	res->divergence = mean;
	res->svg = PROJ_TOP;
	for (size_t i = 0; i < N; i++) {
		struct organ *o = &res->organs[i];
		/* The newest is at the edge, the oldest N - 1 plastochrons out. */
		double rho = (P->radii == RADII_VOGEL ?
		    sqrt((double)(N - 1 - i) + 0.5) :
		    R0 * exp(F.S[N - 1] - F.S[i])) * scale;
		double phi = remainder(flip * F.phi[i], 2 * M_PI) * (180 / M_PI);

		if (phi < 0)
			phi += 360;
		frame_dome(o, phi, rho, rim, P->dome);
	}
	contact_radii(res);
	/* Rays only where every angle is the same (alternate leaves). */
	if (spread > 1e-9 || !divergence_rays(mean, N, &res->rays_p,
	    &res->rays))
		res->rays = res->rays_p = 0;
	result_info_labelled(res, "settled", "mean spread", 2, mean, spread);
	meristem_pair(F.phi, F.S, N, F.near, &pm, &pn);
	result_info_text(res, "regime", regime(N, mean, spread, pm, pn));
	/* The pair the growth reached, which the layout may not show. */
	if (pm > 0)
		result_info(res, "parastichies-meristem", 2, (double)pm,
		    (double)pn);
	else
		result_info_text(res, "parastichies-meristem", "none");
	result_info(res, "terms", 1, (double)terms);
	if (F.check)
		result_info(res, "bound misses", 1, (double)F.misses);
	free(F.phi);
	free(F.c);
	free(F.s);
	free(F.S);
	free(F.r);
	free(born);
	free(F.fl);
	inhib_gauss_free(&F);
	free(cuts);
	free(gaps);
	inhib_cutv_free(&F.cp);
	free(F.cpi);
	free(F.gpos);
	free(F.fnear);
	inhib_cutv_free(&F.mid);
	free(F.w);
	free(F.Mc);
	free(F.Ms);
	free(F.gv);
	free(F.gd);
	free(F.tw);
	free(F.rev);
	return 0;
}

static int
inhibition_make(const struct model_ctx *ctx, struct result *res)
{
	return inhibition_place(ctx, res, 0);
}

/* The settings the others leave unused: the loader refuses them given. */
static const char *
inhibition_unused(const void *params, size_t k)
{
	const struct inhibition *P = params;

	if (k == IN_EXPONENT && P->kernel == K_GAUSSIAN)
		return "with inhibition.kernel \"gaussian\", which has "
		    "no exponent";
	if (k == IN_START && P->given[IN_TRANSIENT] && P->transient == 0)
		return "with inhibition.transient 0, which leaves no start "
		    "to fade";
	return NULL;
}

const struct model inhibition_model = {
	.name = "inhibition",
	.help = "Douady & Couder: each primordium where the others inhibit "
	    "least; the angle emerges",
	.settings = &inhibition_table,
	.size = sizeof(struct inhibition),
	.make = inhibition_make,
	.needs_count = 1,
	.emerges = 1,
	.unused = inhibition_unused,
};
