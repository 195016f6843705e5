/* diag.c - every diagnostic goes through diag(); the status only rises. */
#include <stdarg.h>
#include <stdio.h>

#include "diag.h"

const char *diag_progname = "phyllo-export";
static enum status worst = ST_OK;

void
diag(enum status st, const char *file, int line, int col, const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, "%s: ", diag_progname);
	if (file != NULL) {
		fputs(file, stderr);
		if (line > 0)
			fprintf(stderr, ":%d", line);
		if (line > 0 && col > 0)
			fprintf(stderr, ":%d", col);
		fputs(": ", stderr);
	}
	if (st == ST_OK)
		fputs("warning: ", stderr);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	if (st > worst)
		worst = st;
}

enum status
diag_status(void)
{
	return worst;
}
