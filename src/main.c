/*
 * main.c - the command line.  Parse options, load the scene, run its
 * model, write one format.  Only this file chooses the exit status.
 */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "diag.h"
#include "mem.h"
#include "phyllo.h"
#include "model.h"
#include "output.h"
#include "scene.h"
#include "writer.h"

#ifndef SHAREDIR
#define SHAREDIR "/usr/local/share/phyllo-export"
#endif

/*
 * A long placement (the collision model) reports on a terminal, once
 * it has taken half a second: how many are placed and how fast.  The
 * line is rubbed out at the end, leaving the terminal as it was.
 */
static struct timespec progress_t0;
static int progress_width;

static double
progress_seconds(void)
{
	struct timespec now;

	clock_gettime(CLOCK_MONOTONIC, &now);
	return (double)(now.tv_sec - progress_t0.tv_sec) +
	    (double)(now.tv_nsec - progress_t0.tv_nsec) / 1e9;
}

static void
progress(long long done, int last)
{
	double sec = progress_seconds();

	if (last) {
		if (progress_width > 0)
			fprintf(stderr, "\r%*s\r", progress_width, "");
		progress_width = 0;
		return;
	}
	if (sec < 0.5)
		return;
	progress_width = fprintf(stderr, "\r%s: placed %lld primordia, "
	    "%.0f a second ", diag_progname, done, done / sec) - 1;
	fflush(stderr);
}

struct args {
	const struct writer *writer;
	const char	*output;	/* -o, or NULL for stdout */
	const char	*scene;
	const char	*template;	/* --template, or NULL */
	int		 arrays;	/* --arrays */
	int		 objects;	/* --blender-objects */
};

static void
usage(FILE *fp)
{
	fputs("usage: phyllo-export (", fp);
	for (const struct writer *w = writers; w->name != NULL; w++)
		fprintf(fp, "%s--%s", w == writers ? "" : " | ", w->name);
	fputs(") [-o FILE]\n"
	    "                     [--template FILE] [--arrays] "
	    "[--blender-objects] SCENE.cfg\n"
	    "       phyllo-export --help | --version\n", fp);
}

static void
help(void)
{
	usage(stdout);
	puts("\nWrite the organs of a phyllotactic structure described by "
	    "SCENE.cfg\n(- for standard input) in one format:\n");
	for (const struct writer *w = writers; w->name != NULL; w++)
		printf("  --%-12s%s\n", w->name, w->help);
	puts("\n  -o FILE        write FILE (replaced only on success) "
	    "instead of standard output\n"
	    "  --template FILE  write --pov or --blender through this template "
	    "instead of\n"
	    "                 the default\n"
	    "  --arrays       --pov: declare the organs as arrays "
	    "(pov-arrays.tmpl)\n"
	    "  --blender-objects  --blender: one linked duplicate per organ "
	    "instead of instances\n"
	    "  -h, --help     show this help\n"
	    "  -V, --version  show the version\n\n"
	    "Models (model = \"NAME\"; in the scene file):");
	for (const struct model *const *m = models; *m != NULL; m++)
		printf("  %-12s %s\n", (*m)->name, (*m)->help);
	puts("\nSee phyllo-export(1) and phyllo-export(5).");
}

enum { WITH_ARRAYS, WITH_OBJECTS };

/* "--pov" or "--pov or --blender": the formats an option goes with. */
static const char *
writers_with(int which)
{
	static char buf[128];
	size_t len = 0;

	buf[0] = '\0';
	for (const struct writer *w = writers; w->name != NULL; w++)
		if (which == WITH_ARRAYS ? w->arrays_tmpl != NULL :
		    (w->opts & TO_OBJECTS) != 0)
			len += (size_t)snprintf(buf + len, sizeof(buf) - len,
			    "%s--%s", len ? " or " : "", w->name);
	return buf;
}

/* Long options beyond the writers' own: output, template, arrays, ... */
enum { OPT_WRITER = 256, NOPTIONS = 6 };

static int
parse(int argc, char *argv[], struct args *a, struct option *longopts)
{
	int n = 0, c, idx;

	for (const struct writer *w = writers; w->name != NULL; w++, n++)
		longopts[n] = (struct option){ w->name, no_argument, NULL,
		    OPT_WRITER + n };
	longopts[n++] = (struct option){ "output", required_argument, NULL,
	    'o' };
	longopts[n++] = (struct option){ "template", required_argument, NULL,
	    't' };
	longopts[n++] = (struct option){ "arrays", no_argument, NULL, 'a' };
	longopts[n++] = (struct option){ "blender-objects", no_argument, NULL,
	    'b' };
	longopts[n++] = (struct option){ "help", no_argument, NULL, 'h' };
	longopts[n++] = (struct option){ "version", no_argument, NULL, 'V' };
	longopts[n] = (struct option){ NULL, 0, NULL, 0 };

	opterr = 0;
	while ((c = getopt_long(argc, argv, ":ho:V", longopts, &idx)) != -1) {
		switch (c) {
		case 'h':
			help();
			return -1;
		case 'V':
			puts("phyllo-export " VERSION);
			return -1;
		case 'o':
			a->output = optarg;
			break;
		case 't':
			a->template = optarg;
			break;
		case 'a':
			a->arrays = 1;
			break;
		case 'b':
			a->objects = 1;
			break;
		case ':':
			diag(ST_USAGE, NULL, 0, 0, "option %s needs an argument",
			    argv[optind - 1]);
			usage(stderr);
			return ST_USAGE;
		case '?':
			diag(ST_USAGE, NULL, 0, 0, "unknown option %s",
			    argv[optind - 1]);
			usage(stderr);
			return ST_USAGE;
		default:
			if (a->writer != NULL &&
			    a->writer != &writers[c - OPT_WRITER]) {
				diag(ST_USAGE, NULL, 0, 0, "choose one of "
				    "--%s and --%s", a->writer->name,
				    writers[c - OPT_WRITER].name);
				return ST_USAGE;
			}
			a->writer = &writers[c - OPT_WRITER];
			break;
		}
	}
	if (a->writer == NULL || optind != argc - 1) {
		diag(ST_USAGE, NULL, 0, 0, "%s", a->writer == NULL ?
		    "no output format given" : optind == argc ?
		    "no scene file given" : "more than one scene file given");
		usage(stderr);
		return ST_USAGE;
	}
	if (a->template != NULL && a->writer->tmpl == NULL) {
		diag(ST_USAGE, NULL, 0, 0, "--%s has no template; --template "
		    "goes with --pov and --blender", a->writer->name);
		return ST_USAGE;
	}
	if (a->arrays && a->writer->arrays_tmpl == NULL) {
		diag(ST_USAGE, NULL, 0, 0, "--arrays goes with %s",
		    writers_with(WITH_ARRAYS));
		return ST_USAGE;
	}
	if (a->objects && !(a->writer->opts & TO_OBJECTS)) {
		diag(ST_USAGE, NULL, 0, 0, "--blender-objects goes with %s",
		    writers_with(WITH_OBJECTS));
		return ST_USAGE;
	}
	if (a->template != NULL && a->arrays) {
		diag(ST_USAGE, NULL, 0, 0, "choose one of --template and "
		    "--arrays");
		return ST_USAGE;
	}
	a->scene = argv[optind];
	return 0;
}

/* 0 to go on, -1 to exit 0 at once (--help), or a status to exit with. */
static int
parse_args(int argc, char *argv[], struct args *a)
{
	struct option *longopts;
	size_t nwriters = 0;
	int rc;

	while (writers[nwriters].name != NULL)
		nwriters++;
	/* Sized from the table, so a new format cannot overrun it. */
	longopts = xcalloc(nwriters + NOPTIONS + 1, sizeof(*longopts));
	rc = parse(argc, argv, a, longopts);
	free(longopts);
	return rc;
}

/* The format's template: --template FILE, installed, or built in. */
static struct tmpl *
load_template(const struct args *a)
{
	const char *name = a->arrays ? a->writer->arrays_tmpl : a->writer->tmpl;
	char path[4096];

	if (a->template != NULL)
		return tmpl_load(a->template, a->writer->vars);
	snprintf(path, sizeof(path), "%s/%s", SHAREDIR, name);
	if (access(path, R_OK) == 0)
		return tmpl_load(path, a->writer->vars);
	return tmpl_builtin(name, a->writer->vars);
}

/* Write the result; on any failure -o's target is left as it was. */
static void
write_result(const struct args *a, const struct tmpl *t,
    const struct result *res)
{
	struct sink s;
	FILE *fp = output_open(a->output);

	if (fp == NULL)
		return;
	sink_init(&s, fp);
	if (t != NULL)
		tmpl_write(t, &s, res, a->objects ? TO_OBJECTS : 0);
	else
		a->writer->write(&s, res);
	if (sink_finish(&s) != 0) {
		diag(ST_SYSTEM, a->output ? a->output : "<stdout>", 0, 0,
		    "%s", strerror(errno));
		output_abort();
	} else
		output_commit();
	sink_free(&s);
}

/* Everything that can fail on the input, before any output. */
static int
prepare(const struct args *a, struct scene *sc, struct tmpl **t,
    struct result *res)
{
	if (scene_load(sc, a->scene) != 0)
		return -1;
	if (a->writer->check != NULL && a->writer->check(sc) != 0)
		return -1;
	if (a->writer->tmpl != NULL && (*t = load_template(a)) == NULL)
		return -1;
	return model_run(sc, res);
}

int
main(int argc, char *argv[])
{
	struct args a = { NULL, NULL, NULL, NULL, 0, 0 };
	struct scene sc;
	struct tmpl *t = NULL;
	struct result res = { 0 };
	int st;

	if ((st = parse_args(argc, argv, &a)) < 0) {
		if (fflush(stdout) != 0) {
			diag(ST_SYSTEM, "<stdout>", 0, 0, "%s", strerror(errno));
			return ST_SYSTEM;
		}
		return ST_OK;
	}
	if (st > 0)
		return st;
	if (isatty(STDERR_FILENO)) {
		clock_gettime(CLOCK_MONOTONIC, &progress_t0);
		model_progress = progress;
	}
	if (prepare(&a, &sc, &t, &res) == 0)
		write_result(&a, t, &res);
	tmpl_free(t);
	result_free(&res);
	scene_free(&sc);
	return diag_status();
}
