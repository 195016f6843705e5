/*
 * compound.c - load a scene and, depth first, the scenes its organs are
 * made of, each after the parts it uses (the pipeline runs them in that
 * order: pipeline/scene_run.c).
 *
 * Object names are one namespace across the whole tree, as they are in
 * POV-Ray and in a .blend: a name made of a scene is made of that scene
 * everywhere, and nowhere a plain object.  So each part is loaded and
 * run once however often it is placed, and writers declare it once.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "scene/compound.h"
#include "base/diag.h"
#include "base/mem.h"
#include "base/path.h"

/* The scenes being loaded, innermost first: what a cycle would revisit. */
struct chain {
	const struct chain *up;
	const char	*file;
	const char	*object;	/* the object it makes; "" the main */
	struct sys_id	 id;
};

struct loader {
	struct compound	*C;
	const struct loading *ld;
	int		(*check)(const struct scene *);
};

struct part *
compound_part(const struct compound *C, const char *object)
{
	for (size_t i = 0; i < C->n; i++)
		if (strcmp(C->parts[i]->object, object) == 0)
			return C->parts[i];
	return NULL;
}

/* "a.cfg -> b.cfg -> a.cfg": the chain from the top down to file. */
static void
chain_words(char *buf, size_t sz, const struct chain *c, const char *file)
{
	const struct chain *stack[COMPOUND_DEPTH_MAX + 1];
	size_t n = 0, len = 0;

	for (; c != NULL && n < COMPOUND_DEPTH_MAX; c = c->up)
		stack[n++] = c;
	buf[0] = '\0';
	while (n-- > 0 && len < sz)
		len += (size_t)snprintf(buf + len, sz - len, "%s -> ",
		    stack[n]->file);
	if (len < sz)
		snprintf(buf + len, sz - len, "%s", file);
}

static int	load(struct loader *, const char *path, const char *object,
		    const struct chain *up, int line);

/* The parts a loaded scene names, each loaded unless it already is. */
static int
load_parts(struct loader *L, struct part *p, const struct chain *me)
{
	const struct scene *sc = &p->sc;

	for (size_t j = 0; j < sc->nobjects; j++) {
		const char *name = sc->objects[j];
		const struct part *had;
		char *path;
		int rc = 0;

		if (sc->object_scene[j] == NULL)
			continue;
		path = path_resolve(p->file, sc->object_scene[j]);
		had = compound_part(L->C, name);
		if (had != NULL) {
			struct sys_stat a, b;

			if (sys_stat(path, &a) != 0 ||
			    sys_stat(had->file, &b) != 0 ||
			    !SYS_SAME(a.id, b.id)) {
				diag(ST_SCENE, p->file, sc->object_line[j], 0,
				    "organ object \"%s\" is made of %s here "
				    "but of %s in %s: one name, one thing",
				    name, path, had->file, had->from);
				rc = -1;
			}
		} else
			rc = load(L, path, name, me, sc->object_line[j]);
		free(path);
		if (rc != 0)
			return -1;
	}
	return 0;
}

/*
 * Load the scene at path, making object ("" for the main scene), named
 * by the scene up at line; its parts first, then itself onto the list.
 */
static int
load(struct loader *L, const char *path, const char *object,
    const struct chain *up, int line)
{
	struct chain me = { up, path, object, { 0, 0 } };
	struct part *p;
	struct sys_stat st;
	char words[1024];
	int depth = 0, loaded;

	if (up != NULL) {
		/*
		 * A part that cannot be read is an error in the scene naming
		 * it (exit 1), wherever the reason lies; and a FIFO would
		 * wait for a writer for ever.
		 */
		const char *why = sys_stat(path, &st) != 0 ? strerror(errno) :
		    st.kind == SYS_DIR ? strerror(EISDIR) :
		    st.kind != SYS_REG ? "not a regular file" :
		    !sys_readable(path) ? strerror(errno) : NULL;

		if (why != NULL) {
			diag(ST_SCENE, up->file, line, 0, "scene file %s of "
			    "organ object \"%s\": %s", path, object, why);
			return -1;
		}
		me.id = st.id;
		for (const struct chain *c = up; c != NULL; c = c->up) {
			if (SYS_SAME(c->id, st.id) ||
			    strcmp(c->object, object) == 0) {
				chain_words(words, sizeof(words), up, path);
				diag(ST_SCENE, up->file, line, 0, "scenes "
				    "include each other: %s", words);
				return -1;
			}
			depth++;
		}
		if (depth >= COMPOUND_DEPTH_MAX ||
		    L->C->n >= COMPOUND_PARTS_MAX) {
			diag(ST_SCENE, up->file, line, 0, "more than %d %s",
			    depth >= COMPOUND_DEPTH_MAX ? COMPOUND_DEPTH_MAX :
			    COMPOUND_PARTS_MAX, depth >= COMPOUND_DEPTH_MAX ?
			    "scenes in one chain of includes" :
			    "parts in one structure");
			return -1;
		}
	} else if (strcmp(path, "-") != 0 && sys_stat(path, &st) == 0)
		me.id = st.id;

	p = xcalloc(1, sizeof(*p));
	p->file = xstrdup(path);
	snprintf(p->object, sizeof(p->object), "%s", object);
	p->from = up != NULL ? up->file : NULL;
	p->from_line = line;
	loaded = scene_load_as(&p->sc, p->file, object, L->ld) == 0;
	if (loaded)
		me.file = p->sc.file;		/* "<stdin>" for "-" */
	if (!loaded ||
	    (L->check != NULL && L->check(&p->sc) != 0) ||
	    load_parts(L, p, &me) != 0) {
		if (up != NULL)
			diag(ST_SCENE, up->file, line, 0, "in %s, the scene "
			    "of organ object \"%s\" included here", path,
			    object);
		scene_free(&p->sc);
		free(p->file);
		free(p);
		return -1;
	}
	L->C->parts = xreallocarray(L->C->parts, L->C->n + 1,
	    sizeof(*L->C->parts));
	L->C->parts[L->C->n++] = p;
	return 0;
}

/*
 * A name made of a scene is nowhere a plain object, and no part takes
 * the main structure's name.
 */
static int
names_agree(const struct compound *C)
{
	const struct part *top = C->parts[C->n - 1];

	for (size_t i = 0; i < C->n; i++) {
		const struct scene *sc = &C->parts[i]->sc;
		const struct part *q;

		if (C->parts[i] != top &&
		    strcmp(C->parts[i]->object, top->sc.name) == 0) {
			diag(ST_SCENE, C->parts[i]->from,
			    C->parts[i]->from_line, 0, "organ object \"%s\" "
			    "has the name of the structure, %s",
			    top->sc.name, top->file);
			return -1;
		}
		for (size_t j = 0; j < sc->nobjects; j++)
			if (sc->object_scene[j] == NULL &&
			    (q = compound_part(C, sc->objects[j])) != NULL) {
				diag(ST_SCENE, sc->file, sc->object_line[j], 0,
				    "organ object \"%s\" is a plain object "
				    "here but is made of %s in %s: one name, "
				    "one thing", sc->objects[j], q->file,
				    q->from);
				return -1;
			}
	}
	return 0;
}

int
compound_load(struct compound *C, const char *path, const struct loading *ld,
    int (*check)(const struct scene *))
{
	struct loader L = { C, ld, check };

	*C = (struct compound){ NULL, 0 };
	if (load(&L, path, "", NULL, 0) != 0)
		return -1;
	return names_agree(C);
}

void
compound_free(struct compound *C)
{
	for (size_t i = 0; i < C->n; i++) {
		result_free(&C->parts[i]->res);
		scene_free(&C->parts[i]->sc);
		free(C->parts[i]->file);
		free(C->parts[i]);
	}
	free(C->parts);
	*C = (struct compound){ NULL, 0 };
}
