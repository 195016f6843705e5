/*
 * out_pov.c - POV-Ray include files.  The layout comes from a template
 * (templates/pov.tmpl); this file gives the placeholders in POV-Ray's
 * terms.  POV-Ray is Y up and left-handed, so a point (x, y, z) of our
 * frame is <x, z, y> there, and so is every frame axis; the organ's
 * local +x is u, +y is w (up) and +z is v.  With the swap the three
 * rows form a rotation again (determinant +1): organs are not mirrored.
 */
#include <math.h>
#include <string.h>

#include "base/diag.h"
#include "writers/povwords.h"
#include "writers/writer.h"

static void
vec(struct sink *s, const double a[3], double k)
{
	sink_putc(s, '<');
	sink_num(s, a[0] * k);
	sink_puts(s, ", ");
	sink_num(s, a[2] * k);
	sink_puts(s, ", ");
	sink_num(s, a[1] * k);
	sink_putc(s, '>');
}

/* matrix <u*s, w*s, v*s, pos>, each in POV-Ray's axes. */
static void
put_matrix(struct sink *s, const struct tmpl_ctx *c)
{
	const struct organ *o = tmpl_organ(c);
	double v[3];
	const double *rows[4] = { o->u, o->w, v, o->pos };

	organ_v(o, v);
	sink_putc(s, '<');
	for (int i = 0; i < 4; i++) {
		double k = i < 3 ? o->scale : 1;

		sink_num(s, rows[i][0] * k);
		sink_puts(s, ", ");
		sink_num(s, rows[i][2] * k);
		sink_puts(s, ", ");
		sink_num(s, rows[i][1] * k);
		sink_puts(s, i < 3 ? ",  " : "");
	}
	sink_putc(s, '>');
}

static void put_pos(struct sink *s, const struct tmpl_ctx *c)
{ vec(s, tmpl_organ(c)->pos, 1); }
static void put_u(struct sink *s, const struct tmpl_ctx *c)
{ vec(s, tmpl_organ(c)->u, 1); }
static void
put_v(struct sink *s, const struct tmpl_ctx *c)
{
	double v[3];

	organ_v(tmpl_organ(c), v);
	vec(s, v, 1);
}
static void put_w(struct sink *s, const struct tmpl_ctx *c)
{ vec(s, tmpl_organ(c)->w, 1); }

/* The placeholders' colour of an organ object, its OBJECT_HUE. */
static void
put_colour(struct sink *s, const struct tmpl_ctx *c)
{
	double h = OBJECT_HUE(c->object) / 60;
	double rgb[3], x = 1 - fabs(fmod(h, 2) - 1);
	int k = (int)h;

	rgb[0] = k == 0 || k == 5 ? 1 : k == 1 || k == 4 ? x : 0;
	rgb[1] = k == 1 || k == 2 ? 1 : k == 0 || k == 3 ? x : 0;
	rgb[2] = k == 3 || k == 4 ? 1 : k == 2 || k == 5 ? x : 0;
	for (int i = 0; i < 3; i++)
		rgb[i] = 0.25 + 0.7 * rgb[i];
	sink_puts(s, "rgb <");
	for (int i = 0; i < 3; i++) {
		sink_num(s, rgb[i]);
		sink_puts(s, i < 2 ? ", " : ">");
	}
}

const struct tmpl_var pov_vars[] = {
	{ "MATRIX", TS_ORGAN, put_matrix, NULL },
	{ "POS", TS_ORGAN, put_pos, NULL },
	{ "U", TS_ORGAN, put_u, NULL },
	{ "V", TS_ORGAN, put_v, NULL },
	{ "W", TS_ORGAN, put_w, NULL },
	{ "COLOR", TS_OBJECT | TS_ORGAN, put_colour, NULL },
	{ NULL, 0, NULL, NULL }
};

/* Names POV-Ray would read as its own words. */
int
pov_check(const struct scene *sc)
{
	if (pov_reserved(sc->name)) {
		scene_error(sc, sc->given[S_NAME], "name \"%s\" is a POV-Ray "
		    "reserved word; capitalise it", sc->name);
		return -1;
	}
	for (size_t i = 0; i < sc->nranges; i++)
		for (size_t k = 0; k < sc->ranges[i].nnames; k++) {
			const char *o = sc->ranges[i].names[k];

			if (pov_reserved(o)) {
				diag(ST_SCENE, sc->file, sc->ranges[i].at.line,
				    0, "organ object \"%s\" is a POV-Ray "
				    "reserved word; capitalise it", o);
				return -1;
			}
		}
	return 0;
}
