/*
 * measured.c - the measured model: organs where a real plant has them,
 * read from a points file (florets clicked on a photograph, scales from
 * a scan; measured_csv.c), each given a frame on the surface they lie
 * on and a size from their spacing, so that every writer renders the
 * very head with the artist's own organs; and measured as they are,
 * without an order (analysis/unordered.c): its parastichies zone by
 * zone, its divergence and Vogel's fit.
 *
 * The result's organs are the file's rows, in the order of its column
 * n if it has one; centred on the axis found (or guessed), a photograph
 * flipped to y up, scaled to outer if given.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/axis.h"
#include "analysis/kdtree.h"
#include "analysis/unordered.h"
#include "compat/compat.h"
#include "base/diag.h"
#include "geometry/geometry.h"
#include "base/mem.h"
#include "models/measured_csv.h"
#include "models/model.h"
#include "base/path.h"

enum { MS_POINTS, MS_YAXIS, MS_CENTRE, MS_OUTER, MS_OBLIQUE, MS__N };

enum { YAXIS_UP, YAXIS_DOWN };
enum { OBLIQUE_KEEP, OBLIQUE_UNDO };

struct measured {
	struct group_at	 at;
	int		 given[MS__N];
	struct file_list points;	/* the file, as written */
	int		 yaxis;
	double		 centre[3];	/* a guess of where the axis is */
	double		 outer;
	int		 oblique;
};

#define M(f)	offsetof(struct measured, f)

static const char *const yaxis_names[] = { "up", "down", NULL };
static const char *const oblique_names[] = { "keep", "undo", NULL };

static const struct row measured_rows[] = {
	[MS_POINTS] = { .name = "points", .type = T_FILES, .off = M(points),
	  .defstr = "none",
	  .doc = "CSV of the organs' centres: columns x, y and optionally z, "
	  "n, radius" },
	[MS_YAXIS] = { .name = "yaxis", .type = T_CHOICE, .off = M(yaxis),
	  .words = yaxis_names, .def = YAXIS_UP, .defstr = "up",
	  .doc = "down: image coordinates, y growing down the picture" },
	[MS_CENTRE] = { .name = "centre", .type = T_VEC3, .off = M(centre),
	  .lo = -HUGE_VAL, .hi = HUGE_VAL, .defstr = "found",
	  .unit = "length",
	  .doc = "a guess of a point on the axis, in the file's coordinates; "
	  "the fit starts there" },
	[MS_OUTER] = { .name = "outer", .type = T_FLOAT, .off = M(outer),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .defstr = "as measured",
	  .unit = "length",
	  .doc = "the organs' largest distance from the axis: the points are "
	  "scaled to it" },
	[MS_OBLIQUE] = { .name = "oblique", .type = T_CHOICE,
	  .off = M(oblique), .words = oblique_names, .def = OBLIQUE_KEEP,
	  .defstr = "keep",
	  .doc = "undo: place the organs as seen square on, the view's "
	  "squash the fit found undone" },
};

static const struct table measured_table = TABLE(measured_rows,
    struct measured);

/* The points file, readable and regular (a FIFO would wait for ever). */
static int
open_points(const struct model_ctx *ctx, const struct measured *P,
    char **path)
{
	int line = GIVEN_AT(P, MS_POINTS);
	const char *why;
	struct sys_stat st;

	if (!P->given[MS_POINTS]) {
		model_error(ctx, P->at.line > 0 ? P->at.line : 1, "missing "
		    "setting 'measured.points': the file of the organs' "
		    "centres");
		return -1;
	}
	if (P->points.n != 1) {
		model_error(ctx, line, "measured.points names one file, not "
		    "%zu", P->points.n);
		return -1;
	}
	*path = path_resolve(ctx->file, P->points.v[0]);
	/* A FIFO would wait for a writer for ever. */
	why = sys_stat(*path, &st) != 0 ? strerror(errno) :
	    st.kind == SYS_DIR ? strerror(EISDIR) :
	    st.kind != SYS_REG ? "not a regular file" :
	    !sys_readable(*path) ? strerror(errno) : NULL;
	if (why != NULL) {
		model_error(ctx, line, "measured.points %s: %s", *path, why);
		free(*path);
		*path = NULL;
		return -1;
	}
	return 0;
}

static const struct points *by_n_points;

static int
by_n(const void *a, const void *b)
{
	long long x = by_n_points->n[*(const size_t *)a];
	long long y = by_n_points->n[*(const size_t *)b];

	return x < y ? -1 : x > y;
}

/* The rows in the order of column n, where the file has one. */
static size_t *
row_order(const struct points *P)
{
	size_t *ix = xcalloc(P->count, sizeof(*ix));

	for (size_t i = 0; i < P->count; i++)
		ix[i] = i;
	if (P->n != NULL) {
		by_n_points = P;
		qsort(ix, P->count, sizeof(*ix), by_n);
		by_n_points = NULL;
	}
	return ix;
}

/*
 * Points further from their nearest than STRAY spacings of that one's
 * (a lattice's organs are one spacing apart, at a rim or a cut too):
 * a click beside the head, a typo in a number.  Warned of, the
 * furthest by its line: it is measured as an organ, and sets the head's
 * extent (outer) and its rim.
 */
#define STRAY	4

static void
stray(const struct points *P, const char *path, const size_t *near,
    const double *d0, const double *radius)
{
	size_t worst = 0, many = 0;
	double most = 0;

	for (size_t i = 0; i < P->count; i++) {
		double at = 2 * radius[near[i]];	/* near[i]'s spacing */

		if (near[i] == i || at <= 0 || d0[i] <= STRAY * at)
			continue;
		many++;
		if (d0[i] / at > most) {
			most = d0[i] / at;
			worst = i;
		}
	}
	if (many > 0)
		diag(ST_OK, path, P->line[worst], 0, "this point is %.3g "
		    "spacings from any other%s: a stray click? it is measured "
		    "as an organ, and sets the head's extent and rim", most,
		    many > 1 ? " (and more points are far out)" : "");
}

/*
 * Each point's radius, half the median distance to its four nearest
 * (a lattice's first shell, but for the third direction's pair; a
 * click's jitter averages out), and the closest pair.  A point within
 * a tenth of its fourth nearest's distance of another is warned of,
 * once: one organ clicked twice, likely (its own spacing, not the
 * head's: organs at a tip or centre may be far smaller than the rest;
 * a model's first organs may nearly meet).  The same point twice is
 * the reader's error.
 */
static void
spacing(const struct points *P, const double (*p)[3], const char *path,
    double *radius, size_t closest[2], double *dmin)
{
	struct kd T;
	size_t *near = xcalloc(P->count, sizeof(*near));
	double *d0 = xcalloc(P->count, sizeof(*d0));
	int warned = 0;

	*dmin = HUGE_VAL;
	kd_init_points(&T, p, P->count);
	for (size_t i = 0; i < P->count; i++) {
		struct kd_near nb;
		double d[KD_K];
		int n = 0;

		kd_nearest(&T, p[i], i, 0, &nb);
		for (int k = 0; k < nb.n; k++)
			d[n++] = sqrt(nb.d2[k]) / nb.inv;
		radius[i] = n >= 4 ? (d[1] + d[2]) / 4 : n > 0 ? d[0] / 2 : 0;
		near[i] = n > 0 ? nb.j[0] : i;
		d0[i] = n > 0 ? d[0] : 0;
		if (n > 0 && d[0] < *dmin) {
			*dmin = d[0];
			closest[0] = i;
			closest[1] = nb.j[0];
		}
		if (n >= 4 && d[0] < 0.1 * d[3] && !warned) {
			size_t j = nb.j[0], late = P->line[i] > P->line[j] ? i : j;

			diag(ST_OK, path, P->line[late], 0, "this point is %.3g "
			    "from the one at line %d, under a tenth of the "
			    "spacing about them (%.3g): the same organ twice?",
			    d[0], P->line[late == i ? j : i], d[3]);
			warned = 1;
		}
	}
	kd_free(&T);
	stray(P, path, near, d0, radius);
	free(near);
	free(d0);
}

/*
 * How far a head reaches from the centre found on its shortest side,
 * of the way it reaches on its median side, in SECTORS directions: a head
 * the picture's frame cut near its centre leaves the centre's search
 * too little of a ring to read (the trials hold at 0.7 of the radius;
 * cuts nearer than a fifth gave divergences far off, with small
 * errors).  Under REACH_LOW, a warning: the centre may be off; or, given,
 * not the head's.  Fewer directions on a small head, eight points a
 * direction at least: else some would hold none, cut or not; and none
 * under REACH_MIN points, too few to read (and a few clicks of Vogel's
 * spiral are lopsided).
 */
#define SECTORS		24
#define REACH_LOW	0.5
#define REACH_MIN	60

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

static void
reach(const struct axis_point *ap, size_t n, const char *path, int given)
{
	double far[SECTORS] = { 0 }, lo, hi;
	int sectors = n / 8 < 4 ? 4 : n / 8 > SECTORS ? SECTORS : (int)(n / 8);

	for (size_t i = 0; i < n; i++) {
		double a = atan2(ap[i].p[1], ap[i].p[0]) / (2 * M_PI) + 0.5;
		int k = (int)(a * sectors) % sectors;

		far[k] = fmax(far[k], ap[i].rho);
	}
	/* Of the median side's: a stray click makes no side long. */
	qsort(far, (size_t)sectors, sizeof(*far), cmp_double);
	lo = far[0];
	hi = far[sectors / 2];
	/* hi 0: no points at all on half the sides, a centre outside. */
	if (n < REACH_MIN || (hi > 0 && lo >= REACH_LOW * hi))
		return;
	if (given)
		diag(ST_OK, path, 0, 0, "about measured.centre the points "
		    "reach %.2g of the head's radius on one side: a head cut "
		    "there, or a centre not the head's?", hi > 0 ? lo / hi : 0);
	else
		diag(ST_OK, path, 0, 0, "the points reach %.2g of the head's "
		    "radius on one side (a head the picture's frame cut?): "
		    "the centre found may be off, and with it the "
		    "divergence; give measured.centre if you know it",
		    hi > 0 ? lo / hi : 0);
}

/* The measurement's facts for --info (the parastichies: out_info). */
static void
facts(struct result *res, const struct points *P, const size_t *row,
    const struct unordered *U, const struct measured *M, double unit,
    const size_t closest[2], double dmin)
{
	double flip = M->yaxis == YAXIS_DOWN ? -1 : 1;

	result_info_labelled(res, "centre", "x y", 2, U->centre[0],
	    flip * U->centre[1]);
	if (!U->surface)
		result_info_labelled(res, "oblique", "ratio angle", 2,
		    U->squash, fmod(flip * U->squash_deg + 180, 180));
	result_info(res, "spacing", 1, unit * U->spacing);
	/* By the file's n, or its rows counted from 0. */
	result_info_labelled(res, "closest", "distance organ organ", 3,
	    unit * dmin, (double)(P->n ? P->n[row[closest[0]]] :
	    (long long)closest[0]), (double)(P->n ? P->n[row[closest[1]]] :
	    (long long)closest[1]));
	if (!isnan(U->divergence)) {
		double d = U->divergence;

		/* Followed from the tip outward. */
		double out = U->older_out ? fmod(360 - d, 360) : d;

		result_info_labelled(res, "divergence-measured",
		    "mean error bands", 3, d <= 180 ? d : 360 - d,
		    U->divergence_err, (double)U->divergence_bands);
		result_info_text(res, "spiral", out <= 180 ?
		    "counter-clockwise outward" : "clockwise outward");
	}
	if (!isnan(U->vogel_c))
		result_info_labelled(res, "vogel", "c c-error exponent "
		    "exponent-error", 4, unit * U->vogel_c,
		    unit * U->vogel_c_err, U->exponent, U->exponent_err);
	if (U->surface && !isnan(U->rise))
		result_info_labelled(res, "rise", "mean error", 2,
		    unit * U->rise, unit * U->rise_err);
	if (!isnan(U->contact))
		result_info(res, "contact", 1, unit * U->contact);
}

/*
 * Where the file gives an order: the share of the contacts the
 * measurement read whose organs the file's n set as many apart, n
 * counting from the rim or base (a plant's order) or from the tip
 * (Vogel's), whichever agrees.
 */
static void
order_agrees(struct result *res, const struct points *P, const size_t *row,
    const struct unordered *U)
{
	size_t same[2] = { 0, 0 }, all = 0;

	if (P->n == NULL)
		return;
	for (size_t i = 0; i < U->count; i++)
		for (int s = 0; s < 2; s++) {
			const struct uorgan *c = &U->c[i];
			long long d;

			if (c->prev[s] < 0)
				continue;
			all++;
			d = P->n[row[i]] - P->n[row[c->prev[s]]];
			same[0] += d == c->dk[s];
			same[1] += -d == c->dk[s];
		}
	if (all > 0)
		result_info(res, "order-agrees", 1, (double)(same[0] > same[1] ?
		    same[0] : same[1]) / (double)all);
}

/*
 * Which organs are the older: where the file's n counts from the rim or
 * base (a plant's order, the collision model's), those far from the
 * tip; else, and without an n, those near it, as Vogel counts (a head's
 * outermost florets then read their contacts inward, where the spirals
 * a botanist counts at the rim run).
 */
static int
older_out(const struct points *P, const size_t *row,
    const struct axis_point *ap)
{
	double sn = 0, ss = 0, sns = 0, k = (double)P->count;

	if (P->n == NULL)
		return 0;
	for (size_t i = 0; i < P->count; i++) {
		double n = (double)P->n[row[i]];

		sn += n;
		ss += ap[i].s;
		sns += n * ap[i].s;
	}
	/* n falling as s rises (their covariance's sign): from the far end. */
	return k * sns - sn * ss < 0;
}

/*
 * The organs, centred, scaled, each framed on the fitted surface; as
 * the fit sees them (the view's squash undone) if undo, else as the
 * file has them.
 */
static void
place(struct result *res, const double (*p)[3], const struct axis *A,
    const struct axis_point *ap, const double *radius, const double *given,
    double unit, int undo)
{
	for (size_t i = 0; i < res->count; i++) {
		struct organ *o = &res->organs[i];
		double x = unit * (undo ? ap[i].p[0] : p[i][0] - A->centre[0]);
		double y = unit * (undo ? ap[i].p[1] : p[i][1] - A->centre[1]);
		double z = unit * p[i][2], rho = hypot(x, y);
		double phi = rho > 0 ? atan2(y, x) * 180 / M_PI : 0;

		if (phi < 0)
			phi += 360;
		/* u along the curve away from the tip; a head's: outward. */
		frame_revolution(o, phi, rho, z, ap[i].t[0], ap[i].t[1]);
		o->pos[0] = x;
		o->pos[1] = y;
		o->radius = unit * (given != NULL ? given[i] : radius[i]);
		o->scale = o->radius;
		o->object = 0;
	}
}

static int
measured_make(const struct model_ctx *ctx, struct result *res)
{
	const struct measured *M = ctx->params;
	struct points P;
	struct axis A;
	struct axis_point *ap;
	struct unordered *U;
	double (*p)[3], *radius, *given = NULL, guess[2], unit = 1, dmin;
	double flip = M->yaxis == YAXIS_DOWN ? -1 : 1, far = 0;
	size_t *row, closest[2] = { 0, 0 };
	char *path;

	if (open_points(ctx, M, &path) != 0)
		return -1;
	if (points_read(&P, path) != 0) {
		free(path);
		return -1;
	}
	row = row_order(&P);
	p = xcalloc(P.count, sizeof(*p));
	radius = xcalloc(P.count, sizeof(*radius));
	if (P.radius != NULL)
		given = xcalloc(P.count, sizeof(*given));
	for (size_t i = 0; i < P.count; i++) {
		memcpy(p[i], P.p[row[i]], sizeof(p[i]));
		p[i][1] *= flip;
		if (given != NULL)
			given[i] = P.radius[row[i]];
	}
	guess[0] = M->centre[0];
	guess[1] = flip * M->centre[1];
	axis_find(&A, (const double (*)[3])p, P.count, P.has_z,
	    M->given[MS_CENTRE] ? guess : NULL);
	/* The rows by line, for the message about a repeated organ. */
	{
		struct points byrow = P;
		int *line = xcalloc(P.count, sizeof(*line));

		for (size_t i = 0; i < P.count; i++)
			line[i] = P.line[row[i]];
		byrow.line = line;
		spacing(&byrow, (const double (*)[3])p, path, radius, closest,
		    &dmin);
		free(line);
	}
	ap = xcalloc(P.count, sizeof(*ap));
	axis_points(&A, (const double (*)[3])p, P.count, ap);
	if (!A.surface)
		reach(ap, P.count, path, M->given[MS_CENTRE]);
	U = unordered_measure(&A, ap, (const double (*)[3])p, P.count,
	    older_out(&P, row, ap));
	for (size_t i = 0; i < P.count; i++)
		far = fmax(far, M->oblique == OBLIQUE_UNDO ? ap[i].rho :
		    hypot(p[i][0] - A.centre[0], p[i][1] - A.centre[1]));
	if (M->given[MS_OUTER] && far > 0)
		unit = M->outer / far;
	result_init(res, P.count);
	place(res, (const double (*)[3])p, &A, ap, radius, given, unit,
	    M->oblique == OBLIQUE_UNDO);
	res->divergence = isnan(U->divergence) ? 0 : U->divergence <= 180 ?
	    U->divergence : 360 - U->divergence;
	res->svg = U->surface ? PROJ_UNROLL : PROJ_TOP;
	res->rim_last = 1;
	facts(res, &P, row, U, M, unit, closest, dmin);
	order_agrees(res, &P, row, U);
	U->unit = unit;
	res->unordered = U;
	axis_free(&A);
	free(ap);
	free(p);
	free(radius);
	free(given);
	free(row);
	free(path);
	points_free(&P);
	return 0;
}

/* The file the model reads, for -o's check (run.c). */
static void
measured_inputs(const void *params, const char *scene,
    void (*add)(const char *path, const char *what))
{
	const struct measured *M = params;
	char *path;

	if (!M->given[MS_POINTS] || M->points.n != 1)
		return;
	path = path_resolve(scene, M->points.v[0]);
	add(path, "the points file");
	free(path);
}

const struct model measured_model = {
	.name = "measured",
	.help = "a real plant's organs from a points file, measured without "
	    "an order",
	.settings = &measured_table,
	.size = sizeof(struct measured),
	.make = measured_make,
	.count_else = "points",
	.emerges = 1,
	.counts_itself = 1,
	.inputs = measured_inputs,
};
