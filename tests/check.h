/*
 * check.h - the test programs' one way of reporting: a line "ok - ..."
 * or "not ok - ..." per check, which tests/run.sh counts, and an exit
 * status saying whether any failed.  Each program sets check_topic.
 */
#ifndef CHECK_H
#define CHECK_H

#include <stdarg.h>
#include <stdio.h>

static const char *check_topic = "";
static int check_failures;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void
check(int ok, const char *fmt, ...)
{
	va_list ap;

	printf("%s - %s", ok ? "ok" : "not ok", check_topic);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	putchar('\n');
	check_failures += !ok;
}

#endif
