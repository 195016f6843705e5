/* diag.c - every diagnostic goes through diag(); the status only rises. */
#include <stdarg.h>
#include <stdio.h>

#include "base/diag.h"

const char *diag_progname = "phyllo-export";
static enum status worst = ST_OK;
static char context[128];
static const char *const *set_args;
static int nset;

void
diag_overrides(const char *const *args, int n)
{
	set_args = args;
	nset = n;
}

void
diag_context(const char *what)
{
	snprintf(context, sizeof(context), "%s", what != NULL ? what : "");
}

static int hushed;

void
diag_hush(int on)
{
	hushed += on ? 1 : -1;
}

void
diag(enum status st, const char *file, int line, int col, const char *fmt, ...)
{
	va_list ap;

	if (hushed > 0)
		return;

	fprintf(stderr, "%s: ", diag_progname);
	if (line >= DIAG_LINE_SET && line - DIAG_LINE_SET < nset)
		fprintf(stderr, "--set %s: ", set_args[line - DIAG_LINE_SET]);
	else if (file != NULL) {
		fputs(file, stderr);
		if (line > 0)
			fprintf(stderr, ":%d", line);
		if (line > 0 && col > 0)
			fprintf(stderr, ":%d", col);
		fputs(": ", stderr);
	}
	if (st == ST_OK)
		fputs("warning: ", stderr);
	if (context[0] != '\0')
		fprintf(stderr, "%s: ", context);
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
