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

#include "compound.h"
#include "diag.h"
#include "flatten.h"
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
	int		 flatten;	/* --flatten */
	int		 frames;	/* --frames N, or 0 */
};

#define FRAMES_MAX	100000

static void
usage(FILE *fp)
{
	fputs("usage: phyllo-export (", fp);
	for (const struct writer *w = writers; w->name != NULL; w++)
		fprintf(fp, "%s--%s", w == writers ? "" : " | ", w->name);
	fputs(") [-o FILE]\n"
	    "                     [--template FILE] [--arrays] "
	    "[--blender-objects]\n"
	    "                     [--flatten] [--frames N] SCENE.cfg\n"
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
	    "  --flatten      --csv: every leaf organ of a compound structure, "
	    "in the world\n"
	    "  --frames N     N frames, f = 0 .. 1 and F = 1 .. N in the scene; "
	    "-o FILE%03d\n"
	    "                 names one file a frame (--blender: one script "
	    "animating them)\n"
	    "  -h, --help     show this help\n"
	    "  -V, --version  show the version\n\n"
	    "Models (model = \"NAME\"; in the scene file):");
	for (const struct model *const *m = models; *m != NULL; m++)
		printf("  %-12s %s\n", (*m)->name, (*m)->help);
	puts("\nSee phyllo-export(1) and phyllo-export(5).");
}

enum { WITH_ARRAYS, WITH_OBJECTS, WITH_FLATTEN };

/* "--pov" or "--pov or --blender": the formats an option goes with. */
static const char *
writers_with(int which)
{
	static char buf[128];
	size_t len = 0;

	buf[0] = '\0';
	for (const struct writer *w = writers; w->name != NULL; w++)
		if (which == WITH_ARRAYS ? w->arrays_tmpl != NULL :
		    (w->opts & (which == WITH_OBJECTS ? TO_OBJECTS :
		    TO_FLATTEN)) != 0)
			len += (size_t)snprintf(buf + len, sizeof(buf) - len,
			    "%s--%s", len ? " or " : "", w->name);
	return buf;
}

/* --frames N: a count from 1 to FRAMES_MAX, or 0 after a diagnostic. */
static int
frames_arg(const char *arg)
{
	char *end;
	long n;

	errno = 0;
	n = strtol(arg, &end, 10);
	if (errno != 0 || end == arg || *end != '\0' || n < 1 ||
	    n > FRAMES_MAX) {
		diag(ST_USAGE, NULL, 0, 0, "--frames %s: give a whole number "
		    "from 1 to %d", arg, FRAMES_MAX);
		return 0;
	}
	return (int)n;
}

/*
 * The file of frame F: pattern with its one %d (flags 0, a width) made
 * F, and %% made %.  Our own expansion, so -o is never a printf format.
 * buf NULL: only check the pattern.  0, or -1 after a diagnostic.
 */
static int
frame_path(const char *pattern, int F, char *buf, size_t sz)
{
	static const char *const need = "--frames writes one file a frame: "
	    "-o needs one %d in the name (head%03d.inc)";
	char tmp[4096];
	size_t len = 0;
	int conversions = 0;

	if (pattern == NULL) {
		diag(ST_USAGE, NULL, 0, 0, "%s, not standard output", need);
		return -1;
	}
	for (const char *p = pattern; *p != '\0'; p++) {
		int zero = 0, width = 0;

		if (*p != '%' || p[1] == '%') {
			if (len + 1 < sizeof(tmp))
				tmp[len++] = *p;
			p += *p == '%';
			continue;
		}
		if (*++p == '0')
			zero = *p++ == '0';
		while (*p >= '0' && *p <= '9' && width < 100)
			width = width * 10 + (*p++ - '0');
		if (*p != 'd' || conversions++ > 0) {
			diag(ST_USAGE, NULL, 0, 0, "-o %s: %s", pattern, need);
			return -1;
		}
		len += (size_t)snprintf(tmp + len, len < sizeof(tmp) ?
		    sizeof(tmp) - len : 0, zero ? "%0*d" : "%*d", width, F);
	}
	if (conversions == 0) {
		diag(ST_USAGE, NULL, 0, 0, "-o %s: %s", pattern, need);
		return -1;
	}
	if (len >= sizeof(tmp)) {
		diag(ST_USAGE, NULL, 0, 0, "-o %s: file name too long", pattern);
		return -1;
	}
	tmp[len] = '\0';
	if (buf != NULL)
		snprintf(buf, sz, "%s", tmp);
	return 0;
}

/* Long options beyond the writers' own: output, template, arrays, ... */
enum { OPT_WRITER = 256, NOPTIONS = 8 };

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
	longopts[n++] = (struct option){ "flatten", no_argument, NULL, 'f' };
	longopts[n++] = (struct option){ "frames", required_argument, NULL,
	    'F' };
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
		case 'f':
			a->flatten = 1;
			break;
		case 'F':
			if ((a->frames = frames_arg(optarg)) == 0)
				return ST_USAGE;
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
	if (a->flatten && !(a->writer->opts & TO_FLATTEN)) {
		diag(ST_USAGE, NULL, 0, 0, "--flatten goes with %s",
		    writers_with(WITH_FLATTEN));
		return ST_USAGE;
	}
	if (a->frames && !(a->writer->opts & TO_ANIMATE) &&
	    frame_path(a->output, 1, NULL, 0) != 0)
		return ST_USAGE;
	if (a->template != NULL && a->arrays) {
		diag(ST_USAGE, NULL, 0, 0, "choose one of --template and "
		    "--arrays");
		return ST_USAGE;
	}
	a->scene = argv[optind];
	if (a->frames && strcmp(a->scene, "-") == 0) {
		diag(ST_USAGE, NULL, 0, 0, "--frames reads the scene once a "
		    "frame: give a file, not standard input");
		return ST_USAGE;
	}
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

/* The structures a template writes, and the merged parts it owns. */
struct structures {
	const struct result **all;
	size_t		 n;
	struct result	*merged;
	size_t		 nmerged;
};

/* Whether the main structure places part p itself. */
static int
placed_by_main(const struct result *main, const struct result *p)
{
	for (size_t j = 0; main->sub != NULL && j < main->nobjects; j++)
		if (main->sub[j] == p)
			return 1;
	return 0;
}

/*
 * Every structure of frames c[0 .. nc-1], parts first; the main alone
 * for a template without @@structures.  A writer that nests only one
 * level (TO_SHALLOW) gets the parts the main places, each with its own
 * parts merged into it.
 */
static void
structures(const struct args *a, const struct tmpl *t,
    const struct compound *c, size_t nc, struct structures *L)
{
	size_t total = 0;

	for (size_t k = 0; k < nc; k++)
		total += c[k].n;
	*L = (struct structures){ xcalloc(total, sizeof(*L->all)), 0,
	    xcalloc(total, sizeof(*L->merged)), 0 };
	if (!tmpl_structures(t)) {
		if (total > nc)
			diag(ST_OK, NULL, 0, 0, "the template has no "
			    "@@structures block: the parts of the structure "
			    "are written as placeholders");
		for (size_t k = 0; k < nc; k++)
			L->all[L->n++] = compound_main(&c[k]);
		return;
	}
	for (size_t k = 0; k < nc; k++)
		for (size_t i = 0; i < c[k].n; i++) {
			const struct result *r = &c[k].parts[i]->res;

			if (!(a->writer->opts & TO_SHALLOW) || i + 1 == c[k].n)
				L->all[L->n++] = r;
			else if (!placed_by_main(compound_main(&c[k]), r))
				continue;	/* merged into the parts using it */
			else if (r->sub == NULL)
				L->all[L->n++] = r;
			else {
				flatten_result(r, &L->merged[L->nmerged]);
				L->all[L->n++] = &L->merged[L->nmerged++];
			}
		}
}

/*
 * Write frames c[0 .. nc-1] to path (NULL: stdout); the file stays a
 * temporary until output_commit().  0, or -1 after a diagnostic.
 */
static int
write_file(const struct args *a, const struct tmpl *t, const char *path,
    const struct compound *c, size_t nc)
{
	unsigned opts = (a->objects ? TO_OBJECTS : 0) |
	    (a->flatten ? TO_FLATTEN : 0);
	struct sink s;
	FILE *fp = output_open(path);
	int rc = 0;

	if (fp == NULL)
		return -1;
	sink_init(&s, fp);
	if (t != NULL) {
		struct structures L;

		structures(a, t, c, nc, &L);
		tmpl_write(t, &s, L.all, L.n, opts);
		for (size_t i = 0; i < L.nmerged; i++)
			result_free(&L.merged[i]);
		free(L.merged);
		free(L.all);
	} else
		a->writer->write(&s, compound_main(&c[nc - 1]), opts);
	if (sink_finish(&s) != 0) {
		diag(ST_SYSTEM, path ? path : "<stdout>", 0, 0, "%s",
		    strerror(errno));
		output_abort();
		rc = -1;
	} else
		rc = output_close();
	sink_free(&s);
	return rc;
}

/* Load and run frame fr of the scene, with everything it includes. */
static int
make_frame(const struct args *a, struct compound *c, const struct frame *fr)
{
	if (compound_load(c, a->scene, fr, a->writer->check) != 0)
		return -1;
	return compound_run(c, fr);
}

/*
 * Every frame: one file each, or (a format that animates) all in one.
 * Nothing is put in place unless every frame was made and written.
 */
static void
run(const struct args *a, const struct tmpl *t)
{
	int nframes = a->frames ? a->frames : 1;
	int together = a->frames && (a->writer->opts & TO_ANIMATE);
	struct compound *c = xcalloc((size_t)nframes, sizeof(*c));
	char path[4096];
	int rc = 0, made = 0;

	for (int F = 1; F <= nframes && rc == 0; F++) {
		struct frame fr = { F, nframes };
		struct compound *cf = &c[together ? F - 1 : 0];

		rc = make_frame(a, cf, a->frames ? &fr : NULL);
		made++;
		if (rc == 0 && !together)
			rc = a->frames && frame_path(a->output, F, path,
			    sizeof(path)) != 0 ? -1 : write_file(a, t,
			    a->frames ? path : a->output, cf, 1);
		if (!together)
			compound_free(cf);
	}
	if (rc == 0 && together)
		rc = write_file(a, t, a->output, c, (size_t)nframes);
	if (rc == 0)
		output_commit();
	else
		output_abort();
	for (int k = 0; together && k < made; k++)
		compound_free(&c[k]);
	free(c);
}

int
main(int argc, char *argv[])
{
	struct args a = { NULL, NULL, NULL, NULL, 0, 0, 0, 0 };
	struct tmpl *t = NULL;
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
	if (a.writer->tmpl == NULL || (t = load_template(&a)) != NULL)
		run(&a, t);
	tmpl_free(t);
	return diag_status();
}
