/* mesh.c - the placeholder mesh, the objects' preview colours, freeing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "meshes/mesh.h"
#include "base/phyllo.h"

/* The icosahedron: (0, +-1, +-t) and its cyclic turns, t the golden ratio. */
static const signed char ico_v[12][3] = {
	{ -1, 2, 0 }, { 1, 2, 0 }, { -1, -2, 0 }, { 1, -2, 0 },
	{ 0, -1, 2 }, { 0, 1, 2 }, { 0, -1, -2 }, { 0, 1, -2 },
	{ 2, 0, -1 }, { 2, 0, 1 }, { -2, 0, -1 }, { -2, 0, 1 }
};
static const unsigned char ico_f[20][3] = {
	{ 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
	{ 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
	{ 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
	{ 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 }
};

/* Vertex at the middle of a and b, on the sphere; made once per edge. */
static uint32_t
midpoint(struct mesh *m, uint32_t a, uint32_t b, uint32_t edge[][3],
    size_t *nedge)
{
	double p[3], len = 0;

	for (size_t i = 0; i < *nedge; i++)
		if ((edge[i][0] == a && edge[i][1] == b) ||
		    (edge[i][0] == b && edge[i][1] == a))
			return edge[i][2];
	for (int k = 0; k < 3; k++) {
		p[k] = ((double)m->pos[a][k] + m->pos[b][k]) / 2;
		len += p[k] * p[k];
	}
	for (int k = 0; k < 3; k++)
		m->pos[m->nvert][k] = m->normal[m->nvert][k] =
		    (float)(p[k] / sqrt(len));
	edge[*nedge][0] = a;
	edge[*nedge][1] = b;
	edge[*nedge][2] = (uint32_t)m->nvert;
	(*nedge)++;
	return (uint32_t)m->nvert++;
}

void
mesh_placeholder(struct mesh *m)
{
	const double t = (1 + sqrt(5)) / 2;
	uint32_t edge[30][3];
	size_t nedge = 0;
	struct mesh_prim *p;

	*m = (struct mesh){0};
	m->pos = xcalloc(42, sizeof(*m->pos));
	m->normal = xcalloc(42, sizeof(*m->normal));
	for (int i = 0; i < 12; i++) {
		double v[3], len = 0;

		for (int k = 0; k < 3; k++) {
			v[k] = ico_v[i][k] == 2 ? t : ico_v[i][k] == -2 ? -t :
			    ico_v[i][k];
			len += v[k] * v[k];
		}
		for (int k = 0; k < 3; k++)
			m->pos[i][k] = m->normal[i][k] = (float)(v[k] /
			    sqrt(len));
	}
	m->nvert = 12;
	m->prim = p = xcalloc(1, sizeof(*m->prim));
	m->nprim = 1;
	p->index = xcalloc(80 * 3, sizeof(*p->index));
	for (int f = 0; f < 20; f++) {
		uint32_t a = ico_f[f][0], b = ico_f[f][1], c = ico_f[f][2];
		uint32_t ab = midpoint(m, a, b, edge, &nedge);
		uint32_t bc = midpoint(m, b, c, edge, &nedge);
		uint32_t ca = midpoint(m, c, a, edge, &nedge);
		uint32_t tri[4][3] = { { a, ab, ca }, { b, bc, ab },
		    { c, ca, bc }, { ab, bc, ca } };

		memcpy(p->index + p->nindex, tri, sizeof(tri));
		p->nindex += 12;
	}
	for (size_t i = 0; i < m->nvert; i++)
		for (int k = 0; k < 3; k++) {
			m->min[k] = i == 0 || m->pos[i][k] < m->min[k] ?
			    m->pos[i][k] : m->min[k];
			m->max[k] = i == 0 || m->pos[i][k] > m->max[k] ?
			    m->pos[i][k] : m->max[k];
		}
}

/* An sRGB component, 0 .. 1, as linear light. */
static double
linear(double c)
{
	return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

void
mesh_hue_color(size_t k, float rgb[3])
{
	/* hsl(h, 70%, 45%): chroma (1 - |2l - 1|) s, lightness l. */
	const double c = (1 - fabs(2 * 0.45 - 1)) * 0.7, m = 0.45 - c / 2;
	/* The SVG's hue is a whole number of degrees. */
	double h = (double)(unsigned long long)OBJECT_HUE(k) / 60;
	double x = c * (1 - fabs(fmod(h, 2) - 1));
	double r[3];
	int s = (int)h;

	r[0] = s == 0 || s == 5 ? c : s == 1 || s == 4 ? x : 0;
	r[1] = s == 1 || s == 2 ? c : s == 0 || s == 3 ? x : 0;
	r[2] = s == 3 || s == 4 ? c : s == 2 || s == 5 ? x : 0;
	for (int i = 0; i < 3; i++)
		rgb[i] = (float)linear(r[i] + m);
}

void
mesh_free(struct mesh *m)
{
	if (m == NULL)
		return;
	for (size_t i = 0; i < m->nprim; i++)
		free(m->prim[i].index);
	free(m->prim);
	free(m->pos);
	free(m->normal);
	*m = (struct mesh){0};
}
