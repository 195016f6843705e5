/*
 * fuzz_template.c - libFuzzer harness for the template engine, parsing
 * and writing two structures, a part and the main one, so that
 * @@structures, @@part and @@main are live.
 */
#include <stdint.h>
#include <string.h>

#include "models/model.h"
#include "pipeline/pipeline.h"
#include "scene/scene.h"
#include "writers/template.h"
#include "writers/writer.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const char text[] = "model = \"planar\"; count = 5;\n"
	    "organs = ( { object = [\"A\", \"B\"]; } );";
	static struct scene sc;
	static struct result res, part;
	static int ready;
	const struct result *all[2] = { &part, &res };
	struct tmpl *t;
	struct sink s;

	if (!ready) {
		if (scene_load_buffer(&sc, "t.cfg", text, strlen(text)) != 0 ||
		    scene_run(&sc, &res, NULL) != 0 ||
		    scene_run(&sc, &part, NULL) != 0)
			return 0;
		part.part = 1;
		ready = 1;
	}
	if ((t = tmpl_parse("fuzz.tmpl", (const char *)data, size,
	    pov_vars)) == NULL)
		return 0;
	sink_init(&s, NULL);
	tmpl_write(t, &s, all, 2, 0);
	sink_free(&s);
	tmpl_free(t);
	return 0;
}
