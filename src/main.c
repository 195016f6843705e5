/*
 * main.c - the command line: parse the options, load the template, and
 * hand the rest to run() (run.c), with progress shown on a terminal
 * (progress.c).  Only this file chooses the exit status.
 */
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "compat/compat.h"
#include "base/diag.h"
#include "base/mem.h"
#include "models/model.h"
#include "writers/output.h"
#include "progress.h"
#include "scene/override.h"
#include "scene/suggest.h"
#include "run.h"
#include "writers/writer.h"

struct args {
	const struct writer *writer;
	const char	*output;	/* -o, or NULL for stdout */
	const char	*scene;
	const char	*template;	/* --template, or NULL */
	int		 arrays;	/* --arrays */
	int		 objects;	/* --blender-objects */
	int		 flatten;	/* --flatten */
	int		 frames;	/* --frames N, or 0 */
	double		 max_output;	/* --max-output, bytes; 0: none */
	struct override	*set;		/* --set, in order */
	int		 nset;
	const char	**set_args;	/* their arguments, for messages */
};

#define FRAMES_MAX	100000
/* What a run may write unless --max-output says otherwise: 4 GiB. */
#define MAX_OUTPUT	(4.0 * 1024 * 1024 * 1024)

static void
usage(FILE *fp)
{
	fputs("usage: phyllo-export (", fp);
	for (const struct writer *w = writers; w->name != NULL; w++)
		fprintf(fp, "%s--%s", w == writers ? "" : " | ", w->name);
	fputs(") [-o FILE]\n"
	    "                     [--template FILE] [--arrays] "
	    "[--blender-objects]\n"
	    "                     [--flatten] [--frames N] [--max-output SIZE]\n"
	    "                     [--set [OBJECT:]PATH=VALUE ...] SCENE.cfg\n"
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
	    "  --set PATH=VALUE  change or add a setting of the scene, VALUE as "
	    "the scene\n"
	    "                 file writes it (count=300, planar.scale=0.05, "
	    "organs.1.tilt=\"20*f\");\n"
	    "                 OBJECT:PATH for the scene making organ object "
	    "OBJECT\n"
	    "  --max-output SIZE  refuse to write more than SIZE bytes (K, M, "
	    "G, T: KiB ...;\n"
	    "                 0: no limit) [4G]\n"
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
 * --max-output SIZE: bytes, or a number with K, M, G or T (powers of
 * 1024, as head -c and truncate -s read them); 0 lifts the limit.
 */
static int
size_arg(const char *arg, double *bytes)
{
	static const char units[] = "KMGT";
	const char *u;
	char *end;
	double v;

	errno = 0;
	v = strtod(arg, &end);
	if (end != arg && *end != '\0' && end[1] == '\0' &&
	    (u = strchr(units, toupper((unsigned char)*end))) != NULL) {
		v *= pow(1024, (double)(u - units + 1));
		end++;
	}
	if (errno != 0 || end == arg || *end != '\0' || !(v >= 0) ||
	    !isfinite(v) || !isdigit((unsigned char)arg[0])) {
		diag(ST_USAGE, NULL, 0, 0, "--max-output %s: give a size in "
		    "bytes, or with K, M, G or T (4G); 0 for no limit", arg);
		return -1;
	}
	*bytes = v;
	return 0;
}

/*
 * An option getopt_long() did not take: arg as given, opt its optopt
 * (the letter of an unknown short one, the value of a long one given
 * an argument it does not take, 0 for an unknown or ambiguous long
 * one).  A slip of a long one's name gets the name it was meant to be
 * ("--inof": did you mean --info?); the usage after.
 */
static void
bad_option(const char *arg, int opt, const struct option *longopts)
{
	const char *words[64], *near = NULL, *name;
	char list[256] = "";
	size_t n = 0, len, matches = 0;
	int is_long = strncmp(arg, "--", 2) == 0;

	/* arg may be any word, argv[0] even: its name only if it is long. */
	name = is_long ? arg + 2 : "";
	len = strcspn(name, "=");
	if (opt != 0) {
		/*
		 * arg is the word getopt_long() is past: a long option's
		 * with "=" (--csv=x), or the word before a short one's
		 * cluster (-qx): which, only the option's value says.
		 */
		const char *takes_none = NULL;

		for (n = 0; len > 0 && name[len] == '=' && takes_none == NULL &&
		    longopts[n].name != NULL; n++)
			if (longopts[n].val == opt && longopts[n].has_arg ==
			    no_argument && strncmp(longopts[n].name, name,
			    len) == 0)
				takes_none = longopts[n].name;
		if (takes_none != NULL)
			diag(ST_USAGE, NULL, 0, 0, "option --%s takes no "
			    "argument", takes_none);
		else
			diag(ST_USAGE, NULL, 0, 0, "unknown option -%c", opt);
		usage(stderr);
		return;
	}
	for (; n < 64 && longopts[n].name != NULL; n++) {
		words[n] = longopts[n].name;
		if (len > 0 && strncmp(words[n], name, len) == 0) {
			matches++;
			snprintf(list + strlen(list), sizeof(list) - strlen(list),
			    "%s--%s", matches > 1 ? ", " : "", words[n]);
		}
	}
	if (matches > 1) {
		diag(ST_USAGE, NULL, 0, 0, "option --%.*s is ambiguous: %s",
		    (int)len, name, list);
		usage(stderr);
		return;
	}
	if (len > 0 && len < 64) {
		char typed[64];

		snprintf(typed, sizeof(typed), "%.*s", (int)len, name);
		near = suggest(typed, words, n);
	}
	diag(ST_USAGE, NULL, 0, 0, "unknown option %s%s%s%s", arg, near ?
	    " (did you mean --" : "", near ? near : "", near ? "?)" : "");
	usage(stderr);
}

/* Long options beyond the writers' own: output, template, arrays, ... */
enum { OPT_WRITER = 256, NOPTIONS = 10 };

/* Whether name holds a %d as --frames fills in (%03d, not %%d). */
static int
frame_pattern(const char *name)
{
	for (const char *p = name; (p = strchr(p, '%')) != NULL; p++) {
		if (p[1] == '%') {
			p++;
			continue;
		}
		p += strspn(p + 1, "0123456789");
		if (p[1] == 'd')
			return 1;
	}
	return 0;
}

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
	longopts[n++] = (struct option){ "max-output", required_argument,
	    NULL, 'M' };
	longopts[n++] = (struct option){ "set", required_argument, NULL, 's' };
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
		case 'M':
			if (size_arg(optarg, &a->max_output) != 0)
				return ST_USAGE;
			break;
		case 's':
			/* argc bounds them: sized once, before the loop. */
			a->set_args[a->nset] = optarg;
			if (override_parse(optarg, &a->set[a->nset++]) != 0)
				return ST_USAGE;
			break;
		case ':':
			diag(ST_USAGE, NULL, 0, 0, "option %s needs an argument",
			    argv[optind - 1]);
			usage(stderr);
			return ST_USAGE;
		case '?':
			bad_option(argv[optind - 1], optopt, longopts);
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
	if (a->frames && a->writer->scenes != NULL) {
		diag(ST_USAGE, NULL, 0, 0, "--%s gives the scene as written: "
		    "--frames does not go with it", a->writer->name);
		return ST_USAGE;
	}
	if (a->frames && !(a->writer->opts & TO_ANIMATE) &&
	    output_frame_path(a->output, 1, NULL, 0) != 0)
		return ST_USAGE;
	if (a->template != NULL && a->arrays) {
		diag(ST_USAGE, NULL, 0, 0, "choose one of --template and "
		    "--arrays");
		return ST_USAGE;
	}
	if ((a->writer->opts & TO_BINARY) && a->output == NULL &&
	    sys_isatty(STDOUT_FILENO)) {
		/* As gzip: bytes on a terminal garble it and help no one. */
		diag(ST_USAGE, NULL, 0, 0, "--%s writes binary data, not to a "
		    "terminal: give -o FILE or redirect standard output",
		    a->writer->name);
		return ST_USAGE;
	}
	if (!a->frames && a->output != NULL && frame_pattern(a->output))
		diag(ST_OK, NULL, 0, 0, "-o %s: a %%d in the name is filled "
		    "in only with --frames; writing the file as named",
		    a->output);
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
	a->set = xcalloc((size_t)argc, sizeof(*a->set));
	a->set_args = xcalloc((size_t)argc, sizeof(*a->set_args));
	rc = parse(argc, argv, a, longopts);
	free(longopts);
	diag_overrides(a->set_args, a->nset);
	return rc;
}

/*
 * The format's template: --template FILE, installed, or built in; path
 * is left the file's name, or "" for the built-in one.  A program that
 * travels (Windows, the Blender add-on's) is built with SHAREDIR ""
 * and keeps to its own.
 */
static struct tmpl *
load_template(const struct args *a, char *path, size_t sz)
{
	const char *name = a->arrays ? a->writer->arrays_tmpl : a->writer->tmpl;

	if (a->template != NULL) {
		snprintf(path, sz, "%s", a->template);
		return tmpl_load(a->template, a->writer->vars);
	}
	snprintf(path, sz, "%s/%s", SHAREDIR, name);
	if (SHAREDIR[0] != '\0' && sys_readable(path))
		return tmpl_load(path, a->writer->vars);
	path[0] = '\0';
	return tmpl_builtin(name, a->writer->vars);
}

int
main(int argc, char *argv[])
{
	struct args a = { NULL, NULL, NULL, NULL, 0, 0, 0, 0, MAX_OUTPUT, NULL,
	    0, NULL };
	struct tmpl *t = NULL;
	char path[4096] = "";
	int st;

	st = parse_args(argc, argv, &a);
	if (st < 0 && fflush(stdout) != 0)	/* --help, --version */
		diag(ST_SYSTEM, "<stdout>", 0, 0, "%s", strerror(errno));
	if (st == 0 && sys_isatty(STDERR_FILENO))
		progress_start();
	if (st == 0 && (a.writer->tmpl == NULL ||
	    (t = load_template(&a, path, sizeof(path))) != NULL)) {
		struct job j = { a.writer, t, path[0] ? path : NULL, a.scene,
		    a.output, (a.objects ? TO_OBJECTS : 0) |
		    (a.flatten ? TO_FLATTEN : 0), a.frames, a.set, a.nset,
		    a.max_output, sys_isatty(STDERR_FILENO) ?
		    progress_written : NULL, sys_isatty(STDERR_FILENO) ?
		    progress_placed : NULL };

		run(&j);
		progress_clear();
	}
	tmpl_free(t);
	diag_overrides(NULL, 0);
	free(a.set);
	free(a.set_args);
	return st > 0 ? st : (int)diag_status();
}
