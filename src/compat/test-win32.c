/*
 * test-win32.c - configure: the Windows calls compat_win32.c makes,
 * and its entry point: linked with -municode, wmain() is the program's.
 */
#define WIN32_LEAN_AND_MEAN
#include <windows.h>

#include <fcntl.h>
#include <io.h>
#include <stdio.h>
#include <wchar.h>

int
wmain(int argc, wchar_t *argv[])
{
	static SRWLOCK lock = SRWLOCK_INIT;
	BY_HANDLE_FILE_INFORMATION fi;
	WIN32_FIND_DATAW fd;
	HANDLE h = CreateFileW(argv[0], FILE_READ_ATTRIBUTES, FILE_SHARE_READ,
	    NULL, OPEN_EXISTING, FILE_FLAG_BACKUP_SEMANTICS, NULL);
	DWORD mode;

	AcquireSRWLockExclusive(&lock);
	ReleaseSRWLockExclusive(&lock);
	_setmode(_fileno(stdout), _O_BINARY);
	(void)GetConsoleMode((HANDLE)_get_osfhandle(1), &mode);
	(void)GetFileInformationByHandle(h, &fi);
	(void)FindFirstFileW(L"*", &fd);
	(void)_wfopen(argv[0], L"rb");
	(void)_waccess(argv[0], 4);
	return argc + !MoveFileExW(argv[0], argv[0], MOVEFILE_REPLACE_EXISTING |
	    MOVEFILE_WRITE_THROUGH) + MultiByteToWideChar(CP_UTF8, 0, "", -1,
	    NULL, 0) + (int)GetFullPathNameW(argv[0], 0, NULL, NULL) +
	    (OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, 1) == NULL);
}
