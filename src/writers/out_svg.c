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
#include <string.h>

#include "result/flatten.h"
#include "base/mem.h"
#include "analysis/parastichy.h"
#include "analysis/unordered.h"
#include "writers/unordered_out.h"
#include "writers/writer.h"

#define BINS	64	/* along the structure, for the arc length */

/* Organ positions on the page, before the y flip. */
static double (*project(const struct result *r, int *unrolled))[2]
{
	double (*p)[2] = xcalloc(r->count ? r->count : 1, sizeof(*p));
	double zlo = HUGE_VAL, zhi = -HUGE_VAL, rhomax = 0;
	double S[BINS + 1], br[BINS], bz[BINS];
	size_t N = r->count;
	int nb;

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
	/*
	 * The generating curve through the bins' mean (rho, z), by index;
	 * no more bins than organs, or some would be empty, at (0, 0).
	 */
	nb = N < BINS ? (int)N : BINS;
	for (int b = 0; b < nb; b++) {
		size_t from = N * (size_t)b / (size_t)nb;
		size_t to = N * (size_t)(b + 1) / (size_t)nb;
		double sr = 0, sz = 0;

		for (size_t i = from; i < to; i++) {
			sr += hypot(r->organs[i].pos[0], r->organs[i].pos[1]);
			sz += r->organs[i].pos[2];
		}
		br[b] = to > from ? sr / (double)(to - from) : 0;
		bz[b] = to > from ? sz / (double)(to - from) : 0;
	}
	S[0] = 0;
	for (int b = 1; b < nb; b++)
		S[b] = S[b - 1] + hypot(br[b] - br[b - 1], bz[b] - bz[b - 1]);
	for (size_t i = 0; i < N; i++) {
		const double *q = r->organs[i].pos;
		double rho = hypot(q[0], q[1]), best = HUGE_VAL;

		p[i][0] = atan2(q[1], q[0]) * rho;
		/*
		 * Up: the arc length where the organ's own (rho, z) meets the
		 * curve, not where its index falls (the collision model does
		 * not place in order of height), so that a spiral through it
		 * bends where the organs do, and nowhere else.
		 */
		for (int b = 0; b + 1 < nb; b++) {
			double dr = br[b + 1] - br[b], dz = bz[b + 1] - bz[b];
			double len2 = dr * dr + dz * dz, u = len2 > 0 ?
			    ((rho - br[b]) * dr + (q[2] - bz[b]) * dz) / len2 : 0;
			double d;

			u = fmin(fmax(u, 0), 1);
			d = hypot(rho - br[b] - u * dr, q[2] - bz[b] - u * dz);
			if (d < best) {
				best = d;
				p[i][1] = S[b] + (S[b + 1] - S[b]) * u;
			}
		}
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

/* Organ o as a disc at (x, y) on the page, before the y flip. */
static void
circle(struct sink *s, double x, double y, const struct organ *o)
{
	sink_puts(s, "<circle cx=\"");
	sink_num(s, x);
	sink_puts(s, "\" cy=\"");
	sink_num(s, -y);
	sink_puts(s, "\" r=\"");
	sink_num(s, o->radius);
	sink_puts(s, "\" fill=\"hsl(");
	sink_uint(s, (unsigned long long)OBJECT_HUE(o->object));
	sink_puts(s, ",70%,45%)\"/>\n");
}

struct sampled {
	struct sink	 s;
	double		 weights, bytes;
};

static void
sample_circle(void *ctx, const struct organ *o, double weight)
{
	struct sampled *S = ctx;
	struct sink *s = &S->s;
	double before = sink_bytes(s);

	circle(s, o->pos[0], o->pos[1], o);
	/*
	 * An organ ends a step of each of its two families at most: a
	 * Bezier each, three points of two numbers, and a chain's start
	 * (a point more) each, a family's single steps being chains.
	 */
	for (int k = 0; k < 2 * 4; k++) {
		sink_putc(s, k % 4 == 0 ? 'C' : ' ');
		sink_num(s, o->pos[0]);
		sink_putc(s, ',');
		sink_num(s, o->pos[1]);
	}
	S->weights += weight;
	S->bytes += weight * (sink_bytes(s) - before);
}

/*
 * A sample's circles and path steps, scaled to every organ, and room
 * for the head, the 64 zones' paths and labels, and the legend.
 */
double
svg_bytes(const struct result *r, unsigned opts)
{
	struct sampled S = { .weights = 0 };
	double bytes = 2048 + 64 * 2 * 400;

	(void)opts;
	sink_init_count(&S.s);
	result_sample(r, 64, sample_circle, &S);
	if (S.weights > 0)
		bytes += S.bytes / S.weights * (double)r->count;
	sink_free(&S.s);
	return bytes;
}

static void
text(struct sink *s, double x, double y, double size, const char *colour,
    const char *words)
{
	/*
	 * At a font size of 100, scaled down: renderers hint a glyph at the
	 * page's size, and the view box's units may be far below a pixel.
	 * A white halo keeps a label legible over the organs.
	 */
	sink_puts(s, "<text transform=\"translate(");
	sink_num(s, x);
	sink_putc(s, ' ');
	sink_num(s, y);
	sink_puts(s, ") scale(");
	sink_num(s, size / 100);
	sink_puts(s, ")\" font-size=\"100\" font-family=\"sans-serif\" "
	    "stroke=\"#fff\" stroke-width=\"16\" paint-order=\"stroke\" "
	    "fill=\"");
	sink_puts(s, colour);
	sink_puts(s, "\">");
	/* Only identifiers, numbers and our own words: nothing to escape. */
	sink_puts(s, words);
	sink_puts(s, "</text>\n");
}

/* About how wide a line of sans-serif text is, at size. */
static double
text_width(const char *words, double size)
{
	return 0.56 * size * (double)strlen(words);
}

#define LABELS_MAX	(64 * 2)

/* A family's count, where it may go. */
struct label {
	double	 x, y;		/* its middle, on the page (y up) */
	double	 w, h;
	int	 f, k;		/* which family of the pair, its count */
};

/* The picture: organs on the page, their pairs, the labels placed. */
struct page {
	const struct result *r;
	double		(*p)[2];	/* centres on the page, y up */
	int		(*pair)[2];	/* each organ's contact pair */
	int		 unrolled;
	double		 cx, cy;	/* the middle, from above */
	double		 em, width;	/* label size, line width */
	size_t		 first;		/* the first organ measured */
	struct label	 label[LABELS_MAX];
	size_t		 nlabels;
};

/* Whether the step from organ a to organ b does not leap (the unrolled
 * picture's seam, a jump across the head). */
static int
near(const struct page *P, size_t a, size_t b)
{
	const double *pa = P->p[a], *pb = P->p[b];

	return hypot(pb[0] - pa[0], pb[1] - pa[1]) <=
	    4 * (P->r->organs[a].radius + P->r->organs[b].radius);
}

/*
 * Whether the step from organ j - f to organ j belongs to a family f:
 * j - f is one of j's own contact neighbours, and the step does not
 * leap.  Chains of such steps stop where the pattern changes, instead
 * of zig-zagging across a transition.
 */
static int
step(const struct page *P, size_t j, int f)
{
	return (P->pair[j][0] == f || P->pair[j][1] == f) &&
	    near(P, j - (size_t)f, j);
}

/* The turn about the axis from organ a to organ b, in (-180, 180]. */
static double
turn(const struct page *P, size_t a, size_t b)
{
	double d = fmod(P->r->organs[b].phi - P->r->organs[a].phi, 360);

	return d > 180 ? d - 360 : d <= -180 ? d + 360 : d;
}

/*
 * A chain as a smooth curve: the Catmull-Rom spline through its centres,
 * which passes through each, written as cubic Beziers.
 */
static void
curve(struct sink *s, const struct page *P, const size_t *ix, size_t n)
{
	sink_putc(s, 'M');
	sink_num(s, P->p[ix[0]][0]);
	sink_putc(s, ',');
	sink_num(s, -P->p[ix[0]][1]);
	for (size_t i = 0; i + 1 < n; i++) {
		const double *a = P->p[ix[i > 0 ? i - 1 : 0]], *b = P->p[ix[i]];
		const double *c = P->p[ix[i + 1]];
		const double *d = P->p[ix[i + 2 < n ? i + 2 : n - 1]];

		sink_putc(s, 'C');
		sink_num(s, b[0] + (c[0] - a[0]) / 6);
		sink_putc(s, ',');
		sink_num(s, -(b[1] + (c[1] - a[1]) / 6));
		sink_putc(s, ' ');
		sink_num(s, c[0] - (d[0] - b[0]) / 6);
		sink_putc(s, ',');
		sink_num(s, -(c[1] - (d[1] - b[1]) / 6));
		sink_putc(s, ' ');
		sink_num(s, c[0]);
		sink_putc(s, ',');
		sink_num(s, -c[1]);
	}
}

/* How near the rim or base a chain's end at organ i lies: larger, nearer. */
static double
outwardness(const struct page *P, size_t i)
{
	const double *q = P->p[i];

	if (!P->unrolled)
		return hypot(q[0] - P->cx, q[1] - P->cy);
	return P->r->rim_last ? q[1] : -q[1];
}

static int
overlaps(const struct page *P, double x, double y, double w, double h)
{
	for (size_t i = 0; i < P->nlabels; i++) {
		const struct label *l = &P->label[i];

		/* With a third of a line's room between them. */
		if (fabs(l->x - x) < (l->w + w) / 2 + P->em / 3 &&
		    fabs(l->y - y) < (l->h + h) / 2 + P->em / 3)
			return 1;
	}
	return 0;
}

/*
 * Place family f's count k just beyond the first of the chain ends
 * ends[0 .. n-1] (best first) whose place no label has yet; none if
 * every place is taken.
 */
static void
place_label(struct page *P, const size_t *ends, size_t n, int f, int k)
{
	char words[16];
	double w, h = P->em;

	if (P->nlabels == LABELS_MAX || n == 0)
		return;
	snprintf(words, sizeof(words), "%d", k);
	w = text_width(words, P->em);
	for (size_t i = 0; i < n; i++) {
		const double *q = P->p[ends[i]];
		double r = P->r->organs[ends[i]].radius + 0.7 * h;
		double dx = 0, dy = P->r->rim_last ? 1 : -1, d;
		double x, y;

		if (!P->unrolled && (d = hypot(q[0] - P->cx, q[1] - P->cy)) >
		    0) {
			dx = (q[0] - P->cx) / d;
			dy = (q[1] - P->cy) / d;
		}
		x = q[0] + dx * r;
		y = q[1] + dy * r;
		if (!overlaps(P, x, y, w, h)) {
			P->label[P->nlabels++] = (struct label){ x, y, w, h, f,
			    k };
			return;
		}
	}
	/* No room by any of its ends: the families' key names it. */
}

/*
 * A family's colour, by its place among the families drawn (smallest
 * number first): the same family has the same colour in every zone, so
 * a spiral keeps its colour through a transition.  Dark, to stand out
 * from the organs' light discs.
 */
static const char *const family_colours[] = { "#b01c2e", "#1f4fb5",
    "#1d7a34", "#7b2fa8", "#222222", "#0e7c86", "#a0196b", "#5c4a00",
    "#d4004c", "#3a3aff", "#2e8b00", "#6a0dad" };
#define NCOLOURS	(sizeof(family_colours) / sizeof(family_colours[0]))

/*
 * The chain of family f from organ i (no step leads to it) into chain;
 * its length.  It runs while its steps are contacts and turn the way
 * its first did: where a family's turn changes sign (a divergence
 * passing f steps to a whole number of turns) it is spokes there, not
 * a spiral.  A family of the innermost pair also runs back from where
 * the measurement starts towards the centre, through organs too few
 * to have their contacts yet: its spirals start there, and cut off at
 * the first zone they would meet as a ring of short arcs.
 */
static size_t
chain_from(const struct page *P, size_t i, int f, int inner, size_t *chain)
{
	size_t count = P->r->count, s = i, n = 0, F = (size_t)f;

	while (inner && i < P->first + F && s >= F && near(P, s - F, s) &&
	    (s + F > i || turn(P, s - F, s) * turn(P, s, s + F) > 0))
		s -= F;
	chain[n++] = s;
	while (chain[n - 1] + F < count &&
	    (chain[n - 1] + F <= i || step(P, chain[n - 1] + F, f)) &&
	    (n < 2 || turn(P, chain[n - 2], chain[n - 1]) *
	    turn(P, chain[n - 1], chain[n - 1] + F) > 0))
		chain[n] = chain[n - 1] + F, n++;
	return n;
}

/*
 * Family f: every chain of contact steps j - f -> j over the whole
 * structure, wherever f is a contact, as a curve, in one path; its count
 * placed at a chain's end nearest the rim or base.  ci: its colour;
 * inner: a family of the innermost pair.  Chains of two steps at least,
 * one alone being no spiral to follow -- but where a zone is too short
 * to hold two (the rim's newest family, often), its single steps: the
 * legend names no family the picture does not draw.  Whether any was.
 */
static int
family(struct sink *s, struct page *P, size_t ci, int f, int inner)
{
	size_t count = P->r->count, F = (size_t)f;
	size_t *chain = xcalloc(count + 1, sizeof(*chain));
	size_t *ends = xcalloc(count + 1, sizeof(*ends)), nends = 0;
	size_t least = 3;
	int open = 0;

again:
	/*
	 * From the first organ the analysis measures, or a step before it
	 * where the step is a contact of the organ measured: before them,
	 * too few organs have their contacts yet (a head's centre), and
	 * chains there would loop about nothing.
	 */
	for (size_t i = P->first > F ? P->first - F : 0; i < count; i++) {
		size_t n;

		/* A chain starts where no step leads to it. */
		if (i >= P->first + F && step(P, i, f) &&
		    (i < P->first + 2 * F || !step(P, i - F, f) ||
		    turn(P, i - 2 * F, i - F) * turn(P, i - F, i) > 0))
			continue;
		if ((n = chain_from(P, i, f, inner, chain)) < least)
			continue;
		if (!open) {
			sink_puts(s, "<path fill=\"none\" stroke=\"");
			sink_puts(s, family_colours[ci % NCOLOURS]);
			sink_putc(s, '"');
			attr(s, "stroke-width", P->width);
			sink_puts(s, " stroke-linecap=\"round\" d=\"");
			open = 1;
		}
		curve(s, P, chain, n);
		ends[nends++] = P->r->rim_last ? chain[n - 1] : chain[0];
	}
	if (!open && least == 3) {
		least = 2;
		goto again;
	}
	if (open)
		sink_puts(s, "\"/>\n");
	/*
	 * The ends nearest the rim or base first; ends level to a
	 * millionth of a label's size are a tie, kept in organ order: a
	 * row at the base is level but for residues of rounding, which
	 * differ from one maths library to another (glibc's, mingw-w64's,
	 * WebAssembly's musl) and would move the label between them.
	 */
	for (size_t i = 1; i < nends; i++)
		for (size_t j = i; j > 0 && outwardness(P, ends[j]) >
		    outwardness(P, ends[j - 1]) + 1e-6 * P->em; j--) {
			size_t t = ends[j];

			ends[j] = ends[j - 1];
			ends[j - 1] = t;
		}
	place_label(P, ends, nends, (int)ci, f);
	free(chain);
	free(ends);
	return open;
}

/* The families the zones name, each once, smallest first; how many. */
static size_t
families(const struct para_zone *z, size_t nz, int *f, size_t max)
{
	size_t n = 0;

	for (size_t k = 0; k < nz; k++)
		for (int e = 0; e < 2; e++) {
			int v = e ? z[k].n : z[k].m;
			size_t i = 0;

			while (i < n && f[i] != v)
				i++;
			if (i == n && n < max && v > 0)
				f[n++] = v;
		}
	for (size_t i = 1; i < n; i++)
		for (size_t j = i; j > 0 && f[j] < f[j - 1]; j--) {
			int t = f[j];

			f[j] = f[j - 1];
			f[j - 1] = t;
		}
	return n;
}

/*
 * The organ objects' colours, a disc and a name each, wrapped to the
 * width w from (x, y) down; how many lines it took (s NULL: only that).
 */
static int
key(struct sink *s, const struct result *r, double x, double y, double w,
    double em)
{
	double at = x;
	int lines = 1;

	for (size_t k = 0; k < r->nobjects; k++) {
		double need = 1.2 * em + text_width(r->objects[k], 0.8 * em) +
		    em;

		if (at > x && at + need > x + w) {
			at = x;
			y += 1.2 * em;
			lines++;
		}
		if (s == NULL) {
			at += need;
			continue;
		}
		sink_puts(s, "<circle");
		attr(s, "cx", at + 0.4 * em);
		attr(s, "cy", y - 0.3 * em);
		attr(s, "r", 0.35 * em);
		sink_puts(s, " fill=\"hsl(");
		sink_uint(s, (unsigned long long)OBJECT_HUE(k));
		sink_puts(s, ",70%,45%)\"/>\n");
		text(s, at + 1.1 * em, y, 0.8 * em, "#222", r->objects[k]);
		at += need;
	}
	return lines;
}

void
svg_write(struct sink *s, const struct result *r, unsigned opts)
{
	double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
	double pad, w, h, em, rmed = 0;
	struct para_zone z[64];
	size_t nz = r->unordered != NULL ? unordered_para_zones(r->unordered, z,
	    64) : r->count >= 3 ? para_zones(r, NULL, z, 64) : 0;
	struct page *P = xcalloc(1, sizeof(*P));
	char line[160];
	int keylines, f[128];
	size_t nf = 0;

	(void)opts;
	P->r = r;
	P->p = r->unordered != NULL ? unordered_svg_page(r, &P->unrolled) :
	    project(r, &P->unrolled);
	P->pair = xcalloc(r->count ? r->count : 1, sizeof(*P->pair));
	if (nz > 0 && r->unordered == NULL)
		para_pairs(r, P->pair);
	for (size_t i = 0; i < r->count; i++) {
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], P->p[i][k] - r->organs[i].radius);
			hi[k] = fmax(hi[k], P->p[i][k] + r->organs[i].radius);
		}
		rmed += r->organs[i].radius;
	}
	if (r->count == 0)
		lo[0] = lo[1] = -1, hi[0] = hi[1] = 1;
	rmed = r->count ? rmed / (double)r->count : 0.01;
	w = hi[0] - lo[0];
	h = hi[1] - lo[1];
	P->cx = (lo[0] + hi[0]) / 2;
	P->cy = (lo[1] + hi[1]) / 2;
	pad = 0.02 * fmax(fmax(w, h), 1e-9);
	em = P->em = 0.028 * fmax(w, h);
	P->width = fmax(0.18 * rmed, 0.002 * fmax(w, h));
	/* Labels beyond the rim or base: room for them. */
	lo[0] -= 1.5 * em;
	lo[1] -= 1.5 * em;
	hi[0] += 1.5 * em;
	w = hi[0] - lo[0];
	/* Room above for the legend: five lines and the key's. */
	keylines = key(NULL, r, lo[0], 0, w, em);
	hi[1] += (6.5 + 1.2 * keylines) * em;
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
	for (size_t i = 0; i < r->count; i++)
		circle(s, P->p[i][0], P->p[i][1], &r->organs[i]);
	/* Every family the zones show, counted near the rim or base. */
	P->first = nz > 0 ? (size_t)z[0].from : 0;
	nf = families(z, nz, f, 128);
	if (r->unordered != NULL)
		nf = unordered_svg_families(s, r, P->p, f, nf, family_colours,
		    NCOLOURS, P->width);
	else
		for (size_t i = 0, k = 0; i < nf; i++) {
			/* The centre's family, where its organs come first. */
			int inner = r->rim_last && (f[i] == z[0].m ||
			    f[i] == z[0].n);

			/* The key lists what is drawn, in its colour. */
			if (family(s, P, k, f[i], inner))
				f[k++] = f[i];
			if (i + 1 == nf)
				nf = k;
		}
	for (size_t i = 0; i < P->nlabels; i++) {
		const struct label *l = &P->label[i];

		snprintf(line, sizeof(line), "%d", l->k);
		text(s, l->x - l->w / 2, -(l->y - 0.35 * l->h), l->h,
		    family_colours[(size_t)l->f % NCOLOURS], line);
	}
	/* The legend, top left, and the objects' key below it. */
	snprintf(line, sizeof(line), "%s: %s model, %zu organs%s", r->name,
	    r->model, r->count, P->unrolled ? ", unrolled" : ", from above");
	text(s, lo[0], -hi[1] + 1.2 * em, em, "#222", line);
	if (r->unordered != NULL)
		unordered_svg_divergence(line, sizeof(line), r);
	else
		snprintf(line, sizeof(line), "divergence %.4f degrees",
		    r->divergence);
	text(s, lo[0], -hi[1] + 2.4 * em, em, "#222", line);
	if (nz > 0) {
		const struct para_zone *b = r->rim_last ? &z[nz - 1] : &z[0];

		double at = lo[0];

		/* Seen from above the first or last organs are the rim. */
		const char *edge = P->unrolled ? "base" : "rim";
		char seen[80];

		if (b->m == 0 && b->nseen == 0)
			/* Measured without an order: no lattice read there. */
			snprintf(line, sizeof(line), "no pair clear at the %s",
			    edge);
		else if (b->m == 0) {
			para_seen_text(b, seen, sizeof(seen));
			snprintf(line, sizeof(line), "no one pair at the %s: "
			    "a %s", edge, seen);
		} else
			snprintf(line, sizeof(line), "parastichies %d and %d "
			    "at the %s", b->m, b->n, edge);
		text(s, lo[0], -hi[1] + 3.6 * em, em, "#222", line);
		/* The families' key: each number in its colour. */
		text(s, at, -hi[1] + 4.8 * em, 0.8 * em, "#222", "families:");
		at += text_width("families: ", 0.8 * em);
		for (size_t i = 0; i < nf; i++) {
			snprintf(line, sizeof(line), "%d", f[i]);
			text(s, at, -hi[1] + 4.8 * em, 0.8 * em,
			    family_colours[i % NCOLOURS], line);
			at += text_width(line, 0.8 * em) + 0.6 * em;
		}
	}
	(void)key(s, r, lo[0], -hi[1] + 6.0 * em, w, em);
	sink_puts(s, "</svg>\n");
	free(P->pair);
	free(P->p);
	free(P);
}
