/* scene.h - a scene file, loaded and checked against the settings table. */
#ifndef SCENE_H
#define SCENE_H

#include <stdio.h>

#include "expr.h"

#define NAME_LEN	32		/* longest name or organ object name */
#define COUNT_MAX	10000000	/* most organs a scene may ask for */
#define SCENE_BYTES_MAX	(16L * 1024 * 1024)

enum model {
	MODEL_PLANAR,
	MODEL_CYLINDRICAL,
	MODEL_COLLISION,
	MODEL__MAX
};

struct planar_params {
	double	 scale;		/* Vogel's c */
	double	 outer;		/* fit c so the last organ sits here */
	double	 inner;		/* radius of the first ring */
	double	 exponent;	/* r = inner + c n^exponent */
	double	 dome;		/* height of the centre above the rim */
};

/* A number or expression setting, and where it was given. */
struct expr_setting {
	struct expr	*e;		/* NULL: not given */
	int		 line;
};

/* A short array of integers, [8, 13] or [8, 13, 21]. */
struct int_list {
	int		 v[3];
	int		 n;
};

/* The collision model's receptacle presets (collision.receptacle.shape). */
enum shape {
	SHAPE_DISK,
	SHAPE_CONE,
	SHAPE_HEMISPHERE,
	SHAPE_SPHERE,
	SHAPE_CYLINDER,
	SHAPE_ELLIPSOID,
	SHAPE_CAP
};

#define PROFILE_POINTS_MAX	3001	/* 1000 Bezier segments */

/* A list of (radius, height) points: the receptacle's profile. */
struct point_list {
	double		(*p)[2];	/* owned */
	int		 n;
};

struct coll_params {
	struct point_list profile;
	int		 shape;		/* enum shape, if given */
	double		 width;		/* receptacle.radius of a preset */
	double		 height;	/* receptacle.height of a preset */
	struct expr_setting radius;	/* of primordium n */
	struct expr_setting epsilon;	/* how far t may fall back */
};

struct cyl_params {
	struct expr_setting radius;	/* of the cylinder; may vary */
	struct int_list	 parastichies;
	double		 rise;		/* on a cylinder of radius 1 */
	double		 length;
};

#define VARIANTS_MAX	256		/* objects in one organs entry */
#define RANGES_MAX	1024		/* entries in organs */

/* One entry of organs = ( ... ): an index range and what its organs are. */
struct organ_range {
	int		 line;
	long long	 from, to;	/* inclusive; to = -1: the last */
	char		(*names)[NAME_LEN + 1];	/* object variants, owned */
	size_t		 nnames;
	unsigned	*ids;		/* names as indices into objects */
	double		*weights;	/* one per name, or NULL */
	size_t		 nweights;
	int		 weights_line;
	struct expr_setting scale, altitude, tilt, roll;
};

struct scene {
	const char	*file;		/* as named in messages */
	char		 name[NAME_LEN + 1];
	int		 model;		/* enum model */
	double		 divergence;	/* degrees */
	long long	 count;
	long long	 seed;
	struct planar_params planar;
	struct cyl_params cyl;
	struct coll_params coll;
	struct organ_range *ranges;	/* owned */
	size_t		 nranges;
	const char	**objects;	/* distinct organ object names */
	size_t		 nobjects;
	int		*given;		/* per table row: line, or 0 */
};

int	 scene_load(struct scene *, const char *path);
int	 scene_load_buffer(struct scene *, const char *file,
	    const char *text, size_t len);
void	 scene_free(struct scene *);
int	 scene_given(const struct scene *, const char *path);
void	 scene_error(const struct scene *, const char *path,
	    const char *fmt, ...)
#if defined(__GNUC__)
	    __attribute__((format(printf, 3, 4)))
#endif
	    ;
int	 scene_eval(const struct scene *, const struct expr_setting *,
	    const char *path, const char *item, struct expr_env *,
	    double *v);
const char *scene_model_name(int model);
void	 scene_settings_list(FILE *);

#endif
