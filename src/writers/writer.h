/* writer.h - the output formats; each is one file and one table entry. */
#ifndef WRITER_H
#define WRITER_H

#include "result/organ.h"
#include "scene/scene.h"
#include "base/sink.h"
#include "writers/template.h"

/*
 * Writers only read the result; errors in the sink are the caller's.
 * opts: the TO_* options the writer takes (template.h).
 */
typedef void writer_fn(struct sink *, const struct result *, unsigned opts);
/* The bytes a writer_fn would write, estimated without writing them. */
typedef double writer_bytes_fn(const struct result *, unsigned opts);

struct compound;
struct override;
/*
 * A format written from the scenes as read, placing nothing (--settings,
 * --cfg): the compound loaded with every setting kept as written, and
 * the overrides; 0, or -1 after a diagnostic.
 */
typedef int scenes_fn(struct sink *, const struct compound *,
    const struct override *, int nset);

/*
 * A format writes either through its own function, or from a template
 * with its own placeholders; check() refuses names it cannot carry.
 */
struct writer {
	const char	*name;	/* its option, without the dashes */
	writer_fn	*write;
	writer_bytes_fn	*bytes;	/* with write */
	scenes_fn	*scenes;	/* instead of both */
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
writer_fn gltf_write;
writer_fn info_write;
writer_fn svg_write;
writer_bytes_fn csv_bytes;
writer_bytes_fn gltf_bytes;
writer_bytes_fn info_bytes;
writer_bytes_fn svg_bytes;
scenes_fn settings_write;
scenes_fn cfg_write;

extern const struct tmpl_var pov_vars[];
int	pov_check(const struct scene *);
extern const struct tmpl_var blender_vars[];

#endif
