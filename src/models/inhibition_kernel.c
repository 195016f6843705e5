/*
 * inhibition_kernel.c - the energy E on the meristem's edge and its
 * derivatives: the power law's near primordia one by one, plus the
 * far field's modes (the Gaussian kernel's are all of it:
 * inhibition_gauss.c).
 */
#include <math.h>

#include "models/inhibition_impl.h"

/*
 * The near ones' E, E' and E'' at the point (ct, st) of the edge, from
 * primordium from to n - 1 (the r of the k-th newest in r[k]).
 */
static HOT void
near_energy(const struct field *F, double ct, double st, double e[3])
{
	double a0[LANES] = { 0 }, a1[LANES] = { 0 }, a2[LANES] = { 0 };
	double hs = F->hs;
	size_t i = F->from, n = F->n;

	/*
	 * d^2 = q = R0^2 + r^2 - 2 R0 r cos(th - phi), q1 and q2 its
	 * derivatives; one division for p, p / q and p / q^2.  For s = 3
	 * LANES at a time.
	 */
	if (hs == 1.5)
		for (; i + LANES <= n; i += LANES)
			for (int l = 0; l < LANES; l++) {
				double r = F->r[n - 1 - i - l];
				double c = F->c[i + l], s = F->s[i + l];
				double cd = ct * c + st * s, sd = st * c - ct * s;
				double q = R0 * R0 + r * r - 2 * R0 * r * cd;
				double q1 = 2 * R0 * r * sd, q2 = 2 * R0 * r * cd;
				double iq = 1 / q, p = iq * sqrt(iq), pq = p * iq;

				a0[l] += p;
				a1[l] += -1.5 * pq * q1;
				a2[l] += 1.5 * pq * (2.5 * iq * q1 * q1 - q2);
			}
	e[0] = e[1] = e[2] = 0;
	for (; i < n; i++) {
		double r = F->r[n - 1 - i];
		double cd = ct * F->c[i] + st * F->s[i];
		double sd = st * F->c[i] - ct * F->s[i];
		double q = R0 * R0 + r * r - 2 * R0 * r * cd;
		double q1 = 2 * R0 * r * sd, q2 = 2 * R0 * r * cd;
		double iq = 1 / q, p = hs == 1.5 ? iq * sqrt(iq) :
		    pull_at(F, q), pq = p * iq;

		e[0] += p;
		e[1] += -hs * pq * q1;
		e[2] += hs * pq * ((hs + 1) * iq * q1 * q1 - q2);
	}
	for (int l = 0; l < LANES; l++) {
		e[0] += a0[l];
		e[1] += a1[l];
		e[2] += a2[l];
	}
}

/*
 * E, E' and E'' at th: each primordium has moved out once more since
 * it was born.
 */
void
inhib_energy(const struct field *F, double th, double e[3])
{
	double ct = cos(th), st = sin(th);

	near_energy(F, ct, st, e);
	if (F->moments)
		inhib_far_energy(F, ct, st, F->nmodes, e);
}

/* The near ones' E alone, LANES at a time as near_energy() sums it. */
static HOT double
near_only(const struct field *F, double ct, double st)
{
	double acc[LANES] = { 0 }, e = 0;
	size_t i = F->from, n = F->n;

	if (F->hs == 1.5)
		for (; i + LANES <= n; i += LANES)
			for (int l = 0; l < LANES; l++) {
				double r = F->r[n - 1 - i - l];
				double cd = ct * F->c[i + l] + st * F->s[i + l];
				double q = R0 * R0 + r * r - 2 * R0 * r * cd;
				double iq = 1 / q;

				acc[l] += iq * sqrt(iq);
			}
	for (; i < n; i++) {
		double r = F->r[n - 1 - i];
		double cd = ct * F->c[i] + st * F->s[i];
		double q = R0 * R0 + r * r - 2 * R0 * r * cd, iq = 1 / q;

		e += F->hs == 1.5 ? iq * sqrt(iq) : pull_at(F, q);
	}
	for (int l = 0; l < LANES; l++)
		e += acc[l];
	return e;
}

/* E alone at th, summed as inhib_energy() sums it. */
double
inhib_energy_only(const struct field *F, double th)
{
	double ct = cos(th), st = sin(th), e[3] = { near_only(F, ct, st), 0,
	    0 };

	if (F->moments)
		inhib_far_energy(F, ct, st, F->nmodes, e);
	return e[0];
}
