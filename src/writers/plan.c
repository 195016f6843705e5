/*
 * plan.c - which structures of a compound a writer writes, and their
 * size.  Taken from the result's tree of parts, so that anything holding
 * a result (--info's estimates, a test) can ask; the order is the
 * compound's: each part after the parts it places, each once.
 */
#include <stdlib.h>

#include "result/flatten.h"
#include "base/mem.h"
#include "writers/plan.h"

static int
listed(const struct plan *P, const struct result *r)
{
	for (size_t i = 0; i < P->n; i++)
		if (P->all[i] == r)
			return 1;
	return 0;
}

/* Whether structure r places part p itself. */
static int
places(const struct result *r, const struct result *p)
{
	for (size_t j = 0; j < r->nobjects; j++)
		if (r->sub[j] == p)
			return 1;
	return 0;
}

/* r's parts, depth first, then r; each once. */
static void
add_tree(struct plan *P, const struct result *r, size_t *cap)
{
	for (size_t j = 0; r->sub != NULL && j < r->nobjects; j++)
		if (r->sub[j] != NULL && !listed(P, r->sub[j]))
			add_tree(P, r->sub[j], cap);
	if (P->n == *cap)
		P->all = xreallocarray(P->all, *cap = *cap * 2 + 8,
		    sizeof(*P->all));
	P->all[P->n++] = r;
}

void
plan_make(struct plan *P, const struct writer *w, const struct tmpl *t,
    const struct result *main)
{
	struct plan tree = { NULL, 0, NULL, 0 };
	size_t cap = 0;

	*P = tree;
	if (t == NULL || !tmpl_structures(t) || main->sub == NULL) {
		P->all = xcalloc(1, sizeof(*P->all));
		P->all[P->n++] = main;
		return;
	}
	if (!(w->opts & TO_SHALLOW)) {
		add_tree(P, main, &cap);
		return;
	}
	/*
	 * One level: of the whole tree, in its order, what the main places
	 * itself, each with its own parts opened.
	 */
	add_tree(&tree, main, &cap);
	P->all = xcalloc(tree.n, sizeof(*P->all));
	P->views = xcalloc(tree.n, sizeof(*P->views));
	for (size_t i = 0; i < tree.n; i++) {
		const struct result *p = tree.all[i];

		if (p != main && !places(main, p))
			continue;
		if (p != main && p->sub != NULL) {
			flatten_view(p, &P->views[P->nviews]);
			p = &P->views[P->nviews++];
		}
		P->all[P->n++] = p;
	}
	free(tree.all);
}

void
plan_free(struct plan *P)
{
	for (size_t i = 0; i < P->nviews; i++)
		flatten_free(&P->views[i]);
	free(P->views);
	free(P->all);
	*P = (struct plan){ NULL, 0, NULL, 0 };
}

double
plan_bytes(const struct plan *P, const struct writer *w, const struct tmpl *t,
    enum tmpl_piece piece, unsigned opts)
{
	if (t != NULL)
		return tmpl_bytes(t, piece, P->all, P->n, opts);
	return w->bytes(P->all[P->n - 1], opts);
}
