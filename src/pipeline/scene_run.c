/*
 * scene_run.c - running a loaded scene: its model places the organs
 * from the context built here, the one place a scene becomes what a
 * model sees; then the organs entries dress them (organs.c), and the
 * result is given the facts of the scene that writers need.  A
 * compound's scenes so, parts first, each part's result linked to the
 * structures that place it.
 */
#include <stdio.h>
#include <string.h>

#include "scene/compound.h"
#include "base/diag.h"
#include "geometry/geometry.h"
#include "base/mem.h"
#include "models/model.h"
#include "pipeline/pipeline.h"

void
scene_model_ctx(const struct scene *sc, struct model_ctx *ctx,
    void (*progress)(long long done, int last))
{
	*ctx = (struct model_ctx){
		.params = sc->params,
		.file = sc->file,
		.count = sc->count,
		.count_line = sc->given[S_COUNT],
		.seed = sc->seed,
		.divergence = sc->divergence,
		.divergence_line = sc->given[S_DIVERGENCE],
		.progress = progress,
	};
}

int
scene_run(const struct scene *sc, struct result *res,
    void (*progress)(long long done, int last))
{
	struct model_ctx ctx;

	scene_model_ctx(sc, &ctx, progress);
	if (model_run(sc->model, &ctx, res) != 0)
		return -1;
	stretch_apply(res, sc->stretch);
	memcpy(res->name, sc->name, sizeof(res->name));
	res->model = sc->model->name;
	res->seed = sc->seed;
	res->source = xstrdup(sc->file);
	res->objects = xcalloc(sc->nobjects, sizeof(*res->objects));
	for (size_t i = 0; i < sc->nobjects; i++)
		snprintf(res->objects[i], sizeof(res->objects[i]), "%s",
		    sc->objects[i]);
	res->nobjects = sc->nobjects;
	res->frame = sc->frame_no;
	res->frames = 1;
	res->frame_f = sc->frame_f;
	/* A mean of angles that differ lays out no rays. */
	if (!sc->model->emerges && !divergence_rays(res->divergence,
	    res->count, &res->rays_p, &res->rays))
		res->rays = res->rays_p = 0;
	if (organs_apply(sc, res) != 0) {
		result_free(res);
		return -1;
	}
	return 0;
}

int
compound_run(struct compound *C, const struct frame *fr,
    void (*progress)(long long done, int last))
{
	for (size_t i = 0; i < C->n; i++) {
		struct part *p = C->parts[i];
		struct result *r = &p->res;

		if (scene_run(&p->sc, r, progress) != 0) {
			if (p->from != NULL)
				diag(ST_SCENE, p->from, p->from_line, 0, "in %s, "
				    "the scene of organ object \"%s\" included "
				    "here", p->file, p->object);
			return -1;
		}
		r->frames = fr != NULL ? fr->count : 1;
		if (p->object[0] != '\0') {
			r->part = 1;
			memcpy(r->name, p->object, sizeof(r->name));
		}
		for (size_t j = 0; j < p->sc.nobjects; j++) {
			if (p->sc.object_scene[j] == NULL)
				continue;
			if (r->sub == NULL)
				r->sub = xcalloc(r->nobjects, sizeof(*r->sub));
			r->sub[j] = &compound_part(C, p->sc.objects[j])->res;
		}
	}
	return 0;
}
