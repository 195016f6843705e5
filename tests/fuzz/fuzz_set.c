/*
 * fuzz_set.c - libFuzzer harness for --set: the input's first line is
 * the argument (OBJECT:PATH=VALUE), the rest a scene file.  The
 * argument is parsed, put into the scene as it loads (keeping every
 * setting as written), spliced into the scene's text as --cfg does and
 * its path taken out of the text as --cfg takes out a setting a --set
 * leaves unused, and its strings written as JSON as --settings does;
 * loaded again as --settings loads it, keeping settings the others
 * leave unused.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/cfgtext.h"
#include "writers/json.h"
#include "scene/override.h"
#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const uint8_t *nl = memchr(data, '\n', size);
	size_t alen = nl != NULL ? (size_t)(nl - data) : size;
	char *arg = malloc(alen + 1);
	struct override o;
	struct sink s;

	if (arg == NULL || memchr(data, '\0', alen) != NULL) {
		free(arg);
		return 0;
	}
	memcpy(arg, data, alen);
	arg[alen] = '\0';
	sink_init(&s, NULL);
	json_string(&s, arg);
	for (int listing = 0, ok = override_parse(arg, &o) == 0; ok &&
	    listing < 2; listing++) {
		struct loading ld = { .set = &o, .nset = 1, .record = 1,
		    .listing = listing };
		struct scene sc;
		const char *text = nl != NULL ? (const char *)nl + 1 : "";
		size_t len = nl != NULL ? size - alen - 1 : 0;

		if (scene_load_buffer_as(&sc, "fuzz.cfg", text, len, o.object,
		    &ld) == 0) {
			size_t n;
			char *spliced = cfgtext_splice(sc.text, sc.len, o.path,
			    o.value, &n);
			char *cut = cfgtext_cut(sc.text, sc.len, o.path, &n);

			for (size_t i = 0; i < sc.nwritten; i++)
				json_string(&s, sc.written[i].text);
			free(spliced);
			free(cut);
		}
		scene_free(&sc);
	}
	sink_free(&s);
	free(arg);
	return 0;
}
