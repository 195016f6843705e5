/*
 * fuzz_scene.c - libFuzzer harness for the whole scene path: bytes ->
 * scene -> model -> organs -> every writer, into memory.  Scenes that
 * ask for more than 20,000 organs (or a collision scene without a
 * count, a million) are loaded and checked but not run, to keep each
 * input fast; the limits themselves have their own tests.
 */
#include <stddef.h>
#include <stdint.h>

#include "model.h"
#include "scene.h"
#include "writer.h"

static model_fn *const models[MODEL__MAX] = {
	[MODEL_PLANAR] = planar_run,
	[MODEL_CYLINDRICAL] = cylindrical_run,
	[MODEL_COLLISION] = collision_run,
};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct scene sc;
	struct result res = { 0 };
	struct tmpl *t;
	struct sink s;

	if (scene_load_buffer(&sc, "fuzz.cfg", (const char *)data, size) != 0)
		goto out;
	if (sc.count > 20000 || scene_given(&sc, "cylindrical.length") ||
	    models[sc.model] == NULL)
		goto out;
	/* The collision model's default bound is a million. */
	if (sc.model == MODEL_COLLISION && !scene_given(&sc, "count"))
		goto out;
	if (models[sc.model](&sc, &res) != 0 || organs_apply(&sc, &res) != 0)
		goto out;
	sink_init(&s, NULL);
	csv_write(&s, &sc, &res);
	info_write(&s, &sc, &res);
	if (pov_check(&sc) == 0 &&
	    (t = tmpl_builtin("pov.tmpl", pov_vars)) != NULL) {
		tmpl_write(t, &s, &sc, &res, 0);
		tmpl_free(t);
	}
	sink_free(&s);
out:
	result_free(&res);
	scene_free(&sc);
	return 0;
}
