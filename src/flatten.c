/*
 * flatten.c - open the parts of a compound structure: each leaf organ
 * is carried by the organ placing its part, and by the organ placing
 * that one, up to the structure itself.  --csv --flatten writes what
 * this gives; --blender merges a part's own parts into it with it,
 * because Blender expands instances of instances only so deep.
 */
#include <stdlib.h>
#include <string.h>

#include "flatten.h"
#include "mem.h"

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

void
flatten_walk(const struct result *r, const struct xform *P, leaf_fn *fn,
    void *ctx)
{
	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];
		const struct result *part = r->sub ? r->sub[o->object] : NULL;

		if (part != NULL) {
			struct xform inner;

			compose(P, o, &inner);
			flatten_walk(part, &inner, fn, ctx);
		} else
			fn(ctx, r, o, P);
	}
}

size_t
flatten_count(const struct result *r)
{
	size_t n = 0;

	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];

		n += r->sub && r->sub[o->object] ? flatten_count(
		    r->sub[o->object]) : 1;
	}
	return n;
}

struct collect {
	struct result	*out;
	size_t		 n;
};

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

static void
collect(void *ctx, const struct result *r, const struct organ *o,
    const struct xform *P)
{
	struct collect *c = ctx;
	struct organ *w = &c->out->organs[c->n++];

	place_organ(P, o, w);
	w->object = object_id(c->out, r->objects[o->object]);
}

void
flatten_result(const struct result *r, struct result *out)
{
	struct collect c = { out, 0 };

	result_init(out, flatten_count(r));
	memcpy(out->name, r->name, sizeof(out->name));
	out->model = r->model;
	out->seed = r->seed;
	out->divergence = r->divergence;
	out->svg = r->svg;
	out->rim_last = r->rim_last;
	out->source = xstrdup(r->source);
	out->part = r->part;
	out->frame = r->frame;
	out->frames = r->frames;
	out->frame_f = r->frame_f;
	flatten_walk(r, &xform_identity, collect, &c);
}
