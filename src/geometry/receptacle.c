/*
 * receptacle.c - a receptacle as Bezier control points: the scene's
 * own profile, checked, or one of the presets.
 * Every preset stands on z = 0 with its base first: the rim of a disk,
 * cone or cap, the bottom of a cylinder, the lower pole of a sphere or
 * an ellipsoid.  Circular arcs are cubic Bezier arcs of at most 5.625
 * degrees, within 2e-11 of the circle's radius: the area model's
 * Fibonacci sphere is then exact to 1e-9 (at 45 degrees it was 5e-6).
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/diag.h"
#include "geometry/curve.h"
#include "base/mem.h"
#include "geometry/receptacle.h"

static const char *const shape_names[] = {
	[SHAPE_DISK] = "disk", [SHAPE_CONE] = "cone",
	[SHAPE_HEMISPHERE] = "hemisphere", [SHAPE_SPHERE] = "sphere",
	[SHAPE_CYLINDER] = "cylinder", [SHAPE_ELLIPSOID] = "ellipsoid",
	[SHAPE_CAP] = "cap", NULL
};

#define RC(f)	offsetof(struct receptacle, f)

static const struct row receptacle_rows[] = {
	[RC_PROFILE] = { .name = "profile", .type = T_POINTS,
	  .off = RC(profile), .lo = 0, .hi = HUGE_VAL, .defstr = "none",
	  .doc = "3k+1 (radius, height) control points of k cubic Bezier "
	  "segments, base first" },
	[RC_SHAPE] = { .name = "shape", .type = T_CHOICE, .off = RC(shape),
	  .defstr = "none", .words = shape_names,
	  .doc = "a preset receptacle instead of a profile" },
	[RC_RADIUS] = { .name = "radius", .type = T_FLOAT, .off = RC(radius),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .def = 1,
	  .defstr = "1", .unit = "length",
	  .doc = "radius of the preset at its widest" },
	[RC_HEIGHT] = { .name = "height", .type = T_FLOAT, .off = RC(height),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .defstr = "per shape",
	  .unit = "length",
	  .doc = "height of the cone, cylinder, ellipsoid or cap" },
};

const struct table receptacle_table = TABLE(receptacle_rows,
    struct receptacle);

/* A straight segment as one Bezier segment, thirds between. */
static double (*line(double x0, double z0, double x1, double z1, int *n))[2]
{
	double (*p)[2] = xcalloc(4, sizeof(*p));

	for (int i = 0; i < 4; i++) {
		p[i][0] = x0 + (x1 - x0) * i / 3;
		p[i][1] = z0 + (z1 - z0) * i / 3;
	}
	p[3][0] = x1;
	p[3][1] = z1;
	*n = 4;
	return p;
}

/*
 * The arc (a sin th, cz + b cos th) for th from th0 to th1 (radians, th
 * measured from +z): the affine image of a circular arc, so the image
 * of its Bezier arcs.  Each arc of angle D has its inner control points
 * 4/3 tan(D/4) along the tangents.
 */
static double (*arc(double a, double b, double cz, double th0, double th1,
    int *n))[2]
{
	int k = (int)ceil(fabs(th1 - th0) / (M_PI / 32) - 1e-9);
	double (*p)[2], D, h;

	if (k < 1)
		k = 1;
	D = (th1 - th0) / k;
	h = 4.0 / 3 * tan(D / 4);
	p = xcalloc((size_t)(3 * k + 1), sizeof(*p));
	for (int i = 0; i <= k; i++) {
		double th = th0 + D * i;
		double x = sin(th), z = cos(th), dx = cos(th), dz = -sin(th);

		if (i == k) {		/* land on the end exactly */
			th = th1;
			x = sin(th);
			z = cos(th);
			dx = cos(th);
			dz = -sin(th);
		}
		p[3 * i][0] = a * x;
		p[3 * i][1] = cz + b * z;
		if (i > 0) {
			p[3 * i - 1][0] = a * (x - h * dx);
			p[3 * i - 1][1] = cz + b * (z - h * dz);
		}
		if (i < k) {
			p[3 * i + 1][0] = a * (x + h * dx);
			p[3 * i + 1][1] = cz + b * (z + h * dz);
		}
	}
	/* The poles lie on the axis, not a rounding error beside it. */
	for (int i = 0; i < 3 * k + 1; i++)
		if (fabs(p[i][0]) < 1e-15 * a)
			p[i][0] = 0;
	*n = 3 * k + 1;
	return p;
}

/* A spherical cap of base radius R and height H, rim to apex. */
static double (*cap(double R, double H, int *n))[2]
{
	double rs = (R * R + H * H) / (2 * H);

	return arc(rs, rs, H - rs, atan2(R, rs - H), 0, n);
}

static double
default_height(int shape, double R)
{
	switch (shape) {
	case SHAPE_CONE:
		return R;
	case SHAPE_CYLINDER:
		return 2 * R;
	case SHAPE_ELLIPSOID:
		return 3 * R;
	case SHAPE_CAP:
		return R / 2;
	default:
		return 2 * R;
	}
}

static double (*preset(const char *file, const struct receptacle *rc,
    int *n))[2]
{
	double R = rc->radius, H;
	int shape = rc->shape;

	if (rc->given[RC_HEIGHT] && (shape == SHAPE_DISK ||
	    shape == SHAPE_HEMISPHERE || shape == SHAPE_SPHERE)) {
		diag(ST_SCENE, file, rc->given[RC_HEIGHT], 0, "shape \"%s\" "
		    "has no height of its own; give only its radius",
		    shape_names[shape]);
		return NULL;
	}
	H = rc->given[RC_HEIGHT] ? rc->height : default_height(shape, R);
	switch (shape) {
	case SHAPE_DISK:
		return line(R, 0, 0, 0, n);
	case SHAPE_CONE:
		return line(R, 0, 0, H, n);
	case SHAPE_CYLINDER:
		return line(R, 0, R, H, n);
	case SHAPE_HEMISPHERE:
		return cap(R, R, n);
	case SHAPE_CAP:
		return cap(R, H, n);
	case SHAPE_SPHERE:
		return arc(R, R, R, M_PI, 0, n);
	case SHAPE_ELLIPSOID:
		return arc(R, H / 2, H / 2, M_PI, 0, n);
	}
	return NULL;
}

double (*receptacle_points(const char *file,
    const struct receptacle *rc, int *n))[2]
{
	const struct point_list *pl = &rc->profile;
	const char *at = rc->at.path;
	int have_profile = rc->given[RC_PROFILE] != 0;
	int have_shape = rc->given[RC_SHAPE] != 0;
	double (*p)[2];

	if (have_profile == have_shape) {
		diag(ST_SCENE, file, have_profile ? rc->given[RC_SHAPE] :
		    GIVEN_AT(rc, RC_SHAPE), 0, "give %s.profile or %s.shape, "
		    "%s", at, at, have_profile ? "not both" : "one of them");
		return NULL;
	}
	if (have_shape)
		return preset(file, rc, n);
	if (rc->given[RC_RADIUS] || rc->given[RC_HEIGHT]) {
		diag(ST_SCENE, file, rc->given[RC_RADIUS] ?
		    rc->given[RC_RADIUS] : rc->given[RC_HEIGHT], 0,
		    "%s.radius and height size a preset shape; a profile has "
		    "its own coordinates", at);
		return NULL;
	}
	if (pl->n < 4 || (pl->n - 1) % 3 != 0) {
		diag(ST_SCENE, file, rc->given[RC_PROFILE], 0, "the profile "
		    "has %d point%s; cubic Bezier segments joined end to end "
		    "take 3k+1 (4, 7, 10, ...)", pl->n, pl->n == 1 ? "" : "s");
		return NULL;
	}
	p = xcalloc((size_t)pl->n, sizeof(*p));
	memcpy(p, pl->p, (size_t)pl->n * sizeof(*p));
	*n = pl->n;
	return p;
}

int
receptacle_curve(const char *file, const struct receptacle *rc,
    struct curve *cv)
{
	double (*pts)[2];
	int npts;

	if ((pts = receptacle_points(file, rc, &npts)) == NULL)
		return -1;
	if (curve_init(cv, (const double (*)[2])pts, npts) != 0) {
		diag(ST_SCENE, file, GIVEN_AT(rc, RC_PROFILE), 0,
		    "the receptacle's profile has no length");
		free(pts);
		return -1;
	}
	free(pts);
	return 0;
}
