/*
 * check.h - the test programs' one way of reporting: a line "ok - ..."
 * or "not ok - ..." per check, which tests/run.sh counts, and an exit
 * status saying whether any failed.  Each program sets check_topic.
 * Beside it, the property helpers more than one program uses.
 */
#ifndef CHECK_H
#define CHECK_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/vec.h"
#include "result/organ.h"

static const char *check_topic = "";
static int check_failures;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void
check(int ok, const char *fmt, ...)
{
	va_list ap;

	printf("%s - %s", ok ? "ok" : "not ok", check_topic);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	putchar('\n');
	check_failures += !ok;
}

/* Value k of a result's --info line key, NaN if there is none. */
static inline double
info(const struct result *r, const char *key, int k)
{
	for (int i = 0; i < r->ninfo; i++)
		if (strcmp(r->info[i].key, key) == 0)
			return r->info[i].val[k];
	return NAN;
}

/* Largest deviation from an orthonormal right-handed frame. */
static inline double
frame_error(const struct organ *o)
{
	double c[3], v[3], e = 0;

	organ_v(o, v);
	e = fmax(e, fabs(vec_dot(o->u, o->u) - 1));
	e = fmax(e, fabs(vec_dot(v, v) - 1));
	e = fmax(e, fabs(vec_dot(o->w, o->w) - 1));
	e = fmax(e, fabs(vec_dot(o->u, v)));
	e = fmax(e, fabs(vec_dot(o->u, o->w)));
	e = fmax(e, fabs(vec_dot(v, o->w)));
	vec_cross(c, o->u, v);
	for (int i = 0; i < 3; i++)
		e = fmax(e, fabs(c[i] - o->w[i]));
	return e;
}

#endif
