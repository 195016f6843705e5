/* organ.h - the seam between models and writers: an array of placed organs. */
#ifndef ORGAN_H
#define ORGAN_H

#include <stddef.h>

#include "base/phyllo.h"
#include "base/vec.h"

/*
 * One placed organ in the world frame (right-handed, Z up).  The frame
 * is orthonormal: w is the outward surface normal, u the tangent of the
 * generating curve pointing away from the tip (radially outward on a
 * disk), v = w x u, which organ_v() computes rather than the array
 * storing it (10 M organs must fit in about 1 GiB).  An organ model
 * built with its outward direction along local +X and its up along
 * local +Z lands here by the matrix [u v w] * scale + pos.
 */
struct organ {
	double		 pos[3];
	double		 u[3], w[3];
	double		 scale;		/* applied to the organ model */
	double		 radius;	/* packing/primordium radius */
	double		 phi;		/* angle about the axis, degrees */
	double		 height;	/* along the axis, before offsets */
	unsigned	 object;	/* index into result.objects */
};

/*
 * A model's own facts for --info: "key: v1 v2 ...", or with labels,
 * "key: label1 v1; label2 v2".
 */
struct info_item {
	const char	*key;
	double		 val[6];
	int		 nval;
	const char	*text;		/* a word instead of numbers (static) */
	const char	*labels;	/* one word a value (static), or NULL */
};

#define INFO_MAX 16

struct flat;
struct meshes;
struct unordered;

/* How the SVG preview shows a structure. */
enum projection {
	PROJ_TOP,	/* from above, +Y up the page */
	PROJ_UNROLL	/* unrolled: angle times radius across, height up */
};

/*
 * What a model made, with everything a writer needs to know of the
 * scene it came from, so that writers take the result alone.
 */
struct result {
	struct organ	*organs;	/* owned */
	size_t		 count;
	double		 divergence;	/* as used, degrees */
	char		 name[NAME_LEN + 1];	/* the scene's name */
	const char	*model;		/* the model's name (static) */
	long long	 seed;
	enum projection	 svg;		/* the model's preferred view */
	int		 rim_last;	/* the rim or base: the last organs */
	long long	 rays, rays_p;	/* the divergence is rays_p/rays of a
					   turn and lines organs up; or 0 */
	char		*source;	/* the scene file as named, owned */
	char		(*objects)[NAME_LEN + 1];	/* owned */
	size_t		 nobjects;
	/*
	 * A compound structure (compound.h): for each object, the result
	 * it is made of when it is a part (a sub-scene), else NULL.  The
	 * array is owned, the parts are not.  NULL when nothing is a part.
	 */
	const struct result **sub;
	/*
	 * A view of a compound with its parts opened (flatten.h): organs
	 * is NULL and the leaves are walked from here; owned, freed by
	 * flatten_free() (result_free() does not know it).
	 */
	struct flat	*flat;
	/*
	 * The organ objects' meshes (meshes.h), for writers that write
	 * them: shared by a compound's results; NULL when none were read.
	 */
	const struct meshes *meshes;
	int		 part;		/* this is a part, named for its object */
	int		 frame, frames;	/* F of how many (--frames); 1 of 1 */
	double		 frame_f;	/* f: 0 .. 1 over the frames */
	struct info_item info[INFO_MAX];
	int		 ninfo;
	/*
	 * Organs in no known order, measured without one (the measured
	 * model; analysis/unordered.h): what --info and --svg say of its
	 * spirals instead of reading them from the order.  One allocation,
	 * owned; NULL for the models, whose order is their own.
	 */
	struct unordered *unordered;
};

static inline void
organ_v(const struct organ *o, double v[3])
{
	vec_cross(v, o->w, o->u);
}

void	result_init(struct result *, size_t count);
void	result_free(struct result *);
void	result_info(struct result *, const char *key, int nval, ...);
void	result_info_text(struct result *, const char *key, const char *text);
/* A fact of values each with its label: labels "length radius". */
void	result_info_labelled(struct result *, const char *key,
	    const char *labels, int nval, ...);

#endif
