/*
 * out_cfg.c - --cfg: the scene file again, each --set written into it
 * where its setting stands (or added to the group holding it), every
 * comment and line as it was: what the Blender panel's "Save to scene
 * file" writes, and one file of a sweep from a shell.  A setting the
 * file gives that a --set leaves unused (the exponent, the kernel made
 * Gaussian) is taken out, since the file would not load with it.  The
 * text made is read again and must give the settings the scene gives
 * with its --set; anything else is a fault of ours, and nothing is
 * written.
 */
#include <stdlib.h>
#include <string.h>

#include "scene/cfgtext.h"
#include "scene/compound.h"
#include "base/diag.h"
#include "base/mem.h"
#include "scene/override.h"
#include "writers/writer.h"

/* Whether a (but what it drops) and b hold the same settings, written
 * alike. */
static int
same_settings(const struct scene *a, const struct scene *b)
{
	size_t kept = 0;

	for (size_t i = 0; i < a->nwritten; i++) {
		size_t j = 0;

		if (a->written[i].dropped)
			continue;
		kept++;
		while (j < b->nwritten && strcmp(a->written[i].path,
		    b->written[j].path) != 0)
			j++;
		if (j == b->nwritten || strcmp(a->written[i].text,
		    b->written[j].text) != 0)
			return 0;
	}
	return kept == b->nwritten;
}

int
cfg_write(struct sink *s, const struct compound *c,
    const struct override *set, int nset)
{
	const struct scene *sc = &c->parts[c->n - 1]->sc;
	struct loading ld = { .record = 1 };
	struct scene again;
	size_t len = sc->len;
	char *text = xmalloc(len + 1);
	int rc = 0;

	memcpy(text, sc->text, len + 1);
	for (int k = 0; k < nset && rc == 0; k++) {
		size_t n;
		char *next;

		if (set[k].object[0] != '\0') {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: --cfg writes the "
			    "main scene; a part's setting goes into its own "
			    "file", set[k].arg);
			rc = -1;
		} else if ((next = cfgtext_splice(text, len, set[k].path,
		    set[k].value, &n)) == NULL) {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: the path is not "
			    "in %s as a group or an entry of a list",
			    set[k].arg, sc->file);
			rc = -1;
		} else {
			free(text);
			text = next;
			len = n;
		}
	}
	for (size_t i = 0; i < sc->nwritten && rc == 0; i++) {
		size_t n;
		char *next;

		if (!sc->written[i].dropped)
			continue;
		if ((next = cfgtext_cut(text, len, sc->written[i].path,
		    &n)) == NULL) {
			diag(ST_SYSTEM, sc->file, sc->written[i].line, 0,
			    "'%s' cannot be taken out of the text: a fault of "
			    "phyllo-export's (nothing written)",
			    sc->written[i].path);
			rc = -1;
		} else {
			free(text);
			text = next;
			len = n;
		}
	}
	if (rc == 0) {
		rc = scene_load_buffer_as(&again, sc->file, text, len, "", &ld);
		if (rc == 0 && !same_settings(sc, &again)) {
			diag(ST_SYSTEM, sc->file, 0, 0, "the settings written "
			    "back read otherwise: a fault of phyllo-export's "
			    "(nothing written)");
			rc = -1;
		}
		scene_free(&again);
	}
	if (rc == 0)
		sink_write(s, text, len);
	free(text);
	return rc;
}
