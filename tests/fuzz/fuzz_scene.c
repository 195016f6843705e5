/*
 * fuzz_scene.c - libFuzzer harness for the whole scene path: bytes ->
 * scene (and the scenes it includes) -> model -> organs -> every
 * writer, into memory.  The input is written to a file in a directory
 * that also holds three parts it may name, part.cfg, nested.cfg (which
 * names part.cfg) and deep.cfg (which names nested.cfg), and is loaded
 * as frame 2 of 3, so f and F are live.  Each writer's size estimate is
 * made too, and the Blender script is written in the pieces --frames
 * writes it in, its parts opened as views; and first listed as
 * --settings loads and lists it.
 * Scenes that ask for more than 20,000 organs, or leave the count to the
 * model, are loaded and checked but not run, to keep each input fast;
 * the limits themselves have their own tests.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "pipeline/pipeline.h"
#include "scene/compound.h"
#include "result/flatten.h"
#include "models/model.h"
#include "writers/plan.h"
#include "scene/scene.h"
#include "writers/writer.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char dir[] = "/tmp/phyllo-fuzz-XXXXXX";
static char path[64];

static void
put(const char *name, const char *text)
{
	char p[64];
	FILE *fp;

	snprintf(p, sizeof(p), "%s/%s", dir, name);
	if ((fp = fopen(p, "w")) == NULL || fputs(text, fp) < 0 ||
	    fclose(fp) != 0)
		abort();
}

static void
setup(void)
{
	if (path[0] != '\0')
		return;
	if (mkdtemp(dir) == NULL)
		abort();
	put("part.cfg", "model = \"planar\";\ncount = \"3 + F\";\n"
	    "organs = ( { object = \"Bud\"; tilt = \"30 * f\"; } );\n");
	put("nested.cfg", "model = \"planar\";\ncount = 4;\n"
	    "organs = ( { object = \"Part\"; scene = \"part.cfg\"; } );\n");
	put("deep.cfg", "model = \"planar\";\ncount = \"2 + F\";\n"
	    "organs = ( { object = \"Stem\"; to = 0; }, { object = \"Nest\";"
	    " scene = \"nested.cfg\"; from = 1; } );\n");
	snprintf(path, sizeof(path), "%s/fuzz.cfg", dir);
}

/* Whether every scene of c is small enough to run. */
static int
small(const struct compound *c)
{
	for (size_t i = 0; i < c->n; i++) {
		const struct scene *sc = &c->parts[i]->sc;

		/*
		 * Without count a model finds its own (cylindrical.length,
		 * the collision model's bound of a million): too slow.
		 */
		if (!sc->given[S_COUNT] || sc->count > 20000)
			return 0;
		/* The inhibition model's primordia cost a sum each: fewer. */
		if (strcmp(sc->model->name, "inhibition") == 0 &&
		    sc->count > 2000)
			return 0;
	}
	return 1;
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct frame fr = { 2, 3 };
	struct loading ld = { .frame = &fr, .record = 1 };
	struct loading listing = { .record = 1, .listing = 1 };
	struct compound c;
	struct result merged;
	const struct result *all[2];
	struct tmpl *t;
	struct sink s;
	FILE *fp;

	setup();
	if ((fp = fopen(path, "wb")) == NULL ||
	    fwrite(data, 1, size, fp) != size || fclose(fp) != 0)
		abort();
	/* As --settings loads and lists it: settings left unused kept. */
	if (compound_load(&c, path, &listing, NULL) == 0) {
		sink_init(&s, NULL);
		settings_write(&s, &c, NULL, 0);
		sink_free(&s);
	}
	compound_free(&c);
	if (compound_load(&c, path, &ld, pov_check) != 0 || !small(&c) ||
	    compound_run(&c, &fr, NULL) != 0)
		goto out;
	all[0] = compound_main(&c);
	sink_init(&s, NULL);
	csv_write(&s, all[0], 0);
	if (flatten_leaves(all[0]) <= 100000)
		csv_write(&s, all[0], TO_FLATTEN);
	info_write(&s, all[0], 0);
	svg_write(&s, all[0], 0);
	if ((t = tmpl_builtin("pov.tmpl", pov_vars)) != NULL) {
		for (size_t i = 0; i < c.n; i++) {
			all[0] = &c.parts[i]->res;
			tmpl_write(t, &s, all, 1, 0);
		}
		tmpl_free(t);
	}
	if (flatten_leaves(compound_main(&c)) <= 100000) {
		/* The view --blender writes a part with parts through. */
		flatten_view(compound_main(&c), &merged);
		all[0] = &merged;
		if ((t = tmpl_builtin("blender.tmpl", blender_vars)) != NULL) {
			tmpl_write(t, &s, all, 1, 0);
			tmpl_free(t);
		}
		flatten_free(&merged);
	}
	/* Each format's estimate, and the script in --frames' pieces. */
	for (const struct writer *w = writers; w->name != NULL; w++) {
		struct plan P;

		/* --settings and --cfg write the scene, and size nothing. */
		if (w->tmpl == NULL && w->bytes == NULL)
			continue;
		t = w->tmpl != NULL ? tmpl_builtin(w->tmpl, w->vars) : NULL;
		plan_make(&P, w, t, compound_main(&c));
		(void)plan_bytes(&P, w, t, TMPL_ALL, TO_FLATTEN);
		if (t != NULL && (w->opts & TO_ANIMATE) &&
		    flatten_leaves(compound_main(&c)) <= 100000)
			for (int k = TMPL_HEAD; k <= TMPL_TAIL; k++)
				tmpl_write_piece(t, (enum tmpl_piece)k, &s,
				    P.all, P.n, 0);
		plan_free(&P);
		tmpl_free(t);
	}
	sink_free(&s);
out:
	compound_free(&c);
	return 0;
}
