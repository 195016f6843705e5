/*
 * curve.c - the receptacle's generating curve, and where along it a
 * point leaves a disk.
 *
 * The collision model needs, for a new primordium sliding up its
 * generating curve, the first parameter at which it no longer overlaps
 * an earlier one.  In the meridian plane of the new primordium that is
 * where the curve leaves a disk: the squared distance
 * g(u) = |p(u) - q|^2, a polynomial of degree 6 per Bezier segment,
 * crosses S2.  Sampling, or the paper's bisection, can step over a
 * gap; here each piece of the curve is bounded by the box of its
 * control points, and where g is provably convex on a piece (|p''|
 * |p - q| < |p'|^2) the crossing is unique and Newton's method finds it
 * from the free side.  Pieces that are neither clearly inside, clearly
 * outside nor convex are halved (de Casteljau), which only happens for
 * disks as large as the curve's own bends.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/curve.h"
#include "base/mem.h"

#define PIECES_PER_CURVE	512	/* pieces along a smooth profile */
#define PIECES_MAX		8192

/* 8-point Gauss-Legendre nodes and weights on [-1, 1]. */
static const double gl_x[4] = {
	0.1834346424956498, 0.5255324099163290,
	0.7966664774136267, 0.9602898564975363
};
static const double gl_w[4] = {
	0.3626837833783620, 0.3137066458778873,
	0.2223810344533745, 0.1012285362903763
};

static double	convex_radius(const double b[4][2]);

static void
to_power(struct piece *p)
{
	for (int k = 0; k < 2; k++) {
		double b0 = p->b[0][k], b1 = p->b[1][k], b2 = p->b[2][k],
		    b3 = p->b[3][k];

		p->c[0][k] = b0;
		p->c[1][k] = 3 * (b1 - b0);
		p->c[2][k] = 3 * (b2 - 2 * b1 + b0);
		p->c[3][k] = b3 - 3 * b2 + 3 * b1 - b0;
	}
}

static inline void
piece_eval(const struct piece *p, double u, double x[2], double d[2])
{
	for (int k = 0; k < 2; k++) {
		x[k] = ((p->c[3][k] * u + p->c[2][k]) * u + p->c[1][k]) * u +
		    p->c[0][k];
		if (d != NULL)
			d[k] = (3 * p->c[3][k] * u + 2 * p->c[2][k]) * u +
			    p->c[1][k];
	}
}

/* The box of control points b: least and largest of each coordinate. */
static void
bez_box(const double b[4][2], double box[2][2])
{
	for (int k = 0; k < 2; k++) {
		box[k][0] = box[k][1] = b[0][k];
		for (int i = 1; i < 4; i++) {
			if (b[i][k] < box[k][0])
				box[k][0] = b[i][k];
			if (b[i][k] > box[k][1])
				box[k][1] = b[i][k];
		}
	}
}

/* Split b at u: the part before into lo, after into hi (either NULL). */
static void
bez_split(const double b[4][2], double u, double lo[4][2], double hi[4][2])
{
	for (int k = 0; k < 2; k++) {
		double a = b[0][k] + (b[1][k] - b[0][k]) * u;
		double m = b[1][k] + (b[2][k] - b[1][k]) * u;
		double c = b[2][k] + (b[3][k] - b[2][k]) * u;
		double am = a + (m - a) * u, mc = m + (c - m) * u;
		double x = am + (mc - am) * u;

		if (lo != NULL) {
			lo[0][k] = b[0][k];
			lo[1][k] = a;
			lo[2][k] = am;
			lo[3][k] = x;
		}
		if (hi != NULL) {
			hi[0][k] = x;
			hi[1][k] = mc;
			hi[2][k] = c;
			hi[3][k] = b[3][k];
		}
	}
}

/* The part of b between u0 and u1. */
static void
bez_sub(const double b[4][2], double u0, double u1, double out[4][2])
{
	double tmp[4][2];

	bez_split(b, u1, tmp, NULL);
	if (u1 > 0)
		bez_split((const double (*)[2])tmp, u0 / u1, NULL, out);
	else
		memcpy(out, tmp, sizeof(tmp));
}

/* Arc length of piece p from 0 to u; with area, the area it sweeps. */
static double
piece_measure(const struct piece *p, double u, double *area)
{
	double sum = 0, sweep = 0, h = u / 2;

	for (int i = 0; i < 4; i++)
		for (int sgn = -1; sgn <= 1; sgn += 2) {
			double x[2], d[2], ds;

			piece_eval(p, h + sgn * h * gl_x[i], x, d);
			ds = sqrt(d[0] * d[0] + d[1] * d[1]);
			sum += gl_w[i] * ds;
			sweep += gl_w[i] * 2 * M_PI * x[0] * ds;
		}
	if (area != NULL)
		*area = sweep * h;
	return sum * h;
}

static double
piece_length(const struct piece *p, double u)
{
	return piece_measure(p, u, NULL);
}

/* 4-point Gauss-Legendre nodes and weights on [-1, 1], the positive half. */
static const double gl4_x[2] = { 0.3399810435848563, 0.8611363115940526 };
static const double gl4_w[2] = { 0.6521451548625461, 0.3478548451374538 };

/*
 * The area piece p sweeps between u0 and u1, by Gauss-Legendre with the
 * half nodes x and weights w (their mirror images are implied).
 */
static inline double
piece_area_nodes(const struct piece *p, double u0, double u1,
    const double *x, const double *w, int half)
{
	double h = (u1 - u0) / 2, m = (u0 + u1) / 2, sum = 0;

	for (int i = 0; i < half; i++)
		for (int sgn = -1; sgn <= 1; sgn += 2) {
			double q[2], d[2];

			piece_eval(p, m + sgn * h * x[i], q, d);
			sum += w[i] * q[0] * sqrt(d[0] * d[0] + d[1] * d[1]);
		}
	return 2 * M_PI * sum * h;
}

/* With 8 points: the table's. */
static double
piece_area_gl(const struct piece *p, double u0, double u1)
{
	return piece_area_nodes(p, u0, u1, gl_x, gl_w, 4);
}

/*
 * From 0 to u with 4 points, for the inverse's Newton steps: the table
 * was built with 8 points, adaptively; inside one short piece the
 * integrand is so smooth that 4 points agree with it to 1e-15.
 */
static double
piece_area_to(const struct piece *p, double u)
{
	return piece_area_nodes(p, 0, u, gl4_x, gl4_w, 2);
}

/*
 * The same, adaptively: halves until the two agree with the whole to
 * tol, which the smooth pieces of a Bezier curve reach at once; a
 * cusp (a pole's tangent turning) takes a few levels.
 */
static double
piece_area_adapt(const struct piece *p, double u0, double u1, double whole,
    double tol, int depth)
{
	double m = (u0 + u1) / 2;
	double a = piece_area_gl(p, u0, m), b = piece_area_gl(p, m, u1);

	if (depth >= 30 || fabs(a + b - whole) <= tol)
		return a + b;
	return piece_area_adapt(p, u0, m, a, tol / 2, depth + 1) +
	    piece_area_adapt(p, m, u1, b, tol / 2, depth + 1);
}

static double
seg_polylen(const double (*b)[2])
{
	double len = 0;

	for (int i = 0; i < 3; i++)
		len += hypot(b[i + 1][0] - b[i][0], b[i + 1][1] - b[i][1]);
	return len;
}

int
curve_init(struct curve *cv, const double (*pts)[2], int npts)
{
	int nseg = (npts - 1) / 3;
	double total = 0, s = 0, a;
	size_t n = 0, *per = xcalloc((size_t)nseg, sizeof(*per));

	memset(cv, 0, sizeof(*cv));
	for (int k = 0; k < nseg; k++)
		total += seg_polylen(pts + 3 * k);
	if (!(total > 0) || !isfinite(total)) {
		free(per);
		return -1;
	}
	for (int k = 0; k < nseg; k++) {
		double want = ceil(seg_polylen(pts + 3 * k) / total *
		    PIECES_PER_CURVE);

		per[k] = want < 1 ? 1 : (size_t)want;
		n += per[k];
	}
	/* Many segments: fewer pieces each, never below one. */
	while (n > PIECES_MAX) {
		n = 0;
		for (int k = 0; k < nseg; k++) {
			per[k] = (per[k] + 1) / 2;
			n += per[k];
		}
	}
	cv->pc = xcalloc(n, sizeof(*cv->pc));
	cv->t0 = xcalloc(n + 1, sizeof(*cv->t0));
	cv->first = xcalloc((size_t)nseg + 1, sizeof(*cv->first));
	cv->tmax = nseg;
	for (int k = 0; k < nseg; k++) {
		cv->first[k + 1] = cv->first[k] + per[k];
		for (size_t j = 0; j < per[k]; j++) {
			struct piece *p = &cv->pc[cv->npc++];
			double u0 = (double)j / (double)per[k];
			double u1 = (double)(j + 1) / (double)per[k];

			bez_sub((const double (*)[2])(pts + 3 * k), u0, u1,
			    p->b);
			to_power(p);
			p->kappa = convex_radius((const double (*)[2])p->b);
			bez_box((const double (*)[2])p->b, p->box);
			p->t0 = k + u0;
			p->t1 = k + u1;
			cv->t0[cv->npc - 1] = p->t0;
			cv->t0[cv->npc] = p->t1;
			p->s0 = s;
			s += piece_measure(p, 1, &a);
			p->a0 = cv->area;
			for (int e = 0; e < 2; e++) {
				double x[2], d[2];

				piece_eval(p, e, x, d);
				p->da[e] = 2 * M_PI * x[0] * sqrt(d[0] * d[0] +
				    d[1] * d[1]);
			}
			/* A tolerance in the size of the piece's own area. */
			cv->area += piece_area_adapt(p, 0, 1, a,
			    1e-15 * fabs(a) + 1e-300, 0);
			for (int i = 0; i < 4; i++) {
				if (p->b[i][0] > cv->rho_max)
					cv->rho_max = p->b[i][0];
				/* The hodograph's control points bound p'. */
				if (i < 3)
					cv->speed = fmax(cv->speed, 3 * hypot(
					    p->b[i + 1][0] - p->b[i][0],
					    p->b[i + 1][1] - p->b[i][1]) /
					    (p->t1 - p->t0));
			}
		}
	}
	free(per);
	cv->length = s;
	if (!(s > 0)) {
		curve_free(cv);
		return -1;
	}
	return 0;
}

void
curve_free(struct curve *cv)
{
	free(cv->pc);
	free(cv->t0);
	free(cv->first);
	memset(cv, 0, sizeof(*cv));
}

/*
 * The piece holding t (the last that starts at or before it), and t as
 * that piece's u.  A segment's pieces split its u evenly, so the index
 * comes from t, set right where rounding put it one off; the starts
 * are read from their own short array.  The walk asks this a dozen
 * times a primordium: a search through the pieces themselves took 5%
 * of its time.
 */
static size_t
piece_find(const struct curve *cv, double t, double *u)
{
	const double *t0 = cv->t0;
	size_t k = 0, i, n;
	double f;

	if (t > 0)
		k = t < cv->tmax ? (size_t)t : (size_t)cv->tmax - 1;
	n = cv->first[k + 1] - cv->first[k];
	f = (t - (double)k) * (double)n;
	i = cv->first[k] + (f > 0 ? (f < (double)n ? (size_t)f : n - 1) : 0);
	while (i > 0 && t0[i] > t)
		i--;
	while (i + 1 < cv->npc && t0[i + 1] <= t)
		i++;
	*u = (t - t0[i]) / (t0[i + 1] - t0[i]);
	if (*u < 0)
		*u = 0;
	else if (*u > 1)
		*u = 1;
	return i;
}

void
curve_eval(const struct curve *cv, double t, double p[2], double d[2])
{
	double u;
	const struct piece *pc = &cv->pc[piece_find(cv, t, &u)];

	piece_eval(pc, u, p, d);
	if (d != NULL) {
		d[0] /= pc->t1 - pc->t0;
		d[1] /= pc->t1 - pc->t0;
	}
}

double
curve_s(const struct curve *cv, double t)
{
	double u;
	const struct piece *pc = &cv->pc[piece_find(cv, t, &u)];

	return pc->s0 + piece_length(pc, u);
}

double
curve_t(const struct curve *cv, double s)
{
	size_t lo = 0, hi = cv->npc - 1;
	const struct piece *pc;
	double a = 0, b = 1, u, want;

	if (s <= 0)
		return 0;
	if (s >= cv->length)
		return cv->tmax;
	while (lo < hi) {
		size_t mid = (lo + hi + 1) / 2;

		if (cv->pc[mid].s0 <= s)
			lo = mid;
		else
			hi = mid - 1;
	}
	pc = &cv->pc[lo];
	want = s - pc->s0;
	/* Newton on the arc length, kept inside a bracket. */
	u = 0.5;
	for (int i = 0; i < 60 && b - a > 1e-15; i++) {
		double x[2], d[2], f = piece_length(pc, u) - want, fp, nu;

		if (f < 0)
			a = u;
		else
			b = u;
		piece_eval(pc, u, x, d);
		fp = hypot(d[0], d[1]);
		nu = fp > 0 ? u - f / fp : -1;
		if (!(nu > a && nu < b))
			nu = (a + b) / 2;
		if (fabs(nu - u) < 1e-16)
			break;
		u = nu;
	}
	return pc->t0 + u * (pc->t1 - pc->t0);
}

double
curve_area(const struct curve *cv, double t)
{
	double u;
	const struct piece *pc = &cv->pc[piece_find(cv, t, &u)];

	return pc->a0 + (u > 0 ? piece_area_gl(pc, 0, u) : 0);
}

double
curve_t_area(const struct curve *cv, double a, size_t *hint, double p[2],
    double d[2])
{
	size_t i = hint != NULL && *hint < cv->npc ? *hint : 0;
	const struct piece *pc;
	double lo = 0, hi = 1, u, want, span;

	if (a <= 0 || a >= cv->area) {
		double t = a <= 0 ? 0 : cv->tmax;

		if (p != NULL)
			curve_eval(cv, t, p, d);
		return t;
	}
	if (cv->pc[i].a0 > a)
		i = 0;
	while (i + 1 < cv->npc && cv->pc[i + 1].a0 <= a)
		i++;
	if (hint != NULL)
		*hint = i;
	pc = &cv->pc[i];
	want = a - pc->a0;
	span = (i + 1 < cv->npc ? cv->pc[i + 1].a0 : cv->area) - pc->a0;
	/*
	 * The first guess takes the area's rate as linear across the piece
	 * (a quadratic to solve), good to about the cube of the piece's
	 * length; Newton then needs a step or two, kept inside a bracket.
	 * A step below 1e-5 of the piece leaves an error of about its
	 * square, 1e-10 of a piece, 1e-13 of the curve: done.
	 */
	{
		double f0 = pc->da[0], f1 = pc->da[1], qa = (f1 - f0) / 2;
		double c = want * (f0 + f1) / (2 * span), disc = f0 * f0 +
		    4 * qa * c;

		u = span > 0 && f0 + f1 > 0 && disc >= 0 && f0 + sqrt(disc) >
		    0 ? 2 * c / (f0 + sqrt(disc)) : span > 0 ? want / span : 0.5;
		if (!(u > 0 && u < 1))
			u = span > 0 ? want / span : 0.5;
	}
	for (int k = 0; k < 60; k++) {
		double x[2], d[2], f = piece_area_to(pc, u) - want, fp, nu;

		if (f < 0)
			lo = u;
		else
			hi = u;
		piece_eval(pc, u, x, d);
		fp = 2 * M_PI * x[0] * sqrt(d[0] * d[0] + d[1] * d[1]);
		nu = fp > 0 ? u - f / fp : -1;
		if (!(nu >= lo && nu <= hi)) {
			nu = (lo + hi) / 2;
			if (hi - lo <= 1e-15) {
				u = nu;
				break;
			}
		} else if (fabs(nu - u) < 1e-5) {
			/* Newton's error is about the step squared: 1e-10. */
			u = nu;
			break;
		}
		u = nu;
	}
	if (p != NULL) {
		piece_eval(pc, u, p, d);
		d[0] /= pc->t1 - pc->t0;
		d[1] /= pc->t1 - pc->t0;
	}
	return pc->t0 + u * (pc->t1 - pc->t0);
}

/* Nearest and farthest squared distance from q to a box. */
static void
box_dist(const double box[2][2], const double q[2], double *near2,
    double *far2)
{
	double n2 = 0, f2 = 0;

	for (int k = 0; k < 2; k++) {
		double lo = box[k][0], hi = box[k][1];
		double a = fabs(q[k] - lo), b = fabs(q[k] - hi);
		double dn = q[k] < lo ? lo - q[k] : q[k] > hi ? q[k] - hi : 0;
		double df = a > b ? a : b;	/* fmax() is a call */

		n2 += dn * dn;
		f2 += df * df;
	}
	*near2 = n2;
	*far2 = f2;
}

/* Squared distance from the origin to segment ab. */
static double
seg_dist2(const double a[2], const double b[2])
{
	double ab[2] = { b[0] - a[0], b[1] - a[1] };
	double len2 = ab[0] * ab[0] + ab[1] * ab[1];
	double s = len2 > 0 ? -(a[0] * ab[0] + a[1] * ab[1]) / len2 : 0;
	double x, y;

	s = s < 0 ? 0 : s > 1 ? 1 : s;
	x = a[0] + s * ab[0];
	y = a[1] + s * ab[1];
	return x * x + y * y;
}

/*
 * A radius within which g(u) = |p(u) - q|^2 is convex on b: g'' =
 * 2 (|p'|^2 + (p - q).p'') >= 2 (m1^2 - m2 |p - q|), with m1 a lower
 * bound of |p'| (the distance from 0 to the hodograph's control
 * triangle) and m2 an upper bound of |p''| (linear: its end values).
 */
static double
convex_radius(const double b[4][2])
{
	double d[3][2], m1, m2 = 0, cross[3];
	int inside;

	for (int i = 0; i < 3; i++)
		for (int k = 0; k < 2; k++)
			d[i][k] = 3 * (b[i + 1][k] - b[i][k]);
	for (int i = 0; i < 2; i++) {
		double x = 2 * (d[i + 1][0] - d[i][0]);
		double y = 2 * (d[i + 1][1] - d[i][1]);

		m2 = fmax(m2, hypot(x, y));
	}
	for (int i = 0; i < 3; i++) {
		const double *a = d[i], *c = d[(i + 1) % 3];

		cross[i] = a[0] * c[1] - a[1] * c[0];
	}
	/*
	 * The origin inside the triangle: no lower bound.  A flat
	 * triangle (a straight piece: the hodograph's points in a line,
	 * every cross product 0) holds the origin only on its edges, which
	 * the distances below find; the sign test would say "inside".
	 */
	inside = (cross[0] >= 0 && cross[1] >= 0 && cross[2] >= 0) ||
	    (cross[0] <= 0 && cross[1] <= 0 && cross[2] <= 0);
	if (inside && cross[0] + cross[1] + cross[2] != 0)
		return 0;
	m1 = fmin(seg_dist2(d[0], d[1]), fmin(seg_dist2(d[1], d[2]),
	    seg_dist2(d[2], d[0])));
	return m2 > 0 ? m1 / m2 : HUGE_VAL;
}

/*
 * At u: g(u) - S2, with g(u) = |p(u) - q|^2 the squared distance from
 * q, half its slope (p - q).p' and |p'|^2, which the tangent's exit
 * from the disk needs.  Kept, so that no point is evaluated twice.
 */
struct sq_dist {
	double	 f, half, dd;
};

static inline double
sq_dist(const struct piece *p, double u, const double q[2], double S2,
    struct sq_dist *g)
{
	double x[2], d[2];

	piece_eval(p, u, x, d);
	x[0] -= q[0];
	x[1] -= q[1];
	g->half = x[0] * d[0] + x[1] * d[1];
	g->dd = d[0] * d[0] + d[1] * d[1];
	return g->f = x[0] * x[0] + x[1] * x[1] - S2;
}

/*
 * The crossing of a convex g - S2 from below (at lo) to above (at hi).
 * Newton's method from the free side of a convex function stays there
 * and never overshoots: the root lies within one Newton step below
 * hi, so a step under 1e-12 of a piece ends it (a few 1e-15 of arc
 * length on a usual receptacle: below that, rounding in g is all there
 * is to chase).  It starts where the tangent at lo leaves the disk, or
 * one Newton step beyond if the curve has bent back in by then.
 * Bisection takes over where rounding has the last word.
 */
#define U_EPS	1e-12

static double
crossing(const struct piece *p, double lo, double hi, const double q[2],
    double S2, const struct sq_dist *at_lo, const struct sq_dist *at_hi)
{
	double a = at_lo->dd, b = at_lo->half, disc, top = hi;
	struct sq_dist h = *at_hi, g;	/* h: g at hi, always */

	disc = b * b - a * at_lo->f;
	if (a > 0 && disc >= 0) {
		double guess = lo + (-b + sqrt(disc)) / a;

		if (guess > lo && guess < hi) {
			/*
			 * Still inside, but rising: a convex function lies
			 * above its tangent, so the tangent's zero is free.
			 */
			if (sq_dist(p, guess, q, S2, &g) >= 0) {
				hi = guess;
				h = g;
			} else if (g.half > 0) {
				double beyond = guess - g.f / (2 * g.half);

				lo = guess;
				if (beyond < hi) {
					hi = beyond;
					sq_dist(p, hi, q, S2, &h);
				}
			}
		}
	}
	if (h.f < 0) {
		/* Rounding put the guess inside: back to the known end. */
		lo = hi;
		hi = top;
		h = *at_hi;
	}
	for (int i = 0; i < 100 && hi - lo > U_EPS; i++) {
		double fph = 2 * h.half;
		double step = fph > 0 ? h.f / fph : HUGE_VAL, nu = hi - step;

		if (step <= U_EPS)
			break;
		if (!(nu > lo))
			nu = lo + (hi - lo) / 2;
		if (sq_dist(p, nu, q, S2, &g) < 0)
			lo = nu;
		else {
			hi = nu;
			h = g;
		}
	}
	return hi;
}

static double	exit_part(const struct piece *, const double b[4][2], double,
		    double, const double q[2], double, double);

/*
 * The first u in [u0, u1] at which piece p is free; -1: none.  b holds
 * the control points of that part of p, or of a larger part when the
 * piece is convex for this disk anyway (only its box is used then);
 * near2 and far2 are the squared distances from q to b's box, least
 * and most.
 */
static double
exit_sub(const struct piece *p, const double b[4][2], double near2,
    double far2, double u0, double u1, const double q[2], double S2,
    double kappa)
{
	double k, half[2][4][2], mid;
	struct sq_dist lo, hi;

	if (near2 >= S2)
		return u0;
	if (far2 < S2)
		return -1;
	if (sq_dist(p, u0, q, S2, &lo) >= 0)
		return u0;
	/* A part of a convex piece is convex: no need to look again. */
	k = far2 < kappa * kappa ? kappa : convex_radius(b);
	if (far2 < k * k) {
		if (sq_dist(p, u1, q, S2, &hi) < 0)
			return -1;
		return crossing(p, u0, u1, q, S2, &lo, &hi);
	}
	mid = (u0 + u1) / 2;
	if (mid <= u0 || mid >= u1)	/* as small as doubles go */
		return sq_dist(p, u1, q, S2, &hi) >= 0 ? u1 : -1;
	bez_split(b, 0.5, half[0], half[1]);
	if ((k = exit_part(p, (const double (*)[2])half[0], u0, mid, q, S2,
	    0)) >= 0)
		return k;
	return exit_part(p, (const double (*)[2])half[1], mid, u1, q, S2, 0);
}

/* exit_sub() of a part of p, by its own box. */
static double
exit_part(const struct piece *p, const double b[4][2], double u0,
    double u1, const double q[2], double S2, double kappa)
{
	double box[2][2], near2, far2;

	bez_box(b, box);
	box_dist((const double (*)[2])box, q, &near2, &far2);
	return exit_sub(p, b, near2, far2, u0, u1, q, S2, kappa);
}

double
curve_exit(const struct curve *cv, double t, const double q[2], double S2,
    double at[2])
{
	double u, part[4][2];
	size_t i = piece_find(cv, t, &u);

	for (; i < cv->npc; i++, u = 0) {
		const struct piece *p = &cv->pc[i];
		double e, near2, far2;

		/*
		 * The part from u on, by its own box; but where the piece
		 * is convex for this disk even by its whole box (mostly: the
		 * disk is small beside the piece), that box will do.
		 */
		box_dist((const double (*)[2])p->box, q, &near2, &far2);
		if (u > 0 && !(far2 < p->kappa * p->kappa)) {
			bez_sub((const double (*)[2])p->b, u, 1, part);
			e = exit_part(p, (const double (*)[2])part, u, 1, q, S2,
			    p->kappa);
		} else
			e = exit_sub(p, (const double (*)[2])p->b, near2, far2, u,
			    1, q, S2, p->kappa);
		if (e >= 0) {
			if (at != NULL)
				piece_eval(p, e, at, NULL);
			return p->t0 + e * (p->t1 - p->t0);
		}
	}
	return HUGE_VAL;
}
