/* out_info.c - "key: value" lines about the result, for people and scripts. */
#include <math.h>
#include <string.h>

#include "result/flatten.h"
#include "analysis/parastichy.h"
#include "meshes/meshes.h"
#include "writers/plan.h"
#include "writers/unordered_out.h"
#include "writers/writer.h"

/* "key: label v; label v", a label a value (labels: words). */
static void
labelled(struct sink *s, const char *key, const char *labels, int n,
    const double *v)
{
	sink_puts(s, key);
	sink_putc(s, ':');
	for (int i = 0; i < n && *labels != '\0'; i++) {
		size_t len = strcspn(labels, " ");

		sink_puts(s, i ? "; " : " ");
		sink_write(s, labels, len);
		sink_putc(s, ' ');
		sink_num(s, v[i]);
		labels += len + (labels[len] == ' ');
	}
	sink_putc(s, '\n');
}

static void
line(struct sink *s, const char *key, int n, const double *v)
{
	sink_puts(s, key);
	sink_putc(s, ':');
	for (int i = 0; i < n; i++) {
		sink_putc(s, ' ');
		sink_num(s, v[i]);
	}
	sink_putc(s, '\n');
}

/*
 * The divergence as a fraction of a turn, by its continued fraction's
 * convergents p/q (the golden angle: 1/2, 1/3, 2/5, 3/8, 5/13, ...): the
 * q are the parastichy numbers the divergence can show.  Up to q of the
 * organ count, at most 16.
 */
static void
convergents(struct sink *s, const struct result *r)
{
	double x = fabs(r->divergence) / 360, f;
	long long h0 = 1, h1, k0 = 0, k1 = 1;

	x -= floor(x);
	h1 = 0;
	f = x;
	sink_puts(s, "convergents:");
	for (int i = 0; i < 16; i++) {
		double a;
		long long h, k;

		if (f < 1e-12)
			break;
		f = 1 / f;
		a = floor(f);
		f -= a;
		if (a > 1e12)
			break;
		h = (long long)a * h1 + h0;
		k = (long long)a * k1 + k0;
		if ((double)k > (double)r->count)
			break;
		h0 = h1;
		h1 = h;
		k0 = k1;
		k1 = k;
		sink_putc(s, ' ');
		sink_uint(s, (unsigned long long)h);
		sink_putc(s, '/');
		sink_uint(s, (unsigned long long)k);
	}
	sink_putc(s, '\n');
}

/* "parts: Floret 1000; Stem 1" and "leaves: 1000000": a compound's. */
static void
parts(struct sink *s, const struct result *r)
{
	double leaves = flatten_leaves(r);
	int first = 1;

	sink_puts(s, "parts:");
	for (size_t j = 0; j < r->nobjects; j++) {
		if (r->sub[j] == NULL)
			continue;
		sink_puts(s, first ? " " : "; ");
		sink_puts(s, r->objects[j]);
		sink_putc(s, ' ');
		sink_uint(s, (unsigned long long)r->sub[j]->count);
		first = 0;
	}
	sink_putc(s, '\n');
	line(s, "leaves", 1, &leaves);
}

/* x to three significant digits: an estimate has no more. */
static double
rounded(double x)
{
	double unit = x >= 100 ? pow(10, floor(log10(x)) - 2) : 1;

	return round(x / unit) * unit;
}

static void
size_item(struct sink *s, int *first, const char *name, double bytes)
{
	sink_puts(s, *first ? " " : "; ");
	sink_puts(s, name);
	sink_putc(s, ' ');
	sink_num(s, rounded(bytes));
	*first = 0;
}

/*
 * "output-bytes: pov 26100; blender 12400; ...": what each format would
 * write of this structure, by its default template, as the size limit
 * (--max-output) reckons it.
 */
static void
sizes(struct sink *s, const struct result *r)
{
	int first = 1;

	sink_puts(s, "output-bytes:");
	for (const struct writer *w = writers; w->name != NULL; w++) {
		struct tmpl *t = w->tmpl != NULL ?
		    tmpl_builtin(w->tmpl, w->vars) : NULL;
		struct plan P;

		/*
		 * Not itself, nor what writes the scene instead of organs,
		 * nor meshes that are not there (a warning said so).
		 */
		if (w->write == info_write || w->scenes != NULL ||
		    (w->tmpl != NULL && t == NULL) || ((w->opts & TO_MESHES) &&
		    r->meshes != NULL && r->meshes->missing)) {
			tmpl_free(t);
			continue;
		}
		plan_make(&P, w, t, r);
		size_item(s, &first, w->name, plan_bytes(&P, w, t, TMPL_ALL,
		    0));
		if ((w->opts & TO_FLATTEN) && r->sub != NULL)
			size_item(s, &first, "csv-flatten", plan_bytes(&P, w, t,
			    TMPL_ALL, TO_FLATTEN));
		plan_free(&P);
		tmpl_free(t);
	}
	sink_putc(s, '\n');
}

/* A few lines, and a zone a line at most. */
double
info_bytes(const struct result *r, unsigned opts)
{
	(void)r;
	(void)opts;
	return 16384;
}

void
info_write(struct sink *s, const struct result *r, unsigned opts)
{
	double box[6] = { HUGE_VAL, HUGE_VAL, HUGE_VAL,
	    -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
	double count = (double)r->count;

	(void)opts;
	sink_puts(s, "model: ");
	sink_puts(s, r->model);
	sink_puts(s, "\nname: ");
	sink_puts(s, r->name);
	sink_putc(s, '\n');
	line(s, "count", 1, &count);
	if (unordered_info_divergence(s, r) == 0)
		line(s, "divergence", 1, &r->divergence);
	for (size_t i = 0; i < r->count; i++)
		for (int j = 0; j < 3; j++) {
			box[j] = fmin(box[j], r->organs[i].pos[j]);
			box[j + 3] = fmax(box[j + 3], r->organs[i].pos[j]);
		}
	if (r->count > 0) {
		/* Each axis's smallest and largest organ centre. */
		sink_puts(s, "bbox:");
		for (int j = 0; j < 3; j++) {
			sink_puts(s, j ? "; " : " ");
			sink_putc(s, "xyz"[j]);
			sink_putc(s, ' ');
			sink_num(s, box[j]);
			sink_putc(s, ' ');
			sink_num(s, box[j + 3]);
		}
		sink_putc(s, '\n');
	}
	sink_puts(s, "objects:");
	for (size_t i = 0; i < r->nobjects; i++) {
		sink_putc(s, ' ');
		sink_puts(s, r->objects[i]);
	}
	sink_putc(s, '\n');
	if (r->sub != NULL)
		parts(s, r);
	sizes(s, r);
	if (r->frames > 1) {
		double fr[3] = { r->frame, r->frames, r->frame_f };

		labelled(s, "frame", "F of f", 3, fr);
	}
	for (int i = 0; i < r->ninfo; i++) {
		const struct info_item *it = &r->info[i];

		if (it->labels != NULL) {
			labelled(s, it->key, it->labels, it->nval, it->val);
			continue;
		}
		if (it->text == NULL) {
			line(s, it->key, it->nval, it->val);
			continue;
		}
		sink_puts(s, it->key);
		sink_puts(s, ": ");
		sink_puts(s, it->text);
		sink_putc(s, '\n');
	}
	if (r->unordered != NULL)
		unordered_info(s, r);
	else if (r->count >= 3) {
		/* Measured on the organs as placed, whatever the model. */
		struct para_zone z[64];
		size_t nz = para_zones(r, NULL, z, 64);

		if (nz > 0) {
			const struct para_zone *rim = r->rim_last ?
			    &z[nz - 1] : &z[0];
			double mn[2] = { rim->m, rim->n };
			char seen[80];

			/* A transition says what it saw, never a false pair. */
			if (rim->m == 0) {
				para_seen_text(rim, seen, sizeof(seen));
				sink_puts(s, "parastichies: ");
				sink_puts(s, seen);
				sink_putc(s, '\n');
			} else
				line(s, "parastichies", 2, mn);
			sink_puts(s, "parastichies-along:");
			for (size_t k = 0; k < nz; k++) {
				sink_puts(s, k ? "; " : " ");
				if (z[k].m == 0) {
					para_seen_text(&z[k], seen, sizeof(seen));
					sink_puts(s, seen);
				} else {
					sink_uint(s, (unsigned long long)z[k].m);
					sink_putc(s, '/');
					sink_uint(s, (unsigned long long)z[k].n);
				}
				sink_puts(s, " from organ ");
				sink_uint(s, (unsigned long long)z[k].from);
				sink_puts(s, " (rho ");
				sink_num(s, z[k].rho);
				sink_puts(s, ", z ");
				sink_num(s, z[k].z);
				sink_putc(s, ')');
			}
			sink_putc(s, '\n');
		} else
			sink_puts(s, r->rays > 0 ? "parastichies: none, the "
			    "organs lie on straight rays\n" :
			    "parastichies: none, no organ has contacts turning "
			    "both ways\n");
	}
	convergents(s, r);
	if (r->rays > 0) {
		/* Spokes instead of spirals: run() warns of it too. */
		double rays = (double)r->rays;

		line(s, "rays", 1, &rays);
	}
}
