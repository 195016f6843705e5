/* writers.c - the table of output formats: one entry each. */
#include <stddef.h>

#include "writers/writer.h"

const struct writer writers[] = {
	{ "pov", NULL, NULL, NULL, "pov.tmpl", "pov-arrays.tmpl", 0,
	  pov_vars, pov_check,
	  "a POV-Ray include file declaring the structure" },
	{ "blender", NULL, NULL, NULL, "blender.tmpl", NULL,
	  TO_OBJECTS | TO_ANIMATE | TO_SHALLOW, blender_vars, NULL,
	  "a Python script that builds the structure in Blender" },
	{ "gltf", gltf_write, gltf_bytes, NULL, NULL, NULL,
	  TO_MESHES | TO_BINARY, NULL,
	  NULL, "binary glTF 2.0 (.glb): each organ object's mesh, "
	  "GPU-instanced" },
	{ "csv", csv_write, csv_bytes, NULL, NULL, NULL, TO_FLATTEN, NULL,
	  NULL, "one line per organ: position, frame, scale" },
	{ "svg", svg_write, svg_bytes, NULL, NULL, NULL, 0, NULL, NULL,
	  "a picture: organs, their parastichies, from above or unrolled" },
	{ "info", info_write, info_bytes, NULL, NULL, NULL, TO_SIZES, NULL,
	  NULL, "key: value facts about the result" },
	{ "settings", NULL, NULL, settings_write, NULL, NULL, TO_LISTING,
	  NULL, NULL,
	  "every setting of the scene as JSON: value, default, range, doc" },
	{ "cfg", NULL, NULL, cfg_write, NULL, NULL, 0, NULL, NULL,
	  "the scene file with each --set written into it, comments kept" },
	{ NULL, NULL, NULL, NULL, NULL, NULL, 0, NULL, NULL, NULL }
};
