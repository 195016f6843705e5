/*
 * collision.c - the collision-based model of Fowler, Prusinkiewicz and
 * Battjes (1992): primordia of radius r_n on a surface of revolution,
 * primordium n at angle n alpha and at the smallest curve parameter t
 * where it overlaps no earlier one.
 *
 * The walk up the generating curve is exact: starting at the lowest t
 * allowed, it asks the spatial grid which earlier primordia the new
 * one would overlap there, jumps to the furthest point where it leaves
 * them (curve_exit: the exact crossing, never a sample), and asks
 * again, until nothing overlaps or the tip is passed.  Each jump
 * clears at least one primordium, and every point jumped over is
 * covered, so the first free point found is the smallest.
 *
 * What keeps it fast without epsilon is the cover map (collision_cover.c): most
 * of the receptacle below the front is provably covered, and the walk
 * skips it a cell at a time.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "analysis/design.h"
#include "base/diag.h"
#include "geometry/curve.h"
#include "geometry/geometry.h"
#include "geometry/receptacle.h"
#include "base/mem.h"
#include "models/collision.h"
#include "models/collision_cover.h"
#include "models/collision_impl.h"
#include "models/model.h"

#define COUNT_DEFAULT	1000000	/* primordia when count is not given */
#define COUNT_MOST	5000000	/* 180 bytes each: under 1 GiB */
#define PROGRESS_EVERY	16384
#define CHECK_EVERY	31	/* cells the tests' check of the map takes */
#define LAW_SAMPLES	4096	/* of the radius law, to size the maps */
#define CELLS_PER_ORGAN	64	/* of the cover map, at most */
#define FALLS		0.8	/* a radius law falls below this of the
				   first radius: */
#define TALL_ROWS	1024	/* and the map is this tall: more cells */
#define RISES		1.25	/* a radius law rises to this of the first:
				   wider cells up the band, */
#define EST_SAMPLES	256	/* in parts of it */
#define EST_LOOSE	1.25	/* primordia take at most this times the
				   area of a hexagonal packing (assumed:
				   only the cells' width hangs on it) */
#define FRONT_LOOSE	1.2	/* and about this times (the falling
				   sphere's band of 100,000: 1.2): only
				   the rows' height hangs on it */
#define FALLING_MIN	20000	/* primordia expected, at least, for a
				   map made for a falling radius */
#define R_SMALLEST	1e-12	/* of the receptacle's size: below it the
				   walk's steps vanish in double precision */

enum { CO_RECEPTACLE, CO_RADIUS, CO_EPSILON, CO_PARASTICHIES, CO__N };

struct collision {
	struct group_at	 at;
	int		 given[CO__N];
	struct receptacle receptacle;
	struct expr_setting radius;	/* of primordium n */
	struct expr_setting epsilon;	/* how far t may fall back */
	struct int_list	 parastichies;	/* instead of radius: the pair wanted */
};

#define CO(f)	offsetof(struct collision, f)

static const struct row collision_rows[] = {
	[CO_RECEPTACLE] = { .name = "receptacle", .type = T_GROUP,
	  .off = CO(receptacle), .sub = &receptacle_table,
	  .doc = "the surface of revolution the primordia sit on" },
	[CO_RADIUS] = { .name = "radius", .type = T_EXPR, .off = CO(radius),
	  .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .unit = "length",
	  .doc = "radius of primordium n" },
	[CO_EPSILON] = { .name = "epsilon", .type = T_EXPR,
	  .off = CO(epsilon), .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T) |
	  EXPR_VAR(V_R),
	  .unit = "length",
	  .doc = "arc length t may fall back below the last primordium; "
	  "\"r\": its radius" },
	[CO_PARASTICHIES] = { .name = "parastichies", .type = T_INTS,
	  .off = CO(parastichies), .lo = 1, .hi = 1000, .defstr = "none",
	  .doc = "instead of radius: the contact pair [m, n] wanted at the "
	  "base" },
};

static const struct table collision_table = TABLE(collision_rows,
    struct collision);

/* Primordium n's radius and the fall-back limit; errors name n. */
static int
radius_at(const struct coll *C, struct expr_env *env, long long n,
    long long N, double *r, double *eps)
{
	const struct model_ctx *ctx = C->ctx;
	const struct collision *P = C->p;

	expr_env_organ(env, n, N);
	if (C->rconst > 0)
		*r = C->rconst;
	else if (model_eval(ctx, &P->radius, "collision.radius", "primordium",
	    env, r) != 0)
		return -1;
	if (!(*r > 0)) {
		diag(ST_SCENE, ctx->file, P->radius.line, 0,
		    "collision.radius is %.9g at primordium %lld; it must be "
		    "positive", *r, n);
		return -1;
	}
	*eps = -1;
	if (P->epsilon.e == NULL)
		return 0;
	env->var[V_R] = *r;
	if (model_eval(ctx, &P->epsilon, "collision.epsilon",
	    "primordium", env, eps) != 0)
		return -1;
	if (*eps < 0) {
		diag(ST_SCENE, ctx->file, P->epsilon.line, 0,
		    "collision.epsilon is %.9g at primordium %lld; it must be "
		    "at least 0", *eps, n);
		return -1;
	}
	return 0;
}

/*
 * Primordium n at t, row (-1: not known) of the cover map, angle phi;
 * at is the curve's point at t, if the walk has it (else NULL).
 */
static void
coll_add(struct coll *C, double t, int32_t row, double phi, double c,
    double s, double r, const double *at)
{
	double p[2];
	struct prim *o;

	if (C->n == C->cap) {
		C->cap = C->cap ? 2 * C->cap : 4096;
		C->pr = xreallocarray(C->pr, C->cap, sizeof(*C->pr));
		C->next = xreallocarray(C->next, C->cap, sizeof(*C->next));
	}
	if (at != NULL) {
		p[0] = at[0];
		p[1] = at[1];
	} else
		curve_eval(&C->cv, t, p, NULL);
	o = &C->pr[C->n];
	o->x = p[0] * c;
	o->y = p[0] * s;
	o->z = p[1];
	o->r = r;
	o->t = t;
	if (r > C->rmax)
		C->rmax = r;
	C->n++;
	coll_grid_insert(C, (int32_t)(C->n - 1));
	if (!C->nocover)
		cover_add(&C->cover, t, row, phi, o->x, o->y, o->z, r);
}

/* The organs: frames on the receptacle, the tangent away from the tip. */
static void
fill_result(const struct coll *C, double alpha, struct result *res)
{
	double tiny = 1e-12 * (C->cv.length + 1);	/* a speed of 0 */

	result_init(res, C->n);
	res->divergence = alpha;
	res->svg = PROJ_TOP;
	for (size_t i = 0; i < C->n; i++) {
		const struct prim *o = &C->pr[i];
		struct organ *g = &res->organs[i];
		double p[2], d[2], rho, phi;

		curve_eval(&C->cv, o->t, p, d);
		if (d[0] * d[0] + d[1] * d[1] < tiny * tiny) {
			/* A cusp: the chord across it gives the direction. */
			double a[2], b[2], e = 1e-6 * C->cv.tmax;

			curve_eval(&C->cv, fmax(o->t - e, 0), a, NULL);
			curve_eval(&C->cv, fmin(o->t + e, C->cv.tmax), b, NULL);
			d[0] = b[0] - a[0];
			d[1] = b[1] - a[1];
		}
		rho = hypot(o->x, o->y);
		phi = angle_mod360((double)i, alpha);
		/* The angle is in the position already, but for on the axis. */
		if (rho > 0)
			frame_revolution_cs(g, phi, o->x / rho, o->y / rho, p[0],
			    p[1], -d[0], -d[1]);
		else
			frame_revolution(g, phi, p[0], p[1], -d[0], -d[1]);
		/* Exactly the position placed, not a second evaluation. */
		g->pos[0] = o->x;
		g->pos[1] = o->y;
		g->pos[2] = o->z;
		g->radius = o->r;
		g->scale = o->r;
	}
}

/*
 * What the maps need before placement starts: the smallest radius the
 * law gives up to the bound N, and the area N primordia can cover
 * (2 sqrt 3 r^2 each, hexagonally packed).  Sampled; a sample the law
 * cannot give is left out here and reported when placement gets there.
 */
static void
law_extent(struct coll *C, long long N, double r0, double *rmin,
    double *area)
{
	struct expr_env env = { { 0 }, (uint64_t)C->ctx->seed, 0 };
	long long step = N / LAW_SAMPLES + 1, samples = 0;
	double sum = 0, r;

	*rmin = r0;
	if (C->rconst > 0 || expr_is_constant(C->p->radius.e, &r)) {
		*area = 2 * sqrt(3) * r0 * r0 * (double)N;
		return;
	}
	C->law_step = step;
	C->nlaw = (size_t)((N + step - 1) / step);
	C->law = xcalloc(C->nlaw, sizeof(*C->law));
	for (long long n = 0; n < N; n += step) {
		expr_env_organ(&env, n, N);
		/* A radius the law cannot give: no fall to plan for. */
		if (expr_eval(C->p->radius.e, &env, &r) != EXPR_OK ||
		    !(r > 0)) {
			C->law[n / step] = HUGE_VAL;
			continue;
		}
		C->law[n / step] = r;
		*rmin = fmin(*rmin, r);
		sum += r * r;
		samples++;
	}
	*area = samples ? 2 * sqrt(3) * sum / (double)samples * (double)N :
	    HUGE_VAL;
	/*
	 * The least radius from each sample on; a sample the law cannot
	 * give counts as 0, which promises nothing.
	 */
	C->law_min = xcalloc(C->nlaw, sizeof(*C->law_min));
	for (size_t i = C->nlaw; i-- > 0; ) {
		r = C->law[i] == HUGE_VAL ? 0 : C->law[i];
		C->law_min[i] = i + 1 < C->nlaw ? fmin(r, C->law_min[i + 1]) :
		    r;
	}
}

/*
 * For a radius law that only rises (as sampled), by RISES or more: the
 * least radius of the walks expected to reach each of EST_SAMPLES
 * parts of the band's length L, else NULL.  The front reaches arc
 * length s when the primordia before it cover the area below s;
 * packed no looser than EST_LOOSE times hexagonally, those are at
 * least the first m whose hexagonal area times EST_LOOSE reaches it,
 * and the radius there is at least law(m).  Only how wide the cover
 * map's cells are hangs on this, never where a primordium goes.
 */
static double *
rising_est(const struct coll *C, double L)
{
	double *r_est, area = 0;
	size_t m = 0;

	if (C->law == NULL || !(C->law[C->nlaw - 1] >= RISES * C->law[0]))
		return NULL;
	for (size_t i = 0; i < C->nlaw; i++)
		if (!(C->law[i] < HUGE_VAL) || (i > 0 && C->law[i] <
		    C->law[i - 1]))
			return NULL;
	r_est = xcalloc(EST_SAMPLES, sizeof(*r_est));
	for (int i = 0; i < EST_SAMPLES; i++) {
		/* The area below the part's start. */
		double below = curve_area(&C->cv, curve_t(&C->cv, L * i /
		    EST_SAMPLES));

		for (; m + 1 < C->nlaw; m++) {
			/* law_step primordia of the law's radius at m */
			double hex = 2 * sqrt(3) * C->law[m] * C->law[m] *
			    (double)C->law_step;

			if (!(EST_LOOSE * (area + hex) <= below))
				break;
			area += hex;
		}
		r_est[i] = C->law[m];
	}
	return r_est;
}

/*
 * For a radius law that falls below FALLS of the first radius (as
 * sampled): the least radius of the primordia placed while the front
 * crosses each of EST_SAMPLES parts of the band's length L, else NULL.
 * The front leaves arc length s when the primordia placed cover the
 * area below it: the first m whose hexagonal area, FRONT_LOOSE times,
 * reaches it.  Only how high the cover map's rows are hangs on this,
 * never where a primordium goes.
 */
static double *
falling_est(const struct coll *C, double L, double rmin)
{
	double *r_front, area = 0, last = rmin;
	size_t m = 0;

	if (C->law == NULL || !(rmin < FALLS * C->law[0]))
		return NULL;
	r_front = xcalloc(EST_SAMPLES, sizeof(*r_front));
	for (int i = 0; i < EST_SAMPLES; i++) {
		/* The area below the part's end. */
		double below = curve_area(&C->cv, curve_t(&C->cv, L * (i + 1) /
		    EST_SAMPLES)), least = HUGE_VAL;

		for (; m < C->nlaw; m++) {
			double r = C->law[m] < HUGE_VAL ? C->law[m] : 0;

			least = fmin(least, r);
			area += FRONT_LOOSE * 2 * sqrt(3) * r * r *
			    (double)C->law_step;
			if (!(area < below))
				break;
		}
		if (m < C->nlaw)
			r_front[i] = last = least;
		else
			/*
			 * Past the last primordium: the front gets there in
			 * a looser packing, when the radius is the last, as
			 * far as EST_LOOSE times the hexagonal area; beyond
			 * that, rows four times as high (not expected to be
			 * met; the band is mapped twice over).
			 */
			r_front[i] = below <= EST_LOOSE / FRONT_LOOSE * area ?
			    fmin(least, last) : 4 * fmin(least, last);
	}
	return r_front;
}

/* Placement with radius rconst if > 0, at most cap primordia if > 0. */
static int
place(const struct model_ctx *ctx, struct result *res, int how,
    double rconst, long long cap)
{
	int brute = how == PLACE_BRUTE;
	struct expr_env env = { { 0 }, (uint64_t)ctx->seed, 0 };
	const struct collision *P = ctx->params;
	struct coll C = { .ctx = ctx, .p = P, .nocover = how == PLACE_PLAIN ||
	    how == PLACE_BRUTE, .check = how == PLACE_CHECK,
	    .rconst = rconst };
	double alpha = ctx->divergence, r, eps, rmin, band, k;
	double a_next;
	long long N = ctx->count_line ? ctx->count : COUNT_DEFAULT;
	int rc = -1, full = 0;

	if (cap > 0 && cap < N)
		N = cap;

	if (N > COUNT_MOST) {
		model_error(ctx, ctx->count_line, "count %lld is more than "
		    "the collision model places, %d", N, COUNT_MOST);
		return -1;
	}
	if (P->radius.e == NULL && rconst <= 0) {
		model_error(ctx, GIVEN_AT(P, CO_RADIUS), "missing setting "
		    "'collision.radius' (the primordia's radius, or "
		    "collision.parastichies to have it found)");
		return -1;
	}
	if (receptacle_curve(ctx->file, &P->receptacle, &C.cv) != 0)
		return -1;
	if (radius_at(&C, &env, 0, N, &r, &eps) != 0)
		goto out;
	/* A constant radius is that for every primordium: no evaluating. */
	if (C.rconst <= 0 && expr_is_constant(P->radius.e, &k))
		C.rconst = r;
	law_extent(&C, N, r, &rmin, &band);
	if (rmin < R_SMALLEST * fmax(C.cv.length, C.cv.rho_max)) {
		model_error(ctx, GIVEN_AT(P, CO_RADIUS), "collision.radius "
		    "%.9g is too small for this receptacle: below %g of its "
		    "size, %.9g, the placement cannot be resolved", rmin,
		    R_SMALLEST, fmax(C.cv.length, C.cv.rho_max));
		goto out;
	}
	if (!C.nocover) {
		/*
		 * The band N primordia can cover, twice over for loose
		 * packing, and some rows more.
		 */
		double s = C.cv.length, most = (double)N * CELLS_PER_ORGAN;
		double *r_est, *r_front;

		if (2 * band < C.cv.area)
			s = curve_s(&C.cv, curve_t_area(&C.cv, 2 * band, NULL,
			    NULL, NULL)) + 16 * r;
		/*
		 * A radius that falls, with every walk from the base, up a
		 * tall band: twice the cells.  As the radius falls, cells
		 * far below the front whose bounds covered the last walk
		 * in the column do not cover this one, and the walk looks
		 * at each: on the falling sphere (300,000, a map of 1,722
		 * rows) 8.8 looks a walk, 6.8 of them above the column's
		 * head, seven in ten 128 rows or more below where the walk
		 * ends, in the gaps between larger, earlier primordia,
		 * where a cell's bound (the least over single primordia of
		 * their reach into it) lies up to a cell's size above the
		 * clearance.  Smaller cells make closer bounds: with twice
		 * the cells, 2.4 looks a walk above the head instead of
		 * 4.5 (the sphere, 100,000), for twice cover_add()'s work
		 * a primordium and 64 bytes more.  It pays where the walks
		 * pass many rows; best of five, side by side: the sphere's
		 * band of 300,000 10% less time, and to the tip (260,000)
		 * the disk (1,513 rows) 9%, the sphere (2,746) 13%, the
		 * hemisphere (1,909) 8%, with 2% fewer instructions to 4%
		 * more (the disk's D1 misses 22% fewer).  It did not pay
		 * on the sphere's band of 100,000 (993 rows: as fast, 7%
		 * more instructions), on the disk's and hemisphere's bands
		 * of 95 to 201 rows (20% more time), with epsilon (walks
		 * that start near the front; 20% more) or with a rising
		 * radius (8% to 44% more); four times the cells cost more
		 * than they spared, on the sphere too.
		 */
		if (P->epsilon.e == NULL && C.law != NULL && rmin < FALLS * r &&
		    cover_rows(&C.cv, rmin, s, most) >= TALL_ROWS) {
			most *= 2;
			C.finer = 1;
		}
		r_est = rising_est(&C, fmin(s, C.cv.length));
		/*
		 * Rows as high as a falling radius wants, where the walks
		 * start near the front (epsilon): a walk from the base
		 * would cross high rows long after, at a radius their
		 * bounds are too coarse for.  Not for a few thousand
		 * primordia: the run takes milliseconds either way, and
		 * other rows move placements by rounding (the coneflower's:
		 * a frame's component of 0 became -2.8e-17).
		 */
		r_front = P->epsilon.e != NULL && (double)N * fmin(1,
		    C.cv.area / band) >= FALLING_MIN ? falling_est(&C, fmin(s,
		    C.cv.length), rmin) : NULL;
		cover_init(&C.cover, &C.cv, rmin, s, most, r_est, r_front,
		    EST_SAMPLES);
		free(r_est);
		free(r_front);
	}
	/*
	 * Room for as many as circles of radius r would pack hexagonally,
	 * and a little more: growing a million by doubling copies it all.
	 */
	C.cap = (size_t)fmin((double)N, C.cv.area / (2 * sqrt(3) * r * r) *
	    1.1 + 4096);
	C.pr = xcalloc_big(C.cap, sizeof(*C.pr));
	C.next = xcalloc_big(C.cap, sizeof(*C.next));
	C.reach = fmin(band, C.cv.area);
	coll_grid_fit(&C, r);
	coll_add(&C, 0, -1, 0, 1, 0, r, NULL);
	a_next = angle_mod360(1, alpha) * (M_PI / 180);
	for (long long n = 1; n < N; n++) {
		double a = a_next, c = cos(a), s = sin(a), t0 = 0, s0 = -1, t;
		double at[2];
		int32_t row = -1;

		if (radius_at(&C, &env, n, N, &r, &eps) != 0)
			goto out;
		/*
		 * With epsilon the walk starts at t0 = curve_t(s0); the
		 * exact walk works t0 out only if it must look there.
		 */
		if (eps >= 0) {
			s0 = curve_s(&C.cv, C.pr[n - 1].t) - eps;
			if (brute)
				t0 = curve_t(&C.cv, s0);
		}
		coll_grid_fit(&C, r);
		/* The next walk's first cells on their way in meanwhile. */
		a_next = angle_mod360((double)(n + 1), alpha) * (M_PI / 180);
		if (!C.nocover)
			cover_ahead(&C.cover, a_next);
		t = brute ? coll_place_brute(&C, t0, c, s, r) :
		    coll_place_exact(&C, n, t0, s0, a, c, s, r, &row, at);
		if (t > C.cv.tmax)
			break;
		/*
		 * Bounds under the least radius still to come cover their
		 * cells for good.  With a rising radius that is far above
		 * r_min, the least of all, which the map was made for, and
		 * cover_add() went on lowering bounds that no walk to come
		 * could tell from lower ones.  The least from the sample at
		 * or before the next primordium on, which on a law that
		 * only rises is no more than any radius to come.
		 */
		if (C.law_min != NULL && !C.nocover) {
			size_t i = (size_t)((n + 1) / C.law_step);

			if (i < C.nlaw)
				cover_floor(&C.cover, fmin(r, C.law_min[i]));
		}
		coll_add(&C, t, row, a, c, s, r, brute ? NULL : at);
		if (ctx->progress != NULL && n % PROGRESS_EVERY == 0)
			ctx->progress(n + 1, 0);
	}
	full = (long long)C.n == N;
	if (ctx->progress != NULL)
		ctx->progress((long long)C.n, 1);
	if (full && !ctx->count_line && cap <= 0)
		diag(ST_OK, ctx->file, P->radius.line, 0, "stopped at %d "
		    "primordia, the default bound, with room left on the "
		    "receptacle; set count to place more", COUNT_DEFAULT);
	fill_result(&C, alpha, res);
	result_info(res, "primordia", 1, (double)C.n);
	result_info_labelled(res, "receptacle", "length radius", 2,
	    C.cv.length, C.cv.rho_max);
	if (how == PLACE_CHECK) {
		result_info(res, "refine misses", 2, (double)C.refine_misses,
		    (double)C.refined);
		result_info(res, "start misses", 2, (double)C.start_misses,
		    (double)C.starts);
		result_info(res, "cover misses", 1, (double)cover_check(&C.cover,
		    &C.cv, C.rmax, CHECK_EVERY, coll_near_point, &C));
		result_info(res, "cover doubled", 1, (double)C.finer);
		result_info(res, "cover levels", 1, C.nocover ? 0 :
		    (double)C.cover.levels);
	}
	rc = 0;
out:
	cover_free(&C.cover);
	curve_free(&C.cv);
	free(C.pr);
	free(C.next);
	free(C.law);
	free(C.law_min);
	free(C.slot);
	return rc;
}

const struct receptacle *
collision_receptacle(const struct model_ctx *ctx)
{
	return &((const struct collision *)ctx->params)->receptacle;
}

int
collision_place(const struct model_ctx *ctx, struct result *res, int how)
{
	return place(ctx, res, how, 0, 0);
}

static int
trial_place(void *arg, double r, long long cap, struct result *res)
{
	return place(arg, res, PLACE_EXACT, r, cap);
}

static int
collision_make(const struct model_ctx *ctx, struct result *res)
{
	const struct collision *P = ctx->params;
	int at = P->given[CO_PARASTICHIES];
	double r;

	if (!at)
		return collision_place(ctx, res, PLACE_EXACT);
	r = para_design_receptacle(ctx->file, "collision", at,
	    P->given[CO_RADIUS], &P->receptacle, &P->parastichies, 0,
	    trial_place, (void *)ctx);
	if (r < 0 || place(ctx, res, PLACE_EXACT, r, 0) != 0)
		return -1;
	result_info(res, "radius", 1, r);
	return 0;
}

const struct model collision_model = {
	.name = "collision",
	.help = "Fowler, Prusinkiewicz & Battjes: primordia packed on a "
	    "receptacle",
	.settings = &collision_table,
	.size = sizeof(struct collision),
	.make = collision_make,
};
