/* writer.h - the output formats; each is one file and one table entry. */
#ifndef WRITER_H
#define WRITER_H

#include "organ.h"
#include "scene.h"
#include "sink.h"
#include "template.h"

/*
 * Writers only read the result; errors in the sink are the caller's.
 * opts: the TO_* options the writer takes (template.h).
 */
typedef void writer_fn(struct sink *, const struct result *, unsigned opts);

/*
 * A format writes either through its own function, or from a template
 * with its own placeholders; check() refuses names it cannot carry.
 */
struct writer {
	const char	*name;	/* its option, without the dashes */
	writer_fn	*write;
	const char	*tmpl;	/* default template in templates/ */
	const char	*arrays_tmpl;	/* --arrays: this one instead */
	unsigned	 opts;		/* TO_* options it takes */
	const struct tmpl_var *vars;
	int		(*check)(const struct scene *);
	const char	*help;
};

/* Every format, ending with a NULL name (writers.c). */
extern const struct writer writers[];

writer_fn csv_write;
writer_fn info_write;
writer_fn svg_write;

extern const struct tmpl_var pov_vars[];
int	pov_check(const struct scene *);
extern const struct tmpl_var blender_vars[];

#endif
