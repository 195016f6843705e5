/*
 * dense.h - the inhibition model's minima checked against a dense scan
 * of the whole energy (no cut-off, no far field), for test_inhibition
 * and bench_inhibition: computed from the output's own positions, so
 * it knows nothing of the model's search.
 */
#ifndef DENSE_H
#define DENSE_H

#include <math.h>
#include <stdlib.h>

#include "result/organ.h"

/* Each organ's distance from the axis in the output. */
static const double *rho;

/*
 * The whole energy on the edge when organ n was born.  Organ i was then
 * rho_i / rho_n meristem radii out: all have grown by the same factor
 * since, whatever the growth was.
 */
static double
energy(const double *phi, int n, double s, int gauss, double th)
{
	double e = 0;

	for (int i = 0; i < n; i++) {
		if (gauss) {
			double x = remainder(th - phi[i], 2 * M_PI);

			for (int k = -1; k <= 1; k++)
				e += exp(-(x + 2 * M_PI * k) * (x + 2 * M_PI * k)) /
				    (n - i);
		} else {
			double r = rho[i] / rho[n];
			double d2 = 1 + r * r - 2 * r * cos(th - phi[i]);

			e += pow(d2, -s / 2);
		}
	}
	return e;
}

/* E' at th, for the refinement by the sign of the slope. */
static double
slope(const double *phi, int n, double s, int gauss, double th)
{
	double e = 0;

	for (int i = 0; i < n; i++) {
		if (gauss) {
			double x = remainder(th - phi[i], 2 * M_PI);

			for (int k = -1; k <= 1; k++) {
				double y = x + 2 * M_PI * k;

				e += -2 * y * exp(-y * y) / (n - i);
			}
		} else {
			double r = rho[i] / rho[n];
			double d2 = 1 + r * r - 2 * r * cos(th - phi[i]);

			e += -s / 2 * pow(d2, -s / 2 - 1) * 2 * r * sin(th - phi[i]);
		}
	}
	return e;
}

/*
 * The true minimum: a dense scan, then bisection on the sign of E'
 * around the best sample (values alone could not resolve the flat
 * bottom better than the square root of the rounding).
 */
static double
true_min(const double *phi, int n, double s, int gauss)
{
	int M = 6000, best = 0;
	double h = 2 * M_PI / M, bestE = HUGE_VAL, a, b;

	for (int k = 0; k < M; k++) {
		double e = energy(phi, n, s, gauss, k * h);

		if (e < bestE) {
			bestE = e;
			best = k;
		}
	}
	a = (best - 1) * h;
	b = (best + 1) * h;
	for (int it = 0; it < 60 && b - a > 1e-14; it++) {
		double m = (a + b) / 2;

		if (slope(phi, n, s, gauss, m) > 0)
			b = m;
		else
			a = m;
	}
	return (a + b) / 2;
}

/*
 * The worst distance, in radians, between the angle of a primordium the
 * model placed and the energy's true minimum when it was born, over
 * every every-th primordium from 2 to below to (grown radii: each
 * organ's distance from the axis is its radius then, times a common
 * factor); equal minima (a mirror-symmetric field) are both right.
 * *checked: how many.
 */
static double
dense_worst(const struct result *res, double s, int gauss, int every, int to,
    int *checked)
{
	int N = (int)res->count < to ? (int)res->count : to;
	double *phi = calloc((size_t)(N > 0 ? N : 1), sizeof(*phi));
	double *rh = calloc((size_t)(N > 0 ? N : 1), sizeof(*rh)), worst = 0;

	*checked = 0;
	if (phi == NULL || rh == NULL) {
		free(phi);
		free(rh);
		return HUGE_VAL;
	}
	for (int i = 0; i < N; i++) {
		phi[i] = atan2(res->organs[i].pos[1], res->organs[i].pos[0]);
		rh[i] = hypot(res->organs[i].pos[0], res->organs[i].pos[1]);
	}
	rho = rh;
	for (int n = 2; n < N; n += every) {
		double t = true_min(phi, n, s, gauss);
		double d = fabs(remainder(t - phi[n], 2 * M_PI));

		if (d > 1e-9 && fabs(energy(phi, n, s, gauss, t) -
		    energy(phi, n, s, gauss, phi[n])) <= 1e-9 *
		    energy(phi, n, s, gauss, t))
			d = 0;
		if (d > worst)
			worst = d;
		(*checked)++;
	}
	free(phi);
	free(rh);
	return worst;
}

#endif
