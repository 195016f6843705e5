/*
 * out_info_unordered.c - the parastichies --info reports of organs
 * measured without an order: the pair the rim or base shows, and zone
 * by zone from the tip, each with how many of its organs hold its pair
 * (or the pairs a transition shows, or that none is clear).
 */
#include <math.h>
#include <stdio.h>

#include "analysis/unordered.h"
#include "writers/unordered_out.h"

static void
pair(struct sink *s, int m, int n)
{
	sink_uint(s, (unsigned long long)m);
	sink_putc(s, '/');
	sink_uint(s, (unsigned long long)n);
}

static void
seen(struct sink *s, const struct uzone *z)
{
	sink_puts(s, "transition");
	for (int k = 0; k < z->nseen; k++) {
		sink_putc(s, ' ');
		pair(s, z->seen[k][0], z->seen[k][1]);
	}
}

int
unordered_info_divergence(struct sink *s, const struct result *r)
{
	if (r->unordered == NULL || !isnan(r->unordered->divergence))
		return 0;
	sink_puts(s, "divergence: none\n");
	return 1;
}

void
unordered_info(struct sink *s, const struct result *r)
{
	const struct unordered *U = r->unordered;
	const struct uzone *rim = unordered_rim(U);

	sink_puts(s, "parastichies: ");
	if (rim == NULL || rim->kind == UZ_UNCLEAR)
		sink_puts(s, "none clear");
	else if (rim->kind == UZ_PAIR) {
		sink_uint(s, (unsigned long long)rim->m);
		sink_putc(s, ' ');
		sink_uint(s, (unsigned long long)rim->n);
	} else
		seen(s, rim);
	sink_putc(s, '\n');
	if (U->nzones == 0)
		return;
	sink_puts(s, "parastichies-along:");
	for (size_t k = 0; k < U->nzones; k++) {
		const struct uzone *z = &U->zone[k];

		sink_puts(s, k ? "; " : " ");
		if (z->kind == UZ_PAIR)
			pair(s, z->m, z->n);
		else if (z->kind == UZ_TRANSITION)
			seen(s, z);
		else
			sink_puts(s, "unclear");
		sink_puts(s, " from rho ");
		sink_num(s, U->unit * z->rho);
		sink_puts(s, " (z ");
		sink_num(s, U->unit * z->z);
		sink_puts(s, "), ");
		if (z->kind == UZ_PAIR) {
			sink_uint(s, (unsigned long long)z->agree);
			sink_puts(s, " of ");
		}
		sink_uint(s, (unsigned long long)z->organs);
		sink_puts(s, z->kind == UZ_PAIR ? " organs agree" : " organs");
		if (z->cut)
			sink_puts(s, ", rings cut");
	}
	sink_putc(s, '\n');
}
