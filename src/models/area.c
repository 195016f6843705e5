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

#include "analysis/design.h"
#include "base/diag.h"
#include "geometry/curve.h"
#include "geometry/geometry.h"
#include "geometry/receptacle.h"
#include "base/mem.h"
#include "models/model.h"

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
shares_by_radius(const struct model_ctx *ctx, const struct area *P,
    double total, double rconst, long long most, size_t *count)
{
	struct expr_env env = { { 0 }, (uint64_t)ctx->seed, 0 };
	long long N = ctx->count_line ? ctx->count : COUNT_MAX;
	int capped = ctx->count_line || most > 0;
	size_t n = 0, cap = 4096;
	struct share *sh = xcalloc(cap, sizeof(*sh));
	double used = 0;

	if (most > 0 && most < N)
		N = most;
	if (rconst <= 0 && !ctx->count_line && (expr_vars(P->radius.e) &
	    (EXPR_VAR(V_COUNT) | EXPR_VAR(V_T)))) {
		model_error(ctx, P->radius.line, "area.radius uses N or t, "
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
			model_error(ctx, P->radius.line, "area.radius %.9g is "
			    "so small that the receptacle holds more than %d "
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
			model_error(ctx, P->radius.line, "area.radius is so "
			    "small that the receptacle holds more than %d "
			    "organs; make it larger or set count", COUNT_MAX);
			free(sh);
			return NULL;
		}
		expr_env_organ(&env, (long long)n, N);
		if (rconst > 0)
			r = rconst;
		else if (model_eval(ctx, &P->radius, "area.radius", "organ",
		    &env, &r) != 0) {
			free(sh);
			return NULL;
		}
		if (!(r > 0)) {
			diag(ST_SCENE, ctx->file, P->radius.line, 0,
			    "area.radius is %.9g at organ %zu; it must be "
			    "positive", r, n);
			free(sh);
			return NULL;
		}
		cell = CELL(r);
		if (used + cell > total * (1 + 1e-12) && n == 0) {
			diag(ST_SCENE, ctx->file, P->radius.line, 0,
			    "area.radius %.9g is too large: one organ's cell, "
			    "%.9g, is more than the receptacle's area, %.9g", r,
			    cell, total);
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
place_area(const struct model_ctx *ctx, const struct area *P,
    struct result *res, double rconst, long long cap)
{
	struct curve cv;
	struct share *sh = NULL;
	double rmin = HUGE_VAL, rmax = 0, r_even = 0;
	size_t count = 0, hint = 0;

	if (!P->given[AR_RADIUS] && rconst <= 0 && !ctx->count_line) {
		model_error(ctx, GIVEN_AT(P, AR_RADIUS), "give count (organs "
		    "spread evenly), area.radius (each organ's own size), or "
		    "both");
		return -1;
	}
	if (receptacle_curve(ctx->file, &P->receptacle, &cv) != 0)
		return -1;
	if (!(cv.area > 0)) {
		model_error(ctx, GIVEN_AT(&P->receptacle, RC_PROFILE),
		    "the receptacle has no area: its profile lies on the "
		    "axis");
		curve_free(&cv);
		return -1;
	}
	if (P->given[AR_RADIUS] || rconst > 0) {
		if ((sh = shares_by_radius(ctx, P, cv.area, rconst, cap,
		    &count)) == NULL) {
			curve_free(&cv);
			return -1;
		}
	} else {
		count = (size_t)ctx->count;
		/* N organs of hexagonal packing share the area. */
		r_even = sqrt(cv.area / (2 * sqrt(3.0) * (double)count));
	}

	result_init(res, count);
	res->divergence = ctx->divergence;
	res->svg = PROJ_TOP;
	for (size_t n = 0; n < count; n++) {
		struct organ *o = &res->organs[n];
		double mark = sh != NULL ? sh[n].mark :
		    cv.area * ((double)n + 0.5) / (double)count;

		place(&cv, mark, &hint, angle_mod360((double)n,
		    ctx->divergence), o);
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
	const struct model_ctx *ctx;
	const struct area *P;
};

static int
trial_place(void *arg, double r, long long cap, struct result *res)
{
	const struct trial *T = arg;

	return place_area(T->ctx, T->P, res, r, cap);
}

static int
area_make(const struct model_ctx *ctx, struct result *res)
{
	const struct area *P = ctx->params;
	struct trial T = { ctx, P };
	int at = P->given[AR_PARASTICHIES];
	double r;

	if (!at)
		return place_area(ctx, P, res, 0, 0);
	r = para_design_receptacle(ctx->file, "area", at,
	    P->given[AR_RADIUS], &P->receptacle, &P->parastichies, 1,
	    trial_place, &T);
	/* --info's radius line is the one chosen. */
	return r < 0 ? -1 : place_area(ctx, P, res, r, 0);
}

const struct model area_model = {
	.name = "area",
	.help = "area-based: organs spread evenly by area on a receptacle "
	    "(Fibonacci sphere)",
	.settings = &area_table,
	.size = sizeof(struct area),
	.make = area_make,
};
