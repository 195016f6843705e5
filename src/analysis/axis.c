/*
 * axis.c - where a pattern's axis is and what surface it lies on, from
 * its points alone, for the measured model and its analysis.
 *
 * A head (points in a plane, or nearly): first the squash of an oblique
 * view, from the directions between neighbours.  Around a ring of a
 * phyllotactic head the local lattice turns with the ring, so over the
 * head every direction is as common as any other; an oblique view
 * squashes them towards its long axis, and the correction is the
 * stretch that makes them even again.  Then the centre: there the
 * lattice looks the same from every side of a ring (Vogel's pattern is
 * the same turned by the divergence), so each point's six-fold
 * orientation, measured against the direction to the centre, is one
 * value around a ring.  The centre is where that holds best, found by
 * a search from the guess outward (a point of the head, not its
 * outline: a rim cut by the photograph's frame or a missing side does
 * not move it).
 *
 * A surface of revolution (z given, and tall): every section across the
 * axis is a circle about it, or, squashed, an ellipse of one shape; one
 * least-squares conic over all sections gives the centre and the
 * squash at once.  Then the generating curve: a principal curve through
 * the points' (rho, z), from the tip (the end nearest the axis, or the
 * top of a cylinder) outward.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "analysis/axis.h"
#include "analysis/kdtree.h"

#define SIX		6	/* neighbours a point's orientation reads */
#define SAMPLE_MAX	20000	/* points the squash, spacing and centre read */
#define CURVE_NODES	64	/* most nodes of the generating curve */

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

/* The median of v[0 .. n), which it sorts. */
static double
median(double *v, size_t n)
{
	if (n == 0)
		return 0;
	qsort(v, n, sizeof(*v), cmp_double);
	return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* The eigenvalues l[0] >= l[1] of [[p, q], [q, r]] and the first's angle. */
static void
eigen2(double p, double q, double r, double l[2], double *angle)
{
	double m = (p + r) / 2, d = hypot((p - r) / 2, q);

	l[0] = m + d;
	l[1] = m - d;
	*angle = 0.5 * atan2(2 * q, p - r);
}

/* R(angle) diag(a, b) R(angle)^T. */
static void
along(double a, double b, double angle, double out[2][2])
{
	double c = cos(angle), s = sin(angle);

	out[0][0] = a * c * c + b * s * s;
	out[0][1] = out[1][0] = (a - b) * c * s;
	out[1][1] = a * s * s + b * c * c;
}

/* a = a b, 2 x 2 matrices by rows. */
static void
mul2(double *a, const double *b)
{
	double r[4];

	r[0] = a[0] * b[0] + a[1] * b[2];
	r[1] = a[0] * b[1] + a[1] * b[3];
	r[2] = a[2] * b[0] + a[3] * b[2];
	r[3] = a[2] * b[1] + a[3] * b[3];
	memcpy(a, r, sizeof(r));
}

/* M (x, y), M by rows. */
static void
apply2(const double *M, double x, double y, double out[2])
{
	out[0] = M[0] * x + M[1] * y;
	out[1] = M[2] * x + M[3] * y;
}

/*
 * The stretch that makes the steps to neighbours even in every
 * direction: d holds each point's KD_K steps, of which the SIX
 * shortest under the stretch so far count, their second moment
 * weighted to one a point.  Squashed by S, a lattice's moment is S
 * times its own times S^T, and round a ring of a head the lattice turns
 * through every direction, so its own is even: the stretch is the
 * square root of the moment's two eigenvalues' ratio, along the first.
 * The shortest are chosen again each round (squashing changes which
 * are nearest, and the first choice would hide part of the squash).
 * Only stretched: an oblique view foreshortens one way and leaves the
 * other as it is.
 */
static void
even_directions(const double (*d)[KD_K][2], size_t n, double M[2][2])
{
	M[0][0] = M[1][1] = 1;
	M[0][1] = M[1][0] = 0;
	for (int round = 0; round < 12; round++) {
		double p = 0, q = 0, r = 0, l[2], angle, C[2][2];

		for (size_t i = 0; i < n; i++) {
			double v[KD_K][2], len[KD_K], cut, sum = 0, pp = 0;
			double qq = 0, rr = 0;
			int used = 0;

			for (int k = 0; k < KD_K; k++) {
				apply2(&M[0][0], d[i][k][0], d[i][k][1], v[k]);
				len[k] = v[k][0] * v[k][0] + v[k][1] * v[k][1];
			}
			/* The SIX shortest: up to the sixth's length. */
			{
				double t[KD_K];

				memcpy(t, len, sizeof(t));
				for (int a = 1; a < KD_K; a++)
					for (int b = a; b > 0 && t[b] < t[b - 1];
					    b--) {
						double x = t[b];

						t[b] = t[b - 1];
						t[b - 1] = x;
					}
				cut = t[SIX - 1];
			}
			for (int k = 0; k < KD_K && used < SIX; k++) {
				if (len[k] > cut || len[k] == 0)
					continue;
				pp += v[k][0] * v[k][0];
				qq += v[k][0] * v[k][1];
				rr += v[k][1] * v[k][1];
				sum += len[k];
				used++;
			}
			if (sum > 0) {
				p += pp / sum;
				q += qq / sum;
				r += rr / sum;
			}
		}
		eigen2(p, q, r, l, &angle);
		if (!(l[1] > 0) || l[0] / l[1] < 1 + 1e-9)
			break;
		along(1, sqrt(l[0] / l[1]), angle, C);
		mul2(&C[0][0], &M[0][0]);
		memcpy(M, C, sizeof(C));
	}
}

/* Where the axis is when M squashes: the view's ratio and direction. */
static void
view_of(struct axis *A)
{
	const double *M = &A->M[0][0];
	double l[2], angle;

	/* M^T M's eigenvalues are M's stretches squared. */
	eigen2(M[0] * M[0] + M[2] * M[2], M[0] * M[1] + M[2] * M[3],
	    M[1] * M[1] + M[3] * M[3], l, &angle);
	A->squash = l[0] > 0 ? sqrt(l[1] / l[0]) : 1;
	/* The view squashed the direction M stretches most. */
	A->squash_deg = fmod(angle * 180 / M_PI + 360, 180);
	if (A->squash > 1 - 1e-9)
		A->squash = 1, A->squash_deg = 0;
}

/*
 * The centre's search: each point's six-fold orientation against the
 * direction to a trial centre, summed ring by ring.
 */
struct rings {
	double		(*q)[2];	/* corrected xy, the centre not taken */
	double		(*z6)[2];	/* the orientation, e^(6 i theta) */
	size_t		 n;
	double		 width, inner;	/* a ring's; none within inner */
	double		*acc;		/* 3 a ring */
	size_t		 nrings;
};

static double
coherence(struct rings *G, double cx, double cy)
{
	double F = 0;

	memset(G->acc, 0, 3 * G->nrings * sizeof(*G->acc));
	for (size_t i = 0; i < G->n; i++) {
		double x = G->q[i][0] - cx, y = G->q[i][1] - cy;
		double r = sqrt(x * x + y * y), u, w, a2, b2, a4, b4, a6, b6;
		size_t b;

		if (r < G->inner || (b = (size_t)(r / G->width)) >= G->nrings)
			continue;
		/* (x - iy)^6 / r^6: the direction's sixth power, conjugate. */
		u = x / r;
		w = -y / r;
		a2 = u * u - w * w;
		b2 = 2 * u * w;
		a4 = a2 * a2 - b2 * b2;
		b4 = 2 * a2 * b2;
		a6 = a4 * a2 - b4 * b2;
		b6 = a4 * b2 + b4 * a2;
		G->acc[3 * b] += G->z6[i][0] * a6 - G->z6[i][1] * b6;
		G->acc[3 * b + 1] += G->z6[i][0] * b6 + G->z6[i][1] * a6;
		G->acc[3 * b + 2] += 1;
	}
	for (size_t b = 0; b < G->nrings; b++)
		if (G->acc[3 * b + 2] > 0)
			F += (G->acc[3 * b] * G->acc[3 * b] + G->acc[3 * b + 1] *
			    G->acc[3 * b + 1]) / G->acc[3 * b + 2];
	return F;
}

/*
 * A head's centre, in corrected coordinates, searched from c: a grid
 * over 0.3 of the head's radius either way, then grids a third as
 * fine about the best, to a fiftieth of the spacing.
 */
static void
head_centre(struct rings *G, double spacing, double c[2])
{
	double R2[1024], R, step;
	size_t nr = 0;
	int half = 6;

	for (size_t i = 0; i < G->n && nr < 1024; i += 1 + G->n / 1024) {
		double x = G->q[i][0] - c[0], y = G->q[i][1] - c[1];

		R2[nr++] = sqrt(x * x + y * y);
	}
	R = nr > 0 ? median(R2, nr) * 1.4 : 1;
	/* Rings no finer than the points can fill (an outlier far off). */
	G->width = fmax(0.7 * spacing, 2.5 * R / (double)(4 * G->n + 16));
	G->inner = 1.5 * spacing;
	G->nrings = (size_t)(2.5 * R / G->width) + 2;
	G->acc = xcalloc(3 * G->nrings, sizeof(*G->acc));
	step = 0.3 * R / half;
	while (step > 0.02 * spacing && step > 1e-9 * R) {
		double best = -1, at[2] = { c[0], c[1] };

		for (int i = -half; i <= half; i++)
			for (int j = -half; j <= half; j++) {
				double F = coherence(G, c[0] + i * step,
				    c[1] + j * step);

				if (F > best) {
					best = F;
					at[0] = c[0] + i * step;
					at[1] = c[1] + j * step;
				}
			}
		c[0] = at[0];
		c[1] = at[1];
		half = 3;
		step /= 3;
	}
	free(G->acc);
	G->acc = NULL;
}

/* The squash and centre of a head, into A. */
static void
head(struct axis *A, const struct kd *T, const double (*p)[3], size_t n,
    const double *guess)
{
	double (*d)[KD_K][2] = xcalloc(n + 1, sizeof(*d)), c[2] = { 0, 0 };
	struct rings G = { 0 };
	size_t nd = 0, stride = n > SAMPLE_MAX ? n / SAMPLE_MAX + 1 : 1;
	double Minv[2][2], det;

	/* The steps to the nearest, of points with a whole set of them. */
	for (size_t i = 0; i < n; i += stride) {
		struct kd_near nb;

		kd_nearest(T, p[i], i, 0, &nb);
		if (nb.n < KD_K)
			continue;
		for (int k = 0; k < KD_K; k++) {
			d[nd][k][0] = p[nb.j[k]][0] - p[i][0];
			d[nd][k][1] = p[nb.j[k]][1] - p[i][1];
		}
		nd++;
	}
	even_directions((const double (*)[KD_K][2])d, nd, A->M);
	free(d);
	G.n = (n + stride - 1) / stride;
	G.q = xcalloc(G.n, sizeof(*G.q));
	G.z6 = xcalloc(G.n, sizeof(*G.z6));
	for (size_t i = 0, k = 0; i < n; i += stride, k++) {
		struct kd_near nb;

		apply2(&A->M[0][0], p[i][0], p[i][1], G.q[k]);
		kd_nearest(T, p[i], i, 0, &nb);
		for (int m = 0; m < nb.n && m < SIX; m++) {
			double v[2], len, u, w, a2, b2, a4, b4;

			apply2(&A->M[0][0], p[nb.j[m]][0] - p[i][0],
			    p[nb.j[m]][1] - p[i][1], v);
			len = hypot(v[0], v[1]);
			if (len == 0)
				continue;
			u = v[0] / len;
			w = v[1] / len;
			a2 = u * u - w * w;
			b2 = 2 * u * w;
			a4 = a2 * a2 - b2 * b2;
			b4 = 2 * a2 * b2;
			G.z6[k][0] += (a4 * a2 - b4 * b2) / SIX;
			G.z6[k][1] += (a4 * b2 + b4 * a2) / SIX;
		}
		c[0] += G.q[k][0] / (double)G.n;
		c[1] += G.q[k][1] / (double)G.n;
	}
	if (guess != NULL)
		apply2(&A->M[0][0], guess[0], guess[1], c);
	head_centre(&G, A->spacing, c);
	det = A->M[0][0] * A->M[1][1] - A->M[0][1] * A->M[1][0];
	Minv[0][0] = A->M[1][1] / det;
	Minv[0][1] = -A->M[0][1] / det;
	Minv[1][0] = -A->M[1][0] / det;
	Minv[1][1] = A->M[0][0] / det;
	apply2(&Minv[0][0], c[0], c[1], A->centre);
	free(G.q);
	free(G.z6);
}

/* Gaussian elimination with partial pivoting on [A | b], n <= 4. */
static int
solve(double a[4][5], int n, double x[4])
{
	for (int c = 0; c < n; c++) {
		int p = c;

		for (int r = c + 1; r < n; r++)
			if (fabs(a[r][c]) > fabs(a[p][c]))
				p = r;
		if (!(fabs(a[p][c]) > 1e-300))
			return -1;
		for (int k = 0; k <= n; k++) {
			double t = a[c][k];

			a[c][k] = a[p][k];
			a[p][k] = t;
		}
		for (int r = c + 1; r < n; r++) {
			double f = a[r][c] / a[c][c];

			for (int k = c; k <= n; k++)
				a[r][k] -= f * a[c][k];
		}
	}
	for (int c = n - 1; c >= 0; c--) {
		x[c] = a[c][n];
		for (int k = c + 1; k < n; k++)
			x[c] -= a[c][k] * x[k];
		x[c] /= a[c][c];
	}
	return 0;
}

static const double (*sorting)[3];

static int
by_z(const void *a, const void *b)
{
	double x = sorting[*(const size_t *)a][2];
	double y = sorting[*(const size_t *)b][2];

	return x < y ? -1 : x > y;
}

/*
 * A surface of revolution's centre and squash: x^2 + y^2 = a (x^2 -
 * y^2) + 2 b xy + D x + E y + K, K one a section, in least squares with
 * each section's K taken out; a circle (a = b = 0) if that conic is no
 * ellipse.
 */
static void
sections(struct axis *A, const double (*p)[3], size_t n)
{
	size_t *ix = xcalloc(n, sizeof(*ix)), len = n / 64 > 16 ? n / 64 : 16;
	double m[2] = { 0, 0 }, N[4][5], x[4], Q[2][2], l[2], angle;
	int k, full = 1;

	for (size_t i = 0; i < n; i++) {
		ix[i] = i;
		m[0] += p[i][0] / (double)n;
		m[1] += p[i][1] / (double)n;
	}
	sorting = p;
	qsort(ix, n, sizeof(*ix), by_z);
	sorting = NULL;
again:
	k = full ? 4 : 2;
	memset(N, 0, sizeof(N));
	for (size_t from = 0; from < n; from += len) {
		size_t to = from + len <= n && n - (from + len) >= len ?
		    from + len : n, cnt = to - from;
		double f[5], mean[5] = { 0, 0, 0, 0, 0 };

		for (size_t i = from; i < to; i++) {
			double X = p[ix[i]][0] - m[0], Y = p[ix[i]][1] - m[1];

			mean[0] += (full ? X * X - Y * Y : X) / (double)cnt;
			mean[1] += (full ? 2 * X * Y : Y) / (double)cnt;
			mean[2] += X / (double)cnt;
			mean[3] += Y / (double)cnt;
			mean[4] += (X * X + Y * Y) / (double)cnt;
		}
		for (size_t i = from; i < to; i++) {
			double X = p[ix[i]][0] - m[0], Y = p[ix[i]][1] - m[1];

			f[0] = (full ? X * X - Y * Y : X) - mean[0];
			f[1] = (full ? 2 * X * Y : Y) - mean[1];
			f[2] = X - mean[2];
			f[3] = Y - mean[3];
			f[4] = X * X + Y * Y - mean[4];
			for (int r = 0; r < k; r++) {
				for (int c = 0; c < k; c++)
					N[r][c] += f[r] * f[c];
				N[r][k] += f[r] * f[4];
			}
		}
		if (to == n)
			break;
	}
	if (solve(N, k, x) != 0) {
		x[0] = x[1] = 0;
		x[2] = x[3] = 0;
	}
	if (full && !(hypot(x[0], x[1]) < 0.5)) {
		full = 0;
		goto again;
	}
	if (!full) {
		/* A circle: x^2 + y^2 = D x + E y + K. */
		A->centre[0] = m[0] + x[0] / 2;
		A->centre[1] = m[1] + x[1] / 2;
		A->M[0][0] = A->M[1][1] = 1;
		A->M[0][1] = A->M[1][0] = 0;
		free(ix);
		return;
	}
	/* (xy - c)^T Q (xy - c) = const, Q = [[1 - a, -b], [-b, 1 + a]]. */
	Q[0][0] = 1 - x[0];
	Q[0][1] = Q[1][0] = -x[1];
	Q[1][1] = 1 + x[0];
	{
		double det = Q[0][0] * Q[1][1] - Q[0][1] * Q[1][0];

		A->centre[0] = m[0] + (Q[1][1] * x[2] / 2 - Q[0][1] * x[3] /
		    2) / det;
		A->centre[1] = m[1] + (Q[0][0] * x[3] / 2 - Q[1][0] * x[2] /
		    2) / det;
	}
	/* M = Q^(1/2) scaled to stretch only: the ellipses made circles. */
	eigen2(Q[0][0], Q[0][1], Q[1][1], l, &angle);
	along(sqrt(l[0] / l[1]), 1, angle, A->M);
	free(ix);
}

static int
by_t(const void *a, const void *b)
{
	const double *x = a, *y = b;

	return x[2] < y[2] ? -1 : x[2] > y[2];
}

/* Point (r, z)'s nearest place on the polyline: its arc length. */
static double
project(const double (*node)[3], size_t nn, double r, double z)
{
	double best = HUGE_VAL, at = 0;

	for (size_t k = 0; k + 1 < nn; k++) {
		double dr = node[k + 1][1] - node[k][1];
		double dz = node[k + 1][2] - node[k][2];
		double len2 = dr * dr + dz * dz, u, e;

		u = len2 > 0 ? ((r - node[k][1]) * dr + (z - node[k][2]) *
		    dz) / len2 : 0;
		/* The ends go on straight; inside, a segment ends. */
		if (k > 0 && u < 0)
			u = 0;
		if (k + 2 < nn && u > 1)
			u = 1;
		e = hypot(r - node[k][1] - u * dr, z - node[k][2] - u * dz);
		if (e < best) {
			best = e;
			at = node[k][0] + u * (node[k + 1][0] - node[k][0]);
		}
	}
	return at;
}

/* s of each node from node 0, along the polyline. */
static void
arc(double (*node)[3], size_t nn)
{
	node[0][0] = 0;
	for (size_t k = 1; k < nn; k++)
		node[k][0] = node[k - 1][0] + hypot(node[k][1] -
		    node[k - 1][1], node[k][2] - node[k - 1][2]);
}

/*
 * The generating curve through the corrected points' (rho, z): ordered
 * first along their principal direction, then a few rounds of nodes at
 * the means of equal runs along the curve, smoothed, every point
 * projected on them again.
 */
static void
curve(struct axis *A, const double (*p)[3], size_t n)
{
	double (*rt)[3] = xcalloc(n, sizeof(*rt));
	double mr = 0, mz = 0, crr = 0, crz = 0, czz = 0, l[2], angle;
	size_t nn = n / 40 < 3 ? 3 : n / 40 > CURVE_NODES ? CURVE_NODES : n / 40;
	double (*node)[3] = xcalloc(nn, sizeof(*node));

	for (size_t i = 0; i < n; i++) {
		double x[2];

		apply2(&A->M[0][0], p[i][0] - A->centre[0], p[i][1] - A->centre[1],
		    x);
		rt[i][0] = hypot(x[0], x[1]);
		rt[i][1] = p[i][2];
		mr += rt[i][0] / (double)n;
		mz += rt[i][1] / (double)n;
	}
	for (size_t i = 0; i < n; i++) {
		crr += (rt[i][0] - mr) * (rt[i][0] - mr);
		crz += (rt[i][0] - mr) * (rt[i][1] - mz);
		czz += (rt[i][1] - mz) * (rt[i][1] - mz);
	}
	eigen2(crr, crz, czz, l, &angle);
	for (size_t i = 0; i < n; i++)
		rt[i][2] = (rt[i][0] - mr) * cos(angle) + (rt[i][1] - mz) *
		    sin(angle);
	for (int round = 0; round < 4; round++) {
		qsort(rt, n, sizeof(*rt), by_t);
		for (size_t k = 0; k < nn; k++) {
			size_t from = n * k / nn, to = n * (k + 1) / nn;

			node[k][1] = node[k][2] = 0;
			for (size_t i = from; i < to; i++) {
				node[k][1] += rt[i][0] / (double)(to - from);
				node[k][2] += rt[i][1] / (double)(to - from);
			}
		}
		for (int pass = 0; pass < 2; pass++) {
			double prev[2] = { node[0][1], node[0][2] };

			for (size_t k = 1; k + 1 < nn; k++) {
				double here[2] = { node[k][1], node[k][2] };

				node[k][1] = (prev[0] + 2 * here[0] +
				    node[k + 1][1]) / 4;
				node[k][2] = (prev[1] + 2 * here[1] +
				    node[k + 1][2]) / 4;
				prev[0] = here[0];
				prev[1] = here[1];
			}
		}
		arc(node, nn);
		for (size_t i = 0; i < n; i++)
			rt[i][2] = project((const double (*)[3])node, nn,
			    rt[i][0], rt[i][1]);
	}
	/*
	 * The tip first: the end nearer the axis, or, where both are as
	 * far (a cylinder), the upper one.
	 */
	{
		double r0 = node[0][1], r1 = node[nn - 1][1];
		double far = fmax(r0, r1);
		int flip = fabs(r0 - r1) > 0.1 * far ? r1 < r0 :
		    node[nn - 1][2] > node[0][2];

		if (flip)
			for (size_t k = 0; k < nn / 2; k++) {
				double t[3];

				memcpy(t, node[k], sizeof(t));
				memcpy(node[k], node[nn - 1 - k], sizeof(t));
				memcpy(node[nn - 1 - k], t, sizeof(t));
			}
	}
	arc(node, nn);
	A->node = node;
	A->nnode = nn;
	free(rt);
}

void
axis_find(struct axis *A, const double (*p)[3], size_t n, int has_z,
    const double *guess)
{
	struct kd T;
	double *d = xcalloc(n ? n : 1, sizeof(*d));
	size_t nd = 0, stride = n > SAMPLE_MAX ? n / SAMPLE_MAX + 1 : 1;
	double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
	double hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };

	*A = (struct axis){ .has_z = has_z, .squash = 1 };
	A->M[0][0] = A->M[1][1] = 1;
	kd_init_points(&T, p, n);
	for (size_t i = 0; i < n; i++)
		for (int k = 0; k < 3; k++) {
			lo[k] = fmin(lo[k], p[i][k]);
			hi[k] = fmax(hi[k], p[i][k]);
		}
	/* The median of a sample of SAMPLE_MAX is the median. */
	for (size_t i = 0; i < n; i += stride) {
		struct kd_near nb;

		kd_nearest(&T, p[i], i, 0, &nb);
		d[nd++] = nb.n > 0 ? sqrt(nb.d2[0]) / nb.inv : 0;
	}
	A->spacing = median(d, nd);
	free(d);
	/* Tall, against its width: a cone, not a dome of a head. */
	A->surface = has_z && hi[2] - lo[2] > 0.3 * 0.5 * fmax(hi[0] - lo[0],
	    hi[1] - lo[1]);
	if (A->surface)
		sections(A, p, n);
	else
		head(A, &T, p, n, guess);
	kd_free(&T);
	view_of(A);
	if (has_z)
		curve(A, p, n);
}

/* The curve's unit tangent at node k, from its neighbours. */
static void
node_tangent(const struct axis *A, size_t k, double t[2])
{
	size_t a = k > 0 ? k - 1 : 0, b = k + 1 < A->nnode ? k + 1 : k;
	double dr = A->node[b][1] - A->node[a][1];
	double dz = A->node[b][2] - A->node[a][2], len = hypot(dr, dz);

	t[0] = len > 0 ? dr / len : 1;
	t[1] = len > 0 ? dz / len : 0;
}

/* The segment holding arc length s, and s's place u along it. */
static size_t
segment(const struct axis *A, double s, double *u)
{
	size_t lo = 0, hi = A->nnode - 1;

	while (hi - lo > 1) {
		size_t mid = (lo + hi) / 2;

		if (A->node[mid][0] <= s)
			lo = mid;
		else
			hi = mid;
	}
	*u = A->node[hi][0] > A->node[lo][0] ? (s - A->node[lo][0]) /
	    (A->node[hi][0] - A->node[lo][0]) : 0;
	return lo;
}

void
axis_curve(const struct axis *A, double s, double *rho, double *z)
{
	double u;
	size_t k;

	if (A->nnode < 2) {
		*rho = s;
		*z = 0;
		return;
	}
	k = segment(A, s, &u);
	*rho = A->node[k][1] + u * (A->node[k + 1][1] - A->node[k][1]);
	*z = A->node[k][2] + u * (A->node[k + 1][2] - A->node[k][2]);
}

void
axis_place(const struct axis *A, double s, double phi, double X[3])
{
	double rho, z;

	axis_curve(A, s, &rho, &z);
	X[0] = rho * cos(phi);
	X[1] = rho * sin(phi);
	X[2] = z;
}

void
axis_points(const struct axis *A, const double (*p)[3], size_t n,
    struct axis_point *out)
{
	for (size_t i = 0; i < n; i++) {
		struct axis_point *a = &out[i];

		apply2(&A->M[0][0], p[i][0] - A->centre[0], p[i][1] - A->centre[1],
		    a->p);
		a->p[2] = A->has_z ? p[i][2] : 0;
		a->rho = hypot(a->p[0], a->p[1]);
		a->phi = atan2(a->p[1], a->p[0]);
		if (A->nnode < 2) {
			a->s = a->rho;
			a->t[0] = 1;
			a->t[1] = 0;
		} else {
			double u, t0[2], t1[2], len;
			size_t k;

			a->s = project((const double (*)[3])A->node, A->nnode,
			    a->rho, a->p[2]);
			k = segment(A, a->s, &u);
			u = fmin(fmax(u, 0), 1);
			node_tangent(A, k, t0);
			node_tangent(A, k + 1, t1);
			a->t[0] = (1 - u) * t0[0] + u * t1[0];
			a->t[1] = (1 - u) * t0[1] + u * t1[1];
			len = hypot(a->t[0], a->t[1]);
			a->t[0] = len > 0 ? a->t[0] / len : 1;
			a->t[1] = len > 0 ? a->t[1] / len : 0;
		}
	}
}

void
axis_free(struct axis *A)
{
	free(A->node);
	A->node = NULL;
	A->nnode = 0;
}
