/* test-posix.c - configure: the POSIX calls compat_posix.c makes. */
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

int
main(void)
{
	struct stat st;
	sigset_t all, old;
	char buf[64];
	DIR *d = opendir(".");

	sigfillset(&all);
	sigprocmask(SIG_BLOCK, &all, &old);
	sigprocmask(SIG_SETMASK, &old, NULL);
	signal(SIGXFSZ, SIG_IGN);
	signal(SIGPIPE, SIG_DFL);
	signal(SIGHUP, SIG_DFL);
	if (d != NULL)
		closedir(d);
	return lstat(".", &st) != 0 || S_ISLNK(st.st_mode) ||
	    readlink(".", buf, sizeof(buf)) >= 0 || kill(getpid(), 0) != 0 ||
	    fchmod(-1, 0600) == 0 || fchown(-1, 0, 0) == 0 ||
	    umask(022) > 07777 || isatty(-1) ||
	    open(".", O_WRONLY | O_CREAT | O_EXCL, 0600) >= 0 ||
	    fdopen(-1, "wb") != NULL || fileno(stdin) != 0;
}
