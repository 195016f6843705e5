/*
 * out_svg_unordered.c - the SVG preview of organs measured without an
 * order: the families of contact parastichies drawn through the
 * contacts the measurement read (each organ's nearest earlier neighbour
 * a family's number of organs away), not by stepping through an order,
 * and a mark on the centre the measurement used.  out_svg.c draws the
 * rest as for any model.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "analysis/unordered.h"
#include "base/mem.h"
#include "writers/unordered_out.h"

double
(*unordered_svg_page(const struct result *r, int *unrolled))[2]
{
	const struct unordered *U = r->unordered;
	double (*p)[2] = xcalloc(r->count ? r->count : 1, sizeof(*p));

	*unrolled = r->svg == PROJ_UNROLL;
	for (size_t i = 0; i < r->count; i++) {
		const double *q = r->organs[i].pos;

		if (!*unrolled) {
			p[i][0] = q[0];
			p[i][1] = q[1];
			continue;
		}
		p[i][0] = atan2(q[1], q[0]) * hypot(q[0], q[1]);
		p[i][1] = -U->unit * U->c[i].s;
	}
	return p;
}

static void
point(struct sink *s, char c, const double *a)
{
	sink_putc(s, c);
	sink_num(s, a[0]);
	sink_putc(s, ',');
	sink_num(s, -a[1]);
}

/* A chain as the Catmull-Rom spline through its centres, as Beziers. */
static void
curve(struct sink *s, double (*page)[2], const size_t *ix, size_t n)
{
	point(s, 'M', page[ix[0]]);
	for (size_t i = 0; i + 1 < n; i++) {
		const double *a = page[ix[i > 0 ? i - 1 : 0]], *b = page[ix[i]];
		const double *c = page[ix[i + 1]];
		const double *d = page[ix[i + 2 < n ? i + 2 : n - 1]];
		double c1[2] = { b[0] + (c[0] - a[0]) / 6,
		    b[1] + (c[1] - a[1]) / 6 };
		double c2[2] = { c[0] - (d[0] - b[0]) / 6,
		    c[1] - (d[1] - b[1]) / 6 };

		point(s, 'C', c1);
		point(s, ' ', c2);
		point(s, ' ', c);
	}
}

/* Whether the step from organ a to b leaps (the unrolled seam). */
static int
leaps(const struct result *r, double (*page)[2], size_t a, size_t b)
{
	return hypot(page[b][0] - page[a][0], page[b][1] - page[a][1]) > 4 *
	    (r->organs[a].radius + r->organs[b].radius);
}

/*
 * Family f: next[j] is the organ whose earlier contact f organs away j
 * is (the nearest, if more than one); chains run along next, in one
 * path, from an organ with no such contact of its own, or from one the
 * step into leaps the unrolled seam (the spiral goes on across the
 * page, and would else be drawn no further).
 */
static int
family(struct sink *s, const struct result *r, double (*page)[2], int f,
    const char *colour, double width, long *next, char *has)
{
	const struct unordered *U = r->unordered;
	size_t *chain = xcalloc(r->count + 1, sizeof(*chain));
	long *from = xcalloc(r->count + 1, sizeof(*from));
	int open = 0;

	for (size_t i = 0; i < r->count; i++) {
		next[i] = -1;
		has[i] = 0;
	}
	for (size_t i = 0; i < r->count; i++)
		for (int k = 0; k < 2; k++) {
			long j = U->c[i].prev[k];

			if (j < 0 || U->c[i].dk[k] != f)
				continue;
			has[i] = 1;
			if (next[j] < 0 || hypot(page[i][0] - page[j][0],
			    page[i][1] - page[j][1]) < hypot(page[next[j]][0] -
			    page[j][0], page[next[j]][1] - page[j][1]))
				next[j] = (long)i;
		}
	for (size_t i = 0; i < r->count; i++)
		from[i] = -1;
	for (size_t j = 0; j < r->count; j++)
		if (next[j] >= 0)
			from[next[j]] = (long)j;
	for (size_t i = 0; i < r->count; i++) {
		size_t n = 0;

		if (next[i] < 0 || (has[i] && (from[i] < 0 ||
		    !leaps(r, page, (size_t)from[i], i))))
			continue;
		chain[n++] = i;
		while (n <= r->count && next[chain[n - 1]] >= 0 &&
		    !leaps(r, page, chain[n - 1], (size_t)next[chain[n - 1]]))
			chain[n] = (size_t)next[chain[n - 1]], n++;
		/* Two steps at least: one alone is no spiral to follow. */
		if (n < 3)
			continue;
		if (!open) {
			sink_puts(s, "<path fill=\"none\" stroke=\"");
			sink_puts(s, colour);
			sink_puts(s, "\" stroke-width=\"");
			sink_num(s, width);
			sink_puts(s, "\" stroke-linecap=\"round\" d=\"");
			open = 1;
		}
		curve(s, page, chain, n);
	}
	if (open)
		sink_puts(s, "\"/>\n");
	free(from);
	free(chain);
	return open;
}

size_t
unordered_svg_families(struct sink *s, const struct result *r,
    double (*page)[2], int *f, size_t nf, const char *const *colours,
    size_t ncolours, double width)
{
	long *next = xcalloc(r->count + 1, sizeof(*next));
	char *has = xcalloc(r->count + 1, sizeof(*has));
	size_t k = 0;

	/* The key lists what is drawn, in its colour. */
	for (size_t i = 0; i < nf; i++)
		if (family(s, r, page, f[i], colours[k % ncolours], width,
		    next, has))
			f[k++] = f[i];
	free(next);
	free(has);
	if (r->svg == PROJ_UNROLL || r->count == 0)
		return k;
	/*
	 * The centre used: the axis, at the origin of a head; a cross in a
	 * diamond (no circle nor path: those are the organs and families).
	 */
	sink_puts(s, "<g stroke=\"#000\" fill=\"none\" stroke-width=\"");
	sink_num(s, width);
	sink_puts(s, "\"><title>centre</title><polygon points=\"");
	for (int k = 0; k < 4; k++) {
		sink_puts(s, k ? " " : "");
		sink_num(s, k == 0 ? 4 * width : k == 2 ? -4 * width : 0);
		sink_putc(s, ',');
		sink_num(s, k == 1 ? 4 * width : k == 3 ? -4 * width : 0);
	}
	sink_puts(s, "\"/>");
	for (int k = 0; k < 2; k++) {
		sink_puts(s, k ? "<line x1=\"0\" y1=\"" : "<line y1=\"0\" x1=\"");
		sink_num(s, -8 * width);
		sink_puts(s, k ? "\" x2=\"0\" y2=\"" : "\" y2=\"0\" x2=\"");
		sink_num(s, 8 * width);
		sink_puts(s, "\"/>");
	}
	sink_puts(s, "</g>\n");
	return k;
}

void
unordered_svg_divergence(char *buf, size_t sz, const struct result *r)
{
	const struct unordered *U = r->unordered;

	if (isnan(U->divergence))
		snprintf(buf, sz, "divergence not measured: no lattice read");
	else
		snprintf(buf, sz, "divergence %.4f \xc2\xb1 %.4f degrees, "
		    "measured", r->divergence, fmax(U->divergence_err, 5e-5));
}
