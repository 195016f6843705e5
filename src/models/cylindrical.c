/*
 * cylindrical.c - the cylindrical model: organ k at angle k alpha and
 * height k h on a cylinder (cylindrical_lattice.c has the geometry).
 * The scene names the parastichy pair it wants, [m, n], or a triple
 * [m, n, m+n], or gives the rise h itself.
 *
 * A taper (cylindrical.radius an expression of t) scales the pattern
 * locally: organ k's rise and size follow the radius there, so the
 * lattice stays similar to itself and the parastichies stay visible,
 * as on a spruce cone or ABOP's Carex spike.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "analysis/parastichy.h"
#include "base/diag.h"
#include "geometry/geometry.h"
#include "base/mem.h"
#include "models/cylindrical_lattice.h"
#include "models/model.h"

enum { CY_RADIUS, CY_PARASTICHIES, CY_RISE, CY_LENGTH, CY__N };

struct cylindrical {
	struct group_at	 at;
	int		 given[CY__N];
	struct expr_setting radius;	/* of the cylinder; may vary */
	struct int_list	 parastichies;
	double		 rise;		/* on a cylinder of radius 1 */
	double		 length;
};

#define C(f)	offsetof(struct cylindrical, f)

static const struct row cylindrical_rows[] = {
	[CY_RADIUS] = { .name = "radius", .type = T_EXPR, .off = C(radius),
	  .defstr = "1",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .unit = "length",
	  .doc = "radius of the cylinder; an expression of t tapers it" },
	[CY_PARASTICHIES] = { .name = "parastichies", .type = T_INTS,
	  .off = C(parastichies), .lo = 1, .hi = 1000, .defstr = "none",
	  .doc = "contact parastichy pair [m, n] or triple [m, n, m+n]" },
	[CY_RISE] = { .name = "rise", .type = T_FLOAT, .off = C(rise),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .defstr = "none",
	  .unit = "length",
	  .doc = "height between consecutive organs, for radius 1" },
	[CY_LENGTH] = { .name = "length", .type = T_FLOAT, .off = C(length),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .defstr = "none",
	  .unit = "length",
	  .doc = "length of the structure instead of count" },
};

static const struct table cylindrical_table = TABLE(cylindrical_rows,
    struct cylindrical);

/* Divergence, rise and diameter, and what the pattern is. */
struct pattern {
	double	 alpha, h, d, lo, hi;
	int	 m, n;
};

/* The pattern from cylindrical.parastichies, with every check. */
static int
from_parastichies(const struct model_ctx *ctx, const struct cylindrical *cy,
    struct pattern *p)
{
	const struct int_list *par = &cy->parastichies;
	int at = cy->given[CY_PARASTICHIES];
	int m = par->v[0], n = par->v[1];

	if (m >= n) {
		model_error(ctx, at, "parastichies (%d, %d) must be "
		    "increasing: m < n", m, n);
		return -1;
	}
	if (para_gcd(m, n) != 1) {
		model_error(ctx, at, "parastichies (%d, %d) have the common "
		    "factor %d: the pattern would not be a single spiral", m, n,
		    para_gcd(m, n));
		return -1;
	}
	p->m = m;
	p->n = n;
	cyl_range(m, n, &p->lo, &p->hi);
	if (par->n == 3) {
		if (par->v[2] != m + n) {
			model_error(ctx, at, "a triple must be [m, n, m+n]: "
			    "%d is not %d + %d", par->v[2], m, n);
			return -1;
		}
		cyl_triple(m, n, &p->alpha, &p->h, &p->d);
		if (ctx->divergence_line) {
			model_error(ctx, ctx->divergence_line, "the triple "
			    "(%d, %d, %d) fixes the divergence at %.6f; leave "
			    "divergence out", m, n, m + n, p->alpha);
			return -1;
		}
		return 0;
	}
	if (!ctx->divergence_line)
		/* The golden angle where it fits, else the range's middle. */
		p->alpha = GOLDEN_ANGLE >= p->lo && GOLDEN_ANGLE <= p->hi ?
		    GOLDEN_ANGLE : (p->lo + p->hi) / 2;
	else if (cyl_fold(ctx->divergence) < p->lo - 1e-9 ||
	    cyl_fold(ctx->divergence) > p->hi + 1e-9) {
		model_error(ctx, ctx->divergence_line, "divergence %.9g is "
		    "outside [%.3f, %.3f] for parastichies (%d, %d)",
		    ctx->divergence, p->lo, p->hi, m, n);
		return -1;
	} else
		p->alpha = ctx->divergence;
	if (cyl_pair(m, n, p->alpha, &p->h, &p->d) != 0) {
		/* Only at a range end can rounding tip it over. */
		model_error(ctx, ctx->divergence_line, "no (%d, %d) pattern at "
		    "divergence %.9g", m, n, p->alpha);
		return -1;
	}
	return 0;
}

static int
pattern_find(const struct model_ctx *ctx, const struct cylindrical *cy,
    struct pattern *p)
{
	int have_par = cy->given[CY_PARASTICHIES] != 0;
	int have_rise = cy->given[CY_RISE] != 0;

	if (have_par == have_rise) {
		model_error(ctx, have_par ? cy->given[CY_RISE] :
		    GIVEN_AT(cy, CY_RISE),
		    "give cylindrical.parastichies or cylindrical.rise, %s",
		    have_par ? "not both" : "one of them");
		return -1;
	}
	if (have_par)
		return from_parastichies(ctx, cy, p);
	p->alpha = ctx->divergence;
	p->h = cy->rise;
	if (cyl_contacts(p->alpha, p->h, &p->m, &p->n, &p->d) != 0) {
		model_error(ctx, cy->given[CY_RISE], "rise %.9g is too small "
		    "to find the contact parastichies", p->h);
		return -1;
	}
	cyl_range(p->m, p->n, &p->lo, &p->hi);
	return 0;
}

/* How many organs: count, or as many as fit in cylindrical.length. */
static long long
organ_count(const struct model_ctx *ctx, const struct cylindrical *cy,
    const struct pattern *p, double R)
{
	int have_len = cy->given[CY_LENGTH];
	double n;

	if (ctx->count_line && have_len) {
		model_error(ctx, have_len, "give count or cylindrical.length, "
		    "not both");
		return -1;
	}
	if (!have_len)
		return ctx->count;
	if (R == 0) {
		model_error(ctx, have_len, "cylindrical.length needs a "
		    "constant cylindrical.radius; give count instead");
		return -1;
	}
	n = floor(cy->length / (p->h * R) + 1e-9) + 1;
	if (n > COUNT_MAX) {
		model_error(ctx, have_len, "cylindrical.length %.9g "
		    "holds %.0f organs, more than %d", cy->length, n,
		    COUNT_MAX);
		return -1;
	}
	return (long long)n;
}

/* Organ k's radius; an error names the organ. */
static int
radius_at(const struct model_ctx *ctx, const struct cylindrical *cy,
    struct expr_env *env, long long k, long long N, double *rho)
{
	const struct expr_setting *es = &cy->radius;

	if (es->e == NULL) {
		*rho = 1;
		return 0;
	}
	expr_env_organ(env, k, N);
	if (model_eval(ctx, es, "cylindrical.radius", "organ", env, rho) != 0)
		return -1;
	if (*rho > 0)
		return 0;
	diag(ST_SCENE, ctx->file, es->line, 0, "cylindrical.radius is %.9g at "
	    "organ %lld; it must be positive", *rho, k);
	return -1;
}

static int
cylindrical_make(const struct model_ctx *ctx, struct result *res)
{
	const struct cylindrical *cy = ctx->params;
	struct expr_env env = { { 0 }, (uint64_t)ctx->seed, 0 };
	struct pattern p;
	double Rconst = 0, *rho, *z;	/* 0: the radius varies */
	long long N;
	int dm, dn;

	if (pattern_find(ctx, cy, &p) != 0)
		return -1;
	if (cy->radius.e == NULL)
		Rconst = 1;
	else if (expr_is_constant(cy->radius.e, &Rconst) && !(Rconst > 0)) {
		/* Before the count, which a constant radius may decide. */
		model_error(ctx, cy->given[CY_RADIUS], "cylindrical.radius "
		    "%.9g must be positive", Rconst);
		return -1;
	}
	if ((N = organ_count(ctx, cy, &p, Rconst)) < 0)
		return -1;

	rho = xcalloc((size_t)N, sizeof(*rho));
	z = xcalloc((size_t)N, sizeof(*z));
	for (long long k = 0; k < N; k++) {
		if (radius_at(ctx, cy, &env, k, N, &rho[k]) != 0) {
			free(rho);
			free(z);
			return -1;
		}
		/* The rise follows the radius: the mean of the two organs'. */
		if (k > 0)
			z[k] = z[k - 1] + p.h * (rho[k - 1] + rho[k]) / 2;
	}

	result_init(res, (size_t)N);
	res->divergence = p.alpha;
	res->svg = PROJ_UNROLL;
	for (long long k = 0; k < N; k++) {
		long long a = k > 0 ? k - 1 : k, b = k + 1 < N ? k + 1 : k;
		double slope = b > a && z[b] > z[a] ?
		    (rho[b] - rho[a]) / (z[b] - z[a]) : 0;
		struct organ *o = &res->organs[k];

		/* The tip is at the top: away from it is down, (-drho/dz, -1). */
		frame_revolution(o, angle_mod360((double)k, p.alpha), rho[k], z[k],
		    -slope, -1);
		o->radius = p.d / 2 * rho[k];
		o->scale = o->radius;
	}
	free(rho);
	free(z);

	cyl_encyclic(p.m, p.n, &dm, &dn);
	/* The lattice asked for; --info measures the contacts too. */
	result_info(res, "pattern", 2, (double)p.m, (double)p.n);
	result_info(res, "encyclic", 2, (double)dm, (double)dn);
	result_info(res, "range", 2, p.lo, p.hi);
	result_info(res, "rise", 1, p.h);
	result_info(res, "diameter", 1, p.d);
	return 0;
}

const struct model cylindrical_model = {
	.name = "cylindrical",
	.help = "van Iterson: a parastichy pair on a cylinder, or a taper",
	.settings = &cylindrical_table,
	.size = sizeof(struct cylindrical),
	.make = cylindrical_make,
	.needs_count = 1,
	.count_else = "length",
};
