/*
 * settings.c - the settings every scene has: the top level and the
 * entries of organs.  Each model's group is a table in the model's own
 * file, and a receptacle's in receptacle.c; settings_list() prints
 * them all for tests/man.sh, which checks phyllo-export(5) against it.
 * What every table shares is base/table.c's.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "models/model.h"
#include "scene/scene.h"
#include "scene/settings.h"

#define S(f)	offsetof(struct scene, f)
#define R(f)	offsetof(struct organ_range, f)

static const struct row range_rows[] = {
	[RG_FROM] = { .name = "from", .type = T_INT, .off = R(from), .lo = 0,
	  .hi = HUGE_VAL, .defstr = "0", .unit = "organ",
	  .doc = "first organ of the entry" },
	[RG_TO] = { .name = "to", .type = T_INT, .off = R(to), .lo = -1,
	  .hi = HUGE_VAL, .def = -1, .defstr = "-1",
	  .unit = "organ",
	  .doc = "last organ of the entry; -1 the last of all" },
	[RG_OBJECT] = { .name = "object", .type = T_NAMES, .defstr = "Organ",
	  .doc = "organ object, or an array of variants chosen at random" },
	[RG_WEIGHTS] = { .name = "weights", .type = T_WEIGHTS, .lo = 0,
	  .hi = HUGE_VAL, .defstr = "all 1",
	  .doc = "relative frequency of each variant" },
	[RG_SCENE] = { .name = "scene", .type = T_FILES, .off = R(scenes),
	  .defstr = "none",
	  .doc = "a scene file making the object, relative to this one; "
	  "an array: one per variant" },
	[RG_MESH] = { .name = "mesh", .type = T_FILES, .off = R(meshes),
	  .defstr = "none",
	  .doc = "a Wavefront OBJ file of the object's mesh for --gltf, "
	  "relative to this one; an array: one per variant" },
	[RG_SCALE] = { .name = "scale", .type = T_EXPR, .off = R(scale),
	  .vars = EXPR_ALL, .defstr = "r", .doc = "scale of the organ model" },
	[RG_ALTITUDE] = { .name = "altitude", .type = T_EXPR,
	  .off = R(altitude), .vars = EXPR_ALL, .defstr = "0",
	  .unit = "length",
	  .doc = "offset along the surface normal w" },
	[RG_TILT] = { .name = "tilt", .type = T_EXPR, .off = R(tilt),
	  .vars = EXPR_ALL, .defstr = "0",
	  .unit = "degrees",
	  .doc = "rotation about v lifting u towards w, degrees" },
	[RG_ROLL] = { .name = "roll", .type = T_EXPR, .off = R(roll),
	  .vars = EXPR_ALL, .defstr = "0", .unit = "degrees",
	  .doc = "rotation about w, degrees" },
};

const struct table range_table = TABLE(range_rows, struct organ_range);

static const struct row scene_rows[] = {
	[S_NAME] = { .name = "name", .type = T_IDENT, .off = S(name),
	  .defstr = "the file name",
	  .doc = "identifier naming the result: POV-Ray object, Blender "
	  "collection" },
	[S_MODEL] = { .name = "model", .type = T_MODEL, .off = S(model),
	  .defstr = "none", .doc = "which model places the organs" },
	[S_DIVERGENCE] = { .name = "divergence", .type = T_FLOAT,
	  .off = S(divergence), .lo = -360, .hi = 360, .def = GOLDEN_ANGLE,
	  .defstr = "137.507764",
	  .unit = "degrees",
	  .doc = "divergence angle between consecutive organs, degrees" },
	[S_COUNT] = { .name = "count", .type = T_INT, .off = S(count), .lo = 1,
	  .hi = COUNT_MAX, .defstr = "none", .unit = "organs",
	  .doc = "number of organs" },
	[S_SEED] = { .name = "seed", .type = T_INT, .off = S(seed),
	  .lo = -HUGE_VAL, .hi = HUGE_VAL, .defstr = "0",
	  .doc = "seed of rand() and of the choice among variants" },
	[S_STRETCH] = { .name = "stretch", .type = T_VEC3, .off = S(stretch),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .def = 1,
	  .defstr = "[1, 1, 1]",
	  .doc = "scale the placed structure along x, y and z" },
	[S_ORGANS] = { .name = "organs", .type = T_RANGES, .sub = &range_table,
	  .doc = "list of organ entries, each an index range" },
};

const struct table scene_table = TABLE(scene_rows, struct scene);

static void
list_row(FILE *fp, const char *prefix, const struct row *r)
{
	char path[PATH_LEN];

	snprintf(path, sizeof(path), "%s%s%s", prefix, *prefix ? "." : "",
	    r->name);
	fprintf(fp, "%s\t%s\t%s\n", path, settings_type(r),
	    r->defstr != NULL ? r->defstr : "");
	if (r->sub != NULL)
		for (size_t i = 0; i < r->sub->n; i++)
			list_row(fp, path, &r->sub->rows[i]);
}

/* The top level, then each model's group, then the organs entries. */
void
settings_list(FILE *fp)
{
	for (size_t i = 0; i < scene_table.n; i++)
		if (scene_rows[i].type != T_RANGES)
			list_row(fp, "", &scene_rows[i]);
	for (const struct model *const *m = models; *m != NULL; m++) {
		struct row group = { .name = (*m)->name, .type = T_GROUP,
		    .sub = (*m)->settings };

		list_row(fp, "", &group);
	}
	for (size_t i = 0; i < scene_table.n; i++)
		if (scene_rows[i].type == T_RANGES)
			list_row(fp, "", &scene_rows[i]);
}
