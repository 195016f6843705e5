/*
 * lattice.c - the lattice of one band of unordered points, and its
 * parastichy numbers counted, not guessed.
 *
 * The basis: the steps from each point to its nearest neighbours, in
 * the band's unrolled coordinates, point along a few directions (three
 * where the lattice is near hexagonal); the two most common, reduced to
 * the shortest basis, are refined by least squares over every step that
 * lies on the lattice, long steps included, so that jitter averages out.
 *
 * The numbers: following a family's step from point to point traces
 * its spirals; the number of spirals is the number of such steps that
 * cross a ring around the axis, outward less inward.  That holds for
 * any closed ring round the true axis, so an off centre or a squashed
 * view does not change it; a missing organ is stepped over (two or
 * three steps at once, found where they should land); and it is a
 * whole number by construction, where a formula from the basis's shape
 * (2 pi rho a_s / area, which is also computed, as a check and for a
 * ring the photograph cut) carries the jitter of every step into it.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "analysis/lattice.h"

#define NEAREST		6	/* steps a point gives the directions */
#define BINS		72	/* of twice the direction, 5 degrees each */
#define ON		0.35	/* on the lattice: within this of |a| */
#define CUTS		7	/* rings the spirals are counted across */

static double
dot(const double a[2], const double b[2])
{
	return a[0] * b[0] + a[1] * b[1];
}

void
lattice_step(const struct point_field *F, const struct band_lattice *L,
    size_t i, size_t j, double l[2])
{
	const struct axis_point *p = &F->ap[i], *q = &F->ap[j];
	double rho = (p->rho + q->rho) / 2;
	double area = (F->area[i] + F->area[j]) / 2;

	double d = q->phi - p->phi;

	/* Both in (-pi, pi]: one wrap at most (remainder() was a third). */
	if (d > M_PI)
		d -= 2 * M_PI;
	else if (d <= -M_PI)
		d += 2 * M_PI;
	l[0] = (q->s - p->s) * (rho / L->rho) * (L->area / area);
	l[1] = d * L->rho;
}

int
lattice_round(const struct band_lattice *L, const double l[2], double tol,
    long long *x, long long *y)
{
	double det = L->a[0] * L->b[1] - L->a[1] * L->b[0];
	double fx, fy, best = HUGE_VAL;
	long long rx, ry;

	if (det == 0)
		return 0;
	fx = (l[0] * L->b[1] - l[1] * L->b[0]) / det;
	fy = (L->a[0] * l[1] - L->a[1] * l[0]) / det;
	if (!(fabs(fx) < 1e6 && fabs(fy) < 1e6))
		return 0;
	rx = llround(fx);
	ry = llround(fy);
	/* Within half the shortest step: that lattice point is the nearest. */
	{
		double r[2] = { l[0] - (double)rx * L->a[0] - (double)ry *
		    L->b[0], l[1] - (double)rx * L->a[1] - (double)ry *
		    L->b[1] };

		if ((rx != 0 || ry != 0) && 4 * dot(r, r) < dot(L->a, L->a)) {
			*x = rx;
			*y = ry;
			return dot(r, r) <= tol * tol * dot(L->a, L->a);
		}
	}
	/*
	 * The nearest lattice point but 0 (a step joins two organs):
	 * rounding the coordinates is not always the nearest, and a
	 * jittered pair may stand nearer each other than a step.
	 */
	for (long long i = rx - 1; i <= rx + 1; i++)
		for (long long j = ry - 1; j <= ry + 1; j++) {
			double r[2] = { l[0] - (double)i * L->a[0] -
			    (double)j * L->b[0], l[1] - (double)i * L->a[1] -
			    (double)j * L->b[1] };

			if ((i != 0 || j != 0) && dot(r, r) < best) {
				best = dot(r, r);
				*x = i;
				*y = j;
			}
		}
	return best <= tol * tol * dot(L->a, L->a);
}

/* The shortest basis of the lattice a and b span (Lagrange, Gauss). */
static void
reduce(double a[2], double b[2])
{
	for (int k = 0; k < 64; k++) {
		double mu;

		if (dot(b, b) < dot(a, a)) {
			double t[2] = { a[0], a[1] };

			a[0] = b[0], a[1] = b[1];
			b[0] = t[0], b[1] = t[1];
		}
		mu = round(dot(a, b) / dot(a, a));
		if (mu == 0 || !isfinite(mu))
			break;
		b[0] -= mu * a[0];
		b[1] -= mu * a[1];
	}
}

/* Turned outward (along the curve, away from the tip). */
static void
outward(double v[2])
{
	if (v[0] < 0 || (v[0] == 0 && v[1] < 0)) {
		v[0] = -v[0];
		v[1] = -v[1];
	}
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

struct dir {
	double		 v[2];
	double		 theta;		/* twice its angle, in (-pi, pi] */
};

/*
 * The steps along the most common direction not within avoid of the
 * ones in skip (NAN: none): their typical step, and how many.
 */
static size_t
cluster(const struct dir *d, size_t n, double skip, double out[2])
{
	double h[BINS] = { 0 }, sm[BINS], best = -1, theta, len[4096], L;
	double sum[2] = { 0, 0 };
	size_t members = 0, nl = 0, used = 0;
	int at = 0;

	for (size_t i = 0; i < n; i++) {
		int b = (int)floor((d[i].theta + M_PI) / (2 * M_PI) * BINS);

		h[(b % BINS + BINS) % BINS] += 1;
	}
	for (int b = 0; b < BINS; b++) {
		sm[b] = 0;
		for (int k = -2; k <= 2; k++)
			sm[b] += (3 - abs(k)) * h[(b + k + BINS) % BINS];
		theta = -M_PI + (b + 0.5) * 2 * M_PI / BINS;
		/* Within 25 degrees of the first direction: its own. */
		if (!isnan(skip) && fabs(remainder(theta - skip, 2 * M_PI)) <
		    50 * M_PI / 180)
			continue;
		if (sm[b] > best) {
			best = sm[b];
			at = b;
		}
	}
	theta = -M_PI + (at + 0.5) * 2 * M_PI / BINS;
	/* The members: within 15 degrees; their typical length. */
	for (size_t i = 0; i < n; i++)
		if (fabs(remainder(d[i].theta - theta, 2 * M_PI)) < 30 * M_PI /
		    180) {
			if (nl < 4096)
				len[nl++] = hypot(d[i].v[0], d[i].v[1]);
			members++;
		}
	if (nl == 0)
		return 0;
	qsort(len, nl, sizeof(*len), cmp_double);
	L = len[nl / 2];
	for (size_t i = 0; i < n; i++) {
		double r = hypot(d[i].v[0], d[i].v[1]);
		double dir[2] = { cos(theta / 2), sin(theta / 2) };
		int sign;

		if (!(fabs(remainder(d[i].theta - theta, 2 * M_PI)) < 30 *
		    M_PI / 180) || r < 0.7 * L || r > 1.4 * L)
			continue;
		/* Near the fold all of one direction, not half reversed. */
		sign = dot(d[i].v, dir) < 0 ? -1 : 1;
		sum[0] += sign * d[i].v[0];
		sum[1] += sign * d[i].v[1];
		used++;
	}
	if (used == 0)
		return 0;
	out[0] = sum[0] / (double)used;
	out[1] = sum[1] / (double)used;
	return members;
}

/*
 * Whether step x a + y b is of the first shell: a, b or the shorter of
 * a + b and a - b, either way.  Only those are fitted: every point has
 * them among its KD_K nearest, jittered or not, where of the longer
 * steps only those jitter brought nearer are there, and they would
 * shrink the fitted lattice.
 */
static int
first_shell(const struct band_lattice *L, long long x, long long y)
{
	double p[2] = { L->a[0] + L->b[0], L->a[1] + L->b[1] };
	double m[2] = { L->a[0] - L->b[0], L->a[1] - L->b[1] };
	long long s = dot(p, p) < dot(m, m) ? 1 : -1;

	if (llabs(x) + llabs(y) == 1)
		return 1;
	return llabs(x) == 1 && llabs(y) == 1 && x * y == s;
}

/*
 * A least-squares round: a and b from every first-shell step of the
 * band's points that rounds to a lattice step; how many did, of *total.
 */
static size_t
refine(const struct point_field *F, const size_t *pts, size_t n,
    struct band_lattice *L, size_t *total)
{
	double S[3] = { 0, 0, 0 }, X[2] = { 0, 0 }, Y[2] = { 0, 0 }, det;
	double rt = 0, rs = 0;
	size_t on = 0, fitted = 0;

	*total = 0;
	for (size_t k = 0; k < n; k++) {
		size_t i = pts[k];

		for (int m = 0; m < F->nnn[i]; m++) {
			double l[2];
			long long x, y;

			lattice_step(F, L, i, F->nn[i][m], l);
			(*total)++;
			if (!lattice_round(L, l, ON, &x, &y))
				continue;
			on++;
			if (!first_shell(L, x, y))
				continue;
			fitted++;
			S[0] += (double)(x * x);
			S[1] += (double)(x * y);
			S[2] += (double)(y * y);
			for (int c = 0; c < 2; c++) {
				X[c] += (double)x * l[c];
				Y[c] += (double)y * l[c];
			}
		}
	}
	det = S[0] * S[2] - S[1] * S[1];
	if (fitted < 8 || !(det > 0))
		return 0;
	for (int c = 0; c < 2; c++) {
		L->a[c] = (S[2] * X[c] - S[1] * Y[c]) / det;
		L->b[c] = (S[0] * Y[c] - S[1] * X[c]) / det;
	}
	/* The spread across, for the divergence's error. */
	for (size_t k = 0; k < n; k++) {
		size_t i = pts[k];

		for (int m = 0; m < F->nnn[i]; m++) {
			double l[2], r;
			long long x, y;

			lattice_step(F, L, i, F->nn[i][m], l);
			if (!lattice_round(L, l, ON, &x, &y) ||
			    !first_shell(L, x, y))
				continue;
			r = l[1] - (double)x * L->a[1] - (double)y * L->b[1];
			rt += r * r;
			r = l[0] - (double)x * L->a[0] - (double)y * L->b[0];
			rs += r * r;
		}
	}
	rt = fitted > 4 ? sqrt(rt / (double)(fitted - 4)) : 0;
	rs = fitted > 4 ? sqrt(rs / (double)(fitted - 4)) : 0;
	L->sigma_s[0] = rs * sqrt(2 * S[2] / det);
	L->sigma_s[1] = rs * sqrt(2 * S[0] / det);
	/* Each step is counted from both its ends: half as many. */
	L->sigma_t[0] = rt * sqrt(2 * S[2] / det);
	L->sigma_t[1] = rt * sqrt(2 * S[0] / det);
	return on;
}

int
lattice_basis(const struct point_field *F, const size_t *pts, size_t n,
    struct band_lattice *L)
{
	struct dir *d = xcalloc(NEAREST * n + 1, sizeof(*d));
	double *v = xcalloc(n + 1, sizeof(*v)), a[2], b[2], theta;
	size_t nd = 0, c1, c2, on = 0, total = 0;

	memset(L, 0, sizeof(*L));
	for (int q = 0; q < 3; q++) {
		for (size_t k = 0; k < n; k++)
			v[k] = q == 0 ? F->ap[pts[k]].rho : q == 1 ?
			    F->area[pts[k]] : F->ap[pts[k]].s;
		qsort(v, n, sizeof(*v), cmp_double);
		*(q == 0 ? &L->rho : q == 1 ? &L->area : &L->s) = v[n / 2];
	}
	free(v);
	if (!(L->rho > 0) || !(L->area > 0)) {
		free(d);
		return -1;
	}
	for (size_t k = 0; k < n; k++) {
		size_t i = pts[k];

		for (int m = 0; m < F->nnn[i] && m < NEAREST; m++) {
			lattice_step(F, L, i, F->nn[i][m], d[nd].v);
			outward(d[nd].v);
			d[nd].theta = 2 * atan2(d[nd].v[1], d[nd].v[0]);
			d[nd].theta = remainder(d[nd].theta, 2 * M_PI);
			nd++;
		}
	}
	c1 = cluster(d, nd, NAN, a);
	theta = 2 * atan2(a[1], a[0]);
	c2 = c1 > 0 ? cluster(d, nd, theta, b) : 0;
	free(d);
	/* One direction alone is a row, not a lattice. */
	if (c1 == 0 || c2 < c1 / 6 || fabs(a[0] * b[1] - a[1] * b[0]) <
	    1e-3 * dot(a, a)) {
		return -1;
	}
	memcpy(L->a, a, sizeof(a));
	memcpy(L->b, b, sizeof(b));
	for (int round = 0; round < 3; round++) {
		reduce(L->a, L->b);
		if ((on = refine(F, pts, n, L, &total)) == 0)
			return -1;
	}
	reduce(L->a, L->b);
	outward(L->a);
	outward(L->b);
	L->on = total > 0 ? (double)on / (double)total : 0;
	L->ok = L->on >= 0.5;
	return L->ok ? 0 : -1;
}

/* The point the band's step l from point i should land on, if any. */
static long
landing(const struct point_field *F, const struct band_lattice *L, size_t i,
    const double l[2], long long wx, long long wy)
{
	const struct axis_point *p = &F->ap[i];
	double s = p->s + l[0] * (L->rho / p->rho) * (F->area[i] / L->area);
	double X[3], got[2];
	struct kd_near nb;
	long long x, y;

	axis_place(F->A, s, p->phi + l[1] / L->rho, X);
	kd_nearest(F->T, X, SIZE_MAX, 0, &nb);
	for (int k = 0; k < nb.n && k < 2; k++) {
		if (nb.j[k] == i)
			continue;
		lattice_step(F, L, i, nb.j[k], got);
		if (lattice_round(L, got, HUGE_VAL, &x, &y) && x == wx &&
		    y == wy)
			return (long)nb.j[k];
	}
	return -1;
}

/*
 * The next point along a family (fx, fy: one step of a or of b) from
 * point i: a neighbour one step on, else the point two or three steps
 * on where one is missing; -1 if none.
 */
static long
next_along(const struct point_field *F, const struct band_lattice *L, size_t i,
    int fx, int fy, int *steps)
{
	long best = -1;
	double bestr = HUGE_VAL;

	*steps = 1;
	/* On the axis a step along the curve has no direction. */
	if (!(F->ap[i].rho > 0))
		return -1;
	for (int m = 0; m < F->nnn[i]; m++) {
		double l[2], r[2];
		long long x, y;

		/*
		 * Any step that rounds to it: a jittered neighbour stays in
		 * its lattice cell long after it leaves the ON tolerance.
		 */
		lattice_step(F, L, i, F->nn[i][m], l);
		if (!lattice_round(L, l, HUGE_VAL, &x, &y) || x != fx ||
		    y != fy)
			continue;
		r[0] = l[0] - fx * L->a[0] - fy * L->b[0];
		r[1] = l[1] - fx * L->a[1] - fy * L->b[1];
		if (dot(r, r) < bestr) {
			bestr = dot(r, r);
			best = (long)F->nn[i][m];
		}
	}
	for (int mult = 2; best < 0 && mult <= 3; mult++) {
		double l[2] = { mult * (fx * L->a[0] + fy * L->b[0]),
		    mult * (fx * L->a[1] + fy * L->b[1]) };

		best = landing(F, L, i, l, mult * fx, mult * fy);
		*steps = mult;
	}
	return best;
}

/*
 * A point is the next of one point at most, or a spiral would fork:
 * where a step was missed (its neighbour jittered into another cell),
 * the point before it went on two steps to the point the missed one
 * steps to.  The fewest steps win (the first on a tie), and the loser
 * steps to the winner, which stands between (i + 2 a = j = p + a: p =
 * i + a).  claim: -1 for every point, and so again after.
 */
static void
taken(long *next, int *steps, size_t n, const size_t *order, size_t lo,
    long *claim)
{
	long *touched = xcalloc(n + 1, sizeof(*touched));
	size_t nt = 0;

	for (size_t k = 0; k < n; k++) {
		long j = next[k], w;
		size_t keep, lose;

		if (j < 0)
			continue;
		if ((w = claim[j]) < 0) {
			claim[j] = (long)k;
			touched[nt++] = j;
			continue;
		}
		keep = steps[k] < steps[w] ? k : (size_t)w;
		lose = keep == k ? (size_t)w : k;
		if (steps[lose] > steps[keep]) {
			next[lose] = (long)order[lo + keep];
			steps[lose] -= steps[keep];
		} else
			next[lose] = -1;
		claim[j] = (long)keep;
	}
	while (nt > 0)
		claim[touched[--nt]] = -1;
	free(touched);
}

/* The first point at or after s in the order by s. */
static size_t
first_at(const struct point_field *F, double s)
{
	size_t lo = 0, hi = F->n;

	while (lo < hi) {
		size_t mid = (lo + hi) / 2;

		if (F->sorted_s[mid] < s)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

/* The share of the ring the points of window [lo, hi) go round. */
static double
coverage(const struct point_field *F, size_t lo, size_t hi, double gap)
{
	double *phi = xcalloc(hi - lo + 1, sizeof(*phi)), missing = 0;
	size_t n = hi - lo;

	for (size_t k = lo; k < hi; k++)
		phi[k - lo] = F->ap[F->order[k]].phi;
	qsort(phi, n, sizeof(*phi), cmp_double);
	for (size_t k = 0; k < n; k++) {
		double g = k + 1 < n ? phi[k + 1] - phi[k] :
		    phi[0] + 2 * M_PI - phi[k];

		if (g > gap)
			missing += g;
	}
	free(phi);
	return n > 0 ? 1 - missing / (2 * M_PI) : 0;
}

/* The most common of the counts, and how many of them it is. */
static long long
vote(long long c[CUTS], int *most)
{
	long long best = c[CUTS / 2];

	*most = 0;
	for (int i = 1; i < CUTS; i++)
		for (int j = i; j > 0 && c[j] < c[j - 1]; j--) {
			long long t = c[j];

			c[j] = c[j - 1];
			c[j - 1] = t;
		}
	for (int i = 0, j; i < CUTS; i = j) {
		for (j = i; j < CUTS && c[j] == c[i]; j++)
			;
		if (j - i > *most) {
			*most = j - i;
			best = c[i];
		}
	}
	return best;
}

/*
 * The two of a, b and the shorter of a + b, a - b that cross a ring
 * most squarely, as whole steps (x, y), turned outward: their spirals
 * are counted and labelled.  A family nearly along the ring winds
 * across it and back, and where the organs only nearly make a lattice
 * (the collision model's, as the radius changes) its steps do not keep
 * one number; a family across the ring does.
 */
static void
transversal(const struct band_lattice *L, int f[2][2])
{
	double p[2] = { L->a[0] + L->b[0], L->a[1] + L->b[1] };
	double m[2] = { L->a[0] - L->b[0], L->a[1] - L->b[1] };
	int c[3][2] = { { 1, 0 }, { 0, 1 }, { 1, dot(p, p) < dot(m, m) ? 1 :
	    -1 } };
	double sq[3], best = -1;

	for (int k = 0; k < 3; k++) {
		double v[2] = { c[k][0] * L->a[0] + c[k][1] * L->b[0],
		    c[k][0] * L->a[1] + c[k][1] * L->b[1] };

		sq[k] = fabs(v[0]) / sqrt(dot(v, v));
		if (v[0] < 0) {
			c[k][0] = -c[k][0];
			c[k][1] = -c[k][1];
		}
	}
	for (int i = 0; i < 3; i++)
		for (int j = i + 1; j < 3; j++)
			if (fmin(sq[i], sq[j]) > best) {
				best = fmin(sq[i], sq[j]);
				memcpy(f[0], c[i], sizeof(f[0]));
				memcpy(f[1], c[j], sizeof(f[1]));
			}
}

/* ka and kb from the numbers ku, kv of steps f[0], f[1]; 0 or -1. */
static int
solve_k(struct band_lattice *L, const int f[2][2], long long ku,
    long long kv)
{
	long long det = (long long)f[0][0] * f[1][1] - (long long)f[0][1] *
	    f[1][0];

	if (det == 0)
		return -1;
	L->ka = (ku * f[1][1] - kv * f[0][1]) / det;
	L->kb = (kv * f[0][0] - ku * f[1][0]) / det;
	return 0;
}

/* That estimate's error, from the fitted steps' spread along the curve. */
static double
estimate_error(const struct band_lattice *L, const int f[2])
{
	double cross = L->a[0] * L->b[1] - L->a[1] * L->b[0];

	return 2 * M_PI * L->rho * hypot(f[0] * L->sigma_s[0],
	    f[1] * L->sigma_s[1]) / fabs(cross);
}

/* The number of organs step (x, y) skips, from the basis's shape. */
static double
estimate(const struct band_lattice *L, const int f[2])
{
	double cross = L->a[0] * L->b[1] - L->a[1] * L->b[0];

	return 2 * M_PI * L->rho * (f[0] * L->a[0] + f[1] * L->b[0]) /
	    fabs(cross);
}

int
lattice_count(const struct point_field *F, struct band_lattice *L,
    int count_them)
{
	double cross = L->a[0] * L->b[1] - L->a[1] * L->b[0];
	double reach, cut[CUTS];
	long long count[2][CUTS], k[2];
	size_t lo, hi, need[2] = { 0, 0 }, found[2] = { 0, 0 };
	long *next, *claim;
	int *steps, f2[2][2], most[2];
	double est[2], est_s[2], whole;

	if (cross == 0)
		return -1;
	L->ka_est = 2 * M_PI * L->rho * L->a[0] / fabs(cross);
	L->kb_est = 2 * M_PI * L->rho * L->b[0] / fabs(cross);
	L->ka_err = estimate_error(L, (const int [2]){ 1, 0 });
	L->kb_err = estimate_error(L, (const int [2]){ 0, 1 });
	transversal(L, f2);
	est[0] = estimate(L, f2[0]);
	est[1] = estimate(L, f2[1]);
	for (int f = 0; f < 2; f++)
		est_s[f] = fabs(f2[f][0] * L->a[0] + f2[f][1] * L->b[0]);
	/* A step crosses a ring from three steps away at most. */
	reach = 3.2 * fmax(est_s[0], est_s[1]);
	/* How much of its own rings the band's organs go round. */
	L->coverage = coverage(F, first_at(F, L->s - 0.5 * reach),
	    first_at(F, L->s + 0.5 * reach), 4 * sqrt(dot(L->b, L->b)) /
	    L->rho);
	/*
	 * Rings a third of a step apart about the band's middle, but a
	 * reach inside the outermost and innermost rings, where the spirals
	 * end: those are read with the lattice next to them.
	 */
	{
		double step = fmax(L->a[0], L->b[0]), mid = L->s;
		double ring = 2 * M_PI * L->rho * sqrt(dot(L->a, L->a)) /
		    fabs(cross);
		size_t edge = (size_t)fmin(1.5 * ring, (double)F->n / 4);
		double top = F->sorted_s[F->n - 1 - edge] - step;
		double bottom = F->sorted_s[edge] + step;

		L->clamped = mid > top ? 1 : mid < bottom ? -1 : 0;
		if (mid > top)
			mid = top;
		if (mid < bottom)
			mid = bottom;
		for (int c = 0; c < CUTS; c++)
			cut[c] = mid + (c - CUTS / 2) * step / 3;
		L->s = mid;
	}
	/*
	 * The organs a step from which may cross a ring outward; across
	 * the ring squarely, a family's steps do not cross back.
	 */
	lo = first_at(F, cut[0] - reach);
	hi = first_at(F, cut[CUTS - 1] + 0.5 * reach);
	if (!count_them) {
		L->counted = 0;
		L->ka = L->kb = 0;
		return 0;
	}
	/*
	 * Every ring the counts read, each by the organs a step about it
	 * (together, the rings inside a rim cut by a photograph's frame
	 * would fill its gap): where one is cut, spirals end there.
	 */
	whole = 1;
	for (int c = 0; c < CUTS; c++) {
		double w = 0.75 * fmax(est_s[0], est_s[1]);

		whole = fmin(whole, coverage(F, first_at(F, cut[c] - w),
		    first_at(F, cut[c] + w), 4 * sqrt(dot(L->b, L->b)) /
		    L->rho));
	}
	memset(count, 0, sizeof(count));
	next = xcalloc(hi - lo + 1, sizeof(*next));
	claim = F->claim;
	steps = xcalloc(hi - lo + 1, sizeof(*steps));
	for (int f = 0; f < 2; f++) {
		for (size_t k = lo; k < hi; k++)
			next[k - lo] = next_along(F, L, F->order[k], f2[f][0],
			    f2[f][1], &steps[k - lo]);
		/* Twice: a relinked step may meet another. */
		taken(next, steps, hi - lo, F->order, lo, claim);
		taken(next, steps, hi - lo, F->order, lo, claim);
		/* The points whose step must cross the first ring, found. */
		for (size_t k = lo; k < hi; k++) {
			double si = F->ap[F->order[k]].s;

			if (si < cut[0] - 1.2 * est_s[f] || si >= cut[CUTS - 1])
				continue;
			need[f]++;
			found[f] += next[k - lo] >= 0;
		}
		for (size_t k = lo; k < hi; k++) {
			double si = F->ap[F->order[k]].s, sj;

			if (next[k - lo] < 0)
				continue;
			sj = F->ap[next[k - lo]].s;
			for (int c = 0; c < CUTS; c++)
				count[f][c] += (si < cut[c] && cut[c] <= sj) -
				    (sj < cut[c] && cut[c] <= si);
		}
	}
	free(next);
	free(steps);
	k[0] = vote(count[0], &most[0]);
	k[1] = vote(count[1], &most[1]);
	/*
	 * A whole ring's counts, where five of the seven rings agree, nine
	 * in ten organs a step away from them found the next, and the counts
	 * agree with the basis's shape; a cut ring, or counts that do not,
	 * are labelled by the angle (lattice_by_angle()) from a band next
	 * to it.  A count off by one all along a stretch would give every
	 * band there a wrong divergence that agrees with itself.
	 */
	L->counted = whole > 0.97;
	for (int f = 0; f < 2; f++) {
		double err = estimate_error(L, f2[f]);
		int counts = k[f] > 0 && most[f] >= 5 &&
		    (double)found[f] >= 0.9 * (double)need[f] &&
		    fabs((double)k[f] - est[f]) <= fmin(fmax(0.6, 2.5 * err),
		    fmax(2, 0.08 * est[f]));

		/*
		 * Or the shape alone, where it leaves no doubt (a model's
		 * organs, no jitter): a count can miss or double a spiral
		 * the shape cannot.
		 */
		if (err < 0.3 && fabs(est[f] - round(est[f])) < 0.25 &&
		    round(est[f]) > 0 && (!counts || k[f] != llround(est[f]))) {
			k[f] = llround(est[f]);
			counts = 1;
		}
		L->counted &= counts;
	}
	L->counted = L->counted && solve_k(L, (const int (*)[2])f2, k[0],
	    k[1]) == 0 && L->ka > 0 && L->kb != 0;
	if (!L->counted)
		L->ka = L->kb = 0;
	return 0;
}

/*
 * The organs a step skips, from its turn: a step of k organs turns k
 * divergences less whole turns, and of the few k its shape allows (the
 * estimate, give or take four of its errors or an eighth) the turns of no two are
 * near (at the golden angle k and k + 13 differ by 12.5 degrees, k and
 * k + 89 by 1.8), while a fitted step's turn is known to a small
 * fraction of that: the one whose turn is within tol, the next well
 * clear of it; else 0.
 */
static long long
by_angle(double phi, double est, double err, double alpha, double tol)
{
	double best = HUGE_VAL, second = HUGE_VAL;
	long long at = 0, k0;

	/* A lattice so flat no step skips a number of organs to try. */
	if (!(fabs(est) < 1e6 && err < 1e5))
		return 0;
	k0 = llround(est);
	long long w = llround(fmax(fmax(3, 4 * err), 0.12 * fabs(est)));

	for (long long k = k0 - w > 1 ? k0 - w : 1; k <= k0 + w; k++) {
		double r = fabs(remainder((double)k * alpha - phi, 2 * M_PI));

		if (r < best) {
			second = best;
			best = r;
			at = k;
		} else if (r < second)
			second = r;
	}
	return best <= tol && second > best + 3 * tol ? at : 0;
}

int
lattice_by_angle(struct band_lattice *L, double alpha, double alpha_err)
{
	int f[2][2];
	long long k[2];

	transversal(L, f);
	for (int i = 0; i < 2; i++) {
		double est = estimate(L, f[i]);
		double turn = hypot(f[i][0] * L->sigma_t[0], f[i][1] *
		    L->sigma_t[1]) / L->rho;

		/* Its turn's error, and the divergence's over its organs. */
		k[i] = by_angle((f[i][0] * L->a[1] + f[i][1] * L->b[1]) /
		    L->rho, est, estimate_error(L, f[i]), alpha, 5 * turn +
		    fabs(est) * 5 * alpha_err + 1e-9);
	}
	if (k[0] <= 0 || k[1] <= 0 || solve_k(L, (const int (*)[2])f, k[0],
	    k[1]) != 0 || L->ka == 0 || L->kb == 0) {
		L->ka = L->kb = 0;
		return -1;
	}
	return 0;
}
