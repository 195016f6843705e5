/*
 * table.h - how settings are described: each group of the scene
 * file (the top level, a model's group, a receptacle, an organs entry)
 * is one table of rows over one C struct.  The loader walks the tables
 * (scene/scene_tables.c, each value by its type in scene_values.c), so
 * parsing, defaults, validation, freeing and the man page's list cannot
 * drift apart.  Here, below everything that has a table, so that a
 * model or a receptacle describes its settings without the loader.
 */
#ifndef TABLE_H
#define TABLE_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

enum type {
	T_GROUP,	/* a group: the struct at off, described by sub */
	T_INT,		/* long long */
	T_FLOAT,	/* double; integers are accepted */
	T_IDENT,	/* char[NAME_LEN + 1], [A-Za-z][A-Za-z0-9_]* */
	T_CHOICE,	/* int: index into the row's words */
	T_EXPR,		/* struct expr_setting (expr.h): number or expression */
	T_NAMES,	/* an identifier or an array of them (variants) */
	T_WEIGHTS,	/* an array of numbers, one per variant */
	T_INTS,		/* struct int_list: 2 or 3 positive integers */
	T_POINTS,	/* struct point_list: (x, y) pairs of numbers */
	T_RANGES,	/* the organs list: entries described by sub */
	T_MODEL,	/* the model's name, from the registry (model.h) */
	T_VEC3,		/* double[3]: [x, y, z] */
	T_FILES		/* a file name or an array of them, one per variant */
};

#define COUNT_MAX	10000000	/* most organs a scene may ask for */

/* The values of settings, by type, as the structs tables describe hold them. */

/* A short array of integers, [8, 13] or [8, 13, 21] (T_INTS). */
struct int_list {
	int		 v[3];
	int		 n;
};

#define PROFILE_POINTS_MAX	3001	/* 1000 Bezier segments */

/* A list of (x, y) points, such as a receptacle's profile (T_POINTS). */
struct point_list {
	double		(*p)[2];	/* owned */
	int		 n;
};

#define VARIANTS_MAX	256		/* objects in one organs entry */

/* File names, one per variant of an entry (T_FILES). */
struct file_list {
	char		**v;		/* owned, or NULL: not given */
	size_t		 n;
};

#define F_LO_OPEN	0x01	/* lo itself is not allowed */

struct table;

struct row {
	const char	*name;	/* this part of the path: "scale" */
	enum type	 type;
	size_t		 off;	/* into the struct its table describes */
	const struct table *sub; /* T_GROUP, T_RANGES: their rows */
	double		 lo, hi;	/* numbers: the allowed range */
	unsigned	 flags;
	double		 def;		/* numbers and choices: default */
	const char	*defstr;	/* as the man page says it */
	const char *const *words;	/* T_CHOICE: NULL-terminated */
	unsigned	 vars;		/* T_EXPR: the variables it may use */
	const char	*unit;		/* "degrees", "length", ... or NULL */
	const char	*doc;
};

#define PATH_LEN	96	/* longest dotted path of a setting */

/*
 * Every struct a table describes begins its bookkeeping with this: where
 * the group was given and the path the user wrote, for messages, then
 * an int given[] with the line of each row given, or 0.
 */
struct group_at {
	int		 line;		/* 0: the group was not given */
	char		 path[PATH_LEN];	/* "area.receptacle"; "" on top */
};

struct table {
	const struct row *rows;
	size_t		 n;
	size_t		 at;	/* offset of the struct group_at */
	size_t		 given;	/* offset of int given[n] */
};

#define TABLE(rows_, type_) { (rows_), sizeof(rows_) / sizeof((rows_)[0]), \
	offsetof(type_, at), offsetof(type_, given) }

/* The line to report a problem with row id of p at: its own, else its group's. */
#define GIVEN_AT(p, id)	((p)->given[id] ? (p)->given[id] : \
	(p)->at.line > 0 ? (p)->at.line : 1)

/*
 * A problem with a setting given at line of file (0: at its start):
 * what scene_error() and model_error() print.
 */
void	settings_verror(const char *file, int line, const char *fmt, va_list);

/* The line row name of obj (described by tab) was given at; 0: not given. */
int	settings_given(const struct table *tab, const void *obj,
	    const char *name);

/* A row's type as the man page names it: "number", "expression", ... */
const char *settings_type(const struct row *);

#endif
