/* diag.h - the one place diagnostics are printed, and the exit status. */
#ifndef DIAG_H
#define DIAG_H

#include "compat/compat.h"

/* Exit statuses; the program's status only ever rises. */
enum status {
	ST_OK = 0,
	ST_SCENE = 1,	/* an error in the scene file or a template */
	ST_USAGE = 2,	/* a command-line usage error */
	ST_SYSTEM = 3	/* I/O, memory */
};

/*
 * Print "phyllo-export: FILE:LINE[:COL]: message" (LINE 0 leaves out the
 * position, COL 0 the column) and raise the exit status to st.  ST_OK
 * prints a warning and leaves the status alone.
 */
void	 diag(enum status st, const char *file, int line, int col,
	    const char *fmt, ...)
	    PRINTFLIKE(5, 6)
	    ;
enum status diag_status(void);

/*
 * While hushed (diag_hush(1), as many times as diag_hush(0) undoes),
 * nothing is printed and the status stays: for a trial, as the loader's
 * of a file without its --set (scene_tables.c).
 */
void	 diag_hush(int on);

/*
 * While set, every message names this after its position ("frame 3 of
 * 10 (f = 0.222222222)"); NULL clears it.  The text is copied.
 */
void	 diag_context(const char *);

/*
 * Settings given on the command line (--set PATH=VALUE) are checked as
 * if written in the scene, at a line past any file's end: line
 * DIAG_LINE_SET + k stands for the k-th, and a message at it names the
 * override ("--set planar.scale=0: ...") instead of FILE:LINE.
 */
#define DIAG_LINE_SET	(1 << 28)
void	 diag_overrides(const char *const *args, int n);

/* How to call ourselves in messages: "phyllo-export". */
extern const char *diag_progname;

#endif
