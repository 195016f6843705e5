/*
 * out_csv.c - one line per organ: index, object, position, frame,
 * sizes.  With --flatten, a compound structure's parts are opened: one
 * line per leaf organ, in the world (flatten.c).
 */
#include "flatten.h"
#include "writer.h"

struct lines {
	struct sink	*s;
	size_t		 n;
};

static void
line(void *ctx, const struct result *r, const struct organ *o,
    const struct xform *P)
{
	struct lines *L = ctx;
	struct organ w;
	double v[3];
	const double *vals[4] = { w.pos, w.u, v, w.w };

	place_organ(P, o, &w);
	organ_v(&w, v);
	sink_uint(L->s, L->n++);
	sink_putc(L->s, ',');
	/* Object names are identifiers: no quoting needed. */
	sink_puts(L->s, r->objects[o->object]);
	for (int k = 0; k < 4; k++)
		for (int j = 0; j < 3; j++) {
			sink_putc(L->s, ',');
			sink_num(L->s, vals[k][j]);
		}
	sink_putc(L->s, ',');
	sink_num(L->s, w.scale);
	sink_putc(L->s, ',');
	sink_num(L->s, w.radius);
	sink_putc(L->s, '\n');
}

void
csv_write(struct sink *s, const struct result *r, unsigned opts)
{
	struct lines L = { s, 0 };

	sink_puts(s, "n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,"
	    "scale,radius\n");
	if (opts & TO_FLATTEN) {
		flatten_walk(r, &xform_identity, line, &L);
		return;
	}
	for (size_t i = 0; i < r->count; i++)
		line(&L, r, &r->organs[i], &xform_identity);
}
