/*
 * meshes.c - find and read the OBJ files a compound's scenes name for
 * their organ objects.  Object names are one namespace across the tree
 * (compound.c), so each name has one mesh wherever it is placed; two
 * files for one name is an error, as two scenes are.
 *
 * Every frame loads its scenes afresh, but no setting of a mesh can
 * change with f, so a file is read once a run: later frames find it in
 * the list below, by its identity, and forget it when the run ends.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "scene/compound.h"
#include "base/diag.h"
#include "base/inputs.h"
#include "base/mem.h"
#include "meshes/meshes.h"
#include "meshes/obj.h"
#include "base/path.h"

/* A file read this run. */
struct read {
	struct sys_id	 id;
	struct mesh	*mesh;		/* apart: the list grows */
};

static struct read *reads;
static size_t nreads;

static void
library_read(const char *path)
{
	input_add(path, "a material library of an organ mesh");
}

/* The mesh in the file at path, read unless it was; NULL after a
 * diagnostic. */
static const struct mesh *
mesh_at(const char *path, const struct sys_stat *st)
{
	struct mesh *m;

	for (size_t i = 0; i < nreads; i++)
		if (SYS_SAME(reads[i].id, st->id))
			return reads[i].mesh;
	m = xcalloc(1, sizeof(*m));
	if (obj_load(m, path, library_read) != 0) {
		free(m);
		return NULL;
	}
	reads = xreallocarray(reads, nreads + 1, sizeof(*reads));
	reads[nreads++] = (struct read){ st->id, m };
	return m;
}

void
meshes_forget(void)
{
	for (size_t i = 0; i < nreads; i++) {
		mesh_free(reads[i].mesh);
		free(reads[i].mesh);
	}
	free(reads);
	reads = NULL;
	nreads = 0;
}

/* Where each object's mesh was named, while the table is made. */
struct named {
	char		*file;		/* the path read, owned */
	const char	*scene;		/* the scene naming it */
	int		 line;
	struct sys_id	 id;
};

/* Object j of part p's mesh, added to M unless its name has it. */
static int
add(struct meshes *M, struct named *at, const struct part *p, size_t j,
    unsigned flags)
{
	const struct scene *sc = &p->sc;
	const char *name = sc->objects[j];
	int line = sc->object_mesh_line[j];
	char *path = path_resolve(p->file, sc->object_mesh[j]);
	const struct mesh *mesh;
	const char *why;
	struct sys_stat st;
	size_t i;

	/* A FIFO would wait for a writer for ever. */
	why = sys_stat(path, &st) != 0 ? strerror(errno) :
	    st.kind == SYS_DIR ? strerror(EISDIR) :
	    st.kind != SYS_REG ? "not a regular file" :
	    !sys_readable(path) ? strerror(errno) : NULL;
	if (why != NULL) {
		/* --info wants the rest: only the glTF's size needs it. */
		diag(flags & MESH_SIZES ? ST_OK : ST_SCENE, sc->file, line, 0,
		    "mesh %s of organ object \"%s\": %s%s", path, name, why,
		    flags & MESH_SIZES ? ": the glTF's size is not estimated" :
		    "");
		free(path);
		M->missing = 1;
		return flags & MESH_SIZES ? 0 : -1;
	}
	for (i = 0; i < M->n; i++)
		if (strcmp(M->m[i].name, name) == 0)
			break;
	if (i < M->n) {
		if (!SYS_SAME(at[i].id, st.id))
			diag(ST_SCENE, sc->file, line, 0, "organ object \"%s\" "
			    "has mesh %s here but %s in %s: one name, one "
			    "thing", name, path, at[i].file, at[i].scene);
		free(path);
		return SYS_SAME(at[i].id, st.id) ? 0 : -1;
	}
	if ((mesh = mesh_at(path, &st)) == NULL) {
		free(path);
		return -1;
	}
	M->m[M->n] = (struct object_mesh){ name, mesh };
	at[M->n++] = (struct named){ path, sc->file, line, st.id };
	return 0;
}

/* Whether part i's object j was named by an earlier part. */
static int
named_before(const struct compound *C, size_t i, const char *name)
{
	for (size_t k = 0; k < i; k++)
		for (size_t l = 0; l < C->parts[k]->sc.nobjects; l++)
			if (strcmp(C->parts[k]->sc.objects[l], name) == 0)
				return 1;
	return 0;
}

/*
 * Plain objects with no mesh anywhere: placeholders stand in.  One
 * line a scene, at the first such object, each name said once.
 */
static void
warn_bare(const struct meshes *M, const struct compound *C)
{
	for (size_t i = 0; i < C->n; i++) {
		const struct scene *sc = &C->parts[i]->sc;
		char names[512] = "";
		size_t len = 0, n = 0;
		int line = 0;

		for (size_t j = 0; j < sc->nobjects; j++) {
			if (sc->object_scene[j] != NULL ||
			    meshes_find(M, sc->objects[j]) != NULL ||
			    named_before(C, i, sc->objects[j]))
				continue;
			if (n++ == 0)
				line = sc->object_line[j];
			if (len < sizeof(names))
				len += (size_t)snprintf(names + len,
				    sizeof(names) - len, "%s\"%s\"", len ?
				    ", " : "", sc->objects[j]);
		}
		if (n > 0)
			diag(ST_OK, sc->file, line, 0, "organ object%s %s %s "
			    "no mesh (organs.mesh names an OBJ file): %s",
			    n > 1 ? "s" : "", names, n > 1 ? "have" : "has",
			    n > 1 ? "placeholders stand in" :
			    "a placeholder stands in");
	}
}

int
meshes_load(struct meshes *M, struct compound *C, unsigned flags)
{
	struct named *at;
	size_t most = 0;
	int rc = 0;

	*M = (struct meshes){ NULL, 0, 0 };
	for (size_t i = 0; i < C->n; i++)
		most += C->parts[i]->sc.nobjects;
	M->m = xcalloc(most, sizeof(*M->m));
	at = xcalloc(most, sizeof(*at));
	for (size_t i = 0; i < C->n && rc == 0; i++) {
		const struct scene *sc = &C->parts[i]->sc;

		for (size_t j = 0; j < sc->nobjects && rc == 0; j++)
			if (sc->object_mesh[j] != NULL)
				rc = add(M, at, C->parts[i], j, flags);
	}
	for (size_t i = 0; i < M->n; i++)
		free(at[i].file);
	free(at);
	if (rc != 0)
		return -1;
	if (flags & MESH_WARN)
		warn_bare(M, C);
	for (size_t i = 0; i < C->n; i++)
		C->parts[i]->res.meshes = M;
	return 0;
}

const struct mesh *
meshes_find(const struct meshes *M, const char *name)
{
	for (size_t i = 0; M != NULL && i < M->n; i++)
		if (strcmp(M->m[i].name, name) == 0)
			return M->m[i].mesh;
	return NULL;
}

void
meshes_free(struct meshes *M)
{
	free(M->m);
	*M = (struct meshes){ NULL, 0, 0 };
}

void
meshes_inputs(const struct compound *C)
{
	char what[NAME_LEN + 48];

	for (size_t i = 0; i < C->n; i++) {
		const struct part *p = C->parts[i];

		for (size_t j = 0; j < p->sc.nobjects; j++) {
			char *path;

			if (p->sc.object_mesh[j] == NULL)
				continue;
			path = path_resolve(p->file, p->sc.object_mesh[j]);
			snprintf(what, sizeof(what), "the mesh of organ object "
			    "\"%s\"", p->sc.objects[j]);
			input_add(path, what);
			obj_libraries(path, library_read);
			free(path);
		}
	}
}
