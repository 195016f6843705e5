/*
 * scene.c - a scene file loaded as a whole: read, parsed with libconfig,
 * walked from its root (the model first, then every setting against its
 * table: scene_tables.c, scene_values.c), its organ objects collected;
 * and freed.  The first error ends the load.
 */
#include <ctype.h>
#include <errno.h>
#include <libconfig.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "scene/cfgtext.h"
#include "base/diag.h"
#include "base/mem.h"
#include "models/model.h"
#include "scene/load.h"
#include "scene/override.h"
#include "scene/scene.h"
#include "base/table.h"

/*
 * The default name: the file's base name made into an identifier and
 * capitalised, because every POV-Ray keyword is lowercase ("cone.cfg"
 * must not declare "cone").
 */
static void
name_from_file(char *dst, const char *file)
{
	const char *base = sys_base(file);
	size_t len = strcspn(base, ".");

	if (len > NAME_LEN)
		len = NAME_LEN;
	if (len == 0 || !isalpha((unsigned char)base[0]) ||
	    (base[0] & 0x80) || strcmp(file, "<stdin>") == 0) {
		strcpy(dst, "Phyllotaxis");
		return;
	}
	for (size_t i = 0; i < len; i++) {
		unsigned char c = (unsigned char)base[i];

		dst[i] = (char)(isalnum(c) && !(c & 0x80) ? c : '_');
	}
	dst[0] = (char)toupper((unsigned char)dst[0]);
	dst[len] = '\0';
}

/* "made of floret.cfg" or "a plain object", for messages. */
static void
scene_words(char *buf, size_t sz, const char *file)
{
	char q[SCENE_PATH_MAX + 8];

	if (file == NULL) {
		snprintf(buf, sz, "a plain object");
		return;
	}
	cfgtext_quote(q, sizeof(q), file);
	snprintf(buf, sz, "made of \"%s\"", q);
}

/* Whether two entries' scene files for one object agree (NULL: none). */
static int
same_scene(const char *a, const char *b)
{
	return a == NULL || b == NULL ? a == b : strcmp(a, b) == 0;
}

/*
 * Object j's mesh from variant k of entry rg, when it gives one: any
 * entry naming the object may, and those that do name one file.
 */
static int
set_mesh(struct load *L, const struct organ_range *rg, size_t k, size_t j)
{
	struct scene *sc = L->sc;
	const char *mesh = rg->meshes.v != NULL ? rg->meshes.v[k] : NULL;
	char here[SCENE_PATH_MAX + 8], there[SCENE_PATH_MAX + 8];

	if (mesh == NULL)
		return 0;
	if (sc->object_mesh[j] == NULL) {
		sc->object_mesh[j] = mesh;
		sc->object_mesh_line[j] = rg->given[RG_MESH];
		return 0;
	}
	if (strcmp(sc->object_mesh[j], mesh) == 0)
		return 0;
	cfgtext_quote(here, sizeof(here), mesh);
	cfgtext_quote(there, sizeof(there), sc->object_mesh[j]);
	diag(ST_SCENE, L->file, rg->given[RG_MESH], 0, "organ object \"%s\" "
	    "has mesh \"%s\" here but \"%s\" on line %d: one name, one thing",
	    rg->names[k], here, there, sc->object_mesh_line[j]);
	return -1;
}

/*
 * Collect the distinct organ object names and number the variants.  An
 * object may not carry the scene's name: both name things in one
 * namespace of POV-Ray and of Blender.
 */
static int
collect_objects(struct load *L)
{
	static const char *const fallback = "Organ";
	struct scene *sc = L->sc;
	size_t total = 0;

	for (size_t i = 0; i < sc->nranges; i++)
		total += sc->ranges[i].nnames;
	sc->objects = xcalloc(total + 1, sizeof(*sc->objects));
	sc->object_scene = xcalloc(total + 1, sizeof(*sc->object_scene));
	sc->object_line = xcalloc(total + 1, sizeof(*sc->object_line));
	sc->object_mesh = xcalloc(total + 1, sizeof(*sc->object_mesh));
	sc->object_mesh_line = xcalloc(total + 1,
	    sizeof(*sc->object_mesh_line));
	for (size_t i = 0; i < sc->nranges; i++) {
		struct organ_range *rg = &sc->ranges[i];

		rg->ids = xcalloc(rg->nnames, sizeof(*rg->ids));
		for (size_t k = 0; k < rg->nnames; k++) {
			size_t j;

			if (strcmp(rg->names[k], sc->name) == 0) {
				diag(ST_SCENE, L->file, rg->at.line, 0, "organ "
				    "object \"%s\" has the scene's name",
				    sc->name);
				return -1;
			}
			for (j = 0; j < sc->nobjects; j++)
				if (strcmp(sc->objects[j], rg->names[k]) == 0)
					break;
			if (j == sc->nobjects) {
				sc->objects[sc->nobjects] = rg->names[k];
				sc->object_scene[sc->nobjects] = rg->scenes.v ?
				    rg->scenes.v[k] : NULL;
				sc->object_line[sc->nobjects++] = rg->at.line;
			} else if (!same_scene(sc->object_scene[j],
			    rg->scenes.v ? rg->scenes.v[k] : NULL)) {
				char here[SCENE_PATH_MAX + 32];
				char there[SCENE_PATH_MAX + 32];

				scene_words(here, sizeof(here), rg->scenes.v ?
				    rg->scenes.v[k] : NULL);
				scene_words(there, sizeof(there),
				    sc->object_scene[j]);
				diag(ST_SCENE, L->file, rg->at.line, 0, "organ "
				    "object \"%s\" is %s here but %s on line "
				    "%d: one name, one thing", rg->names[k],
				    here, there, sc->object_line[j]);
				return -1;
			}
			rg->ids[k] = (unsigned)j;
			if (set_mesh(L, rg, k, j) != 0)
				return -1;
		}
	}
	if (sc->nobjects == 0)
		sc->objects[sc->nobjects++] = fallback;
	return 0;
}

static int
load_root(struct load *L, const config_setting_t *root)
{
	struct scene *sc = L->sc;
	const config_setting_t *m = config_setting_get_member(root, "model");
	const struct model *model;

	if (m == NULL) {
		const char *words[MODELS_MAX + 1];
		char list[256];

		load_model_names(words);
		load_words_join(list, sizeof(list), words);
		diag(ST_SCENE, L->file, 1, 0, "missing setting 'model' "
		    "(one of: %s)", list);
		return -1;
	}
	sc->given[S_MODEL] = load_line(m);
	if (load_model(L, m, "model", &sc->model) < 0)
		return -1;
	if (L->record)
		load_record(L, m);
	model = sc->model;
	sc->params = xcalloc(1, model->size);
	load_defaults(model->settings, sc->params);
	load_paths(model->settings, sc->params, model->name);
	if (load_group(L, root, "", &scene_table, sc) < 0 ||
	    (!L->listing && load_check_applies(L) < 0))
		return -1;
	sc->at.line = 1;
	if (!sc->given[S_NAME])
		name_from_file(sc->name, L->file);
	return collect_objects(L);
}

int
scene_load_buffer(struct scene *sc, const char *file, const char *text,
    size_t len)
{
	return scene_load_buffer_as(sc, file, text, len, "", NULL);
}

int
scene_load_buffer_as(struct scene *sc, const char *file, const char *text,
    size_t len, const char *object, const struct loading *ld)
{
	const struct frame *fr = ld != NULL ? ld->frame : NULL;
	struct load L = { .sc = sc, .file = file, .text = text, .len = len,
	    .consts = { { "f", 0 }, { "F", 1 }, { NULL, 0 } },
	    .object = object };
	config_t cfg;
	char *ready;
	int rc = -1, nul_line;

	*sc = (struct scene){ .file = file };
	if (fr != NULL) {
		L.consts[0].value = fr->count > 1 ?
		    (double)(fr->number - 1) / (fr->count - 1) : 0;
		L.consts[1].value = fr->number;
	}
	sc->frame_f = L.consts[0].value;
	sc->frame_no = (int)L.consts[1].value;
	load_defaults(&scene_table, sc);

	if ((ready = cfgtext_prepare(text, len, &nul_line)) == NULL) {
		diag(ST_SCENE, file, nul_line, 0, "NUL byte in scene file");
		return -1;
	}
	config_init(&cfg);
	if (config_read_string(&cfg, ready) != CONFIG_TRUE) {
		const char *f = config_error_file(&cfg);
		const char *why = config_error_text(&cfg);

		/* Bison says this when nesting overflows its stack. */
		if (strcmp(why, "memory exhausted") == 0)
			why = "groups or lists nested too deeply";
		/* libconfig arrays hold one type: [1, 0.5] mixes two. */
		else if (strcmp(why, "mismatched element type in array") == 0)
			why = "mismatched element type in array: write its "
			    "numbers all alike, [1.0, 0.5] not [1, 0.5], or "
			    "use a list, (1, 0.5)";
		diag(ST_SCENE, f != NULL ? f : file,
		    config_error_line(&cfg), 0, "%s", why);
	} else if (ld == NULL || override_apply(config_root_setting(&cfg),
	    ld->set, ld->nset, object) == 0) {
		L.record = ld != NULL && ld->record;
		L.listing = ld != NULL && ld->listing;
		L.overridden = ld != NULL && ld->nset > 0;
		rc = load_root(&L, config_root_setting(&cfg));
		if (rc == 0 && L.record) {
			sc->text = xmalloc(len + 1);
			memcpy(sc->text, text, len);
			sc->text[len] = '\0';
			sc->len = len;
		}
	}
	free(ready);
	config_destroy(&cfg);
	/* Names were copied into the scene, so nothing points into cfg. */
	return rc;
}

int
scene_load(struct scene *sc, const char *path)
{
	return scene_load_as(sc, path, "", NULL);
}

/* Load from a path, "-" meaning standard input. */
int
scene_load_as(struct scene *sc, const char *path, const char *object,
    const struct loading *ld)
{
	const char *file = strcmp(path, "-") == 0 ? "<stdin>" : path;
	FILE *fp = strcmp(path, "-") == 0 ? stdin : sys_fopen(path, "rb");
	char *text = NULL;
	size_t len = 0, cap = 0, got;
	int rc;

	if (fp == NULL) {
		diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		*sc = (struct scene){ .file = file };
		return -1;
	}
	do {
		if (cap - len < 65536)
			text = xreallocarray(text, cap = cap * 2 + 65536, 1);
		got = fread(text + len, 1, cap - len - 1, fp);
		len += got;
	} while (got > 0 && len <= (size_t)SCENE_BYTES_MAX);
	if (ferror(fp) || len > (size_t)SCENE_BYTES_MAX) {
		if (ferror(fp))
			diag(ST_SYSTEM, file, 0, 0, "%s", strerror(errno));
		else
			diag(ST_SCENE, file, 0, 0, "scene file is larger "
			    "than %ld bytes", SCENE_BYTES_MAX);
		if (fp != stdin)
			fclose(fp);
		free(text);
		*sc = (struct scene){ .file = file };
		return -1;
	}
	if (fp != stdin)
		fclose(fp);
	text[len] = '\0';
	rc = scene_load_buffer_as(sc, file, text, len, object, ld);
	free(text);
	return rc;
}

void
scene_free(struct scene *sc)
{
	for (size_t i = 0; i < sc->nranges; i++) {
		struct organ_range *rg = &sc->ranges[i];

		load_free_settings(scene_table.rows[S_ORGANS].sub, rg);
		free(rg->names);
		free(rg->ids);
		free(rg->weights);
		for (size_t k = 0; k < rg->scenes.n; k++)
			free(rg->scenes.v[k]);
		free(rg->scenes.v);
		for (size_t k = 0; k < rg->meshes.n; k++)
			free(rg->meshes.v[k]);
		free(rg->meshes.v);
	}
	free(sc->ranges);
	if (sc->params != NULL)
		load_free_settings(sc->model->settings, sc->params);
	free(sc->params);
	free(sc->objects);
	free(sc->object_scene);
	free(sc->object_line);
	for (size_t i = 0; i < sc->nwritten; i++) {
		free(sc->written[i].path);
		free(sc->written[i].text);
	}
	free(sc->written);
	free(sc->text);
	free(sc->object_mesh);
	free(sc->object_mesh_line);
	*sc = (struct scene){0};
}

/* An error found after loading (by a model's checks), at line. */
void
scene_error(const struct scene *sc, int line, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	settings_verror(sc->file, line, fmt, ap);
	va_end(ap);
}
