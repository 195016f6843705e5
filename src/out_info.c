/* out_info.c - "key: value" lines about the result, for people and scripts. */
#include <math.h>

#include "writer.h"

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

void
info_write(struct sink *s, const struct result *r)
{
	double box[6] = { HUGE_VAL, HUGE_VAL, HUGE_VAL,
	    -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
	double count = (double)r->count;

	sink_puts(s, "model: ");
	sink_puts(s, r->model);
	sink_puts(s, "\nname: ");
	sink_puts(s, r->name);
	sink_putc(s, '\n');
	line(s, "count", 1, &count);
	line(s, "divergence", 1, &r->divergence);
	for (size_t i = 0; i < r->count; i++)
		for (int j = 0; j < 3; j++) {
			box[j] = fmin(box[j], r->organs[i].pos[j]);
			box[j + 3] = fmax(box[j + 3], r->organs[i].pos[j]);
		}
	if (r->count > 0)
		line(s, "bbox", 6, box);
	sink_puts(s, "objects:");
	for (size_t i = 0; i < r->nobjects; i++) {
		sink_putc(s, ' ');
		sink_puts(s, r->objects[i]);
	}
	sink_putc(s, '\n');
	for (int i = 0; i < r->ninfo; i++) {
		const struct info_item *it = &r->info[i];

		if (it->text == NULL) {
			line(s, it->key, it->nval, it->val);
			continue;
		}
		sink_puts(s, it->key);
		sink_puts(s, ": ");
		sink_puts(s, it->text);
		sink_putc(s, '\n');
	}
	if (r->rays > 0) {
		/* Spokes instead of spirals: rarely what was meant. */
		double rays = (double)r->rays;

		line(s, "rays", 1, &rays);
		sink_puts(s, "warning: divergence ");
		sink_num(s, r->divergence);
		sink_puts(s, " is ");
		sink_uint(s, (unsigned long long)r->rays_p);
		sink_putc(s, '/');
		sink_uint(s, (unsigned long long)r->rays);
		sink_puts(s, " of a turn: from organ ");
		sink_uint(s, (unsigned long long)r->rays);
		sink_puts(s, " on, organs line up on ");
		sink_uint(s, (unsigned long long)r->rays);
		sink_puts(s, " rays instead of spirals\n");
	}
}
