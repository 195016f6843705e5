/*
 * inhibition_gauss.c - the Gaussian kernel's energy as a Fourier series
 * whose modes weigh every primordium by one over its age.
 *
 * Its bells summed over their images are (1 + 2 sum e^-(m^2/4) cos(m x))
 * / (2 sqrt(pi)) (Poisson's summation), which after GMODES terms is
 * exact to far below a double's precision, so each energy is O(GMODES)
 * instead of three exponentials a primordium.  But the weights 1 / age
 * change every step: summed again each step the modes cost O(GMODES n),
 * and 200,000 primordia some five minutes.
 *
 * So past GAUSS_EXACT primordia the old ones' weights are a sum of
 * exponentials, each of which a step only multiplies.  From 1/k =
 * integral over s of e^(s - k e^s) ds, the trapezoid rule with step h:
 *
 *     1/k ~ sum_j h l_j e^(-l_j k),   l_j = e^(j h).
 *
 * Its error, for a function analytic in the strip |Im s| < d and
 * integrable along it, is at most 2 M / (e^(2 pi d / h) - 1), M the
 * integral of |f| along the strip's edges (the standard bound; Trefethen
 * and Weideman, SIAM Review 2014, theorem 5.1): here |f(x + iy)| =
 * e^(x - k e^x cos y), so M = 1 / (k cos d), and with d = 1.45, h = 0.2
 * the error is under 3e-19 / k.  The terms left out: below l = 1e-17 /
 * count they add at most 1.1 l (their sum of h l_j), under 1e-17 / k
 * for every age k up to the count; above l = 45 / (GAUSS_NEAR + 1),
 * e^-45 / k at most for the ages past GAUSS_NEAR, the only ones they
 * weigh.  So each weight is 1/k to 2e-17 of itself, below a double's
 * rounding; the GAUSS_NEAR newest are weighed exactly.  The test checks
 * every age to 20,000 and some to 10,000,000.
 *
 * Each exponential's sum over the primordia, G_j = sum h l_j e^(-l_j
 * age) t_i (t_i their cos and sin (m phi_i)), is, a step later, G_j
 * less its decay (1 - e^-l_j) G_j, plus the primordium now GAUSS_NEAR + 1
 * old: O(GMODES) for each of some 280 exponentials, however many came
 * before.  The decay is subtracted, not multiplied: a factor rounded
 * once would be applied n times; a subtraction rounds each step apart.
 */
#include <math.h>
#include <stdlib.h>

#include "base/mem.h"
#include "models/inhibition.h"
#include "models/inhibition_impl.h"

#define GAUSS_EXACT	2000	/* primordia summed exactly, at most */
#define GAUSS_NEAR	32	/* the newest weighed exactly, past it */
#define GAUSS_H		0.2	/* the trapezoid rule's step */
#define ROW		(2 * (GMODES + 1))

/*
 * Room for count primordia: their rows, or for a longer run only the
 * newest GAUSS_NEAR + 1 in a ring, and the exponentials; exact: every
 * weight summed exactly at any count (the tests' reference).
 */
void
inhib_gauss_init(struct field *F, size_t count, int exact)
{
	int j0, j1;

	if (exact || count <= GAUSS_EXACT) {
		F->grows = count > 0 ? count : 1;
		F->gt = xcalloc(F->grows * ROW, sizeof(*F->gt));
		return;
	}
	F->grows = GAUSS_NEAR + 1;
	F->gt = xcalloc(F->grows * ROW, sizeof(*F->gt));
	j0 = (int)floor(log(1e-17 / (double)count) / GAUSS_H);
	j1 = (int)ceil(log(45.0 / (GAUSS_NEAR + 1)) / GAUSS_H);
	F->gexp = j1 - j0 + 1;
	F->gdec = xcalloc((size_t)F->gexp, sizeof(*F->gdec));
	F->gin = xcalloc((size_t)F->gexp, sizeof(*F->gin));
	F->gsum = xcalloc((size_t)F->gexp * ROW, sizeof(*F->gsum));
	for (int j = 0; j < F->gexp; j++) {
		double l = exp((j0 + j) * GAUSS_H);

		F->gdec[j] = -expm1(-l);
		F->gin[j] = GAUSS_H * l * exp(-l * (GAUSS_NEAR + 1));
	}
}

/* Primordium i's row, to write its cos and sin (m phi) in. */
double *
inhib_gauss_row(const struct field *F, size_t i)
{
	return &F->gt[(i % F->grows) * ROW];
}

/*
 * For the tests: the weights a run of count primordia gives the ages
 * k[0 .. n - 1] past GAUSS_NEAR (1/k where it sums them exactly).
 */
void
inhibition_gauss_weights(size_t count, const double *k, double *w,
    size_t n)
{
	struct field F = { 0 };

	inhib_gauss_init(&F, count, 0);
	for (size_t i = 0; i < n; i++) {
		w[i] = F.gexp > 0 ? 0 : 1 / k[i];
		for (int j = 0; j < F.gexp; j++) {
			double l = -log1p(-F.gdec[j]);

			w[i] += GAUSS_H * l * exp(-l * k[i]);
		}
	}
	inhib_gauss_free(&F);
}

/* The modes for the next primordium, F->n of them placed. */
void
inhib_gauss_step(struct field *F)
{
	size_t n = F->n, from = 0;
	double c[ROW] = { 0 };

	if (F->gexp > 0) {
		int J = F->gexp;

		/*
		 * The one now GAUSS_NEAR + 1 old joins; all decay.  In one
		 * pass, an exponential's ROW sums at a time: each c[v] adds
		 * them in the same order as a sum over j alone would, but
		 * the ROW sums are apart, not one chain of additions each
		 * waiting on the last (20,000 at G = 0.02: the whole run
		 * 0.33 -> 0.25 s, best of 5).
		 */
		if (n > GAUSS_NEAR) {
			const double *t = inhib_gauss_row(F, n - GAUSS_NEAR - 1);

			for (int j = 0; j < J; j++) {
				double *g = &F->gsum[(size_t)j * ROW];
				double in = F->gin[j], dec = F->gdec[j];

				for (int v = 0; v < ROW; v++) {
					g[v] += in * t[v] - dec * g[v];
					c[v] += g[v];
				}
			}
			from = n - GAUSS_NEAR;
		}
	}
	for (size_t i = from; i < n; i++) {
		const double *t = inhib_gauss_row(F, i);
		double w = 1.0 / (double)(n - i);	/* 1 / age */

		for (int v = 0; v < ROW; v++)
			c[v] += w * t[v];
	}
	for (int m = 0; m <= GMODES; m++) {
		double a = (m == 0 ? 0.5 : exp(-m * m / 4.0)) / sqrt(M_PI);

		F->Fc[m] = c[2 * m] * a;
		F->Fs[m] = c[2 * m + 1] * a;
	}
	F->from = F->n;
	inhib_far_summary(F);
}

void
inhib_gauss_free(struct field *F)
{
	free(F->gt);
	free(F->gdec);
	free(F->gin);
	free(F->gsum);
}
