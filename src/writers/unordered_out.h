/*
 * unordered_out.h - what --info and --svg write of a result measured
 * without an organ order (analysis/unordered.h), in place of what they
 * read from a model's order.
 */
#ifndef UNORDERED_OUT_H
#define UNORDERED_OUT_H

#include <stddef.h>

#include "base/sink.h"
#include "result/organ.h"

/*
 * "divergence: none" where the organs were measured and no lattice
 * gave one (1), else nothing (0): the result's divergence, 0 there, is
 * for templates.
 */
int	unordered_info_divergence(struct sink *, const struct result *);

/* The parastichies: and parastichies-along: lines. */
void	unordered_info(struct sink *, const struct result *);

/*
 * Organ positions on the page, before the y flip: a head from above, a
 * surface unrolled (across, the angle times the distance from the
 * axis; up, the arc length along the fitted curve, tip at the top).
 */
double	(*unordered_svg_page(const struct result *, int *unrolled))[2];

/*
 * The families f[0 .. nf) as curves through the organs each contact
 * joins, in colours[k % ncolours] (k the rank among those drawn, as the
 * models' are), width wide; and a mark where the centre is.  f keeps
 * the families drawn, in order; their number is returned.
 */
size_t	unordered_svg_families(struct sink *, const struct result *,
	    double (*page)[2], int *f, size_t nf,
	    const char *const *colours, size_t ncolours, double width);

/* The legend's line on the divergence: measured, with its error. */
void	unordered_svg_divergence(char *, size_t, const struct result *);

#endif
