/*
 * out_gltf.c - binary glTF 2.0 (.glb): one node per organ object, its
 * mesh drawn once per organ by EXT_mesh_gpu_instancing, whose per-organ
 * TRANSLATION, ROTATION and SCALE are 40 bytes an organ.
 *
 * glTF is Y up and right-handed: a point (x, y, z) of ours (Z up) is
 * (x, z, -y) there.  An organ mesh has its outward direction along
 * local +X and its up along local +Y, so an organ with frame u, v, w
 * maps local X to u, Y to w and Z to u x w = -v: the same organ, not
 * mirrored, as POV-Ray's (x outward, y up) and Blender's (X, Z).
 *
 * A compound structure is flattened to its leaf objects (the extension
 * instances one mesh, not a tree of nodes), walked once per object and
 * attribute through a view (flatten.h), so that memory follows the
 * parts, not the leaves.  Everything in the JSON is known before the
 * first organ is walked -- counts, meshes, offsets -- so the file is
 * written front to back in one go, to a pipe as well as a file, and its
 * size is known exactly beforehand.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "result/flatten.h"
#include "writers/json.h"
#include "base/mem.h"
#include "meshes/mesh.h"
#include "meshes/meshes.h"
#include "writers/writer.h"

#define GLB_MAGIC	0x46546c67u	/* "glTF" */
#define GLB_JSON	0x4e4f534au	/* "JSON" */
#define GLB_BIN		0x004e4942u	/* "BIN\0" */

/* Component types and buffer-view targets of glTF. */
#define GL_FLOAT		5126
#define GL_UNSIGNED_INT		5125
#define GL_ARRAY_BUFFER		34962
#define GL_ELEMENT_ARRAY_BUFFER	34963

/* Bytes an organ takes: TRANSLATION, ROTATION (x, y, z, w), SCALE. */
#define INSTANCE_BYTES	(12 + 16 + 12)

/* A mesh's vertices and triangles, once however many objects share it. */
struct geometry {
	const struct mesh *mesh;
	size_t		 accessor;	/* its first: POSITION, NORMAL,
					   then each primitive's
					   indices */
};

/* An organ object with organs: a node and a mesh of its own. */
struct node {
	size_t		 object;	/* in the written result's objects */
	double		 count;		/* its organs */
	size_t		 geometry;
	size_t		 accessor;	/* TRANSLATION, then ROTATION, SCALE */
	size_t		 material;	/* its first */
};

/* Everything the JSON says, worked out before a byte is written. */
struct gltf {
	const struct result *r;		/* walked: the result, or view */
	struct result	 view;		/* a compound's leaves; owned */
	struct node	*node;
	size_t		 nnode;
	struct geometry	*geom;
	size_t		 ngeom;
	struct mesh	 placeholder;	/* made if an object has no mesh */
	/* Each accessor's bytes, in order; its buffer view is its own. */
	double		*view_bytes;
	size_t		 naccessors;
	double		 bin;		/* the BIN chunk */
};

static size_t
geometry_accessors(const struct mesh *m)
{
	return 2 + m->nprim;
}

/* One accessor more, of bytes bytes, in a buffer view of its own. */
static void
add_accessor(struct gltf *G, size_t *cap, double bytes)
{
	if (G->naccessors == *cap)
		G->view_bytes = xreallocarray(G->view_bytes, *cap = *cap * 2 +
		    16, sizeof(*G->view_bytes));
	G->view_bytes[G->naccessors++] = bytes;
	G->bin += bytes;
}

/* The geometry of mesh m, added unless another object shares it. */
static size_t
geometry_of(struct gltf *G, const struct mesh *m, size_t *cap)
{
	size_t i;

	for (i = 0; i < G->ngeom; i++)
		if (G->geom[i].mesh == m)
			return i;
	G->geom = xreallocarray(G->geom, G->ngeom + 1, sizeof(*G->geom));
	G->geom[i] = (struct geometry){ m, G->naccessors };
	add_accessor(G, cap, 12.0 * (double)m->nvert);
	add_accessor(G, cap, 12.0 * (double)m->nvert);
	for (size_t p = 0; p < m->nprim; p++)
		add_accessor(G, cap, 4.0 * (double)m->prim[p].nindex);
	G->ngeom++;
	return i;
}

static void
count_organ(void *ctx, const struct organ *o)
{
	((double *)ctx)[o->object]++;
}

/* The nodes of r's objects that have organs, their meshes, the layout. */
static void
gltf_plan(struct gltf *G, const struct result *r)
{
	size_t cap = 0, materials = 0;
	double *count;

	*G = (struct gltf){0};
	G->r = r;
	if (r->sub != NULL) {
		flatten_view(r, &G->view);
		G->r = &G->view;
	}
	count = xcalloc(G->r->nobjects ? G->r->nobjects : 1, sizeof(*count));
	if (G->r->flat != NULL)
		for (size_t k = 0; k < G->r->nobjects; k++)
			count[k] = result_object_organs(G->r, k);
	else
		result_each(G->r, RESULT_ALL, count_organ, count);
	G->node = xcalloc(G->r->nobjects ? G->r->nobjects : 1,
	    sizeof(*G->node));
	for (size_t k = 0; k < G->r->nobjects; k++) {
		const struct mesh *m = meshes_find(r->meshes, G->r->objects[k]);
		struct node *n;

		if (count[k] == 0)
			continue;
		if (m == NULL) {
			if (G->placeholder.nvert == 0)
				mesh_placeholder(&G->placeholder);
			m = &G->placeholder;
		}
		n = &G->node[G->nnode++];
		n->object = k;
		n->count = count[k];
		n->geometry = geometry_of(G, m, &cap);
		n->material = materials;
		materials += m->nprim;
	}
	for (size_t i = 0; i < G->nnode; i++) {
		G->node[i].accessor = G->naccessors;
		add_accessor(G, &cap, 12 * G->node[i].count);
		add_accessor(G, &cap, 16 * G->node[i].count);
		add_accessor(G, &cap, 12 * G->node[i].count);
	}
	free(count);
}

static void
gltf_free(struct gltf *G)
{
	flatten_free(&G->view);
	mesh_free(&G->placeholder);
	free(G->node);
	free(G->geom);
	free(G->view_bytes);
}

/*
 * A float in 9 digits, which read back as a float are the very float
 * the binary holds: accessor bounds must be exact.
 */
static void
put_float(struct sink *s, float x)
{
	char buf[32];

	snprintf(buf, sizeof(buf), "%.9g", (double)x);
	sink_puts(s, buf);
}

static void
put_floats(struct sink *s, const float *x, int n)
{
	sink_putc(s, '[');
	for (int i = 0; i < n; i++) {
		if (i > 0)
			sink_putc(s, ',');
		put_float(s, x[i]);
	}
	sink_putc(s, ']');
}

/* "key":n */
static void
put_key_uint(struct sink *s, const char *key, double n)
{
	sink_puts(s, key);
	sink_uint(s, (unsigned long long)n);
}

static void
put_accessor(struct sink *s, size_t i, double count, int ctype,
    const char *type, const struct mesh *bounds)
{
	put_key_uint(s, i ? ",{\"bufferView\":" : "{\"bufferView\":",
	    (double)i);
	put_key_uint(s, ",\"componentType\":", ctype);
	put_key_uint(s, ",\"count\":", count);
	sink_puts(s, ",\"type\":\"");
	sink_puts(s, type);
	sink_putc(s, '"');
	if (bounds != NULL) {
		sink_puts(s, ",\"min\":");
		put_floats(s, bounds->min, 3);
		sink_puts(s, ",\"max\":");
		put_floats(s, bounds->max, 3);
	}
	sink_putc(s, '}');
}

static void
put_accessors(struct sink *s, const struct gltf *G)
{
	size_t a = 0;

	sink_puts(s, ",\"accessors\":[");
	for (size_t g = 0; g < G->ngeom; g++) {
		const struct mesh *m = G->geom[g].mesh;

		put_accessor(s, a++, (double)m->nvert, GL_FLOAT, "VEC3", m);
		put_accessor(s, a++, (double)m->nvert, GL_FLOAT, "VEC3", NULL);
		for (size_t p = 0; p < m->nprim; p++)
			put_accessor(s, a++, (double)m->prim[p].nindex,
			    GL_UNSIGNED_INT, "SCALAR", NULL);
	}
	for (size_t i = 0; i < G->nnode; i++) {
		put_accessor(s, a++, G->node[i].count, GL_FLOAT, "VEC3", NULL);
		put_accessor(s, a++, G->node[i].count, GL_FLOAT, "VEC4", NULL);
		put_accessor(s, a++, G->node[i].count, GL_FLOAT, "VEC3", NULL);
	}
	sink_putc(s, ']');
}

static void
put_view(struct sink *s, const struct gltf *G, size_t a, double *offset,
    int target)
{
	put_key_uint(s, a ? ",{\"buffer\":0,\"byteOffset\":" :
	    "{\"buffer\":0,\"byteOffset\":", *offset);
	put_key_uint(s, ",\"byteLength\":", G->view_bytes[a]);
	if (target != 0)
		put_key_uint(s, ",\"target\":", target);
	sink_putc(s, '}');
	*offset += G->view_bytes[a];
}

/*
 * One buffer view an accessor, tightly packed: the vertices' and the
 * indices' say so; the organs' are no vertex data of core glTF.
 */
static void
put_buffer_views(struct sink *s, const struct gltf *G)
{
	double offset = 0;
	size_t a = 0;

	sink_puts(s, ",\"bufferViews\":[");
	for (size_t g = 0; g < G->ngeom; g++) {
		const struct mesh *m = G->geom[g].mesh;

		for (size_t i = 0; i < geometry_accessors(m); i++)
			put_view(s, G, a++, &offset, i < 2 ?
			    GL_ARRAY_BUFFER : GL_ELEMENT_ARRAY_BUFFER);
	}
	while (a < G->naccessors)
		put_view(s, G, a++, &offset, 0);
	sink_putc(s, ']');
}

static void
put_meshes(struct sink *s, const struct gltf *G)
{
	sink_puts(s, ",\"meshes\":[");
	for (size_t i = 0; i < G->nnode; i++) {
		const struct node *n = &G->node[i];
		const struct geometry *g = &G->geom[n->geometry];
		size_t idx = g->accessor + 2;

		sink_puts(s, i ? ",{\"name\":" : "{\"name\":");
		json_string(s, G->r->objects[n->object]);
		sink_puts(s, ",\"primitives\":[");
		for (size_t p = 0; p < g->mesh->nprim; p++) {
			put_key_uint(s, p ? ",{\"attributes\":{\"POSITION\":" :
			    "{\"attributes\":{\"POSITION\":",
			    (double)g->accessor);
			put_key_uint(s, ",\"NORMAL\":",
			    (double)g->accessor + 1);
			put_key_uint(s, "},\"indices\":", (double)(idx + p));
			put_key_uint(s, ",\"material\":", (double)(n->material +
			    p));
			sink_putc(s, '}');
		}
		sink_puts(s, "]}");
	}
	sink_putc(s, ']');
}

/*
 * A material a primitive: the .mtl's Kd, or the object's hue as the SVG
 * shows it.  Not metal (glTF's default is), and two-sided: a petal is
 * often one sheet, and POV-Ray and Blender show both its sides.
 */
static void
put_materials(struct sink *s, const struct gltf *G)
{
	int first = 1;

	sink_puts(s, ",\"materials\":[");
	for (size_t i = 0; i < G->nnode; i++) {
		const struct node *n = &G->node[i];
		const struct mesh *m = G->geom[n->geometry].mesh;

		for (size_t p = 0; p < m->nprim; p++) {
			const struct mesh_prim *pr = &m->prim[p];
			float c[4] = { 0, 0, 0, 1 };

			if (pr->colored)
				memcpy(c, pr->color, sizeof(c));
			else
				mesh_hue_color(n->object, c);
			sink_puts(s, first ? "{\"name\":" : ",{\"name\":");
			json_string(s, pr->material[0] != '\0' ? pr->material :
			    G->r->objects[n->object]);
			sink_puts(s, ",\"pbrMetallicRoughness\":{"
			    "\"baseColorFactor\":");
			put_floats(s, c, 4);
			sink_puts(s, ",\"metallicFactor\":0,"
			    "\"roughnessFactor\":0.6},\"doubleSided\":true");
			if (c[3] < 1)
				sink_puts(s, ",\"alphaMode\":\"BLEND\"");
			sink_putc(s, '}');
			first = 0;
		}
	}
	sink_putc(s, ']');
}

/* The structure is the root node; each object with organs its child. */
static void
put_nodes(struct sink *s, const struct gltf *G, const struct result *r)
{
	sink_puts(s, ",\"scene\":0,\"scenes\":[{\"name\":");
	json_string(s, r->name);
	sink_puts(s, ",\"nodes\":[0]}],\"nodes\":[{\"name\":");
	json_string(s, r->name);
	for (size_t i = 0; i < G->nnode; i++) {
		sink_puts(s, i ? "," : ",\"children\":[");
		sink_uint(s, i + 1);
	}
	sink_puts(s, G->nnode ? "]}" : "}");
	for (size_t i = 0; i < G->nnode; i++) {
		const struct node *n = &G->node[i];

		sink_puts(s, ",{\"name\":");
		json_string(s, G->r->objects[n->object]);
		put_key_uint(s, ",\"mesh\":", (double)i);
		put_key_uint(s, ",\"extensions\":{\"EXT_mesh_gpu_instancing\":"
		    "{\"attributes\":{\"TRANSLATION\":", (double)n->accessor);
		put_key_uint(s, ",\"ROTATION\":", (double)n->accessor + 1);
		put_key_uint(s, ",\"SCALE\":", (double)n->accessor + 2);
		sink_puts(s, "}}}}");
	}
	sink_putc(s, ']');
}

/* The JSON chunk's text, unpadded. */
static void
put_json(struct sink *s, const struct gltf *G, const struct result *r)
{
	sink_puts(s, "{\"asset\":{\"version\":\"2.0\",\"generator\":"
	    "\"phyllo-export " VERSION "\"},"
	    "\"extensionsUsed\":[\"EXT_mesh_gpu_instancing\"],"
	    "\"extensionsRequired\":[\"EXT_mesh_gpu_instancing\"]");
	put_nodes(s, G, r);
	if (G->nnode > 0) {
		put_meshes(s, G);
		put_materials(s, G);
		put_key_uint(s, ",\"buffers\":[{\"byteLength\":", G->bin);
		sink_puts(s, "}]");
		put_buffer_views(s, G);
		put_accessors(s, G);
	}
	sink_puts(s, "}");
}

/* The whole file's bytes: header, JSON chunk padded to 4, BIN chunk. */
static double
glb_bytes(double json, double bin)
{
	return 12 + 8 + 4 * ceil(json / 4) + (bin > 0 ? 8 + bin : 0);
}

double
gltf_bytes(const struct result *r, unsigned opts)
{
	struct gltf G;
	struct sink s;
	double n;

	(void)opts;
	gltf_plan(&G, r);
	sink_init_count(&s);
	put_json(&s, &G, r);
	n = glb_bytes(sink_bytes(&s), G.bin);
	sink_free(&s);
	gltf_free(&G);
	return n;
}

/* Bytes of the BIN chunk, gathered before they go to the sink. */
struct stream {
	struct sink	*s;
	int		 what;		/* 0 TRANSLATION, 1 ROTATION, 2 SCALE */
	size_t		 len;
	unsigned char	 buf[16 * 4096];
};

static void
flush(struct stream *S)
{
	sink_write(S->s, (const char *)S->buf, S->len);
	S->len = 0;
}

/* Little-endian, as glTF's binary is, whatever the machine's order. */
static void
put_u32(struct stream *S, uint32_t u)
{
	unsigned char *p;

	if (S->len + 4 > sizeof(S->buf))
		flush(S);
	p = S->buf + S->len;
	p[0] = (unsigned char)u;
	p[1] = (unsigned char)(u >> 8);
	p[2] = (unsigned char)(u >> 16);
	p[3] = (unsigned char)(u >> 24);
	S->len += 4;
}

static void
put_f32(struct stream *S, double x)
{
	float f = (float)x;
	uint32_t u;

	memcpy(&u, &f, sizeof(u));
	put_u32(S, u);
}

/*
 * The rotation taking the organ mesh's axes to the organ's in glTF's
 * world, as a unit quaternion (x, y, z, w).  Its matrix has columns
 * C u, C w and C (u x w) = -C v, C our Z-up frame to glTF's Y-up one,
 * (x, y, z) -> (x, z, -y).  Shepperd's method: from the largest of
 * the four squares, so that nothing is divided by a small number.
 */
static void
rotation(const struct organ *o, double q[4])
{
	double v[3], R[3][3], t, d;
	const double *col[3];

	organ_v(o, v);
	col[0] = o->u;
	col[1] = o->w;
	col[2] = v;
	for (int c = 0; c < 3; c++) {
		double sign = c == 2 ? -1 : 1;

		R[0][c] = sign * col[c][0];
		R[1][c] = sign * col[c][2];
		R[2][c] = -sign * col[c][1];
	}
	t = R[0][0] + R[1][1] + R[2][2];
	if (t > 0) {
		d = 2 * sqrt(1 + t);
		q[3] = d / 4;
		q[0] = (R[2][1] - R[1][2]) / d;
		q[1] = (R[0][2] - R[2][0]) / d;
		q[2] = (R[1][0] - R[0][1]) / d;
	} else if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
		d = 2 * sqrt(1 + R[0][0] - R[1][1] - R[2][2]);
		q[3] = (R[2][1] - R[1][2]) / d;
		q[0] = d / 4;
		q[1] = (R[0][1] + R[1][0]) / d;
		q[2] = (R[0][2] + R[2][0]) / d;
	} else if (R[1][1] > R[2][2]) {
		d = 2 * sqrt(1 + R[1][1] - R[0][0] - R[2][2]);
		q[3] = (R[0][2] - R[2][0]) / d;
		q[0] = (R[0][1] + R[1][0]) / d;
		q[1] = d / 4;
		q[2] = (R[1][2] + R[2][1]) / d;
	} else {
		d = 2 * sqrt(1 + R[2][2] - R[0][0] - R[1][1]);
		q[3] = (R[1][0] - R[0][1]) / d;
		q[0] = (R[0][2] + R[2][0]) / d;
		q[1] = (R[1][2] + R[2][1]) / d;
		q[2] = d / 4;
	}
	/* Unit length to the last bit the frame's rounding left, w >= 0. */
	d = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
	if (q[3] < 0)
		d = -d;
	for (int i = 0; i < 4; i++)
		q[i] /= d;
}

/* One organ's TRANSLATION, ROTATION or SCALE. */
static void
instance(void *ctx, const struct organ *o)
{
	struct stream *S = ctx;
	double q[4];

	switch (S->what) {
	case 0:
		put_f32(S, o->pos[0]);
		put_f32(S, o->pos[2]);
		put_f32(S, -o->pos[1]);
		break;
	case 1:
		rotation(o, q);
		for (int i = 0; i < 4; i++)
			put_f32(S, q[i]);
		break;
	default:
		for (int i = 0; i < 3; i++)
			put_f32(S, o->scale);
		break;
	}
}

static void
put_geometry(struct stream *S, const struct mesh *m)
{
	for (size_t i = 0; i < m->nvert; i++)
		for (int k = 0; k < 3; k++)
			put_f32(S, m->pos[i][k]);
	for (size_t i = 0; i < m->nvert; i++)
		for (int k = 0; k < 3; k++)
			put_f32(S, m->normal[i][k]);
	for (size_t p = 0; p < m->nprim; p++)
		for (size_t i = 0; i < m->prim[p].nindex; i++)
			put_u32(S, m->prim[p].index[i]);
}

void
gltf_write(struct sink *s, const struct result *r, unsigned opts)
{
	struct stream *S = xmalloc(sizeof(*S));
	struct gltf G;
	struct sink json;
	double total;

	(void)opts;
	gltf_plan(&G, r);
	sink_init(&json, NULL);
	put_json(&json, &G, r);
	while (json.len % 4 != 0)
		sink_putc(&json, ' ');
	total = glb_bytes((double)json.len, G.bin);
	/* A .glb says its length in 32 bits: 4 GiB at most. */
	if (total > UINT32_MAX) {
		s->err = EFBIG;
		goto out;
	}
	*S = (struct stream){ s, 0, 0, { 0 } };
	put_u32(S, GLB_MAGIC);
	put_u32(S, 2);
	put_u32(S, (uint32_t)total);
	put_u32(S, (uint32_t)json.len);
	put_u32(S, GLB_JSON);
	flush(S);
	sink_write(s, json.buf, json.len);
	if (G.bin > 0) {
		put_u32(S, (uint32_t)G.bin);
		put_u32(S, GLB_BIN);
	}
	for (size_t g = 0; g < G.ngeom; g++)
		put_geometry(S, G.geom[g].mesh);
	for (size_t i = 0; i < G.nnode; i++)
		for (S->what = 0; S->what < 3; S->what++)
			result_each(G.r, G.node[i].object, instance, S);
	flush(S);
out:
	free(S);
	sink_free(&json);
	gltf_free(&G);
}
