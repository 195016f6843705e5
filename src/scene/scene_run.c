/*
 * scene_run.c - running a loaded scene: its model places the organs
 * from the context built here, the one place a scene becomes what a
 * model sees; then the organs entries dress them, and the result is
 * given the facts of the scene that writers need.
 */
#include <stdio.h>
#include <string.h>

#include "geometry/geometry.h"
#include "mem.h"
#include "models/model.h"
#include "scene/scene.h"

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
