/*
 * receptacle.h - a surface of revolution about Z as a setting any model
 * may take: receptacle = { profile = (...); } or { shape = "..."; },
 * turned into cubic Bezier control points of its generating curve.
 */
#ifndef RECEPTACLE_H
#define RECEPTACLE_H

#include "base/table.h"

/* The presets (receptacle.shape). */
enum shape {
	SHAPE_DISK,
	SHAPE_CONE,
	SHAPE_HEMISPHERE,
	SHAPE_SPHERE,
	SHAPE_CYLINDER,
	SHAPE_ELLIPSOID,
	SHAPE_CAP
};

enum { RC_PROFILE, RC_SHAPE, RC_RADIUS, RC_HEIGHT, RC__N };

struct receptacle {
	struct group_at	 at;
	int		 given[RC__N];
	struct point_list profile;
	int		 shape;		/* enum shape, if given */
	double		 radius;	/* of a preset, at its widest */
	double		 height;	/* of a preset */
};

/* Its group's rows: { .type = T_GROUP, .sub = &receptacle_table }. */
extern const struct table receptacle_table;

/*
 * 3k+1 (radius, height) points, base first, owned by the caller; NULL
 * after a diagnostic naming the settings as the scene file (file) wrote
 * them.
 */
double	(*receptacle_points(const char *file, const struct receptacle *,
	    int *n))[2];

struct curve;

/*
 * The same made the curve cv (curve.h), to be freed with curve_free();
 * 0, or -1 after a diagnostic.
 */
int	receptacle_curve(const char *file, const struct receptacle *,
	    struct curve *cv);

#endif
