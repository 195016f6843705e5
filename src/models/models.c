/*
 * models.c - the registry of models, and running one: the checks every
 * model shares, then its own placement; and what the context gives a
 * model to report with.
 */
#include <stdarg.h>
#include <string.h>

#include "models/model.h"

extern const struct model planar_model, cylindrical_model, collision_model,
    area_model, inhibition_model, measured_model;

const struct model *const models[] = {
	&planar_model,
	&cylindrical_model,
	&collision_model,
	&area_model,
	&inhibition_model,
	&measured_model,
	NULL
};

const struct model *
model_find(const char *name)
{
	for (const struct model *const *m = models; *m != NULL; m++)
		if (strcmp((*m)->name, name) == 0)
			return *m;
	return NULL;
}

int
model_run(const struct model *m, const struct model_ctx *ctx,
    struct result *res)
{
	*res = (struct result){0};
	if (m->needs_count && !ctx->count_line && (m->count_else == NULL ||
	    !settings_given(m->settings, ctx->params, m->count_else))) {
		if (m->count_else != NULL)
			model_error(ctx, 1, "missing setting 'count' (or "
			    "%s.%s)", m->name, m->count_else);
		else
			model_error(ctx, 1, "missing setting 'count'");
		return -1;
	}
	return m->make(ctx, res);
}

void
model_error(const struct model_ctx *ctx, int line, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	settings_verror(ctx->file, line, fmt, ap);
	va_end(ap);
}

int
model_eval(const struct model_ctx *ctx, const struct expr_setting *es,
    const char *path, const char *item, struct expr_env *env, double *v)
{
	return expr_setting_eval(es, ctx->file, path, item, env, v);
}
