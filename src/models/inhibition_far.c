/*
 * inhibition_far.c - the power law's far field: the primordia beyond a
 * radius far_r summed as a Fourier series whose moments each
 * plastochron rescales, so a step costs the same however many came
 * before (struct field in inhibition_impl.h says how).
 */
#include <math.h>
#include <stdlib.h>

#include "mem.h"
#include "models/inhibition_impl.h"

#define FAR_TAIL	1e-12	/* its truncation, of a primordium's pull */

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
void
inhib_far_init(struct field *F)
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

/* What bounds the far field: its curvature, its least, its tails. */
void
inhib_far_summary(struct field *F)
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
void
inhib_far_step(struct field *F)
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
	inhib_far_summary(F);
}

/*
 * The far field's E, E', E'' at th from its first modes, added to e
 * (summed apart: e might alias the modes, for all the compiler knows).
 */
void
inhib_far_energy(const struct field *F, double th, int modes, double e[3])
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
