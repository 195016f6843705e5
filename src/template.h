/* template.h - output written from user-editable templates with @PLACEHOLDERS@. */
#ifndef TEMPLATE_H
#define TEMPLATE_H

#include <stddef.h>

#include "organ.h"
#include "sink.h"

#define TMPL_BYTES_MAX	(1024 * 1024)

/* Where a placeholder may stand; a mask of these. */
#define TS_GLOBAL	0x1	/* anywhere */
#define TS_OBJECT	0x2	/* inside @@objects: once per organ object */
#define TS_ORGAN	0x4	/* inside @@organs: once per organ */

/* Writer options a template may read. */
#define TO_OBJECTS	0x1	/* --blender-objects */
#define TO_FLATTEN	0x2	/* --flatten: every leaf organ, in the world */
#define TO_ANIMATE	0x4	/* --frames: one file animating every frame */
#define TO_SHALLOW	0x8	/* parts one level deep: their parts merged */

struct tmpl_ctx {
	const struct result	*r;
	unsigned		 opts;		/* TO_* */
	int			 scope;		/* TS_* being written */
	size_t			 object;	/* in TS_OBJECT */
	size_t			 organ;		/* in TS_ORGAN */
	const struct result *const *all;	/* every structure, the
						   main last */
	size_t			 nall;
};

typedef void tmpl_put_fn(struct sink *, const struct tmpl_ctx *);

/* A placeholder: its name without the @s, where it may stand, its value. */
struct tmpl_var {
	const char	*name;
	int		 scopes;
	tmpl_put_fn	*put;
};

struct tmpl;

struct tmpl	*tmpl_load(const char *path, const struct tmpl_var *extra);
struct tmpl	*tmpl_builtin(const char *name, const struct tmpl_var *extra);
struct tmpl	*tmpl_parse(const char *file, const char *text, size_t len,
		    const struct tmpl_var *extra);
/*
 * Write the structures all[0 .. n-1]: parts before the structures using
 * them, frame by frame; outside @@structures the last one is meant.
 */
void		 tmpl_write(const struct tmpl *, struct sink *,
		    const struct result *const *all, size_t n, unsigned opts);
/* Whether it has a @@structures block (else it writes the main alone). */
int		 tmpl_structures(const struct tmpl *);
void		 tmpl_free(struct tmpl *);

/* Helpers for writers' placeholders. */
const struct organ *tmpl_organ(const struct tmpl_ctx *);

/* The templates compiled into the program (build/builtin.c). */
struct builtin_template {
	const char		*name;
	const unsigned char	*text;
	size_t			 len;
};
extern const struct builtin_template builtin_templates[];

#endif
