/*
 * inhibition_far.c - the power law's far field: the primordia beyond a
 * radius far_r summed as a Fourier series whose moments each
 * plastochron rescales, so a step costs the same however many came
 * before (struct field in inhibition_impl.h says how).
 */
#include <math.h>
#include <stdlib.h>

#include "base/mem.h"
#include "models/inhibition_impl.h"

#define FAR_TAIL	1e-12	/* its truncation, of a primordium's pull */

/*
 * The largest growth factor of a moment's units, e^REBASE, before they
 * are reset: the products with the factors e^-(s+j)(S - base) stay far
 * inside a double's range.
 */
#define REBASE		600

/*
 * The far radius for M modes: the smallest at which the series cut
 * after M leaves out less than FAR_TAIL of what a primordium there
 * pulls at most, sum_j (s)_j / j! x^j = (1 - x)^-s.
 */
static double
far_radius(double s, int M)
{
	double lo = 0, hi = 1;

	for (int it = 0; it < 60; it++) {
		double x = (lo + hi) / 2, t = 1, tail = 0;

		/*
		 * The terms' ratio (s + j - 1) x / j tends to x, from above
		 * (s > 1) or below, so the rest of the tail is at most t r
		 * / (1 - r), r the larger of the two: once that is under
		 * 1e-17 of the tail the sum stops, rather than summing some
		 * thousands of terms to underflow 60 times over (6 ms, a
		 * fifth of a run of 2,000 at G = 0.3).
		 */
		for (int j = 1; j < M + 4000 && t > 0; j++) {
			double ratio = (s + j - 1) / j * x, r = fmax(ratio, x);

			t *= ratio;
			if (j > M) {
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
	return R0 / lo;
}

/*
 * The modes, the weights and the far radius.  MODES put it at 1.52 R0
 * for s = 3.  At slow growth the circle's cuts (the primordia summed
 * one by one anyway) end well inside that, at radius inside, and the
 * near ones between were summed one by one too, 490 of them at G =
 * 0.0005, in every E and every bound.  Where inside is well inside
 * (its log under 3/4 of far_r's: G below about 0.0017) the series
 * takes as many modes as put far_r there (201 at G = 0.0005, 142 at
 * 0.001), and the far field, no longer smooth on a gap's scale, is
 * bounded from its values on a grid of points (inhib_far_least()), as
 * few as hold the modes (a grid twice as fine bounds closer but costs
 * more than it saves).  Just inside, at G = 0.002, the grid cost 4%
 * more than the few primordia it took in saved.
 *
 * At fast growth the other way round: the cuts reach far beyond far_r
 * (inside over far_r^FAST_GRID: G above about 0.08), so all but the
 * newest few are in the far field, which is then most of E.  Bounded
 * by its least on the circle, it let nearly every gap through to a
 * search (10.5 of 12 a step at G = 0.5); from the grid, one in 12.
 * Measured, one core, best of 5: G = 0.5 23 -> 12 ms for 1,000; 0.3
 * 55 -> 29 ms for 2,000; 0.1 77 -> 68 ms for 6,000; at 0.05 the same
 * and at 0.02 the grid's transform cost 8% more than it saved.
 */
#define FAST_GRID	5

/*
 * The grid of the far field's values for M modes: as few points as
 * hold them, 64 at least.
 */
void
inhib_far_grid(struct field *F, int M)
{
	int N;

	for (F->grid = 64; F->grid < 2 * M + 2; F->grid *= 2)
		;
	N = F->grid;
	F->gv = xcalloc((size_t)N, sizeof(*F->gv));
	F->gd = xcalloc((size_t)N, sizeof(*F->gd));
	/* Stage half's turns at half + k (k < half), cos then sin. */
	F->tw = xcalloc(2 * (size_t)N, sizeof(*F->tw));
	for (int half = 1; half < N; half *= 2)
		for (int k = 0; k < half; k++) {
			int j = k * (N / (2 * half));

			F->tw[half + k] = cos(2 * M_PI * j / N);
			F->tw[N + half + k] = sin(2 * M_PI * j / N);
		}
	F->rev = xcalloc((size_t)N, sizeof(*F->rev));
	for (int i = 1, j = 0; i < N; i++) {
		int bit = N >> 1;

		for (; j & bit; bit >>= 1)
			j ^= bit;
		j |= bit;
		F->rev[i] = j;
	}
}

void
inhib_far_init(struct field *F, double inside)
{
	double lam = F->hs, a[MODES_MAX + 1];
	int M = MODES;

	F->far_r = far_radius(2 * lam, MODES);
	if (log(inside) < 0.75 * log(F->far_r)) {
		int lo = MODES, hi = MODES_MAX;	/* far_r(lo) > inside */

		while (hi - lo > 1) {
			int mid = (lo + hi) / 2;

			if (far_radius(2 * lam, mid) <= inside)
				hi = mid;
			else
				lo = mid;
		}
		M = hi;
		F->far_r = far_radius(2 * lam, M);
	}
	if (M > MODES || log(inside) > FAST_GRID * log(F->far_r))
		inhib_far_grid(F, M);
	F->nmodes = M;
	/* Moment (j, m), m <= j, m = j mod 2, at row[m] + (j - m) / 2. */
	F->row[0] = 0;
	for (int m = 0; m <= M; m++)
		F->row[m + 1] = F->row[m] + (size_t)(M - m) / 2 + 1;
	a[0] = 1;	/* (lam)_i / i! */
	for (int i = 1; i <= M; i++)
		a[i] = a[i - 1] * (lam + i - 1) / i;
	F->w = xcalloc(F->row[M + 1], sizeof(*F->w));
	for (int j = 0; j <= M; j++)
		for (int i = 0; i <= j; i++) {
			int m = abs(j - 2 * i);

			F->w[F->row[m] + (size_t)(j - m) / 2] += a[i] * a[j - i];
		}
	F->Mc = xcalloc(F->row[M + 1], sizeof(*F->Mc));
	F->Ms = xcalloc(F->row[M + 1], sizeof(*F->Ms));
}

/* f[j] = e^-(s+j)t, j <= nmodes: a moment's factor for growth t. */
static void
far_factors(const struct field *F, double t, double f[MODES_MAX + 1])
{
	double x = exp(-t);

	f[0] = exp(-2 * F->hs * t);
	for (int j = 1; j <= F->nmodes; j++)
		f[j] = f[j - 1] * x;
}

static void	far_grid(struct field *, const double *mag);

/* amp[m] = |mode m|, m <= nmodes, LANES at a time (a sqrt each). */
static HOT void
far_amplitudes(const struct field *F, double *restrict amp)
{
	const double *Fc = F->Fc, *Fs = F->Fs;
	int m = 0;

	for (; m + LANES <= F->nmodes + 1; m += LANES)
		for (int l = 0; l < LANES; l++)
			amp[m + l] = sqrt(Fc[m + l] * Fc[m + l] + Fs[m + l] *
			    Fs[m + l]);
	for (; m <= F->nmodes; m++)
		amp[m] = sqrt(F->Fc[m] * F->Fc[m] + F->Fs[m] * F->Fs[m]);
}

/*
 * What bounds the far field: its curvature, its least, its tails, and
 * its values on the grid, where it has one.
 */
void
inhib_far_summary(struct field *F)
{
	double amp[MODES_MAX + 1];

	far_amplitudes(F, amp);
	F->far_curv = F->tail[0] = F->tail[1] = 0;
	F->far_least = F->Fc[0];
	for (int m = 1; m <= F->nmodes; m++) {
		double a = amp[m];

		F->far_curv += (double)m * m * a;
		F->far_least -= a;
		if (m > BOUND_MODES) {
			F->tail[0] += a;
			F->tail[1] += m * a;
		}
	}
	F->far_least = fmax(0, F->far_least);
	if (F->grid > 0)
		far_grid(F, amp);
}

/*
 * LANES butterflies, a and b apart (restrict: the compiler may load
 * them all first).
 */
static inline void
butterflies(double *restrict ar, double *restrict ai, double *restrict br,
    double *restrict bi, const double *restrict tc,
    const double *restrict ts)
{
	for (int l = 0; l < LANES; l++) {
		double vr = br[l] * tc[l] - bi[l] * ts[l];
		double vi = br[l] * ts[l] + bi[l] * tc[l];

		br[l] = ar[l] - vr;
		bi[l] = ai[l] - vi;
		ar[l] += vr;
		ai[l] += vi;
	}
}

/*
 * In place, y_j = sum_m x_m e^(2 pi i m j / N), N = F->grid, from x
 * stored at the bit-reversed places (far_grid() puts it there): radix
 * 2.  Our own, not FFTW's: one size a run (at most 1024 points), the
 * turns made once in inhib_far_grid(), and the rounding margin
 * inhib_far_least() takes is that of this plain algorithm; a second
 * library and its plans would not pay for 40 lines.  From the third
 * stage on, LANES butterflies side by side (the transform was a tenth
 * of a step at G = 0.0005, one butterfly at a time); each is the same
 * arithmetic either way.
 */
_Static_assert(LANES >= 1 && (LANES & (LANES - 1)) == 0 && LANES <= 64,
    "fft(): a stage's half from LANES on is a multiple of LANES");

static HOT void
fft(const struct field *F, double *restrict re, double *restrict im)
{
	int N = F->grid, half = 1;
	const double *tc = F->tw, *ts = F->tw + N;

	for (; half < N && half < LANES; half *= 2)
		for (int i = 0; i < N; i += 2 * half)
			for (int k = 0; k < half; k++) {
				double *ar = &re[i + k], *ai = &im[i + k];
				double *br = ar + half, *bi = ai + half;
				double wc = tc[half + k], ws = ts[half + k];
				double vr = *br * wc - *bi * ws;
				double vi = *br * ws + *bi * wc;

				*br = *ar - vr;
				*bi = *ai - vi;
				*ar += vr;
				*ai += vi;
			}
	for (; half < N; half *= 2)
		for (int i = 0; i < N; i += 2 * half)
			for (int k = 0; k < half; k += LANES)
				butterflies(&re[i + k], &im[i + k], &re[i + k +
				    half], &im[i + k + half], &tc[half + k],
				    &ts[half + k]);
}

/*
 * The far field and its E' at the grid's points 2 pi j / N, from one
 * transform: E = sum_m c_m e^(i m th) over m from -M to M, c_m = (Fc_m
 * - i Fs_m) / 2 and c_-m its conjugate, and E' the same with i m c_m:
 * both real, so the transform of c_m + i (i m c_m) = (1 - m) c_m is E
 * + i E' (N > 2M: no two modes fold onto one).  What E'' can be, sum
 * m^2 |mode m|, and the transform's rounding, a few units of the last
 * place of sum (1 + m) |mode m| each stage, bounded at 1e-13 of it.
 */
static void
far_grid(struct field *F, const double *mag)
{
	double *re = F->gv, *im = F->gd, amp = fabs(F->Fc[0]);
	int N = F->grid;

	for (int j = 0; j < N; j++)
		re[j] = im[j] = 0;
	re[0] = F->Fc[0];
	F->m2 = 0;
	for (int m = 1; m <= F->nmodes; m++) {
		double cr = F->Fc[m] / 2, ci = -F->Fs[m] / 2, a = mag[m];
		int p = F->rev[m], q = F->rev[N - m];

		re[p] = (1 - m) * cr;
		im[p] = (1 - m) * ci;
		re[q] = (1 + m) * cr;
		im[q] = -(1 + m) * ci;
		F->m2 += (double)m * m * a;
		amp += (1 + m) * a;
	}
	F->gerr = 1e-13 * amp;
	fft(F, re, im);
}

/*
 * floor(t) for |t| < 2^62, inline: the library's, a call, and the
 * index's remainder below (N a power of two, a mask) were a third of
 * inhib_far_least(), called for every gap and part.
 */
static inline long
floor_long(double t)
{
	long i = (long)t;

	return (double)i > t ? i - 1 : i;
}

/*
 * A lower bound of the far field over [lo, hi] (hi - lo at most 2 pi):
 * its least on the circle, or from the grid.  Each point x of [lo, hi]
 * is within h/2 of a grid point x_j, h = 2 pi / N, and by Taylor E(x)
 * >= E(x_j) + E'(x_j) d - m2 d^2 / 2, d = x - x_j, |E''| <= m2
 * everywhere.  That is concave in d, so over the points of [lo, hi]
 * nearest x_j it is least at one of their ends: the bound is the least
 * of those, less the grid's rounding.
 */
double
inhib_far_least(const struct field *F, double lo, double hi)
{
	double h, least = HUGE_VAL, x, m2 = F->m2 / 2;
	long j, jhi, N = F->grid;

	if (N == 0)
		return F->far_least;
	h = 2 * M_PI / (double)N;
	j = floor_long(lo / h + 0.5);
	jhi = floor_long(hi / h + 0.5);
	x = (double)j * h;
	for (long at = j & (N - 1); j <= jhi; j++, x += h) {
		double u = lo > x - h / 2 ? lo - x : -h / 2;
		double v = hi < x + h / 2 ? hi - x : h / 2;
		double f = F->gv[at], d = F->gd[at];
		double tu = f + (d - m2 * u) * u, tv = f + (d - m2 * v) * v;

		least = tu < least ? tu : least;
		least = tv < least ? tv : least;
		if (++at == N)
			at = 0;
	}
	least -= F->gerr;
	return least > F->far_least ? least : F->far_least;
}

/*
 * The powers x[j], j <= nmodes, split by parity: moment (j, m) of row m
 * takes x[m + 2i], which is then h[m / 2 + i] of the half h for m's
 * parity, read in order.
 */
static void
far_halves(const struct field *F, const double *x, double *even,
    double *odd)
{
	for (int j = 0; j <= F->nmodes; j++)
		(j % 2 ? odd : even)[j / 2] = x[j];
}

/* A primordium joins a row: moment k += w[k] q[k] (cos, sin)(m phi). */
static inline void
far_join(double *restrict mc, double *restrict ms, const double *restrict w,
    const double *restrict q, double c, double s, size_t len)
{
	size_t k = 0;

	/* LANES a pass: -O2 vectorises no loop that leaves a remainder. */
	for (; k + LANES <= len; k += LANES)
		for (int l = 0; l < LANES; l++) {
			double v = w[k + l] * q[k + l];

			mc[k + l] += v * c;
			ms[k + l] += v * s;
		}
	for (; k < len; k++) {
		double v = w[k] * q[k];

		mc[k] += v * c;
		ms[k] += v * s;
	}
}

/*
 * The modes from the moments, mode m = sum over its row of fh(j) x
 * moment (j, m), fh the growth's factors split by parity; with the
 * primordium of powers ph and cos and sin (m phi) cm and sm joining
 * the moments on the way, unless ph is NULL.  The one loop of the far
 * field's step over all its moments (M^2 / 4, 10,000 at G = 0.0005):
 * LANES sums a row side by side, built for AVX2 too.
 */
static HOT void
far_modes(struct field *F, double fh[2][MODES_MAX / 2 + 1],
    double ph[2][MODES_MAX / 2 + 1], const double *cm, const double *sm)
{
	for (int m = 0; m <= F->nmodes; m++) {
		double *restrict mc = F->Mc + F->row[m];
		double *restrict ms = F->Ms + F->row[m];
		const double *restrict p = fh[m % 2] + m / 2;
		const double *restrict w = F->w + F->row[m];
		size_t len = F->row[m + 1] - F->row[m], i = 0;
		double ac[LANES] = { 0 }, as[LANES] = { 0 }, c = 0, s = 0;

		if (ph != NULL) {
			far_join(mc, ms, w, ph[m % 2] + m / 2, cm[m], sm[m],
			    len);
		}
		for (; i + LANES <= len; i += LANES)
			for (int l = 0; l < LANES; l++) {
				ac[l] += p[i + l] * mc[i + l];
				as[l] += p[i + l] * ms[i + l];
			}
		for (; i < len; i++) {
			c += p[i] * mc[i];
			s += p[i] * ms[i];
		}
		for (int l = 0; l < LANES; l++) {
			c += ac[l];
			s += as[l];
		}
		F->Fc[m] = c;
		F->Fs[m] = s;
	}
}

/*
 * The modes now, S[n]: with the primordia that have moved beyond far_r
 * joining the moments.  The last to join this step (most steps, one)
 * joins in the same pass over the moments that sums the modes.
 */
void
inhib_far_step(struct field *F)
{
	size_t n = F->n;
	double f[MODES_MAX + 1], t = F->S[n] - F->base;
	double fh[2][MODES_MAX / 2 + 1], ph[2][MODES_MAX / 2 + 1];
	double cm[MODES_MAX + 1], sm[MODES_MAX + 1];
	int join = 0;

	if ((2 * F->hs + F->nmodes) * t > REBASE) {
		far_factors(F, t, f);
		for (int m = 0; m <= F->nmodes; m++)
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
		double pw[MODES_MAX + 1];
		double c1 = F->c[F->from], s1 = F->s[F->from];

		pw[0] = pow(u, -2 * F->hs);
		cm[0] = 1;
		sm[0] = 0;
		for (int m = 1; m <= F->nmodes; m++) {
			pw[m] = pw[m - 1] * iu;
			cm[m] = cm[m - 1] * c1 - sm[m - 1] * s1;
			sm[m] = sm[m - 1] * c1 + cm[m - 1] * s1;
		}
		far_halves(F, pw, ph[0], ph[1]);
		F->from++;
		if (!(F->from < n && R0 * exp(F->S[n] - F->S[F->from]) >=
		    F->far_r)) {
			join = 1;	/* the last: below */
			break;
		}
		for (int m = 0; m <= F->nmodes; m++)
			far_join(F->Mc + F->row[m], F->Ms + F->row[m], F->w +
			    F->row[m], ph[m % 2] + m / 2, cm[m], sm[m],
			    F->row[m + 1] - F->row[m]);
	}
	/*
	 * None out there yet: the modes, the grid and what bounds them
	 * are still the zeros they started as (at G = 0.0005 the first 336
	 * steps, a tenth of the bench's 3,000).
	 */
	if (F->from == 0)
		return;
	far_factors(F, t, f);
	far_halves(F, f, fh[0], fh[1]);
	far_modes(F, fh, join ? ph : NULL, cm, sm);
	inhib_far_summary(F);
}

/*
 * The far field's E, E', E'' at the angle th of cosine ct and sine st
 * from its first modes, added to e.  cos and sin (m th) by rotation, in
 * LANES chains side by side (modes m = l mod LANES turned by LANES th a
 * time): one chain of 200 turns was 8% of the time at G = 0.0005.
 */
static HOT void
far_energy(const struct field *F, double ct, double st, int modes,
    double e[3])
{
	double cm[LANES], sm[LANES], a0[LANES] = { 0 }, a1[LANES] = { 0 };
	double a2[LANES] = { 0 }, kl[LANES], cw, sw;
	const double *Fc = F->Fc, *Fs = F->Fs;
	int m = 0;

	cm[0] = 1;
	sm[0] = 0;
	cm[1] = ct;
	sm[1] = st;
	for (int l = 2; l < LANES; l++) {
		cm[l] = cm[l - 1] * cm[1] - sm[l - 1] * sm[1];
		sm[l] = sm[l - 1] * cm[1] + cm[l - 1] * sm[1];
	}
	cw = cm[LANES - 1] * cm[1] - sm[LANES - 1] * sm[1];
	sw = sm[LANES - 1] * cm[1] + cm[LANES - 1] * sm[1];
	for (int l = 0; l < LANES; l++)
		kl[l] = l;
	/* m + l as a double kept in a lane: converted, it took AVX2's lanes. */
	for (; m + LANES <= modes + 1; m += LANES)
		for (int l = 0; l < LANES; l++) {
			double fc = Fc[m + l], fs = Fs[m + l], k = kl[l];
			double v = fc * cm[l] + fs * sm[l], nc;

			a0[l] += v;
			a1[l] += k * (fs * cm[l] - fc * sm[l]);
			a2[l] -= k * k * v;
			nc = cm[l] * cw - sm[l] * sw;
			sm[l] = sm[l] * cw + cm[l] * sw;
			cm[l] = nc;
			kl[l] = k + LANES;
		}
	for (int l = 0; m + l <= modes; l++) {
		double fc = F->Fc[m + l], fs = F->Fs[m + l], k = m + l;
		double v = fc * cm[l] + fs * sm[l];

		a0[l] += v;
		a1[l] += k * (fs * cm[l] - fc * sm[l]);
		a2[l] -= k * k * v;
	}
	for (int l = 0; l < LANES; l++) {
		e[0] += a0[l];
		e[1] += a1[l];
		e[2] += a2[l];
	}
}

void
inhib_far_energy(const struct field *F, double ct, double st, int modes,
    double e[3])
{
	far_energy(F, ct, st, modes, e);
}
