/*
 * output.c - open the output: standard output, or -o FILE.  A regular
 * FILE is written as a temporary file beside it and renamed over it
 * only when everything was written, so a failed or interrupted run never
 * leaves a damaged or half-written file.  Devices and pipes named with
 * -o (/dev/stdout, /dev/full) are written directly.
 *
 * The temporary file is removed on error, on exit() from anywhere (out
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
#include "output.h"

static FILE *out;
static const char *target;		/* renamed into place; or NULL */
static const char *display = "<stdout>";	/* for messages */
static char tmp[PATH_MAX];		/* non-empty while it exists */
static volatile sig_atomic_t have_tmp;

static void
remove_tmp(void)
{
	if (have_tmp) {
		have_tmp = 0;
		unlink(tmp);
	}
}

static void
on_signal(int sig)
{
	if (have_tmp)
		unlink(tmp);
	signal(sig, SIG_DFL);
	raise(sig);
}

static void
catch_signals(void)
{
	static const int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGPIPE };

	for (size_t i = 0; i < sizeof(sigs) / sizeof(sigs[0]); i++)
		signal(sigs[i], on_signal);
}

FILE *
output_open(const char *path)
{
	struct stat st;
	const char *slash;
	mode_t mask;
	int fd, dirlen;

	target = path;
	if (path != NULL)
		display = path;
	if (path == NULL)
		return out = stdout;
	if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
		target = NULL;
		if ((out = fopen(path, "w")) == NULL)
			diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		return out;
	}
	slash = strrchr(path, '/');
	dirlen = slash != NULL ? (int)(slash - path + 1) : 0;
	if (snprintf(tmp, sizeof(tmp), "%.*s.%s.XXXXXX", dirlen, path,
	    path + dirlen) >= (int)sizeof(tmp)) {
		diag(ST_SYSTEM, path, 0, 0, "file name too long");
		return NULL;
	}
	atexit(remove_tmp);
	catch_signals();
	if ((fd = mkstemp(tmp)) < 0) {
		diag(ST_SYSTEM, path, 0, 0, "cannot create a file beside "
		    "it: %s", strerror(errno));
		return NULL;
	}
	have_tmp = 1;
	/* mkstemp makes 0600; give what a plain create would. */
	mask = umask(0);
	umask(mask);
	if (fchmod(fd, 0666 & ~mask) != 0 ||
	    (out = fdopen(fd, "w")) == NULL) {
		diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		close(fd);
		remove_tmp();
		return NULL;
	}
	return out;
}

/* Close and put the file in place; 0, or -1 after a diagnostic. */
int
output_commit(void)
{
	int rc = 0;

	if (out == NULL)
		return -1;
	if (fflush(out) != 0 || ferror(out))
		rc = -1;
	if (out != stdout && fclose(out) != 0)
		rc = -1;
	out = NULL;
	if (rc == 0 && target != NULL && rename(tmp, target) != 0)
		rc = -1;
	if (rc != 0) {
		diag(ST_SYSTEM, display, 0, 0, "%s", strerror(errno));
		remove_tmp();
		return -1;
	}
	have_tmp = 0;
	return 0;
}

void
output_abort(void)
{
	if (out != NULL && out != stdout)
		fclose(out);
	out = NULL;
	remove_tmp();
}
