/*
 * planar.c - Vogel's model (ABOP ch. 4): organ n at angle n*alpha and
 * radius inner + c*n^e on a disk facing +Z, optionally lifted onto a
 * paraboloid dome.  The packing radius is that of a hexagonal packing
 * with the same area per organ, which is pi*c^2 for Vogel's formula.
 */
#include <math.h>
#include <stddef.h>

#include "analysis/design.h"
#include "analysis/parastichy.h"
#include "geometry/geometry.h"
#include "models/model.h"

enum { PL_SCALE, PL_OUTER, PL_INNER, PL_EXPONENT, PL_DOME, PL_PARASTICHIES,
	PL__N };

struct planar {
	struct group_at	 at;
	int		 given[PL__N];
	double		 scale;		/* Vogel's c */
	double		 outer;		/* fit c so the last organ sits here */
	double		 inner;		/* radius of the first ring */
	double		 exponent;	/* r = inner + c n^exponent */
	double		 dome;		/* height of the centre above the rim */
	struct int_list	 parastichies;	/* instead of count: the rim's pair */
};

#define P(f)	offsetof(struct planar, f)

static const struct row planar_rows[] = {
	[PL_SCALE] = { .name = "scale", .type = T_FLOAT, .off = P(scale),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .def = 1,
	  .defstr = "none",
	  .unit = "length",
	  .doc = "Vogel's c: organ n lies at radius c n^exponent" },
	[PL_OUTER] = { .name = "outer", .type = T_FLOAT, .off = P(outer),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .defstr = "inner + 1",
	  .unit = "length",
	  .doc = "radius of the last organ; sets c instead of scale" },
	[PL_INNER] = { .name = "inner", .type = T_FLOAT, .off = P(inner),
	  .lo = 0, .hi = HUGE_VAL, .defstr = "0",
	  .unit = "length",
	  .doc = "radius at which organ 0 sits" },
	[PL_EXPONENT] = { .name = "exponent", .type = T_FLOAT,
	  .off = P(exponent), .lo = 0, .hi = 4, .flags = F_LO_OPEN,
	  .def = 0.5, .defstr = "0.5", .doc = "exponent of n in the radius" },
	[PL_DOME] = { .name = "dome", .type = T_FLOAT, .off = P(dome),
	  .lo = -HUGE_VAL, .hi = HUGE_VAL, .defstr = "0",
	  .unit = "length",
	  .doc = "height of the centre above the rim (paraboloid)" },
	[PL_PARASTICHIES] = { .name = "parastichies", .type = T_INTS,
	  .off = P(parastichies), .lo = 1, .hi = 1000, .defstr = "none",
	  .doc = "instead of count: the contact pair [m, n] wanted at the rim" },
};

static const struct table planar_table = TABLE(planar_rows, struct planar);

/* n^e; pow() is the model's costliest call, and e is mostly 1/2. */
static double
power(double n, double e)
{
	return e == 0.5 ? sqrt(n) : pow(n, e);
}

static int
planar_check(const struct model_ctx *ctx, const struct planar *p)
{
	if (ctx->count_line && p->given[PL_PARASTICHIES]) {
		model_error(ctx, p->given[PL_PARASTICHIES], "give count or "
		    "planar.parastichies, not both");
		return -1;
	}
	if (p->given[PL_OUTER] && p->given[PL_SCALE]) {
		model_error(ctx, p->given[PL_OUTER], "give planar.scale or "
		    "planar.outer, not both");
		return -1;
	}
	if (p->given[PL_OUTER] && p->outer <= p->inner) {
		model_error(ctx, p->given[PL_OUTER], "planar.outer %.9g must "
		    "be greater than planar.inner %.9g", p->outer, p->inner);
		return -1;
	}
	return 0;
}

static int
place(const struct model_ctx *ctx, const struct planar *p, size_t count,
    struct result *res)
{
	/*
	 * Without scale or outer, the last organ lies one unit out from
	 * inner: a head of radius 1 whatever the count, as the other
	 * models' receptacles are, rather than sqrt(count) units.
	 */
	double outer = p->given[PL_OUTER] ? p->outer : p->inner + 1;
	double c = p->scale, rim;

	if (!p->given[PL_SCALE])
		c = count > 1 ? (outer - p->inner) /
		    pow((double)(count - 1), p->exponent) : outer - p->inner;
	rim = p->inner + c * power((double)(count - 1), p->exponent);

	result_init(res, count);
	res->divergence = ctx->divergence;
	res->svg = PROJ_TOP;
	res->rim_last = 1;
	for (size_t n = 0; n < count; n++) {
		struct organ *o = &res->organs[n];
		double phi = angle_mod360((double)n, ctx->divergence);
		/* m: organ 0 takes its area per organ from n = 1. */
		double m = n > 1 ? (double)n : 1, pm = power(m, p->exponent);
		double rho = p->inner + (n > 0 ? c * pm : 0);

		frame_dome(o, phi, rho, rim, p->dome);
		/* Area per organ d(pi rho^2)/dn shared as hexagons. */
		o->radius = sqrt(M_PI * (p->inner + c * pm) *
		    (c * p->exponent * pm / m) / sqrt(3.0));
		o->scale = o->radius;
		o->object = 0;
	}
	result_info(res, "scale", 1, c);
	result_info(res, "outer", 1, rim);
	return 0;
}

/* Inverse design: the rim pair of a trial count. */
struct trial {
	const struct model_ctx *ctx;
	const struct planar *p;
};

static int
trial_pair(void *ctx, double x, int pair[2])
{
	const struct trial *T = ctx;
	struct result res = { 0 };
	struct para_zone z[64];
	size_t nz;

	if (place(T->ctx, T->p, (size_t)llround(x), &res) != 0)
		return -1;
	nz = para_zones(&res, NULL, z, 64);
	pair[0] = nz ? z[nz - 1].m : 0;
	pair[1] = nz ? z[nz - 1].n : 0;
	result_free(&res);
	return 0;
}

static int
planar_make(const struct model_ctx *ctx, struct result *res)
{
	const struct planar *p = ctx->params;
	const struct int_list *want = &p->parastichies;
	struct trial T = { ctx, p };
	char reach[512];
	double x;

	if (planar_check(ctx, p) < 0)
		return -1;
	if (!p->given[PL_PARASTICHIES])
		return place(ctx, p, (size_t)ctx->count, res);
	if (para_want_check(ctx->file, p->given[PL_PARASTICHIES],
	    "planar.parastichies", want) != 0)
		return -1;
	/* Counts up to where the rim shows about 4 n around it. */
	x = para_search(want->v, 8, fmin(COUNT_MAX, 40.0 * want->v[1] *
	    want->v[1] + 64), 1, trial_pair, &T, reach, sizeof(reach));
	if (x < 0)
		return -1;
	if (x == 0) {
		model_error(ctx, p->given[PL_PARASTICHIES], "no count shows "
		    "parastichies %d/%d at the rim with divergence %.9g; the "
		    "counts tried show %s", want->v[0], want->v[1],
		    ctx->divergence, reach);
		return -1;
	}
	return place(ctx, p, (size_t)llround(x), res);
}

const struct model planar_model = {
	.name = "planar",
	.help = "Vogel: organ n at angle n a, radius c n^(1/2), on a disk or "
	    "dome",
	.settings = &planar_table,
	.size = sizeof(struct planar),
	.make = planar_make,
	.needs_count = 1,
	.count_else = "parastichies",
};
