/*
 * inhibition_kernel.c - the energy E on the meristem's edge and its
 * derivatives: the power law's near primordia one by one, plus the
 * far field's modes (the Gaussian kernel's are all of it:
 * inhibition_gauss.c).
 */
#include <math.h>

#include "models/inhibition_impl.h"

/*
 * E, E' and E'' at th: each primordium has moved out once more since
 * it was born.
 */
void
inhib_energy(const struct field *F, double th, double e[3])
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
		inhib_far_energy(F, th, F->nmodes, e);
}

/* E alone at th, summed as inhib_energy() sums it. */
double
inhib_energy_only(const struct field *F, double th)
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
		inhib_far_energy(F, th, F->nmodes, e);
	return e[0];
}
