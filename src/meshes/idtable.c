/*
 * idtable.c - a small open-addressed table from three numbers to an id,
 * the OBJ reader's (obj.c): a vertex is its (v, normal) pair, and a
 * computed smooth normal its (v, smoothing group).  Linear probing,
 * kept at most half full; the hash is splitmix64's finaliser.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "meshes/idtable.h"

static uint64_t
mix(uint64_t h)
{
	h ^= h >> 30;
	h *= 0xbf58476d1ce4e5b9ULL;
	h ^= h >> 27;
	h *= 0x94d049bb133111ebULL;
	return h ^ (h >> 31);
}

static void
table_grow(struct idtab *T)
{
	struct idtab_slot *old = T->slot;
	size_t oldcap = T->cap;

	T->cap = oldcap ? oldcap * 2 : 1024;
	T->slot = xcalloc(T->cap, sizeof(*T->slot));
	for (size_t i = 0; i < T->cap; i++)
		T->slot[i].id = UINT32_MAX;
	T->n = 0;
	for (size_t i = 0; i < oldcap; i++)
		if (old[i].id != UINT32_MAX)
			idtab_put(T, old[i].k, old[i].id);
	free(old);
}

static struct idtab_slot *
table_find(const struct idtab *T, const uint64_t k[3])
{
	size_t i = (size_t)mix(k[0] ^ mix(k[1] ^ mix(k[2]))) & (T->cap - 1);

	while (T->slot[i].id != UINT32_MAX && (T->slot[i].k[0] != k[0] ||
	    T->slot[i].k[1] != k[1] || T->slot[i].k[2] != k[2]))
		i = (i + 1) & (T->cap - 1);
	return &T->slot[i];
}

void
idtab_put(struct idtab *T, const uint64_t k[3], uint32_t id)
{
	struct idtab_slot *s;

	if (2 * (T->n + 1) > T->cap)
		table_grow(T);
	s = table_find(T, k);
	if (s->id == UINT32_MAX)
		T->n++;
	memcpy(s->k, k, sizeof(s->k));
	s->id = id;
}

uint32_t
idtab_get(const struct idtab *T, const uint64_t k[3])
{
	return T->cap == 0 ? UINT32_MAX : table_find(T, k)->id;
}

void
idtab_free(struct idtab *T)
{
	free(T->slot);
}
