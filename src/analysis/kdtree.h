/* kdtree.h - the nearest organs to a point: a k-d tree over positions. */
#ifndef KDTREE_H
#define KDTREE_H

#include <stddef.h>

#include "result/organ.h"

#define KD_K	8	/* neighbours a search finds: a lattice point has 6 */

/*
 * The organs' positions, copied so that a search reads them in order
 * and not through 120-byte organs; reordered as the tree is built, so
 * that points near in space are near in memory.
 */
struct kd_pt {
	double		 p[3];
	size_t		 i;	/* the organ */
};

struct kd {
	struct kd_pt	*pt;
	size_t		 n;
	struct kd_node	*node;
	size_t		 nnode, cap;
};

/*
 * The KD_K nearest found, sorted by distance, then by index; d2 is the
 * squared distance in units of 1 / inv, a power of two near the point's
 * size (kdtree.c says why), so sqrt(d2[k]) / inv is the distance.
 */
struct kd_near {
	size_t		 j[KD_K];
	double		 d2[KD_K];
	int		 n;
	double		 inv;
};

void	kd_init(struct kd *, const struct result *);
/* The same over points p[0 .. n), organ i being p[i]. */
void	kd_init_points(struct kd *, const double (*p)[3], size_t n);
void	kd_free(struct kd *);

/*
 * The KD_K nearest to p but organ self, or of those before self if
 * earlier; self SIZE_MAX (no organ) for the nearest to a place.
 */
void	kd_nearest(const struct kd *, const double p[3], size_t self,
	    int earlier, struct kd_near *);

#endif
