/*
 * out_settings.c - --settings: every setting of the scene and of its
 * parts, as JSON, from the tables the loader checks them by: its path
 * (as --set takes it), type, value as written (or its default), where
 * it came from, default, range, choices, unit and the man page's one
 * line.  The Blender add-on builds its panel from this, and scripts may
 * read it; nothing is placed.
 *
 *	{ "scene": "sun.cfg", "name": "Sun", "model": "planar",
 *	  "parts": [ { "object": "Floret", "scene": "floret.cfg", ... } ],
 *	  "settings": [ { "path": "planar.scale", "type": "number",
 *	    "value": "0.04", "from": "file", "line": 4, "default": "1",
 *	    "min": 0, "min_open": true, "unit": "length",
 *	    "doc": "Vogel's c: ..." }, ... ] }
 *
 * A setting the scene's others leave unused is listed too, with
 * "applies": false and the loader's reason ("why"), given or not: the
 * panel greys it out and leaves it out of its --set, and finds which
 * apply after each change from this listing alone (a run with such a
 * setting given would be refused).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/compound.h"
#include "base/diag.h"
#include "writers/json.h"
#include "models/model.h"
#include "scene/settings.h"
#include "writers/writer.h"

static const struct written *
find_written(const struct scene *sc, const char *path)
{
	for (size_t i = 0; i < sc->nwritten; i++)
		if (strcmp(sc->written[i].path, path) == 0)
			return &sc->written[i];
	return NULL;
}

static void
key(struct sink *s, const char *k)
{
	sink_puts(s, ", ");
	json_string(s, k);
	sink_puts(s, ": ");
}

/*
 * The value a setting not given takes, in scene-file syntax, where the
 * table gives one (a number, a word, an expression); else NULL, as for
 * "none" or "per shape".
 */
static const char *
default_text(const struct scene *sc, const struct row *r, char *buf,
    size_t sz)
{
	const char *d = r->defstr != NULL ? r->defstr : "none";
	char *end;
	int number = (strtod(d, &end), *end == '\0' && end != d);

	switch (r->type) {
	case T_IDENT:
		snprintf(buf, sz, "\"%s\"", sc->name);
		return buf;
	case T_CHOICE:
		/* A choice may have no default: shape, where profile is. */
		if (strcmp(d, "none") == 0)
			return NULL;
		snprintf(buf, sz, "\"%s\"", r->words[(int)r->def]);
		return buf;
	case T_INT:
	case T_FLOAT:
		if (!number)
			return NULL;
		/* The table's own number: the man page's may be rounded. */
		for (int digits = 15; digits <= 17; digits++) {
			snprintf(buf, sz, "%.*g", digits, r->def);
			if (strtod(buf, NULL) == r->def)
				break;
		}
		return buf;
	case T_EXPR:
		if (strcmp(d, "none") == 0)
			return NULL;
		snprintf(buf, sz, number ? "%s" : "\"%s\"", d);
		return buf;
	case T_VEC3:
		/* A point found when not given (measured.centre): none. */
		if (d[0] != '[')
			return NULL;
		snprintf(buf, sz, "[%.15g.0, %.15g.0, %.15g.0]", r->def,
		    r->def, r->def);
		return buf;
	default:
		return NULL;
	}
}

static void
one(struct sink *s, const struct scene *sc, const char *object,
    const char *path, const struct row *r, const char *why, int *first)
{
	const struct written *w = find_written(sc, path);
	char full[PATH_LEN * 2 + NAME_LEN], def[96];
	const char *value = w != NULL ? w->text :
	    default_text(sc, r, def, sizeof(def));

	snprintf(full, sizeof(full), "%s%s%s", object, *object ? ":" : "",
	    path);
	sink_puts(s, *first ? "\n    { \"path\": " : ",\n    { \"path\": ");
	*first = 0;
	json_string(s, full);
	key(s, "type");
	json_string(s, settings_type(r));
	key(s, "value");
	if (value != NULL)
		json_string(s, value);
	else
		sink_puts(s, "null");
	key(s, "from");
	json_string(s, w == NULL ? "default" : w->line >= DIAG_LINE_SET ?
	    "set" : "file");
	if (w != NULL && w->line > 0 && w->line < DIAG_LINE_SET) {
		key(s, "line");
		json_number(s, w->line);
	}
	key(s, "default");
	json_string(s, r->defstr != NULL ? r->defstr : "none");
	if ((r->type == T_INT || r->type == T_FLOAT || r->type == T_EXPR ||
	    r->type == T_VEC3 || r->type == T_WEIGHTS || r->type == T_INTS) &&
	    (r->lo != 0 || r->hi != 0)) {
		if (isfinite(r->lo)) {
			key(s, "min");
			json_number(s, r->lo);
			if (r->flags & F_LO_OPEN) {
				key(s, "min_open");
				sink_puts(s, "true");
			}
		}
		if (isfinite(r->hi)) {
			key(s, "max");
			json_number(s, r->hi);
		}
	}
	if (r->words != NULL || r->type == T_MODEL) {
		key(s, "choices");
		sink_putc(s, '[');
		if (r->type == T_MODEL)
			for (const struct model *const *m = models; *m; m++) {
				sink_puts(s, m == models ? "" : ", ");
				json_string(s, (*m)->name);
			}
		else
			for (size_t i = 0; r->words[i] != NULL; i++) {
				sink_puts(s, i ? ", " : "");
				json_string(s, r->words[i]);
			}
		sink_putc(s, ']');
	}
	if (r->unit != NULL) {
		key(s, "unit");
		json_string(s, r->unit);
	}
	if (why != NULL) {
		char text[192];

		key(s, "applies");
		sink_puts(s, "false");
		key(s, "why");
		snprintf(text, sizeof(text), "does not apply %s", why);
		json_string(s, text);
	}
	key(s, "doc");
	json_string(s, r->doc != NULL ? r->doc : "");
	sink_puts(s, " }");
}

/*
 * A table's rows at prefix, into its groups; why (or NULL): the reason
 * the group does not apply, which its rows share.
 */
static void
rows(struct sink *s, const struct scene *sc, const char *object,
    const char *prefix, const struct table *tab, const char *why,
    int *first)
{
	char path[PATH_LEN * 2], own[160];

	for (size_t i = 0; i < tab->n; i++) {
		const struct row *r = &tab->rows[i];
		const char *w = why;

		snprintf(path, sizeof(path), "%s%s%s", prefix, *prefix ? "." :
		    "", r->name);
		if (w == NULL && !scene_applies(sc, tab, i, own, sizeof(own)))
			w = own;
		if (r->type == T_GROUP)
			rows(s, sc, object, path, r->sub, w, first);
		else if (r->type != T_RANGES)
			one(s, sc, object, path, r, w, first);
	}
}

/* The top level, the model's group, then each organs entry. */
static void
scene_settings(struct sink *s, const struct scene *sc, const char *object,
    int *first)
{
	char prefix[PATH_LEN];

	rows(s, sc, object, "", &scene_table, NULL, first);
	rows(s, sc, object, sc->model->name, sc->model->settings, NULL,
	    first);
	for (size_t i = 0; i < sc->nranges; i++) {
		snprintf(prefix, sizeof(prefix), "organs.%zu", i);
		rows(s, sc, object, prefix, &range_table, NULL, first);
	}
}

int
settings_write(struct sink *s, const struct compound *c,
    const struct override *set, int nset)
{
	const struct part *main = c->parts[c->n - 1];
	int first = 1;

	(void)set;
	(void)nset;
	sink_puts(s, "{ \"scene\": ");
	json_string(s, main->sc.file);
	sink_puts(s, ", \"name\": ");
	json_string(s, main->sc.name);
	sink_puts(s, ", \"model\": ");
	json_string(s, main->sc.model->name);
	sink_puts(s, ",\n  \"parts\": [");
	for (size_t i = 0; i + 1 < c->n; i++) {
		sink_puts(s, i ? ",\n    { \"object\": " : "\n    { \"object\": ");
		json_string(s, c->parts[i]->object);
		sink_puts(s, ", \"scene\": ");
		json_string(s, c->parts[i]->file);
		sink_puts(s, ", \"model\": ");
		json_string(s, c->parts[i]->sc.model->name);
		sink_puts(s, " }");
	}
	sink_puts(s, c->n > 1 ? "\n  ],\n  \"settings\": [" :
	    "],\n  \"settings\": [");
	scene_settings(s, &main->sc, "", &first);
	for (size_t i = 0; i + 1 < c->n; i++)
		scene_settings(s, &c->parts[i]->sc, c->parts[i]->object,
		    &first);
	sink_puts(s, "\n  ]\n}\n");
	return 0;
}
