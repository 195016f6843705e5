/*
 * out_csv.c - one line per organ: index, object, position, frame,
 * sizes.  With --flatten, a compound structure's parts are opened: one
 * line per leaf organ, the part's organs carried into the world by the
 * organ that places the part.
 */
#include "writer.h"

/*
 * Where a part's organs land: x -> s * R x + t, R's columns the placing
 * organ's u, v, w (orthonormal, so frames stay frames).
 */
struct place {
	double	 R[3][3];	/* R[i][k]: row i of column k */
	double	 s;
	double	 t[3];
};

static const struct place world = {
	{ { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, 1, { 0, 0, 0 }
};

/* R a; the world's R leaves a as it is (a -0 stays -0). */
static void
rotate(const struct place *P, const double a[3], double out[3])
{
	if (P == &world) {
		for (int i = 0; i < 3; i++)
			out[i] = a[i];
		return;
	}
	for (int i = 0; i < 3; i++)
		out[i] = P->R[i][0] * a[0] + P->R[i][1] * a[1] +
		    P->R[i][2] * a[2];
}

static void
line(struct sink *s, size_t n, const char *object, const struct organ *o,
    const struct place *P)
{
	double p[3], u[3], v[3], w[3], ov[3];
	const double *vals[4] = { p, u, v, w };

	organ_v(o, ov);
	rotate(P, o->pos, p);
	if (P != &world)
		for (int i = 0; i < 3; i++)
			p[i] = P->s * p[i] + P->t[i];
	rotate(P, o->u, u);
	rotate(P, ov, v);
	rotate(P, o->w, w);
	sink_uint(s, n);
	sink_putc(s, ',');
	/* Object names are identifiers: no quoting needed. */
	sink_puts(s, object);
	for (int k = 0; k < 4; k++)
		for (int j = 0; j < 3; j++) {
			sink_putc(s, ',');
			sink_num(s, vals[k][j]);
		}
	sink_putc(s, ',');
	sink_num(s, P->s * o->scale);	/* s = 1 in the world: exact */
	sink_putc(s, ',');
	sink_num(s, P->s * o->radius);
	sink_putc(s, '\n');
}

/* The place of a part set by organ o of a structure at P. */
static void
compose(const struct place *P, const struct organ *o, struct place *out)
{
	double v[3], t[3];
	const double *cols[3] = { o->u, v, o->w };

	organ_v(o, v);
	for (int k = 0; k < 3; k++) {
		double c[3];

		rotate(P, cols[k], c);
		for (int i = 0; i < 3; i++)
			out->R[i][k] = c[i];
	}
	out->s = P->s * o->scale;
	rotate(P, o->pos, t);
	for (int i = 0; i < 3; i++)
		out->t[i] = P->s * t[i] + P->t[i];
}

/* Every leaf organ of r placed at P; n counts the lines written. */
static void
leaves(struct sink *s, const struct result *r, const struct place *P,
    size_t *n)
{
	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];
		const struct result *part = r->sub ? r->sub[o->object] : NULL;

		if (part != NULL) {
			struct place inner;

			compose(P, o, &inner);
			leaves(s, part, &inner, n);
		} else
			line(s, (*n)++, r->objects[o->object], o, P);
	}
}

void
csv_write(struct sink *s, const struct result *r, unsigned opts)
{
	size_t n = 0;

	sink_puts(s, "n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,"
	    "scale,radius\n");
	if (opts & TO_FLATTEN) {
		leaves(s, r, &world, &n);
		return;
	}
	for (size_t i = 0; i < r->count; i++)
		line(s, i, r->objects[r->organs[i].object], &r->organs[i],
		    &world);
}
