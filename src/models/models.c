/*
 * models.c - the registry of models, and running one: the model
 * places, organs_apply() dresses, and the result is given the facts of
 * the scene that writers need.
 */
#include <stdio.h>
#include <string.h>

#include "mem.h"
#include "models/model.h"

extern const struct model planar_model, cylindrical_model, collision_model,
    area_model, inhibition_model;

const struct model *const models[] = {
	&planar_model,
	&cylindrical_model,
	&collision_model,
	&area_model,
	&inhibition_model,
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
model_run(const struct scene *sc, struct result *res)
{
	*res = (struct result){0};
	if (sc->model->run(sc, sc->params, res) != 0)
		return -1;
	stretch_apply(res, sc->stretch);
	memcpy(res->name, sc->name, sizeof(res->name));
	res->model = sc->model->name;
	res->seed = sc->seed;
	res->svg = sc->model->svg;
	res->rim_last = sc->model->rim_last;
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
