/*
 * fuzz_obj.c - libFuzzer harness for the OBJ reader and the .mtl
 * reader, and for the glTF writer on whatever mesh the reader makes:
 * every mesh it accepts must hold together (indices in range, unit
 * normals, finite bounds), and the .glb made of it must say its own
 * length, the length --info estimated.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "meshes/mesh.h"
#include "meshes/meshes.h"
#include "meshes/mtl.h"
#include "meshes/obj.h"
#include "writers/writer.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void
check_mesh(const struct mesh *m)
{
	if (m->nvert == 0 || m->nprim == 0)
		abort();
	for (size_t i = 0; i < m->nvert; i++) {
		double len = 0;

		for (int k = 0; k < 3; k++) {
			if (!isfinite(m->pos[i][k]) || m->pos[i][k] < m->min[k] ||
			    m->pos[i][k] > m->max[k])
				abort();
			len += (double)m->normal[i][k] * m->normal[i][k];
		}
		if (fabs(len - 1) > 1e-5)
			abort();	/* glTF wants unit normals */
	}
	for (size_t p = 0; p < m->nprim; p++) {
		if (m->prim[p].nindex == 0 || m->prim[p].nindex % 3 != 0)
			abort();
		for (size_t i = 0; i < m->prim[p].nindex; i++)
			if (m->prim[p].index[i] >= m->nvert)
				abort();
	}
}

/* Three organs of the mesh, written as --gltf writes them. */
static void
check_gltf(const struct mesh *m)
{
	char name[1][NAME_LEN + 1] = { "Organ" };
	struct organ o[3];
	struct object_mesh om = { "Organ", m };
	struct meshes M = { &om, 1, 0 };
	struct result r = {0};
	struct sink s;
	uint32_t len;

	memset(o, 0, sizeof(o));
	for (int i = 0; i < 3; i++) {
		o[i].pos[0] = i;
		o[i].u[0] = 1;
		o[i].w[2] = 1;
		o[i].scale = 0.5;
	}
	r.organs = o;
	r.count = 3;
	r.objects = name;
	r.nobjects = 1;
	r.meshes = &M;
	strcpy(r.name, "Fuzz");
	sink_init(&s, NULL);
	gltf_write(&s, &r, 0);
	if (s.err != 0 || s.len < 12)
		abort();
	memcpy(&len, s.buf + 8, sizeof(len));	/* little-endian here */
	if (len != s.len || gltf_bytes(&r, 0) != (double)s.len)
		abort();
	sink_free(&s);
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct mesh m;
	struct mtl_material *mats = NULL;
	size_t nmats = 0;

	if (obj_parse(&m, "fuzz.obj", (const char *)data, size, NULL,
	    NULL) == 0) {
		check_mesh(&m);
		check_gltf(&m);
		mesh_free(&m);
	}
	if (mtl_parse(&mats, &nmats, "fuzz.mtl", (const char *)data,
	    size) == 0)
		for (size_t i = 0; i < nmats; i++)
			for (int k = 0; k < 4; k++)
				if (!(mats[i].color[k] >= 0 &&
				    mats[i].color[k] <= 1))
					abort();
	free(mats);
	return 0;
}
