/*
 * template_vars.c - the placeholders every template has, for --pov and
 * --blender alike: the structure's (@NAME@, @COUNT@, @FRAME@ ...), an
 * organ object's (@OBJECT@ ...) and an organ's (@X@, @UX@, @PHI@ ...).
 * A writer's own come in its extra table (out_pov.c, out_blender.c);
 * the engine that parses and writes them is template.c.
 */
#include <ctype.h>
#include <string.h>

#include "compat/compat.h"
#include "base/phyllo.h"
#include "result/flatten.h"
#include "writers/template.h"

const struct organ *
tmpl_organ(const struct tmpl_ctx *c)
{
	return c->o;
}

static void put_name(struct sink *s, const struct tmpl_ctx *c)
{ sink_puts(s, c->r->name); }
static void put_count(struct sink *s, const struct tmpl_ctx *c)
{ sink_uint(s, c->r->count); }
static void put_model(struct sink *s, const struct tmpl_ctx *c)
{ sink_puts(s, c->r->model); }
static void put_divergence(struct sink *s, const struct tmpl_ctx *c)
{ sink_num(s, c->r->divergence); }
static void put_seed(struct sink *s, const struct tmpl_ctx *c)
{ sink_num(s, (double)c->r->seed); }
static void put_version(struct sink *s, const struct tmpl_ctx *c)
{ (void)c; sink_puts(s, VERSION); }
static void put_object_count(struct sink *s, const struct tmpl_ctx *c)
{ sink_uint(s, c->r->nobjects); }
static void put_frame(struct sink *s, const struct tmpl_ctx *c)
{ sink_uint(s, (size_t)c->r->frame); }
static void put_frames(struct sink *s, const struct tmpl_ctx *c)
{ sink_uint(s, (size_t)c->r->frames); }
static void put_frame_f(struct sink *s, const struct tmpl_ctx *c)
{ sink_num(s, c->r->frame_f); }
static void put_part(struct sink *s, const struct tmpl_ctx *c)
{ sink_putc(s, c->r->part ? '1' : '0'); }

/*
 * The scene file's base name, reduced to characters that are safe in
 * any comment or string: letters, digits, dot, dash, underscore.
 */
static void
put_scene(struct sink *s, const struct tmpl_ctx *c)
{
	for (const char *base = sys_base(c->r->source); *base != '\0';
	    base++) {
		unsigned char ch = (unsigned char)*base;
		int safe = (ch < 0x80 && isalnum(ch)) || strchr(".-_", ch);

		sink_putc(s, safe ? (char)ch : '_');
	}
}

static size_t
object_of(const struct tmpl_ctx *c)
{
	return c->scope == TS_ORGAN ? tmpl_organ(c)->object : c->object;
}

static void put_object(struct sink *s, const struct tmpl_ctx *c)
{ sink_puts(s, c->r->objects[object_of(c)]); }
static void put_object_index(struct sink *s, const struct tmpl_ctx *c)
{ sink_uint(s, object_of(c)); }

/* How many organs are this object. */
static void
put_object_organs(struct sink *s, const struct tmpl_ctx *c)
{
	sink_uint(s, (unsigned long long)result_object_organs(c->r,
	    object_of(c)));
}

/* "," between items of a block, nothing after the last. */
static void
put_comma(struct sink *s, const struct tmpl_ctx *c)
{
	size_t last = c->scope == TS_ORGAN ? c->r->count : c->r->nobjects;

	if ((c->scope == TS_ORGAN ? c->organ : c->object) + 1 < last)
		sink_putc(s, ',');
}

static void put_n(struct sink *s, const struct tmpl_ctx *c)
{ sink_uint(s, c->organ); }
static void put_t(struct sink *s, const struct tmpl_ctx *c)
{ sink_num(s, c->r->count > 1 ? (double)c->organ /
    (double)(c->r->count - 1) : 0); }

#define ORGAN_FIELD(fn, expr)						\
static void fn(struct sink *s, const struct tmpl_ctx *c)		\
{ const struct organ *o = tmpl_organ(c); sink_num(s, expr); }

ORGAN_FIELD(put_x, o->pos[0])
ORGAN_FIELD(put_y, o->pos[1])
ORGAN_FIELD(put_z, o->pos[2])
ORGAN_FIELD(put_ux, o->u[0])
ORGAN_FIELD(put_uy, o->u[1])
ORGAN_FIELD(put_uz, o->u[2])
/* v is not stored: organ_v() derives it, here as everywhere. */
#define ORGAN_V(fn, k)							\
static void fn(struct sink *s, const struct tmpl_ctx *c)		\
{ double v[3]; organ_v(tmpl_organ(c), v); sink_num(s, v[k]); }

ORGAN_V(put_vx, 0)
ORGAN_V(put_vy, 1)
ORGAN_V(put_vz, 2)
ORGAN_FIELD(put_wx, o->w[0])
ORGAN_FIELD(put_wy, o->w[1])
ORGAN_FIELD(put_wz, o->w[2])
ORGAN_FIELD(put_scale, o->scale)
ORGAN_FIELD(put_radius, o->radius)
ORGAN_FIELD(put_phi, o->phi)
ORGAN_FIELD(put_h, o->height)

#define ANY		(TS_GLOBAL | TS_OBJECT | TS_ORGAN)
#define ITEM		(TS_OBJECT | TS_ORGAN)

const struct tmpl_var tmpl_common[] = {
	{ "NAME", ANY, put_name, NULL },
	{ "COUNT", ANY, put_count, NULL },
	{ "MODEL", ANY, put_model, NULL },
	{ "DIVERGENCE", ANY, put_divergence, NULL },
	{ "SEED", ANY, put_seed, NULL },
	{ "VERSION", ANY, put_version, NULL },
	{ "SCENE", ANY, put_scene, NULL },
	{ "OBJECT_COUNT", ANY, put_object_count, NULL },
	{ "FRAME", ANY, put_frame, NULL },
	{ "FRAMES", ANY, put_frames, NULL },
	{ "FRAME_F", ANY, put_frame_f, NULL },
	{ "PART", ANY, put_part, NULL },
	{ "OBJECT", ITEM, put_object, NULL },
	{ "OBJECT_INDEX", ITEM, put_object_index, NULL },
	{ "OBJECT_ORGANS", ITEM, put_object_organs, NULL },
	{ "COMMA", ITEM, put_comma, NULL },
	{ "N", TS_ORGAN, put_n, NULL },
	{ "T", TS_ORGAN, put_t, NULL },
	{ "X", TS_ORGAN, put_x, NULL }, { "Y", TS_ORGAN, put_y, NULL },
	{ "Z", TS_ORGAN, put_z, NULL },
	{ "UX", TS_ORGAN, put_ux, NULL }, { "UY", TS_ORGAN, put_uy, NULL },
	{ "UZ", TS_ORGAN, put_uz, NULL },
	{ "VX", TS_ORGAN, put_vx, NULL }, { "VY", TS_ORGAN, put_vy, NULL },
	{ "VZ", TS_ORGAN, put_vz, NULL },
	{ "WX", TS_ORGAN, put_wx, NULL }, { "WY", TS_ORGAN, put_wy, NULL },
	{ "WZ", TS_ORGAN, put_wz, NULL },
	{ "SCALE", TS_ORGAN, put_scale, NULL },
	{ "RADIUS", TS_ORGAN, put_radius, NULL },
	{ "PHI", TS_ORGAN, put_phi, NULL },
	{ "H", TS_ORGAN, put_h, NULL },
	{ NULL, 0, NULL, NULL }
};
