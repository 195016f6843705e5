/*
 * run.h - one run of the program: make each frame of a scene and write
 * it, with the output's size known before a byte is written.
 */
#ifndef RUN_H
#define RUN_H

#include "base/sink.h"
#include "writers/template.h"
#include "writers/writer.h"

/* What main.c asks for. */
struct job {
	const struct writer *writer;
	const struct tmpl *tmpl;	/* the writer's template, or NULL */
	const char	*template_path;	/* its file, or NULL (built in) */
	const char	*scene;		/* a path, or "-" */
	const char	*output;	/* -o, or NULL: standard output */
	unsigned	 opts;		/* TO_OBJECTS, TO_FLATTEN */
	int		 frames;	/* --frames N, or 0 */
	struct override	*set;		/* --set, nset of them */
	int		 nset;
	double		 max_output;	/* bytes; 0: no limit */
	/* Told as blocks are written: used of about expected. */
	void		(*told)(const struct budget *);
	/* Told as a model places: how many so far, and last at the end. */
	void		(*placed)(long long done, int last);
};

/*
 * Make every frame and write it; nothing is put in place unless all
 * was made and written.  0, or -1 after a diagnostic.
 */
int	run(const struct job *);

/* "4.3 GiB": a size for people. */
void	run_size_words(char *buf, size_t sz, double bytes);

#endif
