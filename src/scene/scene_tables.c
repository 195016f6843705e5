/*
 * scene_tables.c - a settings table walked over the struct it describes:
 * defaults, paths and freeing; a group's members read, an unknown name
 * answered with the nearest known one; the organs entries; and each
 * setting kept as written, for --settings.
 */
#include <libconfig.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/cfgtext.h"
#include "base/diag.h"
#include "base/mem.h"
#include "models/model.h"
#include "scene/load.h"
#include "scene/scene.h"
#include "base/table.h"
#include "scene/suggest.h"

static struct group_at *
at_of(const struct table *tab, void *base)
{
	return (struct group_at *)((char *)base + tab->at);
}

static int *
given_of(const struct table *tab, void *base)
{
	return (int *)((char *)base + tab->given);
}

/* Numbers and choices take their defaults, in nested groups too. */
void
load_defaults(const struct table *tab, void *base)
{
	for (size_t i = 0; i < tab->n; i++) {
		const struct row *r = &tab->rows[i];
		char *dst = (char *)base + r->off;

		if (r->type == T_INT)
			*(long long *)dst = (long long)r->def;
		else if (r->type == T_FLOAT)
			*(double *)dst = r->def;
		else if (r->type == T_CHOICE)
			*(int *)dst = (int)r->def;
		else if (r->type == T_VEC3)
			for (int k = 0; k < 3; k++)
				((double *)dst)[k] = r->def;
		else if (r->type == T_GROUP)
			load_defaults(r->sub, dst);
	}
}

/*
 * Name the struct base described by tab path, and its nested groups
 * path.name: where they are not written, a message about them still
 * says where ("give area.receptacle.profile or ...").
 */
void
load_paths(const struct table *tab, void *base, const char *path)
{
	snprintf(at_of(tab, base)->path, PATH_LEN, "%s", path);
	for (size_t i = 0; i < tab->n; i++) {
		const struct row *r = &tab->rows[i];
		char sub[PATH_LEN];

		if (r->type != T_GROUP)
			continue;
		/* A group's path past PATH_LEN is a programming error (tables). */
		if (snprintf(sub, sizeof(sub), "%s.%s", path, r->name) >=
		    (int)sizeof(sub))
			abort();
		load_paths(r->sub, (char *)base + r->off, sub);
	}
}

/* Free what the settings of a struct own, in nested groups too. */
void
load_free_settings(const struct table *tab, void *base)
{
	for (size_t i = 0; i < tab->n; i++) {
		const struct row *r = &tab->rows[i];
		char *dst = (char *)base + r->off;

		if (r->type == T_EXPR)
			expr_free(((struct expr_setting *)dst)->e);
		else if (r->type == T_POINTS)
			free(((struct point_list *)dst)->p);
		else if (r->type == T_FILES) {
			/* Emptied: scene_free() frees an entry's again. */
			struct file_list *fl = (struct file_list *)dst;

			for (size_t k = 0; k < fl->n; k++)
				free(fl->v[k]);
			free(fl->v);
			fl->v = NULL;
			fl->n = 0;
		} else if (r->type == T_GROUP)
			load_free_settings(r->sub, dst);
	}
}

/* An entry's scene or mesh files: one for each of its objects. */
static int
files_per_name(const struct load *L, const struct organ_range *rg,
    const struct file_list *fl, int id, const char *path, const char *name)
{
	if (fl->v == NULL || fl->n == rg->nnames)
		return 0;
	diag(ST_SCENE, L->file, rg->given[id], 0, "%s.%s lists %zu file%s "
	    "for %zu objects: one each", path, name, fl->n, fl->n == 1 ? "" :
	    "s", rg->nnames);
	return -1;
}

int
load_ranges(struct load *L, const config_setting_t *s, const char *path,
    const struct table *tab)
{
	struct scene *sc = L->sc;
	int n = config_setting_length(s);

	if (config_setting_type(s) != CONFIG_TYPE_LIST) {
		load_err_at(L, s, "%s must be a list of groups: "
		    "%s = ( { object = \"Seed\"; } );", path, path);
		return -1;
	}
	if (n > RANGES_MAX) {
		load_err_at(L, s, "%s has more than %d entries", path,
		    RANGES_MAX);
		return -1;
	}
	sc->ranges = xcalloc((size_t)n, sizeof(*sc->ranges));
	for (int i = 0; i < n; i++) {
		config_setting_t *e = config_setting_get_elem(s, (unsigned)i);
		struct organ_range *rg = &sc->ranges[i];

		if (!config_setting_is_group(e)) {
			load_err_at(L, e, "%s entry %d must be a group "
			    "{ object = \"Seed\"; ... }", path, i + 1);
			return -1;
		}
		sc->nranges++;
		load_defaults(tab, rg);
		if (load_group(L, e, path, tab, rg) < 0)
			return -1;
		if (rg->names == NULL) {
			rg->names = xcalloc(1, sizeof(*rg->names));
			strcpy(rg->names[0], "Organ");
			rg->nnames = 1;
		}
		if (files_per_name(L, rg, &rg->scenes, RG_SCENE, path,
		    "scene") != 0 || files_per_name(L, rg, &rg->meshes,
		    RG_MESH, path, "mesh") != 0)
			return -1;
		for (size_t k = 0; rg->scenes.v != NULL &&
		    rg->meshes.v != NULL && k < rg->nnames; k++) {
			diag(ST_SCENE, L->file, rg->given[RG_MESH], 0,
			    "%s.mesh: organ object \"%s\" is made of a scene, "
			    "whose own organs have the meshes", path,
			    rg->names[k]);
			return -1;
		}
	}
	return 0;
}

/* Keep setting s as written: its whole path, and its value as text. */
void
load_record(struct load *L, const config_setting_t *s)
{
	struct scene *sc = L->sc;
	char path[PATH_LEN * 2] = "", part[PATH_LEN * 2];

	for (const config_setting_t *p = s; config_setting_parent(p) != NULL;
	    p = config_setting_parent(p)) {
		int n = config_setting_name(p) != NULL ?
		    snprintf(part, sizeof(part), "%s%s%s",
		    config_setting_name(p), *path ? "." : "", path) :
		    snprintf(part, sizeof(part), "%d%s%s",
		    config_setting_index(p), *path ? "." : "", path);

		/* Longer than any setting's path (PATH_LEN): its tail will do. */
		if (n < 0 || (size_t)n >= sizeof(part))
			break;
		memcpy(path, part, sizeof(path));
	}
	sc->written = xreallocarray(sc->written, sc->nwritten + 1,
	    sizeof(*sc->written));
	sc->written[sc->nwritten++] = (struct written){ xstrdup(path),
	    cfgtext_value(s), load_line(s), 0 };
}

static int
load_setting(struct load *L, const config_setting_t *s, const char *path,
    const struct row *r, void *base)
{
	int rc = load_setting_as(L, s, path, r, base);

	if (rc == 0 && L->record && r->type != T_GROUP && r->type != T_RANGES)
		load_record(L, s);
	return rc;
}

/*
 * "unknown setting 'planar.scael' (did you mean planar.scale?)": the
 * nearest of the group's names, and at the top level of the models'.
 */
static void
unknown(const struct load *L, const config_setting_t *s,
    const struct table *tab, const char *path, const char *sub)
{
	const char *words[64 + MODELS_MAX];
	const char *near;
	size_t n = 0;

	for (size_t k = 0; k < tab->n && n < 64; k++)
		words[n++] = tab->rows[k].name;
	for (const struct model *const *m = models; tab == &scene_table &&
	    *m != NULL; m++)
		words[n++] = (*m)->name;
	near = suggest(config_setting_name(s), words, n);
	load_err_at(L, s, "unknown setting '%s'%s%s%s%s%s", sub,
	    near ? " (did you mean " : "", near ? path : "",
	    near && *path ? "." : "", near ? near : "", near ? "?)" : "");
}

int
scene_applies(const struct scene *sc, const struct table *tab, size_t k,
    char *why, size_t sz)
{
	const char *w = NULL;

	if (tab == &scene_table && k == S_DIVERGENCE && sc->model->emerges)
		snprintf(why, sz, "to model \"%s\", whose angle %s",
		    sc->model->name, sc->model->counts_itself ? "is measured" :
		    "emerges");
	else if (tab == &scene_table && k == S_COUNT &&
	    sc->model->counts_itself && sc->model->count_else != NULL)
		snprintf(why, sz, "to model \"%s\", which reads its organs "
		    "from %s.%s", sc->model->name, sc->model->name,
		    sc->model->count_else);
	else if (tab == &scene_table && k == S_COUNT && sc->model->counts_itself)
		snprintf(why, sz, "to model \"%s\", whose organs are its "
		    "input's", sc->model->name);
	else if (tab == sc->model->settings && sc->model->unused != NULL &&
	    (w = sc->model->unused(sc->params, k)) != NULL)
		snprintf(why, sz, "%s", w);
	else
		return 1;
	return 0;
}

/*
 * Whether the file loads as it is, without the --set given with it:
 * then each setting it gives applies there, and one left unused now
 * was made so by a --set.  Tried with the messages hushed.
 */
static int
file_alone_loads(const struct load *L)
{
	struct scene alone;
	int ok;

	diag_hush(1);
	ok = scene_load_buffer_as(&alone, L->file, L->text, L->len,
	    L->object, NULL) == 0;
	scene_free(&alone);
	diag_hush(0);
	return ok;
}

/*
 * A setting given that the scene's other settings leave unused, an
 * error as a setting of another model is ("'inhibition.exponent' does
 * not apply with inhibition.kernel \"gaussian\", ..."): ignored, it
 * would pass for obeyed.  But where the file gives it, and the file
 * alone loads (so a --set made it unused), it is ignored with a
 * warning: --set switches the kernel of a file that gives an exponent
 * without the file being edited (the Blender panel's menus do so).
 * Where the scene is kept as written (--cfg), the main scene's is
 * marked to be taken out of the file written, which would not load
 * with it (the panel's Save after such a switch); a part's file is not
 * written.  0, 1 to drop it, or -1 after the error.
 */
static int
unused_given(struct load *L, int line, const char *what, const char *why)
{
	if (L->overridden && L->alone == 0)	/* once a load */
		L->alone = file_alone_loads(L) ? 1 : -1;
	if (line >= DIAG_LINE_SET || !L->overridden || L->alone < 0) {
		diag(ST_SCENE, L->file, line, 0, "'%s' does not apply %s", what,
		    why);
		return -1;
	}
	if (L->record && *L->object == '\0') {
		struct scene *sc = L->sc;
		size_t i = 0;

		while (i < sc->nwritten && strcmp(sc->written[i].path,
		    what) != 0)
			i++;
		if (i < sc->nwritten) {
			sc->written[i].dropped = 1;
			diag(ST_OK, L->file, line, 0, "'%s' does not apply %s, "
			    "as --set makes it: taken out of the file "
			    "written", what, why);
			return 1;
		}
	}
	if (L->record) {
		diag(ST_SCENE, L->file, line, 0, "'%s' does not apply %s, as "
		    "--set makes it, and the file written would not load: "
		    "take it out of the file first", what, why);
		return -1;
	}
	/* Once, not again for each frame. */
	if (L->sc->frame_no <= 1)
		diag(ST_OK, L->file, line, 0, "'%s' does not apply %s, as "
		    "--set made it: ignored", what, why);
	return 1;
}

int
load_check_applies(struct load *L)
{
	struct scene *sc = L->sc;
	const struct model *m = sc->model;
	int *given = (int *)((char *)sc->params + m->settings->given);
	char why[160], what[PATH_LEN * 2];

	for (int k = S_DIVERGENCE; k <= S_COUNT; k++)
		if (sc->given[k] && !scene_applies(sc, &scene_table, (size_t)k,
		    why, sizeof(why))) {
			if (unused_given(L, sc->given[k],
			    scene_table.rows[k].name, why) < 0)
				return -1;
			sc->given[k] = 0;
		}
	for (size_t k = 0; k < m->settings->n; k++)
		if (given[k] && !scene_applies(sc, m->settings, k, why,
		    sizeof(why))) {
			snprintf(what, sizeof(what), "%s.%s", m->name,
			    m->settings->rows[k].name);
			if (unused_given(L, given[k], what, why) < 0)
				return -1;
			given[k] = 0;
		}
	return 0;
}

/*
 * The members of group g, the struct base described by tab, at path.
 * At the top level, a model's name opens that model's group.
 */
int
load_group(struct load *L, const config_setting_t *g, const char *path,
    const struct table *tab, void *base)
{
	struct group_at *at = at_of(tab, base);
	int n = config_setting_length(g);

	at->line = load_line(g) > 0 ? load_line(g) : 1;
	snprintf(at->path, sizeof(at->path), "%s", path);
	for (int i = 0; i < n; i++) {
		config_setting_t *s = config_setting_get_elem(g, (unsigned)i);
		const char *name = config_setting_name(s);
		const struct model *m;
		char sub[PATH_LEN];
		size_t k;

		/* The model is known before its settings are checked. */
		if (tab == &scene_table && strcmp(name, "model") == 0)
			continue;
		snprintf(sub, sizeof(sub), "%s%s%s", path, *path ? "." : "",
		    name);
		for (k = 0; k < tab->n; k++)
			if (strcmp(tab->rows[k].name, name) == 0)
				break;
		if (k < tab->n) {
			given_of(tab, base)[k] = load_line(s);
			if (load_setting(L, s, sub, &tab->rows[k], base) < 0)
				return -1;
			continue;
		}
		m = tab == &scene_table ? model_find(name) : NULL;
		if (m == NULL) {
			unknown(L, s, tab, path, sub);
			return -1;
		}
		if (m != L->sc->model) {
			load_err_at(L, s, "'%s' does not apply to model \"%s\"",
			    sub, L->sc->model->name);
			return -1;
		}
		if (!config_setting_is_group(s)) {
			load_err_at(L, s, "%s must be a group: %s = { ... };",
			    sub, sub);
			return -1;
		}
		if (load_group(L, s, sub, m->settings, L->sc->params) < 0)
			return -1;
	}
	return 0;
}
