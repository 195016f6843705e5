/* writers.c - the table of output formats: one line each. */
#include <stddef.h>

#include "writer.h"

const struct writer writers[] = {
	{ "pov", NULL, "pov.tmpl", "pov-arrays.tmpl", 0, pov_vars, pov_check,
	  "a POV-Ray include file declaring the structure" },
	{ "blender", NULL, "blender.tmpl", NULL, TO_OBJECTS | TO_ANIMATE | TO_SHALLOW,
	  blender_vars, NULL,
	  "a Python script that builds the structure in Blender" },
	{ "csv", csv_write, NULL, NULL, TO_FLATTEN, NULL, NULL,
	  "one line per organ: position, frame, scale" },
	{ "svg", svg_write, NULL, NULL, 0, NULL, NULL,
	  "a picture: organs, their parastichies, from above or unrolled" },
	{ "info", info_write, NULL, NULL, 0, NULL, NULL,
	  "key: value facts about the result" },
	{ NULL, NULL, NULL, NULL, 0, NULL, NULL, NULL }
};
