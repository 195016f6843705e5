/*
 * compat.h - what systems do differently, behind one small API that
 * the rest of the program calls instead of the system's own: files by
 * UTF-8 names, "the same file", replacing a file, processes, signals,
 * terminals and the syntax of paths.  configure chooses the file behind
 * it by test programs (src/compat/test-*.c, as mandoc does):
 * compat_posix.c (Linux, the BSDs, macOS) or compat_win32.c (64-bit
 * Windows, mingw-w64).  The bottom of the program: it includes nothing
 * of ours.
 */
#ifndef COMPAT_H
#define COMPAT_H

#include <stddef.h>
#include <stdio.h>

/*
 * PRINTFLIKE(f, a): a function that formats as printf(), its format
 * argument f and its first value a, for the compiler to check.  mingw's
 * gcc reads "printf" as Microsoft's formats, which know no %zu, though
 * we link mingw's own C99 printf: configure passes
 * -DPRINTF_FORMAT=gnu_printf there.
 */
#ifndef PRINTF_FORMAT
#define PRINTF_FORMAT	printf
#endif
#if defined(__GNUC__)
#define PRINTFLIKE(f, a)	__attribute__((format(PRINTF_FORMAT, f, a)))
#else
#define PRINTFLIKE(f, a)
#endif

/* A file's identity: two names, links or spellings of one file match. */
struct sys_id {
	unsigned long long	 dev;	/* st_dev; a volume's serial number */
	unsigned long long	 ino;	/* st_ino; the file index */
};

enum sys_kind { SYS_REG, SYS_DIR, SYS_OTHER };	/* OTHER: devices, pipes */

struct sys_stat {
	enum sys_kind	 kind;
	struct sys_id	 id;
};

#define SYS_SAME(a, b)	((a).dev == (b).dev && (a).ino == (b).ino)

/*
 * Files by name; names are UTF-8 everywhere (on Windows through the
 * wide-character calls).  Each returns as the POSIX call it is named
 * after does: -1 (or NULL) with errno set.
 */
FILE	*sys_fopen(const char *path, const char *mode);
int	 sys_stat(const char *path, struct sys_stat *);	/* links followed */
int	 sys_readable(const char *path);	/* 1, or 0 with errno */
int	 sys_writable(const char *path);	/* 1, or 0 with errno */
int	 sys_remove(const char *path);		/* async-signal-safe */

/*
 * Create a new file (never one that exists: errno EEXIST) for writing
 * in binary, which only its owner may read until sys_permit().
 */
FILE	*sys_create(const char *path);
/*
 * Give the file fp writes the permissions of the existing file like
 * (its mode, and its owner where we may), or with like NULL those of a
 * file the user creates (0666 less the umask).  Nothing to do on
 * Windows, where a new file takes its folder's.
 */
int	 sys_permit(FILE *fp, const char *like);
/*
 * Put the file from in the place of the file to, at once: readers see
 * the old file or the new one, never a part.  Where another program
 * holds to open and the system refuses to replace it (Windows), it
 * retries for a second, then fails with errno EBUSY.
 */
int	 sys_replace(const char *from, const char *to);
/*
 * The file path names once symbolic links are followed, into buf (it
 * need not exist); -1 with errno ENAMETOOLONG or ELOOP.
 */
int	 sys_follow(const char *path, char *buf, size_t sz);

/* A folder's entries by name, "." and ".." among them. */
struct sys_dir;
struct sys_dir *sys_opendir(const char *path);
const char *sys_readdir(struct sys_dir *);	/* NULL at the end */
void	 sys_closedir(struct sys_dir *);

/*
 * Paths: where the last part of a path starts (past its folder's
 * separator, '/' or on Windows also '\' or a drive's "C:"), whether a
 * path starts from no folder (Windows: "\", "/" or "C:"), and why a
 * path cannot be a file's name here (a device's name on Windows: CON,
 * NUL; too long) or NULL.
 */
const char *sys_base(const char *path);
int	 sys_absolute(const char *path);
const char *sys_bad_name(const char *path);

/* Processes. */
long	 sys_pid(void);
int	 sys_running(long pid);		/* it, or one of that number */

/*
 * On a signal that ends the program (POSIX: SIGINT, SIGTERM, SIGHUP,
 * SIGPIPE; Windows: Ctrl-C, Ctrl-Break, the console closed), run
 * cleanup, which may only remove files, then end as the signal would.
 * A file size limit (SIGXFSZ) is a write error instead.  While held
 * (sys_hold(1) until sys_hold(0)), cleanup waits.
 */
void	 sys_on_signal(void (*cleanup)(void));
void	 sys_hold(int on);

/* Whether fd is a terminal (a console on Windows, not NUL). */
int	 sys_isatty(int fd);

#endif
