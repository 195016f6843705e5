/*
 * obj.c - Wavefront OBJ as organ meshes need it: v, vt, vn and f
 * (polygons fanned from their first corner; corners v, v/vt, v//vn or
 * v/vt/vn; negative indices count back from the last one read), usemtl
 * and mtllib for the materials' Kd, and s, the smoothing groups of the
 * normals computed for faces that give none.  Our own reader: the
 * format is a page of text, a library would bring more than it holds.
 *
 * The rest of the format's statements (o, g, l, p, curves, surfaces,
 * ...) are allowed and skipped; anything else is an error at its line,
 * which is how a file that is not OBJ at all is told: by its first
 * line, not after reading 64 MiB of it.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "scene/cfgtext.h"
#include "base/diag.h"
#include "base/mem.h"
#include "meshes/idtable.h"
#include "meshes/mtl.h"
#include "meshes/obj.h"
#include "meshes/objtext.h"

/* Statements OBJ defines that an organ mesh does without. */
static const char *const skipped[] = {
	"o", "g", "mg", "l", "p", "vp", "cstype", "deg", "bmat", "step",
	"curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end",
	"con", "lod", "bevel", "c_interp", "d_interp", "shadow_obj",
	"trace_obj", "ctech", "stech", "call", "csh", "maplib", "usemap",
	NULL
};

/* Where a vertex's normal comes from: the key's third number. */
#define NK_GIVEN	(0ULL << 62)	/* vn, its index */
#define NK_SMOOTH	(1ULL << 62)	/* computed, shared: its sum */
#define NK_FLAT		(2ULL << 62)	/* computed, its face's own */
#define NK_ID		((1ULL << 62) - 1)

/* The triangles of one material, as they are read. */
struct group {
	char		 material[MESH_MATERIAL_LEN];
	uint32_t	*index;
	size_t		 n, cap;
};

/* A face's corners: indices into v, vt (or -1) and vn (or -1). */
struct corner {
	long		 v, t, n;
};

struct obj {
	struct objtext	 at;
	const char	*dir;		/* mtllib files' directory, or NULL */
	obj_read_fn	*told;
	double		(*v)[3], (*vn)[3];
	size_t		 nv, nvt, nvn, capv, capvn;
	struct idtab	 verts;		/* (v, 0, normal key): vertex */
	uint64_t	(*vkey)[3];	/* each vertex's key */
	size_t		 nvert, capvert;
	double		(*flat)[3], (*smooth)[3];	/* computed normals */
	size_t		 nflat, capflat, nsmooth, capsmooth;
	struct idtab	 smooth_at;	/* (v, group, 0): its sum */
	unsigned long	 group;		/* smoothing group; 0 off */
	struct group	*groups;
	size_t		 ngroups, cur;
	struct corner	*corner;
	size_t		 capcorner;
	struct mtl_material *mats;
	size_t		 nmats;
};

/* Room for one more in an array of n, cap so far. */
static void *
grow(void *a, size_t n, size_t *cap, size_t size)
{
	if (n < *cap)
		return a;
	*cap = *cap ? *cap * 2 : 256;
	return xreallocarray(a, *cap, size);
}

/* One index of a corner, from 1 or back from -1, of count so far. */
static int
index_of(const struct obj *O, const char **p, const char *end, long count,
    const char *what, long *out)
{
	const char *s = *p, *from = *p;
	int neg = *s == '-';
	long long v = 0;
	char q[160];

	s += neg;
	if (s == end || *s < '0' || *s > '9')
		return objtext_fail(&O->at, "a face corner is v, v/vt, v//vn "
		    "or v/vt/vn, each a whole number");
	for (; s < end && *s >= '0' && *s <= '9'; s++)
		if (v <= INT32_MAX)
			v = v * 10 + (*s - '0');
	*p = s;
	if (v == 0)
		return objtext_fail(&O->at, "%s index 0: OBJ counts from 1 "
		    "(or back from -1)", what);
	if (v > count) {
		objtext_quote(q, sizeof(q), from, s);
		return objtext_fail(&O->at, "%s index %s is out of range: %ld "
		    "so far", what, q, count);
	}
	*out = neg ? count - (long)v : (long)v - 1;
	return 0;
}

/* A corner "v", "v/vt", "v//vn" or "v/vt/vn" at *p. */
static int
corner(struct obj *O, const char **p, const char *end, struct corner *c)
{
	c->t = c->n = -1;
	if (index_of(O, p, end, (long)O->nv, "vertex", &c->v) != 0)
		return -1;
	if (*p == end || **p != '/')
		return 0;
	(*p)++;
	if (*p < end && **p != '/' && index_of(O, p, end, (long)O->nvt,
	    "texture coordinate", &c->t) != 0)
		return -1;
	if (*p == end || **p != '/')
		return 0;
	(*p)++;
	return index_of(O, p, end, (long)O->nvn, "normal", &c->n);
}

/* The vertex of a corner whose normal has key nk, made if new. */
static uint32_t
vertex(struct obj *O, const struct corner *c, uint64_t nk)
{
	/* Texture coordinates are checked but not kept: no texture goes
	 * into the file, and glTF-Validator calls unused ones out. */
	uint64_t k[3] = { (uint64_t)c->v, 0, nk };
	uint32_t id = idtab_get(&O->verts, k);

	if (id != UINT32_MAX)
		return id;
	O->vkey = grow(O->vkey, O->nvert, &O->capvert, sizeof(*O->vkey));
	memcpy(O->vkey[O->nvert], k, sizeof(k));
	idtab_put(&O->verts, k, (uint32_t)O->nvert);
	return (uint32_t)O->nvert++;
}

/* The sum of the computed normals at v in the current smoothing group. */
static uint64_t
smooth_key(struct obj *O, long v)
{
	uint64_t k[3] = { (uint64_t)v, O->group, 0 };
	uint32_t id = idtab_get(&O->smooth_at, k);

	if (id == UINT32_MAX) {
		O->smooth = grow(O->smooth, O->nsmooth, &O->capsmooth,
		    sizeof(*O->smooth));
		memset(O->smooth[O->nsmooth], 0, sizeof(*O->smooth));
		id = (uint32_t)O->nsmooth++;
		idtab_put(&O->smooth_at, k, id);
	}
	return NK_SMOOTH | id;
}

/* f: a polygon, fanned into triangles of the current material. */
static int
face(struct obj *O, const char *p, const char *end)
{
	struct group *g;
	double area[3] = { 0, 0, 0 };
	size_t n = 0;
	uint32_t first = 0, prev = 0;
	int given = 1;

	for (p = objtext_skip(p, end); p < end && *p != '#';
	    p = objtext_skip(p, end)) {
		O->corner = grow(O->corner, n, &O->capcorner,
		    sizeof(*O->corner));
		if (corner(O, &p, end, &O->corner[n]) != 0)
			return -1;
		if (p < end && !objtext_blank(*p) && *p != '#')
			return objtext_fail(&O->at, "a face corner is v, "
			    "v/vt, v//vn or v/vt/vn, each a whole number");
		given &= O->corner[n].n >= 0;
		n++;
	}
	if (n < 3)
		return objtext_fail(&O->at, "a face has 3 corners or more, "
		    "not %zu", n);
	if (O->nvert + n > (size_t)UINT32_MAX / 2)
		return objtext_fail(&O->at, "more vertices than a mesh may "
		    "have");
	/* Newell's normal: twice the area, along the polygon's normal. */
	for (size_t i = 0; i < n; i++) {
		const double *a = O->v[O->corner[i].v];
		const double *b = O->v[O->corner[(i + 1) % n].v];

		area[0] += (a[1] - b[1]) * (a[2] + b[2]);
		area[1] += (a[2] - b[2]) * (a[0] + b[0]);
		area[2] += (a[0] - b[0]) * (a[1] + b[1]);
	}
	if (!given && O->group == 0) {
		O->flat = grow(O->flat, O->nflat, &O->capflat,
		    sizeof(*O->flat));
		memcpy(O->flat[O->nflat++], area, sizeof(area));
	}
	g = &O->groups[O->cur];
	for (size_t i = 0; i < n; i++) {
		const struct corner *c = &O->corner[i];
		uint64_t nk = given ? NK_GIVEN | (uint64_t)c->n :
		    O->group == 0 ? NK_FLAT | (O->nflat - 1) :
		    smooth_key(O, c->v);
		uint32_t id;

		if ((nk & ~NK_ID) == NK_SMOOTH)
			for (int k = 0; k < 3; k++)
				O->smooth[nk & NK_ID][k] += area[k];
		id = vertex(O, c, nk);
		/* Fanned: (first, previous, this) from the third corner on. */
		if (i >= 2) {
			g->index = grow(g->index, g->n + 2, &g->cap,
			    sizeof(*g->index));
			g->index[g->n++] = first;
			g->index[g->n++] = prev;
			g->index[g->n++] = id;
		} else if (i == 0)
			first = id;
		prev = id;
	}
	return 0;
}

/* usemtl NAME: the faces that follow are NAME's. */
static void
use_material(struct obj *O, const char *p, const char *end)
{
	char name[MESH_MATERIAL_LEN];
	size_t n;

	p = objtext_skip(p, end);
	while (end > p && objtext_blank(end[-1]))
		end--;
	n = (size_t)(end - p) < sizeof(name) - 1 ? (size_t)(end - p) :
	    sizeof(name) - 1;
	memcpy(name, p, n);
	name[n] = '\0';
	for (O->cur = 0; O->cur < O->ngroups; O->cur++)
		if (strcmp(O->groups[O->cur].material, name) == 0)
			return;
	O->groups = xreallocarray(O->groups, O->ngroups + 1,
	    sizeof(*O->groups));
	O->groups[O->ngroups] = (struct group){ "", NULL, 0, 0 };
	memcpy(O->groups[O->ngroups].material, name, n + 1);
	O->cur = O->ngroups++;
}

/* s 1, s off: the smoothing group of the faces that follow. */
static int
smoothing(struct obj *O, const char *p, const char *end)
{
	const char *w;
	char *e;
	char q[160];
	unsigned long g;

	p = objtext_skip(p, end);
	w = objtext_word_end(p, end);
	if (w - p == 3 && memcmp(p, "off", 3) == 0) {
		O->group = 0;
		return 0;
	}
	g = p < end && *p >= '0' && *p <= '9' ? strtoul(p, &e, 10) : 0;
	if (p == end || *p < '0' || *p > '9' || e != w) {
		objtext_quote(q, sizeof(q), p, w);
		return objtext_fail(&O->at, "s takes a smoothing group, a "
		    "whole number or off, not \"%s\"", q);
	}
	O->group = g;
	return 0;
}

/* The file an mtllib line names, p to end, in dir (with its '/'). */
static char *
library_path(const char *dir, const char *p, const char *end)
{
	size_t n = (size_t)(end - p), dn;
	char *path = xmalloc(strlen(dir) + n + 1);

	memcpy(path, p, n);
	path[n] = '\0';
	dn = sys_absolute(path) ? 0 : strlen(dir);
	memmove(path + dn, path, n + 1);
	memcpy(path, dir, dn);
	return path;
}

/* mtllib FILE: its materials, read beside the OBJ file. */
static int
material_library(struct obj *O, const char *p, const char *end)
{
	char *path, *text, q[600];
	const char *why;
	size_t len;
	struct sys_stat st;
	int rc;

	p = objtext_skip(p, end);
	while (end > p && objtext_blank(end[-1]))
		end--;
	if (p == end)
		return objtext_fail(&O->at, "mtllib names a material library "
		    "file");
	if (O->dir == NULL)
		return 0;
	path = library_path(O->dir, p, end);
	/* A library that cannot be read leaves the colours to us. */
	why = sys_stat(path, &st) != 0 ? strerror(errno) :
	    st.kind == SYS_DIR ? strerror(EISDIR) :
	    st.kind != SYS_REG ? "not a regular file" :
	    !sys_readable(path) ? strerror(errno) : NULL;
	if (why != NULL) {
		cfgtext_quote(q, sizeof(q), path);
		diag(ST_OK, O->at.file, O->at.line, 0, "material library "
		    "\"%s\": %s: the organ object's own colour stands in", q,
		    why);
		free(path);
		return 0;
	}
	if (O->told != NULL)
		O->told(path);
	rc = objtext_read(path, MTL_BYTES_MAX, "material library", &text,
	    &len);
	if (rc == 0) {
		rc = mtl_parse(&O->mats, &O->nmats, path, text, len);
		free(text);
	}
	free(path);
	return rc;
}

/* One statement; 0 or -1. */
static int
statement(struct obj *O, const char *p, const char *end)
{
	const char *w = objtext_word_end(p, end);
	size_t kw = (size_t)(w - p);
	double x[6];
	char q[160];

#define IS(s)	(kw == sizeof(s) - 1 && memcmp(p, s, kw) == 0)
	if (IS("v")) {
		/* x y z, and w or r g b that some programs add. */
		int n = objtext_numbers(&O->at, w, end, x, 3, 6, "v");

		if (n < 0)
			return -1;
		O->v = grow(O->v, O->nv, &O->capv, sizeof(*O->v));
		memcpy(O->v[O->nv++], x, sizeof(*O->v));
	} else if (IS("vt")) {
		if (objtext_numbers(&O->at, w, end, x, 1, 3, "vt") < 0)
			return -1;
		/* Checked and counted for the faces' indices, not kept. */
		O->nvt++;
	} else if (IS("vn")) {
		if (objtext_numbers(&O->at, w, end, x, 3, 3, "vn") < 0)
			return -1;
		O->vn = grow(O->vn, O->nvn, &O->capvn, sizeof(*O->vn));
		memcpy(O->vn[O->nvn++], x, sizeof(*O->vn));
	} else if (IS("f") || IS("fo"))
		return face(O, w, end);
	else if (IS("usemtl"))
		use_material(O, w, end);
	else if (IS("mtllib"))
		return material_library(O, w, end);
	else if (IS("s"))
		return smoothing(O, w, end);
	else {
		for (const char *const *k = skipped; *k != NULL; k++)
			if (kw == strlen(*k) && memcmp(p, *k, kw) == 0)
				return 0;
		objtext_quote(q, sizeof(q), p, w);
		return objtext_fail(&O->at, "\"%s\" is no OBJ statement (v, "
		    "vt, vn, f, usemtl, ...)", q);
	}
#undef IS
	return 0;
}

/* The statements of text, which ends in a NUL at len. */
static int
parse(struct obj *O, const char *text, size_t len)
{
	const char *p = text, *end = text + len, *nl;

	if (len >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
		p += 3;		/* a byte-order mark, as Windows tools write */
	for (O->at.line = 1; p < end; p = nl + 1, O->at.line++) {
		const char *s;

		if ((nl = memchr(p, '\n', (size_t)(end - p))) == NULL)
			nl = end;
		s = objtext_skip(p, nl);
		if (s < nl && *s != '#' && statement(O, s, nl) != 0)
			return -1;
	}
	return 0;
}

/* A computed or given normal, made unit length. */
static void
unit(const double n[3], float out[3])
{
	double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);

	if (!(len > 1e-300) || !isfinite(len)) {
		/* A face of no area: it shows nothing, any normal will do. */
		out[0] = 0;
		out[1] = 1;
		out[2] = 0;
		return;
	}
	for (int k = 0; k < 3; k++)
		out[k] = (float)(n[k] / len);
}

/* The mesh of what was read. */
static int
finish(struct obj *O, struct mesh *m)
{
	size_t faces = 0;

	for (size_t i = 0; i < O->ngroups; i++)
		faces += O->groups[i].n;
	if (faces == 0) {
		diag(ST_SCENE, O->at.file, 0, 0, "no faces (f lines): an organ "
		    "mesh needs some");
		return -1;
	}
	*m = (struct mesh){0};
	m->nvert = O->nvert;
	m->pos = xcalloc(O->nvert, sizeof(*m->pos));
	m->normal = xcalloc(O->nvert, sizeof(*m->normal));
	for (size_t i = 0; i < O->nvert; i++) {
		const uint64_t *k = O->vkey[i];
		uint64_t id = k[2] & NK_ID;

		for (int j = 0; j < 3; j++) {
			m->pos[i][j] = (float)O->v[k[0]][j];
			if (i == 0 || m->pos[i][j] < m->min[j])
				m->min[j] = m->pos[i][j];
			if (i == 0 || m->pos[i][j] > m->max[j])
				m->max[j] = m->pos[i][j];
		}
		unit((k[2] & ~NK_ID) == NK_GIVEN ? O->vn[id] :
		    (k[2] & ~NK_ID) == NK_SMOOTH ? O->smooth[id] : O->flat[id],
		    m->normal[i]);
	}
	m->prim = xcalloc(O->ngroups, sizeof(*m->prim));
	for (size_t i = 0; i < O->ngroups; i++) {
		struct group *g = &O->groups[i];
		struct mesh_prim *p;

		if (g->n == 0)
			continue;
		p = &m->prim[m->nprim++];
		p->index = g->index;
		p->nindex = g->n;
		g->index = NULL;
		memcpy(p->material, g->material, sizeof(p->material));
		for (size_t k = 0; k < O->nmats; k++)
			if (O->mats[k].has_kd &&
			    strcmp(O->mats[k].name, g->material) == 0) {
				memcpy(p->color, O->mats[k].color,
				    sizeof(p->color));
				p->colored = 1;
			}
	}
	return 0;
}

static void
obj_free(struct obj *O)
{
	for (size_t i = 0; i < O->ngroups; i++)
		free(O->groups[i].index);
	free(O->groups);
	free(O->v);
	free(O->vn);
	idtab_free(&O->verts);
	free(O->vkey);
	free(O->flat);
	free(O->smooth);
	idtab_free(&O->smooth_at);
	free(O->corner);
	free(O->mats);
}

/* Parse text, which ends in a NUL at len. */
static int
parse_text(struct mesh *m, const char *file, const char *text, size_t len,
    const char *dir, obj_read_fn *told)
{
	struct obj O = { .at = { file, 0 }, .dir = dir, .told = told };
	int rc, at = objtext_nul_line(text, len);

	if (at > 0) {
		diag(ST_SCENE, file, at, 0, "NUL byte: an OBJ file is text");
		return -1;
	}
	O.groups = xcalloc(1, sizeof(*O.groups));
	O.ngroups = 1;
	rc = parse(&O, text, len);
	if (rc == 0)
		rc = finish(&O, m);
	obj_free(&O);
	return rc;
}

int
obj_parse(struct mesh *m, const char *file, const char *text, size_t len,
    const char *dir, obj_read_fn *told)
{
	char *copy = xmalloc(len + 1);
	int rc;

	memcpy(copy, text, len);
	copy[len] = '\0';
	rc = parse_text(m, file, copy, len, dir, told);
	free(copy);
	return rc;
}

/* The directory of path, with its '/', or "". */
static char *
dir_of(const char *path)
{
	size_t dn = (size_t)(sys_base(path) - path);
	char *dir = xmalloc(dn + 1);

	memcpy(dir, path, dn);
	dir[dn] = '\0';
	return dir;
}

void
obj_libraries(const char *path, obj_read_fn *told)
{
	char line[4096], *dir;
	FILE *fp;

	if ((fp = sys_fopen(path, "rb")) == NULL)
		return;
	dir = dir_of(path);
	while (fgets(line, sizeof(line), fp) != NULL) {
		const char *p = objtext_skip(line, line + strlen(line));
		const char *end = line + strlen(line), *w;
		char *lib;
		struct sys_stat st;

		if (strncmp(p, "mtllib", 6) != 0 || !objtext_blank(p[6]))
			continue;
		while (end > p && (objtext_blank(end[-1]) || end[-1] == '\n'))
			end--;
		if ((w = objtext_skip(p + 6, end)) == end)
			continue;
		lib = library_path(dir, w, end);
		if (sys_stat(lib, &st) == 0 && st.kind == SYS_REG)
			told(lib);
		free(lib);
	}
	free(dir);
	fclose(fp);
}

int
obj_load(struct mesh *m, const char *path, obj_read_fn *told)
{
	char *text, *dir = dir_of(path);
	size_t len;
	int rc;

	rc = objtext_read(path, OBJ_BYTES_MAX, "OBJ file", &text, &len);
	if (rc == 0)
		rc = parse_text(m, path, text, len, dir, told);
	free(text);
	free(dir);
	return rc;
}

