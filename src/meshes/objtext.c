/* objtext.c - OBJ and .mtl text: lines, words, numbers, messages, files. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "compat/compat.h"
#include "scene/cfgtext.h"
#include "base/diag.h"
#include "base/mem.h"
#include "meshes/objtext.h"

int
objtext_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

const char *
objtext_skip(const char *p, const char *end)
{
	while (p < end && objtext_blank(*p))
		p++;
	return p;
}

/* The end of the word at p. */
const char *
objtext_word_end(const char *p, const char *end)
{
	while (p < end && !objtext_blank(*p))
		p++;
	return p;
}

int
objtext_fail(const struct objtext *O, const char *fmt, ...)
{
	char msg[512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	diag(ST_SCENE, O->file, O->line, 0, "%s", msg);
	return -1;
}

/* The text from p to end (at most a few words), quoted for a message. */
void
objtext_quote(char *dst, size_t sz, const char *p, const char *end)
{
	char raw[40];
	size_t n = (size_t)(end - p) < sizeof(raw) - 1 ? (size_t)(end - p) :
	    sizeof(raw) - 1;

	memcpy(raw, p, n);
	raw[n] = '\0';
	cfgtext_quote(dst, sz, raw);
}

/*
 * The number at *p, if one is there before the line's end or a comment:
 * 1 and *p past it, 0 if none, or -1 after a diagnostic.
 */
int
objtext_number(const struct objtext *O, const char **p, const char *end,
    double *x)
{
	const char *s = objtext_skip(*p, end);
	char *e;
	char q[160];

	if (s == end || *s == '#')
		return 0;
	/* The text ends in a NUL, and no number holds a newline. */
	*x = strtod(s, &e);
	if (e == s || (e < end && !objtext_blank(*e) && *e != '#')) {
		objtext_quote(q, sizeof(q), s, objtext_word_end(s, end));
		return objtext_fail(O, "\"%s\" is not a number", q);
	}
	if (!isfinite(*x) || fabs(*x) > FLT_MAX) {
		objtext_quote(q, sizeof(q), s, e);
		return objtext_fail(O, isfinite(*x) ? "\"%s\" is too large "
		    "for single precision (glTF's)" : "\"%s\" is not a finite "
		    "number", q);
	}
	*p = e;
	return 1;
}

/* Exactly lo to hi numbers to the line's end; how many, or -1. */
int
objtext_numbers(const struct objtext *O, const char *p, const char *end,
    double *x, int lo, int hi, const char *what)
{
	int n = 0, got = 0;
	double extra;

	while (n < hi && (got = objtext_number(O, &p, end, &x[n])) == 1)
		n++;
	if (n < hi && got < 0)
		return -1;
	if (n == hi && (got = objtext_number(O, &p, end, &extra)) != 0)
		return got < 0 ? -1 : objtext_fail(O, "%s takes at most %d "
		    "numbers", what, hi);
	if (n < lo)
		return objtext_fail(O, "%s takes %d numbers, not %d", what,
		    lo, n);
	return n;
}


/* The line of the first NUL in text, or 0. */
int
objtext_nul_line(const char *text, size_t len)
{
	const char *nul = memchr(text, '\0', len);
	int line = 1;

	if (nul == NULL)
		return 0;
	for (const char *p = text; p < nul; p++)
		line += *p == '\n';
	return line;
}


/*
 * The buffer starts at the file's size and grows as it must (a file
 * may grow, or say size 0), not at max: Windows commits every byte
 * asked for, and wine wrote all 64 MiB of it, 0.15 s a mesh.
 */
int
objtext_read(const char *path, long max, const char *what,
    char **text, size_t *len)
{
	FILE *fp = sys_fopen(path, "rb");
	struct stat st;
	size_t got = 0, cap = 65536, n;

	*text = NULL;
	*len = 0;
	if (fp == NULL) {
		diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		return -1;
	}
	if (fstat(fileno(fp), &st) != 0)
		st.st_size = 0;
	if (st.st_size > max) {
		fclose(fp);
		diag(ST_SCENE, path, 0, 0, "%s is larger than %ld bytes", what,
		    max);
		return -1;
	}
	if (st.st_size > 0 && (size_t)st.st_size + 2 > cap)
		cap = (size_t)st.st_size + 2;
	*text = xmalloc(cap);
	while ((n = fread(*text + got, 1, cap - 1 - got, fp)) > 0 &&
	    (got += n) <= (size_t)max)
		if (got == cap - 1) {
			cap = cap * 2 < (size_t)max + 2 ? cap * 2 :
			    (size_t)max + 2;
			*text = xreallocarray(*text, cap, 1);
		}
	if (ferror(fp) || got > (size_t)max) {
		if (ferror(fp))
			diag(ST_SYSTEM, path, 0, 0, "%s", strerror(errno));
		else
			diag(ST_SCENE, path, 0, 0, "%s is larger than %ld "
			    "bytes", what, max);
		fclose(fp);
		free(*text);
		*text = NULL;
		return -1;
	}
	fclose(fp);
	(*text)[got] = '\0';
	*len = got;
	return 0;
}

