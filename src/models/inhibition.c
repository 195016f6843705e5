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
 * on E' searches the rest (next_angle): the least of all minima.
 *
 * With the power law, the primordia beyond a radius far_r are summed
 * as a Fourier series whose moments each plastochron rescales, so a
 * step costs the same however many came before.  The Gaussian kernel
 * weighs every primordium by 1/age, which changes every step: its
 * series is summed again each step, O(n) a primordium, as in the seed,
 * but each evaluation of E is then a few terms.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/parastichy.h"
#include "diag.h"
#include "geometry/geometry.h"
#include "mem.h"
#include "models/inhibition.h"
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
	  .doc = "the inhibition: power (1/d^s) or gaussian (seed 003)" },
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

#define R0		1.0	/* the meristem's radius: the unit */
#define AGE_MAX		700	/* e^700: the largest radius a double holds */
#define GROWTH_MIN	0.0005	/* the slowest growth searched surely */
#define MODES		80	/* of the power law's far field */
#define FAR_TAIL	1e-12	/* its truncation, of a primordium's pull */
#define GMODES		14	/* of the Gaussian's: e^-(15^2/4) < 1e-24 */

/*
 * A cut's primordium as the bounds want it, if it is a near one (the far
 * field is bounded apart): in the cuts' order.
 */
struct cutp {
	double		 c, s;		/* cos and sin of its angle */
	double		 q0, r2;	/* R0^2 + r^2 and 2 R0 r */
	double		 fl;		/* its floor */
};

/*
 * The primordia so far: angle, its cosine and sine; ages from n.
 *
 * With the power law, the pull of a primordium at radius r on the
 * edge point at angle th is (R0^2 + r^2 - 2 R0 r cos(th - phi))^-(s/2)
 * = r^-s sum_j C_j(cos(th - phi)) x^j, x = R0 / r, with C_j the
 * Gegenbauer polynomials of order s/2 (their generating function), and
 * C_j(cos a) = sum_i w_ji cos((j - 2i) a).  So the primordia beyond
 * radius far_r (x below x_far) add up to sum_m Fc_m cos(m th) + Fs_m
 * sin(m th) over m <= MODES, from the moments sum r^-(s+j) cos(m phi)
 * and sin(m phi); a plastochron's growth multiplies each by
 * e^-(s+j)G.  Each primordium joins the moments once and costs nothing
 * after: near ones are summed one by one, the rest in O(MODES^2) a
 * primordium however many came before.
 *
 * The moments are kept in units that do not move: each as it was at the
 * step whose S is base (times its weight), so a plastochron changes
 * nothing stored, and the modes take the growth since base as a factor
 * per j.  The units are reset (base moved up) before those factors could
 * leave a double's range.
 */
struct field {
	const struct inhibition *P;
	double		*phi, *c, *s;
	size_t		 n;		/* placed */
	double		*S;		/* S[n]: G_1 + ... + G_n */
	double		*r;		/* r[k]: the radius now of the k-th
					   newest, for the near ones */
	size_t		 near;		/* newest that cut the circle */
	size_t		 from;		/* the oldest summed one by one; the
					   older are in the moments */
	int		 moments;	/* 0: every one by one (all pairs) */
	double		 far_r;		/* the radius where they join them */
	double		 hs;		/* s / 2 */
	double		*w;		/* per (m, j): the weight of moment
					   (j, m) in mode m */
	double		*Mc, *Ms;	/* the weighted moments at base */
	double		 base;		/* their units' S */
	size_t		 row[MODES + 2];	/* where m's moments start */
	double		 Fc[MODES + 1], Fs[MODES + 1];	/* the modes */
	int		 nmodes;	/* of the far field: MODES or GMODES */
	double		*gt;		/* Gaussian: per primordium cos and
					   sin (m phi), m <= GMODES */
	double		 far_curv;	/* the far field's E'', at most */
	double		 tail[2];	/* the most its modes past BOUND_MODES
					   add to E and to E' */
	double		 far_least;	/* and its least on the circle */
	int		 check;		/* test every gap's bounds */
	long long	 misses;	/* bounds above their gap's least E */
	double		 floor;		/* the near ones' least pulls, */
	double		*fl;		/* each, indexed as r */
	struct cutp	*cp;		/* the near cuts in order, twice round */
	size_t		*cpi;		/* their primordia */
	size_t		 ncp;		/* how many */
	size_t		*gpos;		/* per gap: the first near cut after
					   its start, in cp */
	struct cutp	*mid;		/* the near ones that are not cuts */
	size_t		 nmid;
	size_t		 ncut, cut_n;	/* how many, and n when they were cut */
};

/*
 * The largest growth factor of a moment's units, e^REBASE, before they
 * are reset: the products with the factors e^-(s+j)(S - base) stay far
 * inside a double's range.
 */
#define REBASE		600

/*
 * The weights, and the far radius: the smallest at which the series
 * cut after MODES leaves out less than FAR_TAIL of what a primordium
 * there pulls at most, sum_j (s)_j / j! x^j = (1 - x)^-s.
 */
static void
far_init(struct field *F)
{
	double lam = F->hs, a[MODES + 1], lo = 0, hi = 1;

	/* Moment (j, m), m <= j, m = j mod 2, at row[m] + (j - m) / 2. */
	F->row[0] = 0;
	for (int m = 0; m <= MODES; m++)
		F->row[m + 1] = F->row[m] + (size_t)(MODES - m) / 2 + 1;
	a[0] = 1;	/* (lam)_i / i! */
	for (int i = 1; i <= MODES; i++)
		a[i] = a[i - 1] * (lam + i - 1) / i;
	F->w = xcalloc(F->row[MODES + 1], sizeof(*F->w));
	for (int j = 0; j <= MODES; j++)
		for (int i = 0; i <= j; i++) {
			int m = abs(j - 2 * i);

			F->w[F->row[m] + (size_t)(j - m) / 2] += a[i] * a[j - i];
		}
	for (int it = 0; it < 60; it++) {
		double x = (lo + hi) / 2, t = 1, tail = 0, s = 2 * lam;

		/*
		 * The terms' ratio (s + j - 1) x / j tends to x, from above
		 * (s > 1) or below, so the rest of the tail is at most t r
		 * / (1 - r), r the larger of the two: once that is under
		 * 1e-17 of the tail the sum stops, rather than summing some
		 * thousands of terms to underflow 60 times over (6 ms, a
		 * fifth of a run of 2,000 at G = 0.3).
		 */
		for (int j = 1; j < MODES + 4000 && t > 0; j++) {
			double ratio = (s + j - 1) / j * x, r = fmax(ratio, x);

			t *= ratio;
			if (j > MODES) {
				tail += t;
				if (r < 1 && t * r < 1e-17 * (1 - r) * tail)
					break;
			}
		}
		if (tail <= FAR_TAIL * pow(1 - x, -s))
			lo = x;
		else
			hi = x;
	}
	F->far_r = R0 / lo;
	F->Mc = xcalloc(F->row[MODES + 1], sizeof(*F->Mc));
	F->Ms = xcalloc(F->row[MODES + 1], sizeof(*F->Ms));
}

/* f[j] = e^-(s+j)t, j <= MODES: a moment's factor for growth t. */
static void
far_factors(const struct field *F, double t, double f[MODES + 1])
{
	double x = exp(-t);

	f[0] = exp(-2 * F->hs * t);
	for (int j = 1; j <= MODES; j++)
		f[j] = f[j - 1] * x;
}

/*
 * The modes the lower bounds evaluate: the others, x_far^m smaller and
 * less, are bounded by their amplitudes.
 */
#define BOUND_MODES	24

/* What bounds the far field: its curvature, its least, its tails. */
static void
far_summary(struct field *F)
{
	F->far_curv = F->tail[0] = F->tail[1] = 0;
	F->far_least = F->Fc[0];
	for (int m = 1; m <= F->nmodes; m++) {
		double a = sqrt(F->Fc[m] * F->Fc[m] + F->Fs[m] * F->Fs[m]);

		F->far_curv += (double)m * m * a;
		F->far_least -= a;
		if (m > BOUND_MODES) {
			F->tail[0] += a;
			F->tail[1] += m * a;
		}
	}
	F->far_least = fmax(0, F->far_least);
}

/*
 * The modes now, S[n]: with the primordia that have moved beyond far_r
 * joining the moments.
 */
static void
far_step(struct field *F)
{
	size_t n = F->n;
	double f[MODES + 1], t = F->S[n] - F->base;

	if ((2 * F->hs + MODES) * t > REBASE) {
		far_factors(F, t, f);
		for (int m = 0; m <= MODES; m++)
			for (size_t k = F->row[m]; k < F->row[m + 1]; k++) {
				F->Mc[k] *= f[m + 2 * (int)(k - F->row[m])];
				F->Ms[k] *= f[m + 2 * (int)(k - F->row[m])];
			}
		F->base = F->S[n];
		t = 0;
	}
	while (F->from < n && R0 * exp(F->S[n] - F->S[F->from]) >= F->far_r) {
		/* Its radius in base's units; u^-(s+j) under e^REBASE. */
		double u = R0 * exp(F->base - F->S[F->from]), iu = 1 / u;
		double pw[MODES + 1], cm[MODES + 1], sm[MODES + 1];
		double c1 = F->c[F->from], s1 = F->s[F->from];

		pw[0] = pow(u, -2 * F->hs);
		cm[0] = 1;
		sm[0] = 0;
		for (int m = 1; m <= MODES; m++) {
			pw[m] = pw[m - 1] * iu;
			cm[m] = cm[m - 1] * c1 - sm[m - 1] * s1;
			sm[m] = sm[m - 1] * c1 + cm[m - 1] * s1;
		}
		for (int m = 0; m <= MODES; m++) {
			const double *w = F->w + F->row[m], *p = pw + m;
			double *mc = F->Mc + F->row[m], *ms = F->Ms + F->row[m];
			size_t len = F->row[m + 1] - F->row[m];

			for (size_t i = 0; i < len; i++) {
				double v = w[i] * p[2 * i];

				mc[i] += v * cm[m];
				ms[i] += v * sm[m];
			}
		}
		F->from++;
	}
	far_factors(F, t, f);
	for (int m = 0; m <= MODES; m++) {
		const double *mc = F->Mc + F->row[m], *ms = F->Ms + F->row[m];
		const double *p = f + m;
		size_t len = F->row[m + 1] - F->row[m];
		double c = 0, s = 0;

		for (size_t i = 0; i < len; i++) {
			c += p[2 * i] * mc[i];
			s += p[2 * i] * ms[i];
		}
		F->Fc[m] = c;
		F->Fs[m] = s;
	}
	far_summary(F);
}

/*
 * The Gaussian kernel's whole energy as a Fourier series: its bells
 * summed over their images are (1 + 2 sum e^-(m^2/4) cos(m x)) / (2
 * sqrt(pi)) (Poisson's summation), which after GMODES terms is exact
 * to far below a double's precision.  The weights 1 / age change every
 * step, so the modes are summed again, O(GMODES n), but each energy is
 * then O(GMODES) instead of three exponentials a primordium.
 */
static void
gauss_step(struct field *F)
{
	for (int m = 0; m <= GMODES; m++)
		F->Fc[m] = F->Fs[m] = 0;
	for (size_t i = 0; i < F->n; i++) {
		const double *t = &F->gt[i * 2 * (GMODES + 1)];
		double w = 1.0 / (double)(F->n - i);	/* 1 / age */

		for (int m = 0; m <= GMODES; m++) {
			F->Fc[m] += w * t[2 * m];
			F->Fs[m] += w * t[2 * m + 1];
		}
	}
	for (int m = 0; m <= GMODES; m++) {
		double a = (m == 0 ? 0.5 : exp(-m * m / 4.0)) / sqrt(M_PI);

		F->Fc[m] *= a;
		F->Fs[m] *= a;
	}
	F->from = F->n;
	far_summary(F);
}

/*
 * The far field's E, E', E'' at th from its first modes, added to e
 * (summed apart: e might alias the modes, for all the compiler knows).
 */
static void
far_energy(const struct field *F, double th, int modes, double e[3])
{
	double c1 = cos(th), s1 = sin(th), cm = 1, sm = 0, e0 = 0, e1 = 0;
	double e2 = 0;

	for (int m = 0; m <= modes; m++) {
		double v = F->Fc[m] * cm + F->Fs[m] * sm;
		double nc;

		e0 += v;
		e1 += m * (F->Fs[m] * cm - F->Fc[m] * sm);
		e2 -= (double)m * m * v;
		nc = cm * c1 - sm * s1;
		sm = sm * c1 + cm * s1;
		cm = nc;
	}
	e[0] += e0;
	e[1] += e1;
	e[2] += e2;
}

/*
 * The power law's pull at squared distance q, q^-(s/2): the common
 * s = 3 and 2 without pow().
 */
static inline double
pull_at(const struct field *F, double q)
{
	return F->hs == 1.5 ? 1 / (q * sqrt(q)) : F->hs == 1 ? 1 / q :
	    pow(q, -F->hs);
}

/*
 * E, E' and E'' at th: each primordium has moved out once more since
 * it was born.
 */
static void
energy(const struct field *F, double th, double e[3])
{
	double ct = cos(th), st = sin(th), e0 = 0, e1 = 0, e2 = 0;
	size_t n = F->n;

	for (size_t i = F->from; i < n; i++) {
		double r = F->r[n - 1 - i];
		/* d^2 = R0^2 + r^2 - 2 R0 r cos(th - phi), and its derivatives. */
		double cd = ct * F->c[i] + st * F->s[i];
		double sd = st * F->c[i] - ct * F->s[i];
		double q = R0 * R0 + r * r - 2 * R0 * r * cd;
		double q1 = 2 * R0 * r * sd, q2 = 2 * R0 * r * cd;
		/* One division for p, p / q and p / q^2 (s = 3: and p). */
		double hs = F->hs, iq = 1 / q, p = hs == 1.5 ? iq * sqrt(iq) :
		    pull_at(F, q), pq = p * iq;

		e0 += p;
		e1 += -hs * pq * q1;
		e2 += hs * pq * ((hs + 1) * iq * q1 * q1 - q2);
	}
	e[0] = e0;
	e[1] = e1;
	e[2] = e2;
	if (F->moments)
		far_energy(F, th, F->nmodes, e);
}

/* E alone at th, summed as energy() sums it. */
static double
energy_only(const struct field *F, double th)
{
	double ct = cos(th), st = sin(th), e[3] = { 0, 0, 0 };
	size_t n = F->n;

	for (size_t i = F->from; i < n; i++) {
		double r = F->r[n - 1 - i];
		double cd = ct * F->c[i] + st * F->s[i];
		double q = R0 * R0 + r * r - 2 * R0 * r * cd, iq = 1 / q;

		e[0] += F->hs == 1.5 ? iq * sqrt(iq) : pull_at(F, q);
	}
	if (F->moments)
		far_energy(F, th, F->nmodes, e);
	return e[0];
}

/*
 * The minimum of E inside [a, b], from x, to 1e-12 rad: Newton on E'
 * where E'' > 0 and its step stays inside the bracket of E''s signs,
 * else the bracket's chord or half; or an end, if that is lower.
 */
static double
minimise(const struct field *F, double a, double b, double x, double *emin)
{
	double e[3], ends[2] = { a, b }, last = 0;	/* Newton's step */
	double d[2] = { 0, 0 };		/* E' at a and b, once known */
	int done = 0, tried[2] = { 0, 0 }, moved, kept = -1;

	for (int it = 0; it < 100 && !done; it++) {
		double nx, step;
		int newton;

		energy(F, x, e);
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
	*emin = done ? e[0] : energy_only(F, x);
	for (int side = 0; side < 2; side++) {
		double ee = energy_only(F, ends[side]);

		if (ee < *emin) {
			*emin = ee;
			x = ends[side];
		}
	}
	return x;
}

/* The circle cut at a primordium's angle: where, which, cos and sin. */
struct cut {
	double		 th;
	size_t		 i;
	double		 c, s;
};

static int
cutcmp(const void *a, const void *b)
{
	double x = ((const struct cut *)a)->th, y = ((const struct cut *)b)->th;

	return x < y ? -1 : x > y;
}

/* Where gap g, from cut g, ends: at the next cut, round the circle. */
static inline double
gap_end(const struct cut *cuts, size_t k, size_t g)
{
	return g + 1 < k ? cuts[g + 1].th : cuts[0].th + 2 * M_PI;
}

/* A part of a gap: its ends and their cosines and sines. */
struct part {
	double		 lo, hi, cl, sl, ch, sh;
};

/*
 * The least cosine of the angle from (c, s) to a point of part p
 * narrower than pi: -1 if the opposite point is inside (the sines
 * say), else at the farther end.  No branch the compiler must keep.
 */
static inline double
least_cos(double c, double s, const struct part *p)
{
	int opp = c * p->sl - s * p->cl >= 0 && s * p->ch - c * p->sh >= 0;
	double a = p->cl * c + p->sl * s, b = p->ch * c + p->sh * s;

	return opp ? -1 : a < b ? a : b;
}

/*
 * The least pull of primordium i anywhere in part p: where the part is
 * farthest from it, or opposite it.  For the power law from the ends'
 * cosines and sines alone: no call to the maths library a primordium.
 */
static double
least_pull(const struct field *F, size_t i, const struct part *p)
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

/* The same as above_floor(), for cut u in a part narrower than pi. */
static inline double
cut_above(const struct field *F, const struct cutp *u, const struct part *p)
{
	return pull_at(F, u->q0 - u->r2 * least_cos(u->c, u->s, p)) - u->fl;
}

/*
 * Whether the near cuts from to to - 1 (in F->cp, in order round the
 * circle) are each less than pi from the far end of the gap: then the
 * ones before the gap pull least at its end, and at every part's high
 * end; the ones after, at its start and the parts' low ends.  The
 * outermost two say it for all.
 */
static int
straight_from(const struct field *F, size_t from, size_t to,
    const struct part *gap)
{
	const struct cutp *l, *r;

	if (!(from < to && gap->hi - gap->lo < M_PI))
		return 0;
	l = &F->cp[from];
	r = &F->cp[to - 1];
	return gap->sh * l->c - gap->ch * l->s > 0 &&	/* sin(b - left) */
	    r->s * gap->cl - r->c * gap->sl > 0;	/* sin(right - a) */
}

/* A near cut's squared distance to the edge point (cx, sx). */
static inline double
cut_q(const struct cutp *u, double cx, double sx)
{
	return u->q0 - u->r2 * (u->c * cx + u->s * sx);
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
	double sum = 0;

	if (F->hs == 1.5) {
		size_t d = from;

		/* Two at once, 1/x + 1/y = (x + y) / xy: one division. */
		for (; d + 1 < to; d += 2) {
			const struct cutp *u = &F->cp[d], *v = u + 1;
			double q = cut_q(u, cx, sx), p = cut_q(v, cx, sx);
			double x = q * sqrt(q), y = p * sqrt(p);

			sum += (x + y) / (x * y) - u->fl - v->fl;
		}
		if (d < to) {
			double q = cut_q(&F->cp[d], cx, sx);

			sum += 1 / (q * sqrt(q)) - F->cp[d].fl;
		}
	} else
		for (size_t d = from; d < to; d++)
			sum += pull_at(F, cut_q(&F->cp[d], cx, sx)) -
			    F->cp[d].fl;
	return sum;
}

/*
 * How much primordium i pulls in part p above its floor, the least it
 * pulls anywhere; 0 for one in the far field, which is bounded apart.
 */
static double
above_floor(const struct field *F, size_t i, const struct part *p)
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
mid_above(const struct field *F, size_t k, const struct part *p)
{
	double sum = 0;

	if (p->hi - p->lo < M_PI)
		for (size_t d = 0; d < F->nmid; d++)
			sum += cut_above(F, &F->mid[d], p);
	else
		for (size_t i = F->from; i + k < F->n; i++)
			sum += above_floor(F, i, p);
	return sum;
}

#define TIERS		4

/*
 * Per tier: how many cuts nearest the gap, 0 for all; in how many parts
 * (chosen by measurement: most gaps go at the first, most of the rest
 * at the second and third); and of those cuts, how many nearest are
 * taken part by part (0: all), the others once over the whole gap: far
 * from the gap a pull hardly changes across it.  The third at 64 cuts
 * in 8 parts, not 48 in 4, spares the last tier enough gaps at slow
 * growth to cost 15% less at G = 0.0005 (the same angles).
 */
static const struct {
	size_t		 cuts;
	int		 parts;
	size_t		 fine;
} tiers[TIERS] = { { 6, 1, 0 }, { 16, 4, 6 }, { 64, 8, 16 }, { 0, 16, 16 } };

/* The last tier's parts: each tier's parts are a number dividing it. */
#define SUBPARTS	16

/*
 * A lower bound of E in gap g, [a, b]: every pull is positive and
 * falls with the angle from its primordium, so it is at least its
 * least over the gap, and at least its least anywhere (opposite it):
 * F->floor sums those.  The closer tiers take the least over each of
 * several parts of the gap (the bound is the least of the parts'), for
 * more of the primordia nearest in angle; the far field is at least
 * Taylor's bound over the gap, and at least its least on the circle.
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
static double
gap_bound(const struct field *F, const struct cut *cuts, size_t k,
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
	struct part pt, whole = { a, b, cuts[g].c, cuts[g].s, end->c,
	    end->s };
	int straight;

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
			coarse = side_above(F, first, lo, whole.ch, whole.sh) +
			    side_above(F, hi, first + nc, whole.cl, whole.sl);
		else
			for (size_t d = first; d < first + nc; d++)
				if (d < lo || d >= hi)
					coarse += cut_above(F, &F->cp[d],
					    &whole);
		if (tiers[tier].cuts == 0)
			coarse += mid_above(F, k, &whole);
	}
	if (F->floor + coarse + F->far_least >= stop)
		return F->floor + coarse + F->far_least;
	if (F->moments && tier >= 2) {
		/*
		 * Smooth beside the near ones: Taylor's, over the whole gap,
		 * from the first modes and what the others add at most.
		 */
		double e[3] = { 0, 0, 0 };
		int modes = F->nmodes < BOUND_MODES ? F->nmodes : BOUND_MODES;

		far_energy(F, (a + b) / 2, modes, e);
		far = fmax(F->far_least, e[0] - F->tail[0] - (fabs(e[1]) +
		    F->tail[1]) * (b - a) / 2 - F->far_curv * (b - a) *
		    (b - a) / 8);
	} else if (F->moments)
		far = F->far_least;
	straight = fine > 0 && straight_from(F, lo, hi, &whole);
	/* The parts' ends: the cuts' own cosines, turned by h between. */
	pt.lo = a;
	pt.cl = cuts[g].c;
	pt.sl = cuts[g].s;
	if (parts > 1) {
		ch = cos(h);
		sh = sin(h);
	}
	for (int p = 0; p < parts; p++) {
		double sum = F->floor + coarse;
		unsigned bits = mask << p * sub;

		pt.hi = p + 1 < parts ? pt.lo + h : b;
		if (p + 1 < parts) {
			pt.ch = pt.cl * ch - pt.sl * sh;
			pt.sh = pt.sl * ch + pt.cl * sh;
		} else {
			pt.ch = end->c;
			pt.sh = end->s;
		}
		if (live != NULL && !(*live & bits))
			;	/* ruled out by a coarser tier's part */
		else if (straight)	/* the ones before at hi, after at lo */
			sum += side_above(F, lo, after, pt.ch, pt.sh) +
			    side_above(F, after, hi, pt.cl, pt.sl);
		else if (pt.hi - pt.lo < M_PI)
			for (size_t d = lo; d < hi; d++)
				sum += cut_above(F, &F->cp[d], &pt);
		else
			for (size_t d = first; d < first + nc; d++)
				sum += above_floor(F, F->cpi[d], &pt);
		/* And the near ones that are not cuts. */
		if (tiers[tier].cuts == 0 && fine == nc)
			sum += mid_above(F, k, &pt);
		if (live != NULL && (!(*live & bits) || sum + far >= stop))
			*live &= ~bits;
		else if (sum + far < least) {
			least = sum + far;
			*at = (pt.lo + pt.hi) / 2;
		}
		pt.lo = pt.hi;
		pt.cl = pt.ch;
		pt.sl = pt.sh;
	}
	return least;
}

/*
 * The first tier's bound, the only one most gaps get: the floor, the
 * far field's least, and the nearest near cuts, each at the end of the
 * gap farther from it; as gap_bound() takes it, without its parts,
 * tiers and stops.  gap_bound() itself where those ends are not the
 * farthest points.
 */
static double
first_bound(const struct field *F, const struct cut *cuts, size_t k,
    size_t g, double a, double b, double *at)
{
	size_t kn = F->ncp, nc = tiers[0].cuts < kn ? tiers[0].cuts : kn;
	size_t first = kn > 0 ? (F->gpos[g] + kn - nc / 2) % kn : 0;
	const struct cut *end = &cuts[g + 1 < k ? g + 1 : 0];
	struct part whole = { a, b, cuts[g].c, cuts[g].s, end->c,
	    end->s };

	if (!straight_from(F, first, first + nc, &whole))
		return gap_bound(F, cuts, k, g, a, b, 0, HUGE_VAL, NULL, at);
	*at = (a + b) / 2;
	return F->floor + (F->moments ? F->far_least : 0) + side_above(F,
	    first, first + nc / 2, end->c, end->s) + side_above(F, first +
	    nc / 2, first + nc, cuts[g].c, cuts[g].s);
}

/*
 * For the tests: every tier's bound of every gap, first_bound()'s too,
 * against the least E the search finds in it.  A bound above it is
 * wrong, and would have let the search pass over the gap holding the
 * minimum.
 */
static void
check_bounds(struct field *F, const struct cut *cuts, size_t k)
{
	for (size_t g = 0; g < k; g++) {
		double a = cuts[g].th, b = gap_end(cuts, k, g), at, e;

		if (!(b - a >= 1e-12))
			continue;
		minimise(F, a, b, (a + b) / 2, &e);
		for (int t = 0; t < TIERS; t++)
			if (gap_bound(F, cuts, k, g, a, b, t, HUGE_VAL, NULL,
			    &at) > e * (1 + 1e-12))
				F->misses++;
		if (first_bound(F, cuts, k, g, a, b, &at) > e * (1 + 1e-12))
			F->misses++;
	}
}

/*
 * The circle's cuts, the k newest primordia's angles, in order (newest
 * first among equal angles, as a stable sort of them newest first).
 * From one step to the next the newest joins and, with k the same, the
 * oldest leaves: one removal and one insertion keep the order, where a
 * sort of them all took 8% of the time.  Otherwise they are sorted
 * afresh.
 */
static void
cuts_update(struct field *F, struct cut *cuts, size_t k)
{
	size_t n = F->n, p, lo = 0, hi;
	struct cut nw;

	if (!(F->ncut == k && F->cut_n + 1 == n && k > 0 && n > k)) {
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
	for (p = 0; cuts[p].i != n - 1 - k; p++)
		;
	memmove(cuts + p, cuts + p + 1, (k - 1 - p) * sizeof(*cuts));
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
	F->cut_n = n;
}

/* A gap's search: its bound so far, from which tier, and where to start. */
struct gap {
	double		 lb, at;
	int		 tier;
	unsigned	 live;		/* gap_bound()'s */
};

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
		double to = gp->at, bound = gap_bound(F, cuts, k, g, a, b,
		    ++gp->tier, *emin, &gp->live, &to);

		if (bound > gp->lb) {
			gp->lb = bound;
			gp->at = to;
		}
	}
	if (!(gp->lb < *emin))
		return;
	x = minimise(F, a, b, gp->at, &e);
	if (e < *emin || (e == *emin && g < *gmin)) {
		*emin = e;
		*th = x;
		*gmin = g;
	}
}

/*
 * The angle of least inhibition on the edge.  The circle is cut at the
 * angles of the near newest primordia, so that each gap holds one
 * minimum.  A gap whose lower bound is above the least E found cannot
 * hold the minimum: each gap's bound is made closer while it is below,
 * and the gap searched if its closest bound still is.  As exact as a
 * search of every gap, and most gaps are passed on their first bounds.
 */
static double
next_angle(struct field *F, struct cut *cuts, struct gap *gaps)
{
	size_t k = F->near < F->n ? F->near : F->n, best = 0, gmin = k;
	double th = 0, emin = HUGE_VAL;

	cuts_update(F, cuts, k);
	/* Opposite each primordium its pull is least: the floor of E. */
	F->floor = 0;
	F->nmid = 0;
	for (size_t i = F->from; i < F->n; i++) {
		double *fl = &F->fl[F->n - 1 - i], r = F->r[F->n - 1 - i];

		*fl = pull_at(F, (R0 + r) * (R0 + r));
		F->floor += *fl;
		if (i + k < F->n)
			F->mid[F->nmid++] = (struct cutp){ F->c[i], F->s[i],
			    R0 * R0 + r * r, 2 * R0 * r, *fl };
	}
	/* The near cuts, in order; the far ones' pulls are the far field's. */
	F->ncp = 0;
	for (size_t c = 0; c < k; c++) {
		size_t i = cuts[c].i;
		double r = F->r[F->n - 1 - i];

		if (i >= F->from) {
			F->cpi[F->ncp] = i;
			F->cp[F->ncp++] = (struct cutp){ F->c[i], F->s[i],
			    R0 * R0 + r * r, 2 * R0 * r, F->fl[F->n - 1 - i] };
		}
		F->gpos[c] = F->ncp;	/* cut c itself is before gap c */
	}
	for (size_t c = 0; c < F->ncp; c++) {
		F->cp[F->ncp + c] = F->cp[c];
		F->cpi[F->ncp + c] = F->cpi[c];
	}
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
		gp->lb = b - a >= 1e-12 ? first_bound(F, cuts, k, g, a, b,
		    &gp->at) : HUGE_VAL;	/* no room */
		if (gp->lb < emin)
			search_gap(F, cuts, k, g, gp, &emin, &th, &gmin);
	}
	if (F->check)
		check_bounds(F, cuts, k);
	return th;
}

static void
field_add(struct field *F, double th)
{
	F->phi[F->n] = th;
	F->c[F->n] = cos(th);
	F->s[F->n] = sin(th);
	if (F->gt != NULL) {	/* the Gaussian's cos and sin (m th) */
		double *t = &F->gt[F->n * 2 * (GMODES + 1)];

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

/* The settled divergence: the mean and spread of the last two thirds. */
static void
settled(const double *phi, size_t n, double *mean, double *spread)
{
	size_t from = n / 3, k = 0;
	double sum = 0, sum2 = 0;

	for (size_t i = from > 0 ? from : 1; i < n; i++, k++) {
		double d = fabs(remainder(phi[i] - phi[i - 1], 2 * M_PI)) *
		    (180 / M_PI);

		sum += d;
		sum2 += d * d;
	}
	*mean = k > 0 ? sum / (double)k : 0;
	*spread = k > 1 ? sqrt(fmax(0, sum2 / (double)k - *mean * *mean)) : 0;
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

int
inhibition_place(const struct model_ctx *ctx, struct result *res, int how)
{
	const struct inhibition *P = ctx->params;
	struct field F = { .P = P, .hs = P->exponent / 2 };
	struct expr_env env = { { 0 }, (uint64_t)ctx->seed, 0 };
	size_t N;
	double mean, spread, flip = 1, rim, scale, gmin, *born, T;
	struct cut *cuts;
	size_t terms = 0;
	struct gap *gaps;

	N = (size_t)ctx->count;
	if (P->kernel == K_GAUSSIAN && N > 200000) {
		model_error(ctx, GIVEN_AT(P, IN_KERNEL), "count %zu is more "
		    "than the gaussian kernel places, 200000: it weighs every "
		    "primordium, so each costs as many as came before", N);
		return -1;
	}
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
	if (F.S[N - 1] > AGE_MAX) {
		model_error(ctx, GIVEN_AT(P, IN_GROWTH), "inhibition.growth "
		    "adds up to %.0f over %zu primordia: the oldest would be "
		    "e^%.0f meristem radii out; the sum must stay under %d",
		    F.S[N - 1], N, F.S[N - 1], AGE_MAX);
		free(F.S);
		return -1;
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
	F.cp = xcalloc(2 * near_count(gmin) + 2, sizeof(*F.cp));
	F.cpi = xcalloc(2 * near_count(gmin) + 2, sizeof(*F.cpi));
	F.gpos = xcalloc(near_count(gmin) + 1, sizeof(*F.gpos));
	F.mid = xcalloc(N, sizeof(*F.mid));
	/*
	 * The far field, but for the power law's reference sum of all
	 * pairs; the Gaussian's is all of it.
	 */
	F.moments = P->kernel == K_GAUSSIAN || !(how & INHIB_ALL_PAIRS);
	F.check = how & INHIB_CHECK_BOUNDS;
	F.nmodes = P->kernel == K_GAUSSIAN ? GMODES : MODES;
	if (P->kernel == K_GAUSSIAN)
		F.gt = xcalloc(N * 2 * (GMODES + 1), sizeof(*F.gt));
	else if (F.moments)
		far_init(&F);

	for (size_t n = 0; n < N; n++) {
		/*
		 * Enough recent ones that their gaps hold one minimum each,
		 * for the growth of this plastochron: finer gaps than the
		 * field's features would rank the wrong ones.
		 */
		F.near = near_count(n > 0 ? F.S[n] - F.S[n - 1] : F.S[1]);
		if (P->kernel == K_GAUSSIAN)
			gauss_step(&F);
		else if (F.moments && n > 0)
			far_step(&F);
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
		field_add(&F, n == 0 ? 0 : n == 1 ? M_PI : next_angle(&F,
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
	result_info(res, "settled", 2, mean, spread);
	/* 99.5016: the Lucas angle, 360 / (3 + tau^-1)... of the 1, 3 series. */
	result_info_text(res, "regime", fabs(mean - 180) < 5 ? "distichous" :
	    fabs(mean - GOLDEN_ANGLE) < 2 ? "fibonacci" :
	    fabs(mean - 99.5016) < 2 ? "lucas" : "other");
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
	free(F.gt);
	free(cuts);
	free(gaps);
	free(F.cp);
	free(F.cpi);
	free(F.gpos);
	free(F.mid);
	free(F.w);
	free(F.Mc);
	free(F.Ms);
	return 0;
}

static int
inhibition_run(const struct model_ctx *ctx, struct result *res)
{
	return inhibition_place(ctx, res, 0);
}

const struct model inhibition_model = {
	.name = "inhibition",
	.help = "Douady & Couder: each primordium where the others inhibit "
	    "least; the angle emerges",
	.settings = &inhibition_table,
	.size = sizeof(struct inhibition),
	.run = inhibition_run,
	.needs_count = 1,
	.emerges = 1,
};
