/*
 * progress.c - a long run reports on a terminal once it has taken half
 * a second: the primordia a model has placed, then the bytes written.
 * The line is rubbed out at the end, leaving the terminal as it was.
 * Besides diag.c, the one place outside main.c that writes to stderr:
 * main.c hooks it up only where stderr is a terminal.
 */
#include <stdio.h>
#include <time.h>

#include "base/diag.h"
#include "progress.h"
#include "run.h"

static struct timespec status_t0;
static int status_width;

static double
status_seconds(void)
{
	struct timespec now;

	clock_gettime(CLOCK_MONOTONIC, &now);
	return (double)(now.tv_sec - status_t0.tv_sec) +
	    (double)(now.tv_nsec - status_t0.tv_nsec) / 1e9;
}

void
progress_start(void)
{
	clock_gettime(CLOCK_MONOTONIC, &status_t0);
}

void
progress_clear(void)
{
	if (status_width > 0)
		fprintf(stderr, "\r%*s\r", status_width, "");
	status_width = 0;
}

void
progress_placed(long long done, int last)
{
	double sec = status_seconds();

	if (last)
		progress_clear();
	else if (sec >= 0.5) {
		status_width = fprintf(stderr, "\r%s: placed %lld primordia, "
		    "%.0f a second ", diag_progname, done, done / sec) - 1;
		fflush(stderr);
	}
}

/* Ten times a second at most: a block goes out every 64 KiB. */
void
progress_written(const struct budget *b)
{
	static double next = 0.5;
	char used[32], expected[32];
	double now = status_seconds();

	if (now < next)
		return;
	next = now + 0.1;
	run_size_words(used, sizeof(used), b->used);
	run_size_words(expected, sizeof(expected), b->expected);
	status_width = fprintf(stderr, "\r%s: written %s of about %s ",
	    diag_progname, used, expected) - 1;
	fflush(stderr);
}
