/*
 * fuzz_scene.c - libFuzzer harness for the whole scene path: bytes ->
 * scene -> model -> organs -> every writer, into memory.  Scenes that
 * ask for more than 20,000 organs, or leave the count to the model, are
 * loaded and checked but not run, to keep each input fast; the limits
 * themselves have their own tests.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "model.h"
#include "scene.h"
#include "writer.h"

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
	/*
	 * Without count a model finds its own (cylindrical.length, the
	 * collision model's bound of a million): too slow to fuzz.
	 */
	if (!sc.given[S_COUNT] || sc.count > 20000)
		goto out;
	/* The inhibition model's primordia cost a sum each: fewer. */
	if (strcmp(sc.model->name, "inhibition") == 0 && sc.count > 2000)
		goto out;
	if (model_run(&sc, &res) != 0)
		goto out;
	sink_init(&s, NULL);
	csv_write(&s, &res);
	info_write(&s, &res);
	svg_write(&s, &res);
	if (pov_check(&sc) == 0 &&
	    (t = tmpl_builtin("pov.tmpl", pov_vars)) != NULL) {
		tmpl_write(t, &s, &res, 0);
		tmpl_free(t);
	}
	sink_free(&s);
out:
	result_free(&res);
	scene_free(&sc);
	return 0;
}
