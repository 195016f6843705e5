/* template.h - output written from user-editable templates with @PLACEHOLDERS@. */
#ifndef TEMPLATE_H
#define TEMPLATE_H

#include <stddef.h>

#include "result/organ.h"
#include "base/sink.h"

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
#define TO_MESHES	0x10	/* writes the organ objects' meshes */
#define TO_SIZES	0x20	/* tells every format's size: reads what
				   each reads */
#define TO_LISTING	0x40	/* lists settings the others leave unused,
				   given or not: the loader keeps them */
#define TO_BINARY	0x80	/* bytes, not text: never to a terminal */

struct tmpl_ctx {
	const struct result	*r;
	unsigned		 opts;		/* TO_* */
	int			 scope;		/* TS_* being written */
	size_t			 object;	/* in TS_OBJECT */
	size_t			 organ;		/* in TS_ORGAN: its index, */
	const struct organ	*o;		/* and the organ */
	const struct result *const *all;	/* every structure, the
						   main last */
	size_t			 nall;
	int			 estimate;	/* counting: @@organs sampled */
};

typedef void tmpl_put_fn(struct sink *, const struct tmpl_ctx *);

/*
 * A placeholder: its name without the @s, where it may stand, its
 * value; and, for one whose value grows with the organs, the bytes it
 * writes, so that a size is estimated without writing it.
 */
struct tmpl_var {
	const char	*name;
	int		 scopes;
	tmpl_put_fn	*put;
	double		(*size)(const struct tmpl_ctx *);
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
/* How many @@structures blocks it has (none: it writes the main alone). */
int		 tmpl_structures(const struct tmpl *);

/*
 * A template of one @@structures block written in pieces, so that
 * --frames writes frame after frame without holding them: the text
 * before the block (for the main, all[n - 1]), the block for all[0 ..
 * n-1], the text after it.  Without the block, all is the head.
 */
enum tmpl_piece { TMPL_ALL, TMPL_HEAD, TMPL_BODY, TMPL_TAIL };
void		 tmpl_write_piece(const struct tmpl *, enum tmpl_piece,
		    struct sink *, const struct result *const *all, size_t n,
		    unsigned opts);
/* The bytes a piece would take, estimated without writing it. */
double		 tmpl_bytes(const struct tmpl *, enum tmpl_piece,
		    const struct result *const *all, size_t n, unsigned opts);
void		 tmpl_free(struct tmpl *);

/* The placeholders every template has (template_vars.c), NULL-ended. */
extern const struct tmpl_var tmpl_common[];

/* Helpers for writers' placeholders. */
const struct organ *tmpl_organ(const struct tmpl_ctx *);

/* The templates compiled into the program (build/builtin.c). */
struct builtin_template {
	const char		*name;
	const unsigned char	*text;
	size_t			 len;
	const char		*source;	/* the file, when built */
};
extern const struct builtin_template builtin_templates[];
/*
 * Tell input_add() the templates phyllo-export ships, installed in
 * SHAREDIR and the files the build embedded: -o replacing one would make
 * a user's output every later run's default.
 */
void	tmpl_shipped_inputs(void);

#endif
