/*
 * plan.h - what one frame's output holds: the structures a template
 * writes, and how many bytes a writer will write of them.
 */
#ifndef PLAN_H
#define PLAN_H

#include "result/organ.h"
#include "writers/template.h"
#include "writers/writer.h"

/*
 * The structures a template writes for one frame: each part before the
 * structures placing it, the main last.  A writer that nests one level
 * (TO_SHALLOW) gets the parts the main places, each a view with its own
 * parts opened (flatten.h).  A template without @@structures, or a
 * writer without a template, gets the main alone.
 */
struct plan {
	const struct result **all;
	size_t		 n;
	struct result	*views;		/* owned */
	size_t		 nviews;
};

void	plan_make(struct plan *, const struct writer *, const struct tmpl *,
	    const struct result *main);
void	plan_free(struct plan *);
/* The bytes writer w would write of the plan, or of a piece of it. */
double	plan_bytes(const struct plan *, const struct writer *,
	    const struct tmpl *, enum tmpl_piece, unsigned opts);

#endif
