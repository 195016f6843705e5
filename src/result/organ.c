/* organ.c - the organ array every model fills and every writer reads. */
#include <stdarg.h>
#include <stdlib.h>

#include "base/mem.h"
#include "result/organ.h"

void
result_init(struct result *r, size_t count)
{
	*r = (struct result){0};
	r->organs = xcalloc_big(count, sizeof(*r->organs));
	r->count = count;
}

void
result_free(struct result *r)
{
	free(r->organs);
	free(r->source);
	free(r->objects);
	free(r->sub);
	free(r->unordered);
	*r = (struct result){0};
}

/* Record a fact for --info; facts past INFO_MAX are a programming error. */
void
result_info(struct result *r, const char *key, int nval, ...)
{
	struct info_item *it;
	va_list ap;

	if (r->ninfo >= INFO_MAX || nval > 6)
		abort();
	it = &r->info[r->ninfo++];
	it->key = key;
	it->nval = nval;
	va_start(ap, nval);
	for (int i = 0; i < nval; i++)
		it->val[i] = va_arg(ap, double);
	va_end(ap);
}

void
result_info_labelled(struct result *r, const char *key, const char *labels,
    int nval, ...)
{
	struct info_item *it;
	va_list ap;

	if (r->ninfo >= INFO_MAX || nval > 6)
		abort();
	it = &r->info[r->ninfo++];
	*it = (struct info_item){ .key = key, .nval = nval, .labels = labels };
	va_start(ap, nval);
	for (int i = 0; i < nval; i++)
		it->val[i] = va_arg(ap, double);
	va_end(ap);
}

/* A fact that is a word ("regime: fibonacci"); text must outlive r. */
void
result_info_text(struct result *r, const char *key, const char *text)
{
	result_info(r, key, 0);
	r->info[r->ninfo - 1].text = text;
}
