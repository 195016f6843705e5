/*
 * out_svg.c - an SVG picture for a quick look without a renderer: each
 * organ a circle of its packing radius, coloured by organ object.  The
 * planar model is seen from above (+Y up the page); the cylindrical
 * one unrolled, angle times radius across and height up, where its
 * parastichies are straight lines.
 */
#include <math.h>

#include "writer.h"

/* Where organ o goes on the page, before the y flip. */
static void
project(const struct result *r, const struct organ *o, double p[2])
{
	if (r->svg == PROJ_UNROLL) {
		p[0] = hypot(o->pos[0], o->pos[1]) * o->phi * (M_PI / 180);
		p[1] = o->pos[2];
	} else {
		p[0] = o->pos[0];
		p[1] = o->pos[1];
	}
}

void
svg_write(struct sink *s, const struct result *r)
{
	double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
	double p[2], pad, w, h;

	for (size_t i = 0; i < r->count; i++) {
		project(r, &r->organs[i], p);
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], p[k] - r->organs[i].radius);
			hi[k] = fmax(hi[k], p[k] + r->organs[i].radius);
		}
	}
	w = hi[0] - lo[0];
	h = hi[1] - lo[1];
	pad = 0.02 * fmax(fmax(w, h), 1e-9);
	sink_puts(s, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
	    "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
	sink_num(s, lo[0] - pad);
	sink_putc(s, ' ');
	sink_num(s, -hi[1] - pad);
	sink_putc(s, ' ');
	sink_num(s, w + 2 * pad);
	sink_putc(s, ' ');
	sink_num(s, h + 2 * pad);
	sink_puts(s, "\" width=\"800\" height=\"");
	sink_num(s, round(800 * (h + 2 * pad) / (w + 2 * pad)));
	sink_puts(s, "\">\n<title>");
	/* Identifiers: nothing to escape. */
	sink_puts(s, r->name);
	sink_puts(s, "</title>\n<rect x=\"");
	sink_num(s, lo[0] - pad);
	sink_puts(s, "\" y=\"");
	sink_num(s, -hi[1] - pad);
	sink_puts(s, "\" width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n");
	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];

		project(r, o, p);
		sink_puts(s, "<circle cx=\"");
		sink_num(s, p[0]);
		sink_puts(s, "\" cy=\"");
		sink_num(s, -p[1]);
		sink_puts(s, "\" r=\"");
		sink_num(s, o->radius);
		sink_puts(s, "\" fill=\"hsl(");
		sink_uint(s, (unsigned long long)OBJECT_HUE(o->object));
		sink_puts(s, ",70%,45%)\"/>\n");
	}
	sink_puts(s, "</svg>\n");
}
