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
 * of memory) and on SIGINT, SIGTERM, SIGHUP and SIGPIPE.  SIGXFSZ is
 * ignored, so that a file size limit (ulimit -f) is a write error with
 * a message, not a kill that leaves a temporary file behind.
 *
 * -o never names a file the run reads: the scene, a part's scene, the
 * template (output_input() lists them), so that a slip of the keyboard
 * (phyllo-export --pov -o my.cfg my.cfg) cannot destroy a scene.  Nor
 * one the user may not write: a rename would replace a read-only file
 * that the shell's > and cp refuse to touch.
 */
#include <dirent.h>
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
#include "writers/output.h"

/* A file written but not yet in place. */
struct pending {
	char	 tmp[PATH_MAX];
	char	*target;
};

/* A file read, by identity: another path or a link is the same file. */
struct input {
	dev_t	 dev;
	ino_t	 ino;
	char	*path, *what;
};

static struct input *inputs;
static size_t ninputs;

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

static void
free_inputs(void)
{
	for (size_t i = 0; i < ninputs; i++) {
		free(inputs[i].path);
		free(inputs[i].what);
	}
	free(inputs);
	inputs = NULL;
	ninputs = 0;
}

void
output_input(const char *path, const char *what)
{
	struct stat st;

	if (stat(path, &st) != 0)
		return;
	if (inputs == NULL)
		atexit(free_inputs);
	inputs = xreallocarray(inputs, ninputs + 1, sizeof(*inputs));
	inputs[ninputs++] = (struct input){ st.st_dev, st.st_ino,
	    xstrdup(path), xstrdup(what) };
}

int
output_check(const char *path)
{
	struct stat st;

	if (path == NULL || stat(path, &st) != 0)
		return 0;
	for (size_t i = 0; i < ninputs; i++)
		if (inputs[i].dev == st.st_dev && inputs[i].ino == st.st_ino) {
			diag(ST_USAGE, NULL, 0, 0, "-o %s would replace %s, %s%s: "
			    "give another output file", path, inputs[i].path,
			    inputs[i].what, strcmp(path, inputs[i].path) != 0 ?
			    " (the same file by another name)" : "");
			return -1;
		}
	if (S_ISREG(st.st_mode) && access(path, W_OK) != 0) {
		diag(ST_SYSTEM, path, 0, 0, "%s: -o replaces only a file you may "
		    "write", strerror(errno));
		return -1;
	}
	return 0;
}

/*
 * The file a path names once symbolic links are followed, so that -o
 * through a link replaces the link's target and not the link; the
 * target need not exist yet.  0, or -1 after a diagnostic.
 */
static int
follow_links(const char *path, char *buf, size_t sz)
{
	char link[PATH_MAX], next[PATH_MAX];
	struct stat st;

	if (snprintf(buf, sz, "%s", path) >= (int)sz)
		goto toolong;
	for (int hops = 0; lstat(buf, &st) == 0 && S_ISLNK(st.st_mode);
	    hops++) {
		ssize_t n = readlink(buf, link, sizeof(link) - 1);
		const char *slash = strrchr(buf, '/');
		int dir = slash != NULL && link[0] != '/' ?
		    (int)(slash - buf + 1) : 0;

		if (n < 0 || hops == 40) {
			diag(ST_SYSTEM, path, 0, 0, "%s", n < 0 ?
			    strerror(errno) : strerror(ELOOP));
			return -1;
		}
		link[n] = '\0';
		if (snprintf(next, sizeof(next), "%.*s%s", dir, buf, link) >=
		    (int)sizeof(next) || snprintf(buf, sz, "%s", next) >= (int)sz)
			goto toolong;
	}
	return 0;
toolong:
	diag(ST_SYSTEM, path, 0, 0, "file name too long");
	return -1;
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

/* Whether process pid may still run (it, or one of that number). */
static int
running(long pid)
{
	return kill((pid_t)pid, 0) == 0 || errno != ESRCH;
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
	struct dirent *e;
	DIR *d;

	if (snprintf(dir, sizeof(dir), "%.*s", dirlen ? dirlen : 1,
	    dirlen ? target : ".") >= (int)sizeof(dir) ||
	    (d = opendir(dir)) == NULL)
		return;
	while ((e = readdir(d)) != NULL) {
		const char *p = e->d_name;
		char *end;
		long pid;

		if (strncmp(p, base, blen) != 0 ||
		    strncmp(p += blen, TMP_TAG, strlen(TMP_TAG)) != 0)
			continue;
		p += strlen(TMP_TAG);
		if (*p < '1' || *p > '9')
			continue;
		pid = strtol(p, &end, 10);
		if (strcmp(end, TMP_END) != 0 || pid == (long)getpid() ||
		    running(pid) ||
		    tmp_name(stale, sizeof(stale), target, pid) != 0)
			continue;
		unlink(stale);
	}
	closedir(d);
}

/*
 * Create target's temporary, 0600 and only ours; its name in buf.  The
 * descriptor, -2 for a name too long, or -1 with errno.  One of our own
 * number exists only if a process of that number before us left it.
 */
static int
create_tmp(char *buf, size_t sz, const char *target)
{
	int fd;

	if (tmp_name(buf, sz, target, (long)getpid()) != 0)
		return -2;
	fd = open(buf, O_WRONLY | O_CREAT | O_EXCL, 0600);
	if (fd < 0 && errno == EEXIST && unlink(buf) == 0)
		fd = open(buf, O_WRONLY | O_CREAT | O_EXCL, 0600);
	return fd;
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
	struct stat st;
	const char *slash;
	char target[PATH_MAX];
	mode_t mode;
	int fd, dirlen, had;

	signal(SIGXFSZ, SIG_IGN);
	if (path == NULL)
		return out = stdout;
	display = path;
	if (follow_links(path, target, sizeof(target)) != 0)
		return NULL;
	had = stat(target, &st) == 0;
	if (had && !S_ISREG(st.st_mode)) {
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
	slash = strrchr(target, '/');
	dirlen = slash != NULL ? (int)(slash - target + 1) : 0;
	remove_stale(target, dirlen);
	if ((fd = create_tmp(p->tmp, sizeof(p->tmp), target)) < 0) {
		if (fd == -2)
			diag(ST_SYSTEM, path, 0, 0, "file name too long");
		else
			diag(ST_SYSTEM, path, 0, 0, "%s", dir_problem(target, dirlen));
		return NULL;
	}
	p->target = xstrdup(target);
	npend++;
	/*
	 * The temporary is 0600: give an existing file's own mode and owner
	 * (the owner only where we may), else what a plain create would.
	 */
	if (had) {
		mode = st.st_mode & 07777;
		if (fchown(fd, st.st_uid, st.st_gid) != 0)
			mode &= 0777;	/* no set-id bits for another owner */
	} else {
		mode = umask(0);
		umask(mode);
		mode = 0666 & ~mode;
	}
	if (fchmod(fd, mode) != 0 || (out = fdopen(fd, "w")) == NULL) {
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
