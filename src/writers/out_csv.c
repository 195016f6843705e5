/*
 * out_csv.c - one line per organ: index, object, position, frame,
 * sizes.  With --flatten, a compound structure's parts are opened: one
 * line per leaf organ, in the world (flatten.c).
 */
#include <math.h>

#include "result/flatten.h"
#include "writers/writer.h"

static const char header[] =
    "n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,scale,radius\n";

struct lines {
	struct sink		*s;
	size_t			 n;
	const struct result	*objects;	/* whose names w->object is */
	double			 weights, bytes;	/* of a sample */
};

/* Organ w, placed in the structure's frame. */
static void
put_line(struct lines *L, const char *object, const struct organ *w)
{
	double v[3];
	const double *vals[4] = { w->pos, w->u, v, w->w };

	organ_v(w, v);
	sink_uint(L->s, L->n++);
	sink_putc(L->s, ',');
	/* Object names are identifiers: no quoting needed. */
	sink_puts(L->s, object);
	for (int k = 0; k < 4; k++)
		for (int j = 0; j < 3; j++) {
			sink_putc(L->s, ',');
			sink_num(L->s, vals[k][j]);
		}
	sink_putc(L->s, ',');
	sink_num(L->s, w->scale);
	sink_putc(L->s, ',');
	sink_num(L->s, w->radius);
	sink_putc(L->s, '\n');
}

static void
line(void *ctx, const struct result *r, const struct organ *o,
    const struct xform *P)
{
	struct organ w;

	place_organ(P, o, &w);
	put_line(ctx, r->objects[o->object], &w);
}

void
csv_write(struct sink *s, const struct result *r, unsigned opts)
{
	struct lines L = { s, 0, NULL, 0, 0 };

	sink_puts(s, header);
	if (opts & TO_FLATTEN) {
		flatten_walk(r, &xform_identity, line, &L);
		return;
	}
	for (size_t i = 0; i < r->count; i++)
		line(&L, r, &r->organs[i], &xform_identity);
}

static void
sample_line(void *ctx, const struct organ *w, double weight)
{
	struct lines *L = ctx;
	double before = sink_bytes(L->s);

	put_line(L, L->objects->objects[w->object], w);
	L->weights += weight;
	L->bytes += weight * (sink_bytes(L->s) - before);
}

/*
 * The lines of a sample of the organs (--flatten: of the leaves, by a
 * view), numbered as the last ones would be, scaled to them all.
 */
double
csv_bytes(const struct result *r, unsigned opts)
{
	struct result view = {0};
	struct sink s;
	struct lines L = { &s, 0, r, 0, 0 };
	double n = (double)r->count;

	if ((opts & TO_FLATTEN) && r->sub != NULL) {
		flatten_view(r, &view);
		L.objects = &view;
		n = flatten_leaves(r);
	}
	L.n = n > 1 ? (size_t)fmin(n - 1, 1e18) : 0;
	sink_init_count(&s);
	result_sample(L.objects, 64, sample_line, &L);
	sink_free(&s);
	flatten_free(&view);
	return (double)(sizeof(header) - 1) +
	    (L.weights > 0 ? L.bytes / L.weights * n : 0);
}
