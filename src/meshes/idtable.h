/* idtable.h - a small open-addressed table from three numbers to an id. */
#ifndef IDTABLE_H
#define IDTABLE_H

#include <stddef.h>
#include <stdint.h>

struct idtab_slot {
	uint64_t	 k[3];
	uint32_t	 id;		/* UINT32_MAX: empty */
};

/* All zero is an empty table. */
struct idtab {
	struct idtab_slot *slot;
	size_t		 cap, n;	/* cap a power of two */
};

/* k's id is id, from now on. */
void		idtab_put(struct idtab *, const uint64_t k[3], uint32_t id);
/* k's id, or UINT32_MAX. */
uint32_t	idtab_get(const struct idtab *, const uint64_t k[3]);
void		idtab_free(struct idtab *);

#endif
