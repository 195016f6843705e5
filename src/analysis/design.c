/*
 * design.c - inverse design: the count or radius whose structure shows
 * the parastichy pair a scene asks for, found by measuring trial
 * structures (parastichy.c) over a range searched in log x.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "analysis/design.h"
#include "analysis/parastichy.h"
#include "compat/compat.h"
#include "geometry/curve.h"
#include "geometry/receptacle.h"
#include "base/table.h"

/*
 * A problem with the pair or radius asked for, at line of the scene
 * file (0: at its start): reported as a model's are (model_error()),
 * which is all the models need to give design of their context.
 */
static void PRINTFLIKE(3, 4)
design_error(const char *file, int line, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	settings_verror(file, line, fmt, ap);
	va_end(ap);
}

/* -1, 0, 1: pair a below, at, above b (by the larger number, then the smaller). */
static int
pair_cmp(const int a[2], const int b[2])
{
	if (a[1] != b[1])
		return a[1] < b[1] ? -1 : 1;
	return a[0] < b[0] ? -1 : a[0] > b[0];
}

/* Where want stands at t in [0, 1] of the log range, from below (-1). */
static int
side_at(double t, double lo, double hi, int grows, const int want[2],
    para_measure_fn *measure, void *ctx, int *err)
{
	/* t = 0 is the small-pair end: hi for a radius, lo for a count. */
	double x = grows ? lo * pow(hi / lo, t) : hi * pow(lo / hi, t);
	int pair[2];

	if (measure(ctx, x, pair) != 0) {
		*err = 1;
		return 0;
	}
	return pair[0] == 0 ? -1 : pair_cmp(pair, want);
}

double
para_search(const int want[2], double lo, double hi, int grows,
    para_measure_fn *measure, void *ctx, char *reach, size_t reachsz)
{
	enum { STEPS = 20 };
	int seen[STEPS + 1][2], nseen = 0, err = 0, prev = -2;
	double tf = -1, a, b, t0, t1;

	reach[0] = '\0';
	/* Step from the small pairs up, until want shows or is passed. */
	for (int k = 0; k <= STEPS && tf < 0; k++) {
		double t = (double)k / STEPS;
		double x = grows ? lo * pow(hi / lo, t) : hi * pow(lo / hi, t);
		int pair[2], c;

		if (measure(ctx, x, pair) != 0)
			return -1;
		if (pair[0] == 0)
			continue;
		if (nseen == 0 || pair_cmp(seen[nseen - 1], pair) != 0) {
			seen[nseen][0] = pair[0];
			seen[nseen][1] = pair[1];
			nseen++;
		}
		c = pair_cmp(pair, want);
		if (c == 0) {
			tf = t;
			break;
		}
		if (c > 0 && prev < 0 && k > 0) {
			/* Passed between two steps: look between them. */
			a = (double)(k - 1) / STEPS;
			b = t;
			for (int it = 0; it < 30 && tf < 0; it++) {
				double m = (a + b) / 2;
				int cm = side_at(m, lo, hi, grows, want, measure,
				    ctx, &err);

				if (err)
					return -1;
				if (cm == 0)
					tf = m;
				else if (cm < 0)
					a = m;
				else
					b = m;
			}
		}
		if (c > 0)
			break;
		prev = c;
	}
	if (tf < 0) {
		size_t len = 0;

		for (int k = 0; k < nseen && len + 16 < reachsz; k++)
			len += (size_t)snprintf(reach + len, reachsz - len,
			    "%s%d/%d", k ? " " : "", seen[k][0], seen[k][1]);
		return 0;
	}
	/* The stretch showing want: bracket both of its edges. */
	a = 0;
	b = tf;
	for (int it = 0; it < 10; it++) {
		double m = (a + b) / 2;
		int c = side_at(m, lo, hi, grows, want, measure, ctx, &err);

		if (err)
			return -1;
		if (c < 0)
			a = m;
		else
			b = m;
	}
	t0 = b;
	a = tf;
	b = 1;
	for (int it = 0; it < 10; it++) {
		double m = (a + b) / 2;
		int c = side_at(m, lo, hi, grows, want, measure, ctx, &err);

		if (err)
			return -1;
		if (c > 0)
			b = m;
		else
			a = m;
	}
	t1 = a;
	a = (t0 + t1) / 2;
	return grows ? lo * pow(hi / lo, a) : hi * pow(lo / hi, a);
}

int
para_want_check(const char *file, int line, const char *path,
    const struct int_list *want)
{
	int a;

	if (want->n != 2 || want->v[0] >= want->v[1]) {
		design_error(file, line, "%s must be a pair [m, n] with m < n",
		    path);
		return -1;
	}
	if ((a = para_gcd(want->v[0], want->v[1])) != 1) {
		design_error(file, line, "%s [%d, %d] have the common factor "
		    "%d: a single spiral shows coprime numbers", path,
		    want->v[0], want->v[1], a);
		return -1;
	}
	return 0;
}

struct design {
	para_trial_fn	*trial;
	void		*arg;
	long long	 cap;
};

/* The base pair of a trial radius, on a few organs. */
static int
design_pair(void *ctx, double r, int pair[2])
{
	const struct design *D = ctx;
	struct result res = { 0 };
	struct para_zone z[64];
	size_t nz;

	if (D->trial(D->arg, r, D->cap, &res) != 0)
		return -1;
	nz = para_zones(&res, NULL, z, 64);
	pair[0] = nz ? z[0].m : 0;
	pair[1] = nz ? z[0].n : 0;
	result_free(&res);
	return 0;
}

/*
 * The constant radius whose structure shows the pair want at its base,
 * on a receptacle whose base circle has radius rim, searched up to rhi;
 * want as given at path, line.  The radius, or -1 after a diagnostic.
 */
static double
design_radius(const char *file, int line, const char *path,
    const struct int_list *want, double rim, double rhi,
    para_trial_fn *trial, void *arg)
{
	/* Enough organs for the base to show its pair, and not many more. */
	struct design D = { trial, arg, 12LL * (want->v[0] + want->v[1]) };
	char reach[512];
	double r, est;

	if (para_want_check(file, line, path, want) != 0)
		return -1;
	if (!(rim > 0)) {
		/* At a pole the pair changes organ by organ: no base pair. */
		design_error(file, line, "parastichies = [m, n] needs a "
		    "receptacle with a rim at its base: at a pole the pair "
		    "changes from one organ to the next");
		return -1;
	}
	/*
	 * First near where such a pair usually lies, a base ring of about
	 * n organs of radius 2.3 rim / n; then the whole range.
	 */
	est = 2.3 * rim / want->v[1];
	r = para_search(want->v, est / 3, est * 3, 0,
	    design_pair, &D, reach, sizeof(reach));
	if (r == 0)
		r = para_search(want->v, rhi / 200, rhi, 0, design_pair, &D,
		    reach, sizeof(reach));
	if (r == 0) {
		design_error(file, line, "no constant radius shows "
		    "parastichies %d/%d at the base of this receptacle; the "
		    "radii tried show %s", want->v[0], want->v[1], reach);
		return -1;
	}
	return r;
}

double
para_design_receptacle(const char *file, const char *group,
    int line, int radius_line, const struct receptacle *rc,
    const struct int_list *want, int by_area, para_trial_fn *trial,
    void *arg)
{
	char path[64];
	double (*pts)[2], rim, rhi;
	struct curve cv;
	int npts;

	if (radius_line) {
		design_error(file, line, "give %s.radius or %s.parastichies, "
		    "not both", group, group);
		return -1;
	}
	if ((pts = receptacle_points(file, rc, &npts)) == NULL)
		return -1;
	rim = pts[0][0];
	/* At most a radius whose cell fits four times round the base. */
	rhi = rim * M_PI / 3;
	/* And four times on the whole receptacle. */
	if (by_area && curve_init(&cv, (const double (*)[2])pts, npts) == 0) {
		rhi = fmin(rhi, sqrt(cv.area / (8 * sqrt(3.0))));
		curve_free(&cv);
	}
	free(pts);
	snprintf(path, sizeof(path), "%s.parastichies", group);
	return design_radius(file, line, path, want, rim, rhi, trial, arg);
}
