/*
 * cylindrical_lattice.c - van Iterson's cylindrical phyllotaxis, after
 * ABOP ch. 4.2.
 *
 * Organ k sits at angle k alpha and height k h on a cylinder of radius
 * 1, every organ a circle of diameter d.  An m-parastichy joins organs
 * k, k + m, k + 2m, ...; between two of its organs the pattern turns by
 * delta_m = m alpha - 2 pi D_m, D_m the encyclic number (the nearest
 * whole number of turns).  When the m- and n-parastichies are the
 * opposed pair of contact parastichies, organ 0 touches organs m and n:
 *
 *	delta_m^2 + (m h)^2 = d^2,   delta_n^2 + (n h)^2 = d^2,
 *
 * which give h and d from alpha (ABOP eqs. 4.7, 4.8).  At either end of
 * the range of alpha where this holds a third parastichy touches too
 * (m + n at one end, n - m at the other): the circles then lie on a
 * regular hexagonal grid, and alpha, h and d follow from m and n alone
 * (eqs. 4.10-4.13).
 */
#include <math.h>

#include "models/cylindrical_lattice.h"

#define TAU	(2 * M_PI)

double
cyl_fold(double alpha)
{
	double a = fmod(alpha, 360);

	if (a < 0)
		a += 360;
	return a > 180 ? 360 - a : a == 0 ? 360 : a;
}

/* x reduced to (-pi, pi]. */
static double
wrap(double x)
{
	double w = remainder(x, TAU);

	return w <= -M_PI ? w + TAU : w;
}

/*
 * The smallest positive dm, and its dn >= 0, with n dm - m dn = +-1;
 * returns that sign.  A search, not Euclid: m and n are small.
 */
int
cyl_encyclic(int m, int n, int *dm, int *dn)
{
	for (int a = 1; a <= m + n; a++)
		for (int s = 1; s >= -1; s -= 2)
			if ((n * a - s) % m == 0 && (n * a - s) / m >= 0) {
				*dm = a;
				*dn = (n * a - s) / m;
				return s;
			}
	*dm = *dn = 0;
	return 0;
}

/* The triple-contact divergence of (m, n, m + n), eqs. 4.3 and 4.12. */
static double
triple_alpha(int m, int n)
{
	double S = (double)m * m + (double)m * n + (double)n * n;
	int dm, dn, s = cyl_encyclic(m, n, &dm, &dn);
	/* n delta_m - m delta_n = -2 pi s puts delta_m's sign at -s. */
	double delta_m = -s * M_PI * (m + 2.0 * n) / S;

	return cyl_fold((delta_m + TAU * dm) / m * (180 / M_PI));
}

void
cyl_triple(int m, int n, double *alpha, double *h, double *d)
{
	double S = (double)m * m + (double)m * n + (double)n * n;
	double delta_m = M_PI * (m + 2.0 * n) / S;
	double delta_n = M_PI * (2.0 * m + n) / S;

	*alpha = triple_alpha(m, n);
	*d = TAU / sqrt(S);
	*h = m == n ? M_PI / sqrt(3.0) : sqrt((delta_m * delta_m -
	    delta_n * delta_n) / ((double)n * n - (double)m * m));
}

/*
 * One end is the triple (m, n, m + n), the other the triple whose
 * largest member is n: (min(m, n - m), max(m, n - m), n).
 */
void
cyl_range(int m, int n, double *lo, double *hi)
{
	int a = n - m < m ? n - m : m, b = n - m < m ? m : n - m;
	double x = triple_alpha(m, n), y = triple_alpha(a, b);

	*lo = x < y ? x : y;
	*hi = x < y ? y : x;
}

int
cyl_pair(int m, int n, double alpha, double *h, double *d)
{
	double a = cyl_fold(alpha) * (M_PI / 180);
	double dm = wrap(m * a), dn = wrap(n * a);
	double k = (double)n * n - (double)m * m;
	double h2 = (dm * dm - dn * dn) / k;
	double d2 = ((double)n * n * dm * dm - (double)m * m * dn * dn) / k;

	/*
	 * The m- and n-parastichies through organ 0 must meet again at
	 * organ mn after one turn (eq. 4.5): then their steps span the
	 * lattice of organs.  Their signs need not differ.
	 */
	if (fabs(fabs(n * dm - m * dn) - TAU) > 1e-9 || !(h2 >= 0) ||
	    !(d2 > 0))
		return -1;
	*h = sqrt(h2);
	*d = sqrt(d2);
	return 0;
}

/*
 * The nearest neighbour m of organ 0 on the unrolled cylinder, and the
 * nearest n that forms a basis of the lattice with it (eq. 4.5, as in
 * cyl_pair): organ 0 touches both, so they are the contact parastichies
 * and their distance the circles' diameter.  Beyond k h past the second
 * distance nothing can be nearer.
 */
int
cyl_contacts(double alpha, double h, int *m, int *n, double *d)
{
	double a = cyl_fold(alpha) * (M_PI / 180), best = HUGE_VAL,
	    second = HUGE_VAL;
	int k, k1 = 0, k2 = 0;

	for (k = 1; k * h <= best; k++) {
		double dist = hypot(wrap(k * a), k * h);

		if (k > 10000000)
			return -1;
		if (dist < best) {
			best = dist;
			k1 = k;
		}
	}
	for (k = 1; k * h <= second; k++) {
		double dist = hypot(wrap(k * a), k * h);
		double det = k * wrap(k1 * a) - k1 * wrap(k * a);

		if (k != k1 && dist < second && fabs(fabs(det) - TAU) < 1e-6) {
			second = dist;
			k2 = k;
		}
		if (k > 10000000)
			return -1;
	}
	if (k2 == 0)
		return -1;
	*m = k1 < k2 ? k1 : k2;
	*n = k1 < k2 ? k2 : k1;
	*d = best;
	return 0;
}
