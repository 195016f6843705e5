/*
 * scene_text.h - the unit tests' way to a result: a scene written as
 * text, loaded as the program loads a file ("test.cfg" in messages)
 * and run, organs entries and all.
 */
#ifndef SCENE_TEXT_H
#define SCENE_TEXT_H

#include <string.h>

#include "pipeline/pipeline.h"
#include "scene/scene.h"

/* Load text and run its model; 0, or -1 after a diagnostic. */
static inline int
scene_text_run(const char *text, struct scene *sc, struct result *res)
{
	*res = (struct result){0};
	if (scene_load_buffer(sc, "test.cfg", text, strlen(text)) != 0)
		return -1;
	return scene_run(sc, res, NULL);
}

#endif
