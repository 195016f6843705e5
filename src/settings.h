/* settings.h - the table of scene settings, shared by the loader and its checks. */
#ifndef SETTINGS_H
#define SETTINGS_H

#include <stddef.h>

#include "scene.h"

enum type {
	T_GROUP,	/* a group of further settings */
	T_INT,		/* long long */
	T_FLOAT,	/* double; integers are accepted */
	T_IDENT,	/* char[NAME_LEN + 1], [A-Za-z][A-Za-z0-9_]* */
	T_CHOICE,	/* int: index into the row's word list */
	T_EXPR,		/* struct expr_setting: a number or an expression */
	T_NAMES,	/* an identifier or an array of them (variants) */
	T_WEIGHTS,	/* an array of numbers, one per variant */
	T_INTS,		/* an array of 2 or 3 positive integers */
	T_POINTS,	/* a list of (x, y) pairs of numbers */
	T_RANGES	/* the organs list: struct organ_range entries */
};

enum where {
	IN_SCENE,	/* offset into struct scene */
	IN_RANGE	/* offset into struct organ_range */
};

#define F_LO_OPEN	0x01	/* lo itself is not allowed */
#define F_REQUIRED	0x02	/* every scene must give it */

#define PLANAR		(1u << MODEL_PLANAR)
#define CYL		(1u << MODEL_CYLINDRICAL)
#define COLL		(1u << MODEL_COLLISION)

struct row {
	const char	*path;	/* dotted, e.g. "planar.scale" */
	enum type	 type;
	enum where	 where;
	unsigned	 models;	/* models it applies to; 0: all */
	size_t		 off;
	double		 lo, hi;	/* numbers: the allowed range */
	unsigned	 flags;
	double		 def;		/* numbers and choices: default */
	const char	*defstr;	/* as the man page says it */
	const char	*words;		/* T_CHOICE: space-separated */
	unsigned	 vars;		/* T_EXPR: the variables it may use */
	const char	*doc;
};

extern const struct row rows[];
extern const size_t nrows;

const struct row *row_find(const char *path, enum where);

#endif
