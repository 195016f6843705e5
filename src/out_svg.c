/*
 * out_svg.c - an SVG picture for a quick look without a renderer: each
 * organ a disc of its packing radius, coloured by organ object, the two
 * families of contact parastichies measured along the structure drawn
 * through their centres and counted, and a legend.
 *
 * Heads and low domes are seen from above (+Y up the page).  Tall
 * surfaces of revolution are unrolled: across, the angle times the
 * organ's own distance from the axis; up, the arc length along the
 * generating curve (estimated through the organs themselves, bin by
 * bin), so that spacing reads true where a view from above would crowd
 * the sides.
 */
#include <math.h>
#include <stdlib.h>

#include "mem.h"
#include "parastichy.h"
#include "writer.h"

#define BINS	64	/* along the structure, for the arc length */

/* Organ positions on the page, before the y flip. */
static double (*project(const struct result *r, int *unrolled))[2]
{
	double (*p)[2] = xcalloc(r->count ? r->count : 1, sizeof(*p));
	double zlo = HUGE_VAL, zhi = -HUGE_VAL, rhomax = 0;
	double S[BINS + 1], br[BINS], bz[BINS];
	size_t N = r->count;

	for (size_t i = 0; i < N; i++) {
		const double *q = r->organs[i].pos;

		zlo = fmin(zlo, q[2]);
		zhi = fmax(zhi, q[2]);
		rhomax = fmax(rhomax, hypot(q[0], q[1]));
	}
	*unrolled = r->svg == PROJ_UNROLL || (N >= BINS && zhi - zlo >
	    0.6 * rhomax);
	if (!*unrolled) {
		for (size_t i = 0; i < N; i++) {
			p[i][0] = r->organs[i].pos[0];
			p[i][1] = r->organs[i].pos[1];
		}
		return p;
	}
	/* The generating curve through the bins' mean (rho, z), by index. */
	for (int b = 0; b < BINS; b++) {
		size_t from = N * (size_t)b / BINS, to = N * (size_t)(b + 1) / BINS;
		double sr = 0, sz = 0;

		for (size_t i = from; i < to; i++) {
			sr += hypot(r->organs[i].pos[0], r->organs[i].pos[1]);
			sz += r->organs[i].pos[2];
		}
		br[b] = to > from ? sr / (double)(to - from) : 0;
		bz[b] = to > from ? sz / (double)(to - from) : 0;
	}
	S[0] = 0;
	for (int b = 1; b < BINS; b++)
		S[b] = S[b - 1] + hypot(br[b] - br[b - 1], bz[b] - bz[b - 1]);
	for (size_t i = 0; i < N; i++) {
		const double *q = r->organs[i].pos;
		/* Organ i's place among the bins' centres. */
		double f = ((double)i + 0.5) * BINS / (double)N - 0.5;
		int b = f < 0 ? 0 : f >= BINS - 1 ? BINS - 2 : (int)f;
		double u = fmin(fmax(f - b, 0), 1);

		p[i][0] = atan2(q[1], q[0]) * hypot(q[0], q[1]);
		p[i][1] = S[b] + (S[b + 1] - S[b]) * u;
	}
	return p;
}

static void
attr(struct sink *s, const char *name, double v)
{
	sink_putc(s, ' ');
	sink_puts(s, name);
	sink_puts(s, "=\"");
	sink_num(s, v);
	sink_putc(s, '"');
}

/*
 * One family of parastichies in a zone: chains i, i + f, i + 2f, ...
 * from each of the zone's first f organs, broken where a step leaps
 * (the unrolled view's seam, or the zone's edge).
 */
static void
family(struct sink *s, const struct result *r, const double (*p)[2],
    size_t from, size_t to, int f, const char *colour, double width)
{
	sink_puts(s, "<path fill=\"none\" stroke=\"");
	sink_puts(s, colour);
	sink_puts(s, "\"");
	attr(s, "stroke-width", width);
	sink_puts(s, " d=\"");
	for (size_t i0 = from; i0 < from + (size_t)f && i0 < to; i0++) {
		int pen = 0;

		for (size_t i = i0; i + (size_t)f < to; i += (size_t)f) {
			size_t j = i + (size_t)f;
			double d = hypot(p[j][0] - p[i][0], p[j][1] - p[i][1]);
			double reach = 4 * (r->organs[i].radius +
			    r->organs[j].radius);

			if (!(d <= reach)) {
				pen = 0;
				continue;
			}
			if (!pen) {
				sink_putc(s, 'M');
				sink_num(s, p[i][0]);
				sink_putc(s, ',');
				sink_num(s, -p[i][1]);
				pen = 1;
			}
			sink_putc(s, 'L');
			sink_num(s, p[j][0]);
			sink_putc(s, ',');
			sink_num(s, -p[j][1]);
		}
	}
	sink_puts(s, "\"/>\n");
}

static void
text(struct sink *s, double x, double y, double size, const char *colour,
    const char *words)
{
	/*
	 * At a font size of 100, scaled down: renderers hint a glyph at the
	 * page's size, and the view box's units may be far below a pixel.
	 */
	sink_puts(s, "<text transform=\"translate(");
	sink_num(s, x);
	sink_putc(s, ' ');
	sink_num(s, y);
	sink_puts(s, ") scale(");
	sink_num(s, size / 100);
	sink_puts(s, ")\" font-size=\"100\" font-family=\"sans-serif\" fill=\"");
	sink_puts(s, colour);
	sink_puts(s, "\">");
	/* Only identifiers, numbers and our own words: nothing to escape. */
	sink_puts(s, words);
	sink_puts(s, "</text>\n");
}

void
svg_write(struct sink *s, const struct result *r, unsigned opts)
{
	static const char *const fam[2] = { "#c03030", "#2060c0" };
	double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
	double pad, w, h, em, rmed = 0;
	struct para_zone z[64];
	size_t nz = r->count >= 3 ? para_zones(r, NULL, z, 64) : 0;
	int unrolled;
	double (*p)[2] = project(r, &unrolled);
	char line[160];

	(void)opts;
	for (size_t i = 0; i < r->count; i++) {
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], p[i][k] - r->organs[i].radius);
			hi[k] = fmax(hi[k], p[i][k] + r->organs[i].radius);
		}
		rmed += r->organs[i].radius;
	}
	if (r->count == 0)
		lo[0] = lo[1] = -1, hi[0] = hi[1] = 1;
	rmed = r->count ? rmed / (double)r->count : 0.01;
	w = hi[0] - lo[0];
	h = hi[1] - lo[1];
	pad = 0.02 * fmax(fmax(w, h), 1e-9);
	em = 0.028 * fmax(w, h);
	/* Room above for the legend: five lines. */
	hi[1] += 6.5 * em;
	h = hi[1] - lo[1];
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
	sink_puts(s, "</title>\n<rect");
	attr(s, "x", lo[0] - pad);
	attr(s, "y", -hi[1] - pad);
	sink_puts(s, " width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n");
	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];

		sink_puts(s, "<circle cx=\"");
		sink_num(s, p[i][0]);
		sink_puts(s, "\" cy=\"");
		sink_num(s, -p[i][1]);
		sink_puts(s, "\" r=\"");
		sink_num(s, o->radius);
		sink_puts(s, "\" fill=\"hsl(");
		sink_uint(s, (unsigned long long)OBJECT_HUE(o->object));
		sink_puts(s, ",70%,45%)\"/>\n");
	}
	/* Each zone's two families, counted at the zone's first organs. */
	for (size_t k = 0; k < nz; k++) {
		size_t from = (size_t)z[k].from;
		size_t to = k + 1 < nz ? (size_t)z[k + 1].from : r->count;
		int mn[2] = { z[k].m, z[k].n };

		for (int f = 0; f < 2; f++) {
			size_t at = from + (size_t)mn[f] < to ? from +
			    (size_t)mn[f] : from;

			family(s, r, (const double (*)[2])p, from, to, mn[f],
			    fam[f], 0.18 * rmed);
			snprintf(line, sizeof(line), "%d", mn[f]);
			text(s, p[at][0] + 1.2 * r->organs[at].radius,
			    -p[at][1] + (f ? 1.5 : -0.5) * em * 0.5,
			    0.8 * em, fam[f], line);
		}
	}
	/* The legend, top left. */
	snprintf(line, sizeof(line), "%s: %s model, %zu organs%s", r->name,
	    r->model, r->count, unrolled ? ", unrolled" : ", from above");
	text(s, lo[0], -hi[1] + 1.2 * em, em, "#222", line);
	snprintf(line, sizeof(line), "divergence %.4f degrees", r->divergence);
	text(s, lo[0], -hi[1] + 2.4 * em, em, "#222", line);
	if (nz > 0) {
		const struct para_zone *b = r->rim_last ? &z[nz - 1] : &z[0];

		snprintf(line, sizeof(line), "parastichies %d and %d at the "
		    "%s", b->m, b->n, r->rim_last ? "rim" : "base");
		text(s, lo[0], -hi[1] + 3.6 * em, em, "#222", line);
		text(s, lo[0], -hi[1] + 4.8 * em, 0.8 * em, fam[0],
		    "the smaller family (m)");
		text(s, lo[0] + 0.4 * (w > 0 ? w : 1), -hi[1] + 4.8 * em,
		    0.8 * em, fam[1], "the larger family (n)");
	}
	sink_puts(s, "</svg>\n");
	free(p);
}
