/*
 * measured_csv.c - reading the measured model's points: CSV as
 * spreadsheets, image tools and our own --csv write it.
 *
 * The first line that is neither blank nor a comment is the header; it
 * names the columns, in any case and order, and its first comma, tab or
 * semicolon is the separator (a European spreadsheet writes ';').
 * Fields may be quoted ("x", "1.5"), with "" for a quote inside.  A #
 * outside quotes ends a line's data.  Every line must have the header's
 * number of fields, so a row that lost one is an error at its line, not
 * a shifted column.  Our own reader: a library would bring a dialect
 * system for what is a page of code, and none gives us line numbers.
 *
 * The file is read a block at a time and refused at its first bad line
 * (a photograph given instead of its points stops at its first NUL).
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "base/diag.h"
#include "base/mem.h"
#include "models/measured_csv.h"

enum { COL_X, COL_Y, COL_Z, COL_N, COL_RADIUS, COL__N };

static const char *const col_names[COL__N] = { "x", "y", "z", "n", "radius" };

#define FIELD_MAX	64	/* bytes of a number or a column's name */

struct reader {
	struct points	*P;
	const char	*file;
	int		 line;
	int		 header;	/* read */
	char		 sep;
	int		 col[COL__N];	/* each column's field, or -1 */
	int		 nfields;	/* the header's */
};

static int
fail(const struct reader *R, const char *fmt, ...)
    PRINTFLIKE(2, 3)
    ;

static int
fail(const struct reader *R, const char *fmt, ...)
{
	char msg[512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	diag(ST_SCENE, R->file, R->line, 0, "%s", msg);
	return -1;
}

static int
blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r';
}

/* Text shown in a message: printable bytes, at most a few words. */
static void
shown(char *dst, size_t sz, const char *s, size_t len)
{
	size_t j = 0;

	for (size_t i = 0; i < len && j + 4 < sz; i++)
		dst[j++] = s[i] >= 0x20 && s[i] < 0x7f ? s[i] : '?';
	if (j + 4 >= sz && len > j) {
		dst[j++] = '.';
		dst[j++] = '.';
		dst[j++] = '.';
	}
	dst[j] = '\0';
}

/*
 * The field at *p up to the separator, the line's end or a comment,
 * unquoted into buf (cut at sz - 1 bytes; *len says how long it was);
 * *p is left at what ended it.  0, or -1 after a diagnostic.
 */
static int
field(const struct reader *R, const char **p, const char *end, char *buf,
    size_t sz, size_t *len)
{
	const char *s = *p;
	size_t n = 0;

	while (s < end && blank(*s) && *s != R->sep)
		s++;
	if (s < end && *s == '"') {
		for (s++;; s++) {
			if (s == end)
				return fail(R, "a quoted field has no closing "
				    "quote");
			if (*s == '"') {
				if (s + 1 < end && s[1] == '"')
					s++;
				else
					break;
			}
			if (n + 1 < sz)
				buf[n] = *s;
			n++;
		}
		s++;
		while (s < end && blank(*s) && *s != R->sep)
			s++;
		if (s < end && *s != R->sep && *s != '#')
			return fail(R, "text after a quoted field's closing "
			    "quote");
	} else {
		const char *from = s, *to;

		while (s < end && *s != R->sep && *s != '#')
			s++;
		to = s;
		while (to > from && blank(to[-1]))
			to--;
		n = (size_t)(to - from);
		memcpy(buf, from, n < sz ? n : sz - 1);
	}
	buf[n < sz ? n : sz - 1] = '\0';
	*len = n;
	*p = s;
	return 0;
}

/* Whether another field follows the one that ended at *p; past its separator. */
static int
next(const struct reader *R, const char **p, const char *end)
{
	if (*p < end && **p == R->sep) {
		(*p)++;
		return 1;
	}
	return 0;
}

/* The header's line: where each of our columns is. */
static int
header(struct reader *R, const char *s, const char *end)
{
	char name[FIELD_MAX], seen[256];
	size_t len, have = 0;
	const char *p;
	int k;

	/* The separator: the first of these outside quotes. */
	R->sep = ',';
	for (p = s, k = 0; p < end && *p != '#'; p++) {
		k ^= *p == '"';
		if (!k && (*p == ',' || *p == '\t' || *p == ';')) {
			R->sep = *p;
			break;
		}
	}
	for (k = 0; k < COL__N; k++)
		R->col[k] = -1;
	seen[0] = '\0';
	p = s;
	R->nfields = 0;
	do {
		if (field(R, &p, end, name, sizeof(name), &len) < 0)
			return -1;
		R->nfields++;
		for (size_t i = 0; name[i] != '\0'; i++)
			if (name[i] >= 'A' && name[i] <= 'Z')
				name[i] = (char)(name[i] - 'A' + 'a');
		if (have < sizeof(seen) - 8) {
			char word[24];

			shown(word, sizeof(word), name, strlen(name));
			have += (size_t)snprintf(seen + have, sizeof(seen) - have,
			    "%s%s", have ? ", " : "", word);
		}
		for (k = 0; k < COL__N; k++)
			if (len < sizeof(name) && strcmp(name, col_names[k]) == 0)
				break;
		if (k == COL__N)
			continue;
		if (R->col[k] >= 0)
			return fail(R, "the header names column %s twice",
			    col_names[k]);
		R->col[k] = R->nfields - 1;
	} while (next(R, &p, end));
	for (k = COL_X; k <= COL_Y; k++) {
		if (R->col[k] >= 0)
			continue;
		/* A file without a header begins with numbers. */
		if (strtod(seen, NULL) != 0 || seen[0] == '0')
			return fail(R, "the first line must name the columns "
			    "(x, y and optionally z, n, radius), not hold "
			    "numbers");
		return fail(R, "the header names no column %s (it has: %s)",
		    col_names[k], seen);
	}
	R->header = R->line;
	R->P->header_line = R->line;
	R->P->has_z = R->col[COL_Z] >= 0;
	return 0;
}

/* The number in field text of column k. */
static int
number(const struct reader *R, int k, const char *text, size_t len,
    double *v)
{
	char q[40];
	char *e;

	if (len == 0)
		return fail(R, "no %s: its field is empty", col_names[k]);
	shown(q, sizeof(q), text, len);
	if (len >= FIELD_MAX)
		return fail(R, "%s '%s' is not a number", col_names[k], q);
	/*
	 * A spreadsheet that separates by ';' or tabs writes a decimal
	 * comma where its locale does (1,5): one comma, no point.  Not
	 * hexadecimal (0x10), which strtod() reads: a typo, likely.
	 */
	{
		char *c = strchr(text, ',');

		if (R->sep != ',' && c != NULL && strchr(c + 1, ',') == NULL &&
		    strchr(text, '.') == NULL)
			*c = '.';
	}
	errno = 0;
	*v = strtod(text, &e);
	if (e == text || *e != '\0' || strpbrk(text, "xX") != NULL)
		return fail(R, "%s '%s' is not a number", col_names[k], q);
	if (isnan(*v))
		return fail(R, "%s is NaN: every value must be a finite "
		    "number", col_names[k]);
	if (!isfinite(*v))
		return fail(R, "%s '%s' is infinite: every value must be a "
		    "finite number", col_names[k], q);
	return 0;
}

/* Room for one more point. */
static void
grow(struct points *P)
{
	size_t cap;

	if (P->count < P->cap)
		return;
	cap = P->cap ? 2 * P->cap : 1024;
	P->p = xreallocarray(P->p, cap, sizeof(*P->p));
	P->line = xreallocarray(P->line, cap, sizeof(*P->line));
	/* Kept only if the header names them (finish()). */
	P->radius = xreallocarray(P->radius, cap, sizeof(*P->radius));
	P->n = xreallocarray(P->n, cap, sizeof(*P->n));
	P->cap = cap;
}

/* A data line: one point. */
static int
point(struct reader *R, const char *s, const char *end)
{
	struct points *P = R->P;
	char text[FIELD_MAX];
	double v[COL__N] = { 0, 0, 0, 0, 0 };
	const char *p = s;
	size_t len;
	int f = 0;

	if (P->count == POINTS_MAX)
		return fail(R, "more than %d points", POINTS_MAX);
	do {
		int k;

		if (field(R, &p, end, text, sizeof(text), &len) < 0)
			return -1;
		for (k = 0; k < COL__N && R->col[k] != f; k++)
			;
		if (k < COL__N && number(R, k, text, len, &v[k]) < 0)
			return -1;
		f++;
	} while (next(R, &p, end));
	if (f != R->nfields)
		return fail(R, "%d field%s, but the header (line %d) names %d",
		    f, f == 1 ? "" : "s", R->header, R->nfields);
	if (R->col[COL_N] >= 0 && (v[COL_N] != floor(v[COL_N]) ||
	    fabs(v[COL_N]) > 9007199254740992.0))
		return fail(R, "n %.17g is not a whole number", v[COL_N]);
	if (R->col[COL_RADIUS] >= 0 && !(v[COL_RADIUS] > 0))
		return fail(R, "radius %.9g must be greater than 0",
		    v[COL_RADIUS]);
	grow(P);
	P->p[P->count][0] = v[COL_X];
	P->p[P->count][1] = v[COL_Y];
	P->p[P->count][2] = v[COL_Z];
	P->radius[P->count] = v[COL_RADIUS];
	P->n[P->count] = (long long)v[COL_N];
	P->line[P->count] = R->line;
	P->count++;
	return 0;
}

/* One line, without its newline. */
static int
line(struct reader *R, const char *s, size_t len)
{
	const char *end = s + len, *p;

	/* Text has no control characters but tabs and a CRLF's CR. */
	for (size_t i = 0; i < len; i++) {
		if (s[i] == '\r' && i + 1 < len)
			return fail(R, "a line ends in a carriage return alone "
			    "(an old Mac file?): end lines with a newline");
		if (((unsigned char)s[i] < 0x20 && s[i] != '\t' &&
		    s[i] != '\r') || s[i] == 0x7f)
			return fail(R, "a control character (byte %d): this is "
			    "not a text file of points%s", (unsigned char)s[i],
			    s[i] == 0 && R->line == 1 && i > 0 && s[i - 1] >=
			    0x20 && s[i - 1] < 0x7f ? " (UTF-16? save it as "
			    "UTF-8)" : "");
	}
	if (R->line == 1 && len >= 3 && memcmp(s, "\xef\xbb\xbf", 3) == 0)
		s += 3;		/* a spreadsheet's byte order mark */
	for (p = s; p < end && blank(*p); p++)
		;
	if (p == end || *p == '#')
		return 0;
	return R->header ? point(R, s, end) : header(R, s, end);
}

/* Sorting points by position, then by line. */
static const struct points *sorting;

static int
by_position(const void *a, const void *b)
{
	const double *p = sorting->p[*(const size_t *)a];
	const double *q = sorting->p[*(const size_t *)b];

	for (int k = 0; k < 3; k++)
		if (p[k] != q[k])
			return p[k] < q[k] ? -1 : 1;
	return *(const size_t *)a < *(const size_t *)b ? -1 : 1;
}

static int
by_n(const void *a, const void *b)
{
	long long m = sorting->n[*(const size_t *)a];
	long long n = sorting->n[*(const size_t *)b];

	if (m != n)
		return m < n ? -1 : 1;
	return *(const size_t *)a < *(const size_t *)b ? -1 : 1;
}

/* The same point, or the same n, twice: an error at the later line. */
static int
repeats(struct reader *R, int (*cmp)(const void *, const void *),
    const char *what)
{
	struct points *P = R->P;
	size_t *ix = xcalloc(P->count, sizeof(*ix)), at = 0, first = 0;
	int found = 0;

	for (size_t i = 0; i < P->count; i++)
		ix[i] = i;
	sorting = P;
	qsort(ix, P->count, sizeof(*ix), cmp);
	for (size_t i = 1; i < P->count; i++) {
		size_t a = ix[i - 1], b = ix[i];
		int same = cmp == by_n ? P->n[a] == P->n[b] :
		    memcmp(P->p[a], P->p[b], sizeof(P->p[a])) == 0;

		/* Of every repeat, the one latest in the file is named. */
		if (same && (!found || P->line[b] < P->line[at])) {
			at = b;
			first = a;
			found = 1;
		}
	}
	sorting = NULL;
	if (found) {
		R->line = P->line[at];
		if (cmp == by_n)
			fail(R, "n %lld again: line %d has it too", P->n[at],
			    P->line[first]);
		else
			fail(R, "%s: line %d has the same x, y%s", what,
			    P->line[first], P->has_z ? " and z" : "");
	}
	free(ix);
	return found ? -1 : 0;
}

/*
 * All the points on one line (or one point): no head to measure.  The
 * farthest point from the first gives the line's direction; then the
 * farthest from that line must stand off it by more than rounding.
 */
static int
collinear(const struct points *P)
{
	const double *a = P->p[0];
	double far = 0, d[3], off = 0;
	size_t j = 0;

	for (size_t i = 1; i < P->count; i++) {
		double e = 0;

		for (int k = 0; k < 3; k++)
			e += (P->p[i][k] - a[k]) * (P->p[i][k] - a[k]);
		if (e > far) {
			far = e;
			j = i;
		}
	}
	if (far == 0)
		return 1;
	for (int k = 0; k < 3; k++)
		d[k] = (P->p[j][k] - a[k]) / sqrt(far);
	for (size_t i = 1; i < P->count; i++) {
		double e[3], t = 0, o = 0;

		for (int k = 0; k < 3; k++) {
			e[k] = P->p[i][k] - a[k];
			t += e[k] * d[k];
		}
		for (int k = 0; k < 3; k++)
			o += (e[k] - t * d[k]) * (e[k] - t * d[k]);
		off = fmax(off, o);
	}
	return off <= 1e-18 * far;
}

/* What the file as a whole must be. */
static int
finish(struct reader *R)
{
	struct points *P = R->P;

	if (!R->header) {
		R->line = R->line > 0 ? R->line : 1;
		return fail(R, "no header line naming the columns (x, y and "
		    "optionally z, n, radius): the file holds no points");
	}
	if (P->count < POINTS_MIN)
		return fail(R, "%zu point%s: at least %d are needed to see "
		    "spirals", P->count, P->count == 1 ? "" : "s", POINTS_MIN);
	if (R->col[COL_RADIUS] < 0) {
		free(P->radius);
		P->radius = NULL;
	}
	if (R->col[COL_N] < 0) {
		free(P->n);
		P->n = NULL;
	}
	if (repeats(R, by_position, "a point repeated") < 0)
		return -1;
	if (P->n != NULL && repeats(R, by_n, "") < 0)
		return -1;
	if (collinear(P)) {
		R->line = P->line[0];
		return fail(R, "all %zu points lie on one line: there is no "
		    "head or surface to measure", P->count);
	}
	return 0;
}

void
points_free(struct points *P)
{
	free(P->p);
	free(P->radius);
	free(P->n);
	free(P->line);
	*P = (struct points){ 0 };
}

static void
start(struct reader *R, struct points *P, const char *file)
{
	*P = (struct points){ 0 };
	*R = (struct reader){ .P = P, .file = file };
}

static int
too_long(struct reader *R)
{
	return fail(R, "a line longer than %d bytes: this is not a file of "
	    "points", POINTS_LINE_MAX);
}

int
points_parse(struct points *P, const char *file, const char *text,
    size_t len)
{
	struct reader R;
	const char *s = text, *end = text + len;

	start(&R, P, file);
	while (s < end) {
		const char *nl = memchr(s, '\n', (size_t)(end - s));
		const char *e = nl != NULL ? nl : end;

		R.line++;
		if (e - s > POINTS_LINE_MAX) {
			too_long(&R);
			points_free(P);
			return -1;
		}
		if (line(&R, s, (size_t)(e - s)) < 0) {
			points_free(P);
			return -1;
		}
		s = nl != NULL ? nl + 1 : end;
	}
	if (finish(&R) < 0) {
		points_free(P);
		return -1;
	}
	return 0;
}

int
points_read(struct points *P, const char *path)
{
	struct reader R;
	char *buf = xmalloc(POINTS_LINE_MAX + 1);
	size_t have = 0, at = 0;
	FILE *f = sys_fopen(path, "rb");
	int rc = 0, eof = 0;

	start(&R, P, path);
	if (f == NULL) {
		diag(ST_SCENE, path, 0, 0, "%s", strerror(errno));
		free(buf);
		return -1;
	}
	/* buf[at .. have) holds the lines read and not yet taken. */
	while (rc == 0) {
		char *nl = memchr(buf + at, '\n', have - at);
		size_t len;

		if (nl == NULL && !eof) {
			size_t got;

			memmove(buf, buf + at, have - at);
			have -= at;
			at = 0;
			if (have > POINTS_LINE_MAX) {
				R.line++;
				rc = too_long(&R);
				break;
			}
			got = fread(buf + have, 1, POINTS_LINE_MAX + 1 - have,
			    f);
			have += got;
			if (got == 0 && ferror(f)) {
				diag(ST_SYSTEM, path, R.line + 1, 0, "%s",
				    strerror(errno));
				rc = -1;
			}
			eof = got == 0;
			continue;
		}
		if (nl == NULL && at == have)
			break;
		len = nl != NULL ? (size_t)(nl - (buf + at)) : have - at;
		R.line++;
		rc = line(&R, buf + at, len);
		at += len + (nl != NULL);
	}
	fclose(f);
	free(buf);
	if (rc == 0)
		rc = finish(&R);
	if (rc != 0)
		points_free(P);
	return rc;
}
