/*
 * settings.c - every scene setting in one table: its path, type, the
 * models it applies to, its range, default and a line of doc.  The
 * loader in scene.c walks it, and tests/man.sh checks that
 * phyllo-export(5) lists exactly these rows, so parsing, defaults,
 * validation and the manual cannot drift apart.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "settings.h"

/* 360 (2 - tau), tau the golden ratio. */
#define GOLDEN_ANGLE	137.50776405003785

#define S(f)	offsetof(struct scene, f)
#define R(f)	offsetof(struct organ_range, f)

const struct row rows[] = {
	{ .path = "name", .type = T_IDENT, .off = S(name),
	  .defstr = "the file name",
	  .doc = "identifier naming the result: POV-Ray object, Blender "
	  "collection" },
	{ .path = "model", .type = T_CHOICE, .off = S(model),
	  .flags = F_REQUIRED, .defstr = "none",
	  .words = "planar cylindrical collision",
	  .doc = "which model places the organs" },
	{ .path = "divergence", .type = T_FLOAT, .off = S(divergence),
	  .lo = -360, .hi = 360, .def = GOLDEN_ANGLE, .defstr = "137.507764",
	  .doc = "divergence angle between consecutive organs, degrees" },
	{ .path = "count", .type = T_INT, .off = S(count), .lo = 1,
	  .hi = COUNT_MAX, .defstr = "none", .doc = "number of organs" },
	{ .path = "seed", .type = T_INT, .off = S(seed), .lo = -HUGE_VAL,
	  .hi = HUGE_VAL, .defstr = "0",
	  .doc = "seed of rand() and of the choice among variants" },
	{ .path = "planar", .type = T_GROUP, .models = PLANAR,
	  .doc = "settings of the planar model" },
	{ .path = "planar.scale", .type = T_FLOAT, .models = PLANAR,
	  .off = S(planar.scale), .lo = 0, .hi = HUGE_VAL,
	  .flags = F_LO_OPEN, .def = 1, .defstr = "1",
	  .doc = "Vogel's c: organ n lies at radius c n^exponent" },
	{ .path = "planar.outer", .type = T_FLOAT, .models = PLANAR,
	  .off = S(planar.outer), .lo = 0, .hi = HUGE_VAL,
	  .flags = F_LO_OPEN, .defstr = "none",
	  .doc = "radius of the last organ; sets c instead of scale" },
	{ .path = "planar.inner", .type = T_FLOAT, .models = PLANAR,
	  .off = S(planar.inner), .lo = 0, .hi = HUGE_VAL, .defstr = "0",
	  .doc = "radius at which organ 0 sits" },
	{ .path = "planar.exponent", .type = T_FLOAT, .models = PLANAR,
	  .off = S(planar.exponent), .lo = 0, .hi = 4, .flags = F_LO_OPEN,
	  .def = 0.5, .defstr = "0.5", .doc = "exponent of n in the radius" },
	{ .path = "planar.dome", .type = T_FLOAT, .models = PLANAR,
	  .off = S(planar.dome), .lo = -HUGE_VAL, .hi = HUGE_VAL,
	  .defstr = "0",
	  .doc = "height of the centre above the rim (paraboloid)" },
	{ .path = "cylindrical", .type = T_GROUP, .models = CYL,
	  .doc = "settings of the cylindrical model" },
	{ .path = "cylindrical.radius", .type = T_EXPR, .models = CYL,
	  .off = S(cyl.radius), .defstr = "1",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .doc = "radius of the cylinder; an expression of t tapers it" },
	{ .path = "cylindrical.parastichies", .type = T_INTS, .models = CYL,
	  .off = S(cyl.parastichies), .lo = 1, .hi = 1000, .defstr = "none",
	  .doc = "contact parastichy pair [m, n] or triple [m, n, m+n]" },
	{ .path = "cylindrical.rise", .type = T_FLOAT, .models = CYL,
	  .off = S(cyl.rise), .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN,
	  .defstr = "none",
	  .doc = "height between consecutive organs, for radius 1" },
	{ .path = "cylindrical.length", .type = T_FLOAT, .models = CYL,
	  .off = S(cyl.length), .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN,
	  .defstr = "none", .doc = "length of the structure instead of count" },
	{ .path = "collision", .type = T_GROUP, .models = COLL,
	  .doc = "settings of the collision model" },
	{ .path = "collision.receptacle", .type = T_GROUP, .models = COLL,
	  .doc = "the surface of revolution the primordia sit on" },
	{ .path = "collision.receptacle.profile", .type = T_POINTS,
	  .models = COLL, .off = S(coll.profile), .lo = 0, .hi = HUGE_VAL,
	  .defstr = "none",
	  .doc = "3k+1 (radius, height) control points of k cubic Bezier "
	  "segments, base first" },
	{ .path = "collision.receptacle.shape", .type = T_CHOICE,
	  .models = COLL, .off = S(coll.shape), .defstr = "none",
	  .words = "disk cone hemisphere sphere cylinder ellipsoid cap",
	  .doc = "a preset receptacle instead of a profile" },
	{ .path = "collision.receptacle.radius", .type = T_FLOAT,
	  .models = COLL, .off = S(coll.width), .lo = 0, .hi = HUGE_VAL,
	  .flags = F_LO_OPEN, .def = 1, .defstr = "1",
	  .doc = "radius of the preset at its widest" },
	{ .path = "collision.receptacle.height", .type = T_FLOAT,
	  .models = COLL, .off = S(coll.height), .lo = 0, .hi = HUGE_VAL,
	  .flags = F_LO_OPEN, .defstr = "per shape",
	  .doc = "height of the cone, cylinder, ellipsoid or cap" },
	{ .path = "collision.radius", .type = T_EXPR, .models = COLL,
	  .off = S(coll.radius), .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .doc = "radius of primordium n" },
	{ .path = "collision.epsilon", .type = T_EXPR, .models = COLL,
	  .off = S(coll.epsilon), .defstr = "none",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T) |
	  EXPR_VAR(V_R),
	  .doc = "arc length t may fall back below the last primordium; "
	  "\"r\": its radius" },
	{ .path = "organs", .type = T_RANGES,
	  .doc = "list of organ entries, each an index range" },
	{ .path = "organs.from", .type = T_INT, .where = IN_RANGE,
	  .off = R(from), .lo = 0, .hi = HUGE_VAL, .defstr = "0",
	  .doc = "first organ of the entry" },
	{ .path = "organs.to", .type = T_INT, .where = IN_RANGE,
	  .off = R(to), .lo = -1, .hi = HUGE_VAL, .def = -1, .defstr = "-1",
	  .doc = "last organ of the entry; -1 the last of all" },
	{ .path = "organs.object", .type = T_NAMES, .where = IN_RANGE,
	  .defstr = "Organ",
	  .doc = "organ object, or an array of variants chosen at random" },
	{ .path = "organs.weights", .type = T_WEIGHTS, .where = IN_RANGE,
	  .lo = 0, .hi = HUGE_VAL, .defstr = "all 1",
	  .doc = "relative frequency of each variant" },
	{ .path = "organs.scale", .type = T_EXPR, .where = IN_RANGE,
	  .off = R(scale), .vars = EXPR_ALL, .defstr = "r",
	  .doc = "scale of the organ model" },
	{ .path = "organs.altitude", .type = T_EXPR, .where = IN_RANGE,
	  .off = R(altitude), .vars = EXPR_ALL, .defstr = "0",
	  .doc = "offset along the surface normal w" },
	{ .path = "organs.tilt", .type = T_EXPR, .where = IN_RANGE,
	  .off = R(tilt), .vars = EXPR_ALL, .defstr = "0",
	  .doc = "rotation about v lifting u towards w, degrees" },
	{ .path = "organs.roll", .type = T_EXPR, .where = IN_RANGE,
	  .off = R(roll), .vars = EXPR_ALL, .defstr = "0",
	  .doc = "rotation about w, degrees" },
};

const size_t nrows = sizeof(rows) / sizeof(rows[0]);

static const char *const model_names[MODEL__MAX] = {
	"planar", "cylindrical", "collision"
};

/* The loader's state while walking one file. */
const char *
scene_model_name(int model)
{
	return model >= 0 && model < MODEL__MAX ? model_names[model] : "?";
}

const struct row *
row_find(const char *path, enum where where)
{
	for (size_t i = 0; i < nrows; i++)
		if (rows[i].where == where && strcmp(rows[i].path, path) == 0)
			return &rows[i];
	return NULL;
}

/* The table, one setting a line, for the test that checks the man page. */
void
scene_settings_list(FILE *fp)
{
	static const char *const tn[] = {
		"group", "integer", "number", "identifier", "string",
		"expression", "names", "numbers", "integers", "points", "list"
	};

	for (size_t i = 0; i < nrows; i++)
		fprintf(fp, "%s\t%s\t%s\n", rows[i].path, tn[rows[i].type],
		    rows[i].defstr != NULL ? rows[i].defstr : "");
}
