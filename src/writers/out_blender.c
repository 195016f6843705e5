/*
 * out_blender.c - the placeholders of the Blender script template
 * (templates/blender.tmpl).  The organs travel as base64 of little-
 * endian float32 blocks, grouped by organ object so that the script
 * only slices arrays: every position (x, y, z), then every rotation
 * (Euler XYZ, radians), then every scale.  About 38 bytes an organ.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/diag.h"
#include "result/flatten.h"
#include "base/mem.h"
#include "writers/writer.h"

/* Euler XYZ angles (Blender's default order) of the rotation [u v w]. */
static void
euler_xyz(const struct organ *o, double e[3])
{
	/* R = Rz Ry Rx; its columns are u, v, w. */
	double s = -o->u[2], v[3];

	organ_v(o, v);
	if (s > 1)
		s = 1;
	if (s < -1)
		s = -1;
	e[1] = asin(s);
	if (fabs(s) < 1 - 1e-12) {
		e[0] = atan2(v[2], o->w[2]);
		e[2] = atan2(o->u[1], o->u[0]);
	} else {
		/* Gimbal lock: only X + Z or X - Z is defined; put it in X. */
		e[0] = atan2(-o->w[1] * s, v[1]);
		e[2] = 0;
	}
}

struct b64 {
	struct sink	*s;
	unsigned char	 in[3];
	int		 n;
	size_t		 col;
};

static void
b64_flush(struct b64 *b, int final)
{
	static const char abc[] =
	    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	char out[4];

	if (b->n == 0)
		return;
	if (b->n < 3 && !final)
		return;
	out[0] = abc[b->in[0] >> 2];
	out[1] = abc[((b->in[0] & 3) << 4) | (b->n > 1 ? b->in[1] >> 4 : 0)];
	out[2] = b->n > 1 ? abc[((b->in[1] & 15) << 2) |
	    (b->n > 2 ? b->in[2] >> 6 : 0)] : '=';
	out[3] = b->n > 2 ? abc[b->in[2] & 63] : '=';
	/* Python joins adjacent string literals: lines of 1000. */
	if (b->col == 1000) {
		sink_puts(b->s, "\"\n    \"");
		b->col = 0;
	}
	sink_write(b->s, out, 4);
	b->col += 4;
	b->n = 0;
}

static void
b64_float(struct b64 *b, double x)
{
	float f = (float)x;
	uint32_t u;

	memcpy(&u, &f, sizeof(u));
	for (int i = 0; i < 4; i++) {
		b->in[b->n++] = (unsigned char)(u >> (8 * i));
		b64_flush(b, 0);
	}
}

/* The organs in object order, keeping index order within an object;
 * 32 bits suffice for COUNT_MAX and halve this array. */
static uint32_t *
by_object(const struct result *r)
{
	size_t *start = xcalloc(r->nobjects + 1, sizeof(*start));
	uint32_t *order = xcalloc(r->count, sizeof(*order));

	for (size_t i = 0; i < r->count; i++)
		start[r->organs[i].object + 1]++;
	for (size_t k = 0; k < r->nobjects; k++)
		start[k + 1] += start[k];
	for (size_t i = 0; i < r->count; i++)
		order[start[r->organs[i].object]++] = (uint32_t)i;
	free(start);
	return order;
}

/* One organ's part of one block: its position, rotation or scale. */
struct block {
	struct b64	*b;
	int		 which;
};

static void
block_organ(void *ctx, const struct organ *o)
{
	struct block *k = ctx;
	double e[3];

	if (k->which == 0)
		for (int j = 0; j < 3; j++)
			b64_float(k->b, o->pos[j]);
	else if (k->which == 1) {
		euler_xyz(o, e);
		for (int j = 0; j < 3; j++)
			b64_float(k->b, e[j]);
	} else
		b64_float(k->b, o->scale);
}

/*
 * A view's leaves are walked once per block and object (a walk skips
 * parts without the object), so that no array of them is made.
 */
static void
put_data(struct sink *s, const struct tmpl_ctx *c)
{
	struct b64 b = { s, { 0 }, 0, 0 };
	uint32_t *order = c->r->flat == NULL ? by_object(c->r) : NULL;

	sink_putc(s, '"');
	for (int which = 0; which < 3; which++) {
		struct block k = { &b, which };

		if (order == NULL)
			for (size_t j = 0; j < c->r->nobjects; j++)
				result_each(c->r, j, block_organ, &k);
		else
			for (size_t i = 0; i < c->r->count; i++)
				block_organ(&k, &c->r->organs[order[i]]);
	}
	b64_flush(&b, 1);
	sink_putc(s, '"');
	free(order);
}

/*
 * What put_data() writes, from the count alone: two quotes, base64 of
 * 28 bytes an organ, and a line break of 7 bytes every 1000 characters.
 */
static double
data_size(const struct tmpl_ctx *c)
{
	double chars = 4 * ceil(28 * (double)c->r->count / 3);

	return 2 + chars + (chars > 0 ? floor((chars - 1) / 1000) * 7 : 0);
}

/* True with --blender-objects: linked duplicates, not instances. */
static void
put_linked(struct sink *s, const struct tmpl_ctx *c)
{
	sink_puts(s, c->opts & TO_OBJECTS ? "True" : "False");
}

const struct tmpl_var blender_vars[] = {
	{ "DATA", TS_GLOBAL, put_data, data_size },
	{ "LINKED", TS_GLOBAL, put_linked, NULL },
	{ NULL, 0, NULL, NULL }
};

