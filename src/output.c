/*
 * output.c - open the output: standard output, or -o FILE.  A regular
 * FILE is written as a temporary file beside it and renamed over it
 * only when everything was written, so a failed or interrupted run never
 * leaves a damaged or half-written file.  --frames writes several files
 * the same way: all of them are renamed into place at the end, or none.
 * Devices and pipes named with -o (/dev/stdout, /dev/full) are written
 * directly.
 *
 * Temporary files are removed on error, on exit() from anywhere (out
 * of memory) and on SIGINT, SIGTERM, SIGHUP and SIGPIPE.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "diag.h"
#include "mem.h"
#include "output.h"

/* A file written but not yet in place. */
struct pending {
	char	 tmp[PATH_MAX];
	char	*target;
};

static FILE *out;
static const char *display = "<stdout>";	/* for messages */
static struct pending *pend;
static volatile sig_atomic_t npend;	/* temporaries that exist */
static size_t cap;

static void
remove_tmps(void)
{
	while (npend > 0) {
		npend--;
		unlink(pend[npend].tmp);
		free(pend[npend].target);
	}
}

static void
on_signal(int sig)
{
	for (sig_atomic_t i = 0; i < npend; i++)
		unlink(pend[i].tmp);
	signal(sig, SIG_DFL);
	raise(sig);
}

static void
catch_signals(void)
{
	static const int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGPIPE };
	static int done;

	if (done++)
		return;
	atexit(remove_tmps);
	for (size_t i = 0; i < sizeof(sigs) / sizeof(sigs[0]); i++)
		signal(sigs[i], on_signal);
}

FILE *
output_open(const char *path)
{
	struct pending *p;
	struct stat st;
	const char *slash;
	mode_t mask;
	int fd, dirlen;

	if (path == NULL)
		return out = stdout;
	display = path;
	if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
		if ((out = fopen(path, "w")) == NULL)
			diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		return out;
	}
	catch_signals();
	if ((size_t)npend == cap) {
		/* Grown with signals held: the handler walks pend. */
		sigset_t all, old;

		sigfillset(&all);
		sigprocmask(SIG_BLOCK, &all, &old);
		pend = xreallocarray(pend, cap = cap * 2 + 4, sizeof(*pend));
		sigprocmask(SIG_SETMASK, &old, NULL);
	}
	p = &pend[npend];
	slash = strrchr(path, '/');
	dirlen = slash != NULL ? (int)(slash - path + 1) : 0;
	if (snprintf(p->tmp, sizeof(p->tmp), "%.*s.%s.XXXXXX", dirlen, path,
	    path + dirlen) >= (int)sizeof(p->tmp)) {
		diag(ST_SYSTEM, path, 0, 0, "file name too long");
		return NULL;
	}
	if ((fd = mkstemp(p->tmp)) < 0) {
		diag(ST_SYSTEM, path, 0, 0, "cannot create a file beside "
		    "it: %s", strerror(errno));
		return NULL;
	}
	p->target = xstrdup(path);
	npend++;
	/* mkstemp makes 0600; give what a plain create would. */
	mask = umask(0);
	umask(mask);
	if (fchmod(fd, 0666 & ~mask) != 0 ||
	    (out = fdopen(fd, "w")) == NULL) {
		diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		close(fd);
		output_abort();
		return NULL;
	}
	return out;
}

/* Close the file being written, keeping it for output_commit(). */
int
output_close(void)
{
	int rc = 0;

	if (out == NULL)
		return -1;
	if (fflush(out) != 0 || ferror(out))
		rc = -1;
	if (out != stdout && fclose(out) != 0)
		rc = -1;
	out = NULL;
	if (rc != 0) {
		diag(ST_SYSTEM, display, 0, 0, "%s", strerror(errno));
		output_abort();
	}
	return rc;
}

/* Put every file written in place; 0, or -1 after a diagnostic. */
int
output_commit(void)
{
	if (out != NULL && output_close() != 0)
		return -1;
	for (sig_atomic_t i = 0; i < npend; i++)
		if (rename(pend[i].tmp, pend[i].target) != 0) {
			diag(ST_SYSTEM, pend[i].target, 0, 0, "%s",
			    strerror(errno));
			output_abort();
			return -1;
		}
	while (npend > 0)
		free(pend[--npend].target);
	free(pend);
	pend = NULL;
	cap = 0;
	return 0;
}

/* Close and remove whatever was written: the targets stay as they were. */
void
output_abort(void)
{
	if (out != NULL && out != stdout)
		fclose(out);
	out = NULL;
	remove_tmps();
	free(pend);
	pend = NULL;
	cap = 0;
}
