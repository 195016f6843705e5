/* writer.h - the output formats; each is one file and one table entry. */
#ifndef WRITER_H
#define WRITER_H

#include "organ.h"
#include "scene.h"
#include "sink.h"

/* Writers only read; errors in the sink are reported by the caller. */
typedef void writer_fn(struct sink *, const struct scene *,
    const struct result *);

struct writer {
	const char	*name;	/* its option, without the dashes */
	writer_fn	*write;
	const char	*help;
};

extern const struct writer writers[];

writer_fn csv_write;
writer_fn info_write;

#endif
