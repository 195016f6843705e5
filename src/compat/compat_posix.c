/*
 * compat_posix.c - compat.h on POSIX systems (Linux, the BSDs, macOS):
 * mostly the calls themselves.  configure picks it when
 * test-posix.c builds.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "compat/compat.h"

FILE *
sys_fopen(const char *path, const char *mode)
{
	return fopen(path, mode);
}

int
sys_stat(const char *path, struct sys_stat *st)
{
	struct stat s;

	if (stat(path, &s) != 0)
		return -1;
	st->kind = S_ISREG(s.st_mode) ? SYS_REG : S_ISDIR(s.st_mode) ?
	    SYS_DIR : SYS_OTHER;
	st->id = (struct sys_id){ (unsigned long long)s.st_dev,
	    (unsigned long long)s.st_ino };
	return 0;
}

int
sys_readable(const char *path)
{
	return access(path, R_OK) == 0;
}

int
sys_writable(const char *path)
{
	return access(path, W_OK) == 0;
}

int
sys_remove(const char *path)
{
	return unlink(path);
}

FILE *
sys_create(const char *path)
{
	int fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0600);
	FILE *fp;

	if (fd < 0)
		return NULL;
	if ((fp = fdopen(fd, "wb")) == NULL) {
		close(fd);
		unlink(path);
	}
	return fp;
}

int
sys_permit(FILE *fp, const char *like)
{
	struct stat st;
	mode_t mode;
	int fd = fileno(fp);

	if (like != NULL && stat(like, &st) == 0) {
		mode = st.st_mode & 07777;
		if (fchown(fd, st.st_uid, st.st_gid) != 0)
			mode &= 0777;	/* no set-id bits for another owner */
	} else {
		mode = umask(0);
		umask(mode);
		mode = 0666 & ~mode;
	}
	return fchmod(fd, mode);
}

int
sys_replace(const char *from, const char *to)
{
	return rename(from, to);
}

int
sys_follow(const char *path, char *buf, size_t sz)
{
	char link[4096], next[4096];
	struct stat st;

	if (snprintf(buf, sz, "%s", path) >= (int)sz)
		goto toolong;
	for (int hops = 0; lstat(buf, &st) == 0 && S_ISLNK(st.st_mode);
	    hops++) {
		ssize_t n = readlink(buf, link, sizeof(link) - 1);
		const char *slash = strrchr(buf, '/');
		int dir = slash != NULL && link[0] != '/' ?
		    (int)(slash - buf + 1) : 0;

		if (n < 0)
			return -1;
		if (hops == 40) {
			errno = ELOOP;
			return -1;
		}
		link[n] = '\0';
		if (snprintf(next, sizeof(next), "%.*s%s", dir, buf, link) >=
		    (int)sizeof(next) || snprintf(buf, sz, "%s", next) >= (int)sz)
			goto toolong;
	}
	return 0;
toolong:
	errno = ENAMETOOLONG;
	return -1;
}

struct sys_dir {
	DIR	*d;
};

struct sys_dir *
sys_opendir(const char *path)
{
	struct sys_dir *d;
	DIR *dir = opendir(path);

	if (dir == NULL)
		return NULL;
	if ((d = malloc(sizeof(*d))) == NULL) {
		closedir(dir);
		return NULL;
	}
	d->d = dir;
	return d;
}

const char *
sys_readdir(struct sys_dir *d)
{
	struct dirent *e = readdir(d->d);

	return e != NULL ? e->d_name : NULL;
}

void
sys_closedir(struct sys_dir *d)
{
	closedir(d->d);
	free(d);
}

const char *
sys_base(const char *path)
{
	const char *slash = strrchr(path, '/');

	return slash != NULL ? slash + 1 : path;
}

int
sys_absolute(const char *path)
{
	return path[0] == '/';
}

const char *
sys_bad_name(const char *path)
{
	(void)path;
	return NULL;
}

long
sys_pid(void)
{
	return (long)getpid();
}

int
sys_running(long pid)
{
	return kill((pid_t)pid, 0) == 0 || errno != ESRCH;
}

static void (*volatile cleanup_fn)(void);

static void
on_signal(int sig)
{
	if (cleanup_fn != NULL)
		cleanup_fn();
	signal(sig, SIG_DFL);
	raise(sig);
}

void
sys_on_signal(void (*cleanup)(void))
{
	static const int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGPIPE };

	signal(SIGXFSZ, SIG_IGN);
	if (cleanup_fn != NULL)
		return;
	cleanup_fn = cleanup;
	for (size_t i = 0; i < sizeof(sigs) / sizeof(sigs[0]); i++)
		signal(sigs[i], on_signal);
}

void
sys_hold(int on)
{
	static sigset_t old;
	sigset_t all;

	if (on) {
		sigfillset(&all);
		sigprocmask(SIG_BLOCK, &all, &old);
	} else
		sigprocmask(SIG_SETMASK, &old, NULL);
}

int
sys_isatty(int fd)
{
	return isatty(fd);
}
