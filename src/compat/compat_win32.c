/*
 * compat_win32.c - compat.h on 64-bit Windows (mingw-w64): names are
 * UTF-8 in the program and UTF-16 at the system, so every call taking
 * a name is the wide-character one; "the same file" is a volume's
 * serial number and the file's index; replacing a file is MoveFileExW.
 * configure picks it when test-win32.c builds (and test-posix.c does
 * not).
 *
 * Also the program's entry: linked with -municode, the C library calls
 * wmain() below, which hands main() its arguments in UTF-8, sets the
 * standard streams to binary (the same bytes as on POSIX: .glb intact,
 * no CR before LF) and a console to UTF-8.
 */
#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include <errno.h>
#include <fcntl.h>
#include <io.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <wchar.h>

#include "compat/compat.h"

/* Room for a name: MAX_PATH is the limit, the rest for the check. */
#define WNAME	1024

/* The errno closest to a Windows error. */
static int
errno_of(DWORD err)
{
	switch (err) {
	case ERROR_FILE_NOT_FOUND:
	case ERROR_PATH_NOT_FOUND:
	case ERROR_INVALID_DRIVE:
	case ERROR_INVALID_NAME:
	case ERROR_BAD_NETPATH:
	case ERROR_BAD_NET_NAME:
		return ENOENT;
	case ERROR_ACCESS_DENIED:
	case ERROR_WRITE_PROTECT:
		return EACCES;
	case ERROR_SHARING_VIOLATION:
	case ERROR_LOCK_VIOLATION:
		return EBUSY;
	case ERROR_FILE_EXISTS:
	case ERROR_ALREADY_EXISTS:
		return EEXIST;
	case ERROR_FILENAME_EXCED_RANGE:
		return ENAMETOOLONG;
	case ERROR_DIRECTORY:
		return ENOTDIR;
	case ERROR_DISK_FULL:
	case ERROR_HANDLE_DISK_FULL:
		return ENOSPC;
	case ERROR_NOT_ENOUGH_MEMORY:
	case ERROR_OUTOFMEMORY:
		return ENOMEM;
	default:
		return EIO;
	}
}

/*
 * path in UTF-16, into w (WNAME wide characters); -1 with errno.
 * Windows refuses a full path of MAX_PATH characters or more (unless
 * the user has lifted the limit and the program asks for it): say so
 * here, rather than let the call fail as "not found".
 */
static int
wide(const char *path, wchar_t *w)
{
	DWORD full;

	if (MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, path, -1, w,
	    WNAME) == 0) {
		errno = GetLastError() == ERROR_INSUFFICIENT_BUFFER ?
		    ENAMETOOLONG : EILSEQ;
		return -1;
	}
	full = GetFullPathNameW(w, 0, NULL, NULL);
	if (full > MAX_PATH) {
		errno = ENAMETOOLONG;
		return -1;
	}
	return 0;
}

FILE *
sys_fopen(const char *path, const char *mode)
{
	wchar_t w[WNAME], m[8];
	size_t i;

	if (wide(path, w) != 0)
		return NULL;
	for (i = 0; mode[i] != '\0' && i + 1 < sizeof(m) / sizeof(m[0]); i++)
		m[i] = (wchar_t)mode[i];
	m[i] = L'\0';
	return _wfopen(w, m);
}

int
sys_stat(const char *path, struct sys_stat *st)
{
	BY_HANDLE_FILE_INFORMATION fi;
	wchar_t w[WNAME];
	HANDLE h;

	if (wide(path, w) != 0)
		return -1;
	/* Backup semantics: folders open too. */
	h = CreateFileW(w, FILE_READ_ATTRIBUTES, FILE_SHARE_READ |
	    FILE_SHARE_WRITE | FILE_SHARE_DELETE, NULL, OPEN_EXISTING,
	    FILE_FLAG_BACKUP_SEMANTICS, NULL);
	if (h == INVALID_HANDLE_VALUE) {
		errno = errno_of(GetLastError());
		return -1;
	}
	if (GetFileType(h) == FILE_TYPE_DISK &&
	    GetFileInformationByHandle(h, &fi)) {
		st->kind = fi.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY ?
		    SYS_DIR : SYS_REG;
		st->id = (struct sys_id){ fi.dwVolumeSerialNumber,
		    (unsigned long long)fi.nFileIndexHigh << 32 |
		    fi.nFileIndexLow };
	} else {
		/* A device (NUL, CON) or a pipe: no index, no file. */
		st->kind = SYS_OTHER;
		st->id = (struct sys_id){ ~0ULL, (unsigned long long)
		    GetFileType(h) };
	}
	CloseHandle(h);
	return 0;
}

int
sys_readable(const char *path)
{
	wchar_t w[WNAME];

	return wide(path, w) == 0 && _waccess(w, 4) == 0;
}

/* Windows' own test: the read-only attribute. */
int
sys_writable(const char *path)
{
	wchar_t w[WNAME];

	return wide(path, w) == 0 && _waccess(w, 2) == 0;
}

int
sys_remove(const char *path)
{
	wchar_t w[WNAME];

	if (wide(path, w) != 0)
		return -1;
	if (!DeleteFileW(w)) {
		errno = errno_of(GetLastError());
		return -1;
	}
	return 0;
}

/*
 * Windows says a path whose folder is a file is not found: say, as
 * POSIX does, that the folder is not one.
 */
static int
create_errno(const wchar_t *w, DWORD err)
{
	wchar_t dir[WNAME];
	const wchar_t *end = NULL;
	DWORD a;

	if (err != ERROR_PATH_NOT_FOUND)
		return errno_of(err);
	for (const wchar_t *p = w; *p != L'\0'; p++)
		if (*p == L'/' || *p == L'\\')
			end = p;
	if (end == NULL || end == w)
		return ENOENT;
	wmemcpy(dir, w, (size_t)(end - w));
	dir[end - w] = L'\0';
	a = GetFileAttributesW(dir);
	return a != INVALID_FILE_ATTRIBUTES &&
	    !(a & FILE_ATTRIBUTE_DIRECTORY) ? ENOTDIR : ENOENT;
}

/*
 * Shared for deleting, so that a Ctrl-C can remove it while it is open
 * (sys_on_signal).  Its folder's permissions, as any new file's: a
 * narrower list would stay with the file once it replaces the target.
 */
FILE *
sys_create(const char *path)
{
	wchar_t w[WNAME];
	HANDLE h;
	FILE *fp;
	int fd;

	if (wide(path, w) != 0)
		return NULL;
	h = CreateFileW(w, GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_DELETE,
	    NULL, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, NULL);
	if (h == INVALID_HANDLE_VALUE) {
		errno = create_errno(w, GetLastError());
		return NULL;
	}
	fd = _open_osfhandle((intptr_t)h, _O_WRONLY | _O_BINARY);
	if (fd < 0)
		CloseHandle(h);
	if (fd < 0 || (fp = _fdopen(fd, "wb")) == NULL) {
		if (fd >= 0)
			_close(fd);
		DeleteFileW(w);
		errno = EMFILE;
		return NULL;
	}
	return fp;
}

int
sys_permit(FILE *fp, const char *like)
{
	(void)fp;
	(void)like;
	return 0;
}

/*
 * Whether another program holds w open without letting it be deleted
 * (as most do: C's fopen() among them), which stops a replace.
 */
static int
held_open(const wchar_t *w)
{
	HANDLE h = CreateFileW(w, DELETE, FILE_SHARE_READ | FILE_SHARE_WRITE |
	    FILE_SHARE_DELETE, NULL, OPEN_EXISTING, 0, NULL);

	if (h != INVALID_HANDLE_VALUE) {
		CloseHandle(h);
		return 0;
	}
	return GetLastError() == ERROR_SHARING_VIOLATION;
}

/*
 * A virus scanner or an indexer opens a new file for a moment: a few
 * tries over a second outwait it; a program that keeps the file open
 * (POV-Ray rendering it, an editor) gets EBUSY and a message.
 */
int
sys_replace(const char *from, const char *to)
{
	wchar_t wf[WNAME], wt[WNAME];
	DWORD err;

	if (wide(from, wf) != 0 || wide(to, wt) != 0)
		return -1;
	for (int tries = 0;; tries++) {
		if (MoveFileExW(wf, wt, MOVEFILE_REPLACE_EXISTING |
		    MOVEFILE_WRITE_THROUGH))
			return 0;
		err = GetLastError();
		if ((err == ERROR_ACCESS_DENIED ||
		    err == ERROR_SHARING_VIOLATION ||
		    err == ERROR_LOCK_VIOLATION) && held_open(wt)) {
			if (tries < 10) {
				Sleep(100);
				continue;
			}
			errno = EBUSY;
		} else
			errno = errno_of(err);
		return -1;
	}
}

/*
 * Symbolic links, rare on Windows (making one takes a privilege), are
 * not followed: -o through one replaces the link.
 */
int
sys_follow(const char *path, char *buf, size_t sz)
{
	if (snprintf(buf, sz, "%s", path) >= (int)sz) {
		errno = ENAMETOOLONG;
		return -1;
	}
	return 0;
}

struct sys_dir {
	HANDLE		 h;
	int		 first;		/* data holds the first entry */
	WIN32_FIND_DATAW data;
	char		 name[MAX_PATH * 3];
};

struct sys_dir *
sys_opendir(const char *path)
{
	wchar_t w[WNAME];
	struct sys_dir *d;
	size_t n;

	if (wide(path, w) != 0)
		return NULL;
	n = wcslen(w);
	if (n + 3 > WNAME) {
		errno = ENAMETOOLONG;
		return NULL;
	}
	wcscpy(w + n, n > 0 && (w[n - 1] == L'/' || w[n - 1] == L'\\') ?
	    L"*" : L"\\*");
	if ((d = malloc(sizeof(*d))) == NULL)
		return NULL;
	if ((d->h = FindFirstFileW(w, &d->data)) == INVALID_HANDLE_VALUE) {
		errno = errno_of(GetLastError());
		free(d);
		return NULL;
	}
	d->first = 1;
	return d;
}

const char *
sys_readdir(struct sys_dir *d)
{
	if (!d->first && !FindNextFileW(d->h, &d->data))
		return NULL;
	d->first = 0;
	if (WideCharToMultiByte(CP_UTF8, 0, d->data.cFileName, -1, d->name,
	    (int)sizeof(d->name), NULL, NULL) == 0)
		d->name[0] = '\0';
	return d->name;
}

void
sys_closedir(struct sys_dir *d)
{
	FindClose(d->h);
	free(d);
}

static int
drive(const char *path)
{
	return ((path[0] >= 'A' && path[0] <= 'Z') ||
	    (path[0] >= 'a' && path[0] <= 'z')) && path[1] == ':';
}

const char *
sys_base(const char *path)
{
	const char *base = drive(path) ? path + 2 : path;

	for (const char *p = base; *p != '\0'; p++)
		if (*p == '/' || *p == '\\')
			base = p + 1;
	return base;
}

int
sys_absolute(const char *path)
{
	return path[0] == '/' || path[0] == '\\' || drive(path);
}

/*
 * Names Windows keeps for devices, with any extension (NUL.inc is NUL)
 * in the last part of a path, and characters it allows in none.
 */
const char *
sys_bad_name(const char *path)
{
	static const char *const devices[] = { "CON", "PRN", "AUX", "NUL",
	    "COM1", "COM2", "COM3", "COM4", "COM5", "COM6", "COM7", "COM8",
	    "COM9", "LPT1", "LPT2", "LPT3", "LPT4", "LPT5", "LPT6", "LPT7",
	    "LPT8", "LPT9" };
	static char why[128];
	const char *base = sys_base(path);
	size_t stem = strcspn(base, ".");
	size_t len = strlen(base);

	while (stem > 0 && base[stem - 1] == ' ')
		stem--;
	for (size_t i = 0; i < sizeof(devices) / sizeof(devices[0]); i++)
		if (strlen(devices[i]) == stem &&
		    _strnicmp(base, devices[i], stem) == 0) {
			snprintf(why, sizeof(why), "%s names a device on "
			    "Windows, not a file", devices[i]);
			return why;
		}
	for (const char *p = base; *p != '\0'; p++)
		if (strchr("<>:\"|?*", *p) != NULL || (unsigned char)*p < 32)
			return "Windows allows none of <>:\"|?* and no "
			    "control character in a file's name";
	if (len > 0 && (base[len - 1] == '.' || base[len - 1] == ' '))
		return "Windows drops a final dot or space from a file's "
		    "name";
	return NULL;
}

long
sys_pid(void)
{
	return (long)GetCurrentProcessId();
}

int
sys_running(long pid)
{
	HANDLE h = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE,
	    (DWORD)pid);
	DWORD code;
	int alive;

	if (h == NULL)
		return GetLastError() != ERROR_INVALID_PARAMETER;
	alive = !GetExitCodeProcess(h, &code) || code == STILL_ACTIVE;
	CloseHandle(h);
	return alive;
}

/*
 * Windows calls a console's handler on a thread of its own while the
 * program runs on: sys_hold() is a lock the handler waits for.  It then
 * removes the files (shared for deleting, sys_create()) and ends the
 * program as Ctrl-C's default handler does, with STATUS_CONTROL_C_EXIT
 * (wine's own would exit 0).
 */
static void (*volatile cleanup_fn)(void);
static SRWLOCK hold = SRWLOCK_INIT;

static BOOL WINAPI
on_event(DWORD event)
{
	(void)event;
	AcquireSRWLockExclusive(&hold);
	if (cleanup_fn != NULL)
		cleanup_fn();
	ExitProcess(STATUS_CONTROL_C_EXIT);
	return TRUE;
}

void
sys_on_signal(void (*cleanup)(void))
{
	if (cleanup_fn != NULL)
		return;
	cleanup_fn = cleanup;
	SetConsoleCtrlHandler(on_event, TRUE);
}

void
sys_hold(int on)
{
	if (on)
		AcquireSRWLockExclusive(&hold);
	else
		ReleaseSRWLockExclusive(&hold);
}

/* isatty() says yes to NUL too: a console answers GetConsoleMode. */
int
sys_isatty(int fd)
{
	HANDLE h = (HANDLE)_get_osfhandle(fd);
	DWORD mode;

	return h != INVALID_HANDLE_VALUE && GetConsoleMode(h, &mode);
}

/* ---- The program's entry ---- */

int	main(int, char *[]);

static UINT console_cp;

static void
restore_console(void)
{
	SetConsoleOutputCP(console_cp);
}

int
wmain(int argc, wchar_t *wargv[])
{
	char **argv = calloc((size_t)argc + 1, sizeof(*argv));
	int rc;

	if (argv == NULL)
		return 3;
	for (int i = 0; i < argc; i++) {
		int n = WideCharToMultiByte(CP_UTF8, 0, wargv[i], -1, NULL, 0,
		    NULL, NULL);

		if (n <= 0 || (argv[i] = malloc((size_t)n)) == NULL)
			return 3;
		WideCharToMultiByte(CP_UTF8, 0, wargv[i], -1, argv[i], n, NULL,
		    NULL);
	}
	_setmode(_fileno(stdin), _O_BINARY);
	_setmode(_fileno(stdout), _O_BINARY);
	_setmode(_fileno(stderr), _O_BINARY);
	if (sys_isatty(_fileno(stderr)) && (console_cp =
	    GetConsoleOutputCP()) != CP_UTF8 && SetConsoleOutputCP(CP_UTF8))
		atexit(restore_console);
	rc = main(argc, argv);
	for (int i = 0; i < argc; i++)
		free(argv[i]);
	free(argv);
	return rc;
}
