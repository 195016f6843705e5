/*
 * output.c - open the output: standard output, or -o FILE.  A regular
 * FILE is written as a temporary file beside it and renamed over it
 * only when everything was written, so a failed or interrupted run never
 * leaves a damaged or half-written file.  --frames writes several files
 * the same way: all of them are renamed into place at the end, or none.
 * Devices and pipes named with -o (/dev/stdout, /dev/full) are written
 * directly.
 *
 * The temporary is named for what it is, FILE.phyllo-export-PID.tmp,
 * not hidden: a run killed by SIGKILL (or a power cut) cannot remove it,
 * and a user who finds it must see whose it is.  The next run to the
 * same FILE removes those of processes that no longer run.
 *
 * Temporary files are removed on error, on exit() from anywhere (out
 * of memory) and on the signals that end a program (sys_on_signal():
 * SIGINT, SIGTERM, SIGHUP and SIGPIPE; Ctrl-C on Windows).  A file size
 * limit (ulimit -f) is a write error with a message, not a kill that
 * leaves a temporary file behind.
 *
 * -o never names a file the run reads: the scene, a part's scene, the
 * template (base/inputs.c lists them), so that a slip of the keyboard
 * (phyllo-export --pov -o my.cfg my.cfg) cannot destroy a scene.  Nor
 * one the user may not write: a rename would replace a read-only file
 * that the shell's > and cp refuse to touch.  Nor, on Windows, a
 * device's name (NUL, CON), which no file can have.
 */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "base/diag.h"
#include "base/inputs.h"
#include "base/mem.h"
#include "writers/output.h"

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
		sys_remove(pend[npend].tmp);
		free(pend[npend].target);
	}
}

/* On a signal: only what a signal handler may do. */
static void
remove_on_signal(void)
{
	for (sig_atomic_t i = 0; i < npend; i++)
		sys_remove(pend[i].tmp);
}

static void
catch_signals(void)
{
	static int done;

	sys_on_signal(remove_on_signal);
	if (!done++)
		atexit(remove_tmps);
}

int
output_check(const char *path)
{
	struct sys_stat st;
	const char *why, *in, *what;

	if (path != NULL && (why = sys_bad_name(path)) != NULL) {
		diag(ST_USAGE, NULL, 0, 0, "-o %s: %s: give another name",
		    path, why);
		return -1;
	}
	if (path == NULL || sys_stat(path, &st) != 0)
		return 0;
	if (input_find(&st.id, &in, &what)) {
		diag(ST_USAGE, NULL, 0, 0, "-o %s would replace %s, %s%s: "
		    "give another output file", path, in, what,
		    strcmp(path, in) != 0 ?
		    " (the same file by another name)" : "");
		return -1;
	}
	if (st.kind == SYS_REG && !sys_writable(path)) {
		diag(ST_SYSTEM, path, 0, 0, "%s: -o replaces only a file you may "
		    "write", strerror(errno));
		return -1;
	}
	return 0;
}

/* The temporary of target written by process pid. */
#define TMP_TAG	".phyllo-export-"
#define TMP_END	".tmp"

static int
tmp_name(char *buf, size_t sz, const char *target, long pid)
{
	return snprintf(buf, sz, "%s" TMP_TAG "%ld" TMP_END, target, pid) >=
	    (int)sz ? -1 : 0;
}

/*
 * Remove the temporaries of target that runs killed before they could
 * (SIGKILL, a crash of the machine) left: ours by their name, stale by
 * their process.
 */
static void
remove_stale(const char *target, int dirlen)
{
	const char *base = target + dirlen;
	size_t blen = strlen(base);
	char dir[PATH_MAX], stale[PATH_MAX];
	struct sys_dir *d;
	const char *p;

	if (snprintf(dir, sizeof(dir), "%.*s", dirlen ? dirlen : 1,
	    dirlen ? target : ".") >= (int)sizeof(dir) ||
	    (d = sys_opendir(dir)) == NULL)
		return;
	while ((p = sys_readdir(d)) != NULL) {
		char *end;
		long pid;

		if (strncmp(p, base, blen) != 0 ||
		    strncmp(p += blen, TMP_TAG, strlen(TMP_TAG)) != 0)
			continue;
		p += strlen(TMP_TAG);
		if (*p < '1' || *p > '9')
			continue;
		pid = strtol(p, &end, 10);
		if (strcmp(end, TMP_END) != 0 || pid == sys_pid() ||
		    sys_running(pid) ||
		    tmp_name(stale, sizeof(stale), target, pid) != 0)
			continue;
		sys_remove(stale);
	}
	sys_closedir(d);
}

/*
 * Create target's temporary, only ours; its name in buf.  The stream,
 * or NULL with errno, ENAMETOOLONG for a name too long.  One of our own
 * number exists only if a process of that number before us left it.
 */
static FILE *
create_tmp(char *buf, size_t sz, const char *target)
{
	FILE *fp;

	if (tmp_name(buf, sz, target, sys_pid()) != 0) {
		errno = ENAMETOOLONG;
		return NULL;
	}
	fp = sys_create(buf);
	if (fp == NULL && errno == EEXIST && sys_remove(buf) == 0)
		fp = sys_create(buf);
	return fp;
}

/* Why no file can be made beside target, after create_tmp() failed. */
static const char *
dir_problem(const char *target, int dirlen)
{
	static char why[PATH_MAX + 64];
	int err = errno;

	if (dirlen == 0)
		snprintf(why, sizeof(why), "cannot create a file in the "
		    "current directory: %s", strerror(err));
	else if (err == ENOENT)
		snprintf(why, sizeof(why), "directory %.*s does not exist",
		    dirlen > 1 ? dirlen - 1 : dirlen, target);
	else if (err == ENOTDIR)
		snprintf(why, sizeof(why), "%.*s is not a directory",
		    dirlen > 1 ? dirlen - 1 : dirlen, target);
	else
		snprintf(why, sizeof(why), "cannot create a file in %.*s: %s",
		    dirlen, target, strerror(err));
	return why;
}

FILE *
output_open(const char *path)
{
	struct pending *p;
	struct sys_stat st;
	char target[PATH_MAX];
	int dirlen, had;

	catch_signals();
	if (path == NULL)
		return out = stdout;
	display = path;
	if (sys_follow(path, target, sizeof(target)) != 0) {
		diag(ST_SYSTEM, path, 0, 0, "%s", errno == ENAMETOOLONG ?
		    "file name too long" : strerror(errno));
		return NULL;
	}
	had = sys_stat(target, &st) == 0;
	if (had && st.kind != SYS_REG) {
		if ((out = sys_fopen(path, "wb")) == NULL)
			diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		return out;
	}
	if ((size_t)npend == cap) {
		/* Grown with signals held: the handler walks pend. */
		sys_hold(1);
		pend = xreallocarray(pend, cap = cap * 2 + 4, sizeof(*pend));
		sys_hold(0);
	}
	p = &pend[npend];
	dirlen = (int)(sys_base(target) - target);
	remove_stale(target, dirlen);
	if ((out = create_tmp(p->tmp, sizeof(p->tmp), target)) == NULL) {
		diag(ST_SYSTEM, path, 0, 0, "%s", errno == ENAMETOOLONG ?
		    "file name too long" : dir_problem(target, dirlen));
		return NULL;
	}
	p->target = xstrdup(target);
	npend++;
	/* An existing file's own mode and owner, else a plain create's. */
	if (sys_permit(out, had ? target : NULL) != 0) {
		diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
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
		if (sys_replace(pend[i].tmp, pend[i].target) != 0) {
			diag(ST_SYSTEM, pend[i].target, 0, 0, "%s", errno ==
			    EBUSY ? "another program has the file open: close "
			    "it there and run again" : strerror(errno));
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

/* Our own expansion, so that -o is never a printf format. */
int
output_frame_path(const char *pattern, int F, char *buf, size_t sz)
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
