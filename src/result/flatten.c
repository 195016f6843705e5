/*
 * flatten.c - open the parts of a compound structure: each leaf organ
 * is carried by the organ placing its part, and by the organ placing
 * that one, up to the structure itself.  --csv --flatten writes what
 * this gives; --blender merges a part's own parts into it with it,
 * because Blender expands instances of instances only so deep.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "result/flatten.h"
#include "base/mem.h"

const struct xform xform_identity = {
	{ { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, 1, { 0, 0, 0 }
};

/* R a; the identity leaves a as it is (a -0 stays -0). */
static void
rotate(const struct xform *P, const double a[3], double out[3])
{
	if (P == &xform_identity) {
		memcpy(out, a, 3 * sizeof(*out));
		return;
	}
	for (int i = 0; i < 3; i++)
		out[i] = P->R[i][0] * a[0] + P->R[i][1] * a[1] +
		    P->R[i][2] * a[2];
}

void
place_organ(const struct xform *P, const struct organ *o, struct organ *out)
{
	struct organ w = *o;

	rotate(P, o->pos, w.pos);
	if (P != &xform_identity)
		for (int i = 0; i < 3; i++)
			w.pos[i] = P->s * w.pos[i] + P->t[i];
	rotate(P, o->u, w.u);
	rotate(P, o->w, w.w);
	w.scale = P->s * o->scale;
	w.radius = P->s * o->radius;
	*out = w;
}

/* The place of a part set by organ o of a structure at P. */
static void
compose(const struct xform *P, const struct organ *o, struct xform *out)
{
	struct organ w;
	double v[3];

	place_organ(P, o, &w);
	organ_v(&w, v);
	for (int i = 0; i < 3; i++) {
		out->R[i][0] = w.u[i];
		out->R[i][1] = v[i];
		out->R[i][2] = w.w[i];
		out->t[i] = w.pos[i];
	}
	out->s = w.scale;
}

/*
 * The walk behind flatten_walk() and views: enter, when given, says
 * whether to open a part at all (a view skips parts without the object
 * it is after).
 */
struct walker {
	leaf_fn		*leaf;
	void		*ctx;
	int		(*enter)(void *ctx, const struct result *part);
};

static void
walk(const struct result *r, const struct xform *P, const struct walker *W)
{
	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];
		const struct result *part = r->sub ? r->sub[o->object] : NULL;

		if (part == NULL)
			W->leaf(W->ctx, r, o, P);
		else if (W->enter == NULL || W->enter(W->ctx, part)) {
			struct xform inner;

			compose(P, o, &inner);
			walk(part, &inner, W);
		}
	}
}

void
flatten_walk(const struct result *r, const struct xform *P, leaf_fn *fn,
    void *ctx)
{
	struct walker W = { fn, ctx, NULL };

	walk(r, P, &W);
}

/*
 * A view's bookkeeping: each distinct structure of the tree once, with
 * where its plain objects stand among the view's objects and how many
 * leaves of each view object its own subtree holds.
 */
struct flat_part {
	const struct result *r;
	unsigned	*id;		/* per object of r, when plain */
	double		*leaves;	/* per view object; NULL until tallied */
};

struct flat {
	const struct result *top;
	struct flat_part *part;
	size_t		 n, last;	/* last: the part found last */
	size_t		 nobjects;
};

static size_t
part_of(struct flat *F, const struct result *r)
{
	if (F->last < F->n && F->part[F->last].r == r)
		return F->last;
	for (size_t i = 0; i < F->n; i++)
		if (F->part[i].r == r)
			return F->last = i;
	return (size_t)-1;
}

/* The index of object name in out's objects, added if new. */
static unsigned
object_id(struct result *out, const char *name)
{
	size_t k;

	for (k = 0; k < out->nobjects; k++)
		if (strcmp(out->objects[k], name) == 0)
			return (unsigned)k;
	out->objects = xreallocarray(out->objects, k + 1,
	    sizeof(*out->objects));
	memcpy(out->objects[k], name, sizeof(out->objects[k]));
	out->nobjects = k + 1;
	return (unsigned)k;
}

/*
 * Add r and the parts under it, naming their plain objects in the order
 * a walk of the leaves meets them: a part's names come in at the first
 * organ placing it, so each structure is read once.
 */
static void
gather(struct flat *F, struct result *out, const struct result *r)
{
	size_t me = F->n, seen = 0;
	char *met = xcalloc(r->nobjects ? r->nobjects : 1, 1);

	F->part = xreallocarray(F->part, F->n + 1, sizeof(*F->part));
	F->part[F->n++] = (struct flat_part){ r,
	    xcalloc(r->nobjects ? r->nobjects : 1, sizeof(unsigned)), NULL };
	for (size_t i = 0; i < r->count && seen < r->nobjects; i++) {
		unsigned j = r->organs[i].object;
		const struct result *p = r->sub ? r->sub[j] : NULL;

		if (met[j])
			continue;
		met[j] = 1;
		seen++;
		if (p == NULL)
			F->part[me].id[j] = object_id(out, r->objects[j]);
		else if (part_of(F, p) == (size_t)-1)
			gather(F, out, p);
	}
	free(met);
}

/* Leaves of each view object under part i, tallied once. */
static const double *
tally(struct flat *F, size_t i)
{
	const struct result *r = F->part[i].r;
	double *per, *n;

	if (F->part[i].leaves != NULL)
		return F->part[i].leaves;
	n = xcalloc(r->nobjects ? r->nobjects : 1, sizeof(*n));
	per = xcalloc(F->nobjects ? F->nobjects : 1, sizeof(*per));
	for (size_t k = 0; k < r->count; k++)
		n[r->organs[k].object]++;
	for (size_t j = 0; j < r->nobjects; j++) {
		const struct result *p = r->sub ? r->sub[j] : NULL;

		if (n[j] == 0)
			continue;
		if (p == NULL)
			per[F->part[i].id[j]] += n[j];
		else {
			const double *under = tally(F, part_of(F, p));

			for (size_t k = 0; k < F->nobjects; k++)
				per[k] += n[j] * under[k];
		}
	}
	free(n);
	return F->part[i].leaves = per;
}

static void
flat_free(struct flat *F)
{
	if (F == NULL)
		return;
	for (size_t i = 0; i < F->n; i++) {
		free(F->part[i].id);
		free(F->part[i].leaves);
	}
	free(F->part);
	free(F);
}

/* The parts of r, their leaves' objects named in out's objects. */
static struct flat *
flat_make(const struct result *r, struct result *out)
{
	struct flat *F = xcalloc(1, sizeof(*F));

	F->top = r;
	gather(F, out, r);
	F->nobjects = out->nobjects;
	return F;
}

void
flatten_view(const struct result *r, struct result *out)
{
	struct flat *F;
	double leaves = 0;

	*out = (struct result){0};
	F = flat_make(r, out);
	for (size_t k = 0; k < F->nobjects; k++)
		leaves += tally(F, 0)[k];
	out->flat = F;
	/* Past SIZE_MAX only on paper: no such output gets written. */
	out->count = leaves < (double)SIZE_MAX ? (size_t)leaves : SIZE_MAX;
	memcpy(out->name, r->name, sizeof(out->name));
	out->model = r->model;
	out->seed = r->seed;
	out->divergence = r->divergence;
	out->svg = r->svg;
	out->rim_last = r->rim_last;
	out->source = xstrdup(r->source);
	out->meshes = r->meshes;
	out->part = r->part;
	out->frame = r->frame;
	out->frames = r->frames;
	out->frame_f = r->frame_f;
}

void
flatten_free(struct result *view)
{
	flat_free(view->flat);
	view->flat = NULL;
	result_free(view);
}

double
flatten_leaves(const struct result *r)
{
	struct result names = { 0 };
	struct flat *F;
	double leaves = 0;

	if (r->sub == NULL)
		return (double)r->count;
	F = flat_make(r, &names);
	for (size_t k = 0; k < F->nobjects; k++)
		leaves += tally(F, 0)[k];
	free(names.objects);
	flat_free(F);
	return leaves;
}

/* What result_each() carries through a view's walk. */
struct each {
	struct flat	*F;
	size_t		 k;
	organ_fn	*fn;
	void		*ctx;
};

static int
each_enter(void *ctx, const struct result *part)
{
	struct each *E = ctx;

	return E->k == RESULT_ALL || tally(E->F, part_of(E->F, part))[E->k] > 0;
}

static void
each_leaf(void *ctx, const struct result *r, const struct organ *o,
    const struct xform *P)
{
	struct each *E = ctx;
	unsigned id = E->F->part[part_of(E->F, r)].id[o->object];
	struct organ w;

	if (E->k != RESULT_ALL && id != E->k)
		return;
	place_organ(P, o, &w);
	w.object = id;
	E->fn(E->ctx, &w);
}

void
result_each(const struct result *r, size_t k, organ_fn *fn, void *ctx)
{
	struct each E = { r->flat, k, fn, ctx };
	struct walker W = { each_leaf, &E, each_enter };

	if (r->flat == NULL) {
		for (size_t i = 0; i < r->count; i++)
			if (k == RESULT_ALL || r->organs[i].object == k)
				fn(ctx, &r->organs[i]);
		return;
	}
	walk(r->flat->top, &xform_identity, &W);
}

/*
 * The leaf at fraction x of q's leaves, as if each organ held as many:
 * organ floor(x count), then the fraction left over within it.
 */
static void
descend(struct flat *F, const struct result *q, const struct xform *P,
    double x, double weight, sample_fn *fn, void *ctx)
{
	size_t i = (size_t)(x * (double)q->count);
	const struct organ *o;
	const struct result *part;

	if (q->count == 0)
		return;
	if (i >= q->count)
		i = q->count - 1;
	o = &q->organs[i];
	part = q->sub ? q->sub[o->object] : NULL;
	if (part != NULL) {
		struct xform inner;

		compose(P, o, &inner);
		descend(F, part, &inner, x * (double)q->count - (double)i,
		    weight * (double)part->count, fn, ctx);
	} else {
		struct organ w;

		place_organ(P, o, &w);
		w.object = F->part[part_of(F, q)].id[o->object];
		fn(ctx, &w, weight);
	}
}

void
result_sample(const struct result *r, size_t m, sample_fn *fn, void *ctx)
{
	for (size_t j = 0; j < m && j < r->count; j++) {
		double x = r->count <= m ? ((double)j + 0.5) / (double)r->count :
		    ((double)j + 0.5) / (double)m;

		if (r->flat != NULL)
			descend(r->flat, r->flat->top, &xform_identity, x, 1, fn,
			    ctx);
		else
			fn(ctx, &r->organs[(size_t)(x * (double)r->count)], 1);
	}
}

double
result_object_organs(const struct result *r, size_t k)
{
	double n = 0;

	if (r->flat != NULL)
		return tally(r->flat, 0)[k];
	for (size_t i = 0; i < r->count; i++)
		n += r->organs[i].object == k;
	return n;
}
