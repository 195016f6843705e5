/*
 * main.c - the command line.  Parse options, load the scene, run its
 * model, write one format.  Only this file chooses the exit status.
 */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "model.h"
#include "output.h"
#include "scene.h"
#include "writer.h"

#ifndef VERSION
#define VERSION "0.0"
#endif

const struct writer writers[] = {
	{ "csv", csv_write, "one line per organ: position, frame, scale" },
	{ "info", info_write, "key: value facts about the result" },
	{ NULL, NULL, NULL }
};

static model_fn *const models[MODEL__MAX] = {
	[MODEL_PLANAR] = planar_run,
};

struct args {
	const struct writer *writer;
	const char	*output;	/* -o, or NULL for stdout */
	const char	*scene;
};

static void
usage(FILE *fp)
{
	fputs("usage: phyllo-export (", fp);
	for (const struct writer *w = writers; w->name != NULL; w++)
		fprintf(fp, "%s--%s", w == writers ? "" : " | ", w->name);
	fputs(") [-o FILE] SCENE.cfg\n"
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
	    "  -h, --help     show this help\n"
	    "  -V, --version  show the version\n\n"
	    "Models: planar.  See phyllo-export(1) and phyllo-export(5).");
}

/* 0 to go on, -1 to exit 0 at once (--help), or a status to exit with. */
static int
parse_args(int argc, char *argv[], struct args *a)
{
	enum { OPT_WRITER = 256 };
	static struct option longopts[16];
	int n = 0, c, idx;

	for (const struct writer *w = writers; w->name != NULL; w++, n++)
		longopts[n] = (struct option){ w->name, no_argument, NULL,
		    OPT_WRITER + n };
	longopts[n++] = (struct option){ "output", required_argument, NULL,
	    'o' };
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
	a->scene = argv[optind];
	return 0;
}

/* Write the result; on any failure -o's target is left as it was. */
static void
write_result(const struct args *a, const struct scene *sc,
    const struct result *res)
{
	struct sink s;
	FILE *fp = output_open(a->output);

	if (fp == NULL)
		return;
	sink_init(&s, fp);
	a->writer->write(&s, sc, res);
	if (sink_finish(&s) != 0) {
		diag(ST_SYSTEM, a->output ? a->output : "<stdout>", 0, 0,
		    "%s", strerror(errno));
		output_abort();
	} else
		output_commit();
	sink_free(&s);
}

int
main(int argc, char *argv[])
{
	struct args a = { NULL, NULL, NULL };
	struct scene sc;
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
	if (scene_load(&sc, a.scene) == 0) {
		if (models[sc.model] == NULL)
			scene_error(&sc, "model", "model \"%s\" is not "
			    "implemented yet", scene_model_name(sc.model));
		else if (models[sc.model](&sc, &res) == 0 &&
		    organs_apply(&sc, &res) == 0)
			write_result(&a, &sc, &res);
	}
	result_free(&res);
	scene_free(&sc);
	return diag_status();
}
