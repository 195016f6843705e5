/*
 * area.c - the area-based model (seed 004's compact patterns, after
 * Ridley's area rule): organs spread evenly by area over a surface of
 * revolution.  Organ n sits at angle n alpha and at the point of the
 * generating curve where the area swept from the base reaches its
 * share: with count alone, equal shares, organ n at (n + 1/2)/N of the
 * whole (on a sphere, the Fibonacci sphere lattice); with a radius,
 * each organ takes the area of its own hexagonal cell, 2 sqrt(3) r^2,
 * and sits in the middle of it, so the count follows from the surface
 * and the size may vary along it.
 *
 * Closed form per organ but for one root: the area table of curve.c
 * (adaptive quadrature per Bezier piece) and a monotone Newton step
 * inside the piece (curve_t_area), O(1) an organ since the shares rise.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "geometry/curve.h"
#include "diag.h"
#include "mem.h"
#include "models/model.h"
#include "analysis/design.h"
#include "geometry/receptacle.h"

enum { AR_RECEPTACLE, AR_RADIUS, AR_PARASTICHIES, AR__N };

struct area {
	struct group_at	 at;
	int		 given[AR__N];
	struct receptacle receptacle;
	struct expr_setting radius;	/* of organ n, or not given */
	struct int_list	 parastichies;	/* instead of radius: the pair wanted */
};

#define A(f)	offsetof(struct area, f)

static const struct row area_rows[] = {
	[AR_RECEPTACLE] = { .name = "receptacle", .type = T_GROUP,
	  .off = A(receptacle), .sub = &receptacle_table,
	  .doc = "the surface of revolution the organs cover" },
	[AR_RADIUS] = { .name = "radius", .type = T_EXPR, .off = A(radius),
	  .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .unit = "length",
	  .doc = "radius of organ n; its hexagonal cell's area is its share" },
	[AR_PARASTICHIES] = { .name = "parastichies", .type = T_INTS,
	  .off = A(parastichies), .lo = 1, .hi = 1000, .defstr = "none",
	  .doc = "instead of radius: the contact pair [m, n] wanted at the "
	  "base" },
};

static const struct table area_table = TABLE(area_rows, struct area);

/* The area of the hexagonal cell of a circle of radius r. */
#define CELL(r)		(2 * sqrt(3.0) * (r) * (r))

/* Where each organ's share ends up: its area mark and its radius. */
struct share {
	double	 mark, r;
};

/* Radius mode: organ after organ until the next cell would not fit. */
static struct share *
shares_by_radius(const struct scene *sc, const struct area *P,
    double total, double rconst, long long most, size_t *count)
{
	struct expr_env env = { { 0 }, (uint64_t)sc->seed, 0 };
	long long N = sc->given[S_COUNT] ? sc->count : COUNT_MAX;
	int capped = sc->given[S_COUNT] || most > 0;
	size_t n = 0, cap = 4096;
	struct share *sh = xcalloc(cap, sizeof(*sh));
	double used = 0;

	if (most > 0 && most < N)
		N = most;
	if (rconst <= 0 && !sc->given[S_COUNT] && (expr_vars(P->radius.e) &
	    (EXPR_VAR(V_COUNT) | EXPR_VAR(V_T)))) {
		scene_error(sc, P->radius.line, "area.radius uses N or t, "
		    "which need count: without it the surface decides how "
		    "many organs there are");
		free(sh);
		return NULL;
	}
	{
		double r0;

		/* A constant radius: the count is known before the loop. */
		if (rconst > 0)
			r0 = rconst;
		else if (!expr_is_constant(P->radius.e, &r0))
			r0 = 0;
		if (!capped && r0 > 0 && total / CELL(r0) > COUNT_MAX) {
			scene_error(sc, P->radius.line, "area.radius %.9g is so "
			    "small that the receptacle holds more than %d "
			    "organs; make it larger or set count", r0,
			    COUNT_MAX);
			free(sh);
			return NULL;
		}
	}
	for (;; n++) {
		double r, cell;

		if ((long long)n == N) {
			if (capped)
				break;
			scene_error(sc, P->radius.line, "area.radius is so "
			    "small that the receptacle holds more than %d "
			    "organs; make it larger or set count", COUNT_MAX);
			free(sh);
			return NULL;
		}
		env.n = (long long)n;
		env.var[V_N] = (double)n;
		env.var[V_COUNT] = (double)N;
		env.var[V_T] = N > 1 ? (double)n / (double)(N - 1) : 0;
		if (rconst > 0)
			r = rconst;
		else if (scene_eval(sc, &P->radius, "area.radius", "organ", &env,
		    &r) != 0) {
			free(sh);
			return NULL;
		}
		if (!(r > 0)) {
			diag(ST_SCENE, sc->file, P->radius.line, 0, "area.radius "
			    "is %.9g at organ %zu; it must be positive", r, n);
			free(sh);
			return NULL;
		}
		cell = CELL(r);
		if (used + cell > total * (1 + 1e-12) && n == 0) {
			diag(ST_SCENE, sc->file, P->radius.line, 0, "area.radius "
			    "%.9g is too large: one organ's cell, %.9g, is more "
			    "than the receptacle's area, %.9g", r, cell, total);
			free(sh);
			return NULL;
		}
		if (used + cell > total * (1 + 1e-12))
			break;
		if (n == cap)
			sh = xreallocarray(sh, cap *= 2, sizeof(*sh));
		sh[n].mark = used + cell / 2;
		sh[n].r = r;
		used += cell;
	}
	*count = n;
	return sh;
}

/* The organ at area mark a, angle phi: on the curve, framed. */
static void
place(const struct curve *cv, double a, size_t *hint, double phi,
    struct organ *o)
{
	double p[2], d[2], e = 1e-12 * (cv->length + 1);
	double t = curve_t_area(cv, a, hint, p, d);

	if (d[0] * d[0] + d[1] * d[1] < e * e) {
		/* A cusp: the chord across it gives the direction. */
		double lo[2], hi[2], dt = 1e-6 * cv->tmax;

		curve_eval(cv, fmax(t - dt, 0), lo, NULL);
		curve_eval(cv, fmin(t + dt, cv->tmax), hi, NULL);
		d[0] = hi[0] - lo[0];
		d[1] = hi[1] - lo[1];
	}
	/* u along the generating curve, away from the tip: towards the base. */
	frame_revolution(o, phi, p[0], p[1], -d[0], -d[1]);
}

static int
place_area(const struct scene *sc, const struct area *P, struct result *res,
    double rconst, long long cap)
{
	struct curve cv;
	struct share *sh = NULL;
	double (*pts)[2], rmin = HUGE_VAL, rmax = 0, r_even = 0;
	size_t count = 0, hint = 0;
	int npts;

	if (!P->given[AR_RADIUS] && rconst <= 0 && !sc->given[S_COUNT]) {
		scene_error(sc, GIVEN_AT(P, AR_RADIUS), "give count (organs "
		    "spread evenly), area.radius (each organ's own size), or "
		    "both");
		return -1;
	}
	if ((pts = receptacle_points(sc, &P->receptacle, &npts)) == NULL)
		return -1;
	if (curve_init(&cv, (const double (*)[2])pts, npts) != 0) {
		scene_error(sc, GIVEN_AT(&P->receptacle, RC_PROFILE),
		    "the receptacle's profile has no length");
		free(pts);
		return -1;
	}
	free(pts);
	if (!(cv.area > 0)) {
		scene_error(sc, GIVEN_AT(&P->receptacle, RC_PROFILE),
		    "the receptacle has no area: its profile lies on the "
		    "axis");
		curve_free(&cv);
		return -1;
	}
	if (P->given[AR_RADIUS] || rconst > 0) {
		if ((sh = shares_by_radius(sc, P, cv.area, rconst, cap,
		    &count)) == NULL) {
			curve_free(&cv);
			return -1;
		}
	} else {
		count = (size_t)sc->count;
		/* N organs of hexagonal packing share the area. */
		r_even = sqrt(cv.area / (2 * sqrt(3.0) * (double)count));
	}

	result_init(res, count);
	res->divergence = sc->divergence;
	for (size_t n = 0; n < count; n++) {
		struct organ *o = &res->organs[n];
		double mark = sh != NULL ? sh[n].mark :
		    cv.area * ((double)n + 0.5) / (double)count;

		place(&cv, mark, &hint, angle_mod360((double)n,
		    sc->divergence), o);
		o->radius = sh != NULL ? sh[n].r : r_even;
		o->scale = o->radius;
		if (o->radius < rmin)
			rmin = o->radius;
		if (o->radius > rmax)
			rmax = o->radius;
	}
	result_info(res, "area", 1, cv.area);
	if (count > 0)
		result_info(res, "radius", 2, rmin, rmax);
	result_info_labelled(res, "receptacle", "length radius", 2, cv.length,
	    cv.rho_max);
	free(sh);
	curve_free(&cv);
	return 0;
}

struct trial {
	const struct scene *sc;
	const struct area *P;
};

static int
trial_place(void *ctx, double r, long long cap, struct result *res)
{
	const struct trial *T = ctx;

	return place_area(T->sc, T->P, res, r, cap);
}

static int
area_run(const struct scene *sc, const void *params, struct result *res)
{
	const struct area *P = params;
	struct trial T = { sc, P };
	int at = P->given[AR_PARASTICHIES], npts;
	double (*pts)[2], rim, rhi, r;
	struct curve cv;

	if (!at)
		return place_area(sc, P, res, 0, 0);
	if (P->given[AR_RADIUS]) {
		scene_error(sc, at, "give area.radius or area.parastichies, "
		    "not both");
		return -1;
	}
	if ((pts = receptacle_points(sc, &P->receptacle, &npts)) == NULL)
		return -1;
	rim = pts[0][0];
	/* At most a radius whose cell fits four times. */
	rhi = rim * M_PI / 3;
	if (curve_init(&cv, (const double (*)[2])pts, npts) == 0) {
		rhi = fmin(rhi, sqrt(cv.area / (8 * sqrt(3.0))));
		curve_free(&cv);
	}
	free(pts);
	r = para_design_radius(sc, at, "area.parastichies", &P->parastichies,
	    rim, rhi, trial_place, &T);
	/* --info's radius line is the one chosen. */
	return r < 0 ? -1 : place_area(sc, P, res, r, 0);
}

const struct model area_model = {
	.name = "area",
	.help = "area-based: organs spread evenly by area on a receptacle "
	    "(Fibonacci sphere)",
	.settings = &area_table,
	.size = sizeof(struct area),
	.run = area_run,
	.svg = PROJ_TOP,
};
