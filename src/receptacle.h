/* receptacle.h - the collision model's receptacle as Bezier control points. */
#ifndef RECEPTACLE_H
#define RECEPTACLE_H

#include "scene.h"

/* 3k+1 (radius, height) points, owned by the caller; NULL after a diagnostic. */
double	(*receptacle_points(const struct scene *, int *n))[2];

#endif
