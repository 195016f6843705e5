/*
 * table.c - what every settings table shares, whoever's it is: a row's
 * type as the man page names it, where a row was given, and a problem
 * with a setting reported at its line.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "base/diag.h"
#include "base/table.h"

static const char *const type_names[] = {
	[T_GROUP] = "group", [T_INT] = "integer", [T_FLOAT] = "number",
	[T_IDENT] = "identifier", [T_CHOICE] = "string",
	[T_EXPR] = "expression", [T_NAMES] = "names", [T_WEIGHTS] = "numbers",
	[T_INTS] = "integers", [T_POINTS] = "points", [T_RANGES] = "list",
	[T_MODEL] = "string", [T_VEC3] = "numbers", [T_FILES] = "files"
};

const char *
settings_type(const struct row *r)
{
	return type_names[r->type];
}

void
settings_verror(const char *file, int line, const char *fmt, va_list ap)
{
	char msg[512];

	vsnprintf(msg, sizeof(msg), fmt, ap);
	diag(ST_SCENE, file, line > 0 ? line : 1, 0, "%s", msg);
}

int
settings_given(const struct table *tab, const void *obj, const char *name)
{
	const int *given = (const int *)((const char *)obj + tab->given);

	for (size_t i = 0; i < tab->n; i++)
		if (strcmp(tab->rows[i].name, name) == 0)
			return given[i];
	return 0;
}
