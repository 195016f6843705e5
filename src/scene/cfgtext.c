/*
 * cfgtext.c - prepare a scene file's text for libconfig.
 *
 * libconfig 1.5 (Debian 12) has two blind spots we must cover before it
 * parses: it silently truncates a string at a NUL byte, and it keeps an
 * integer literal without an L suffix in 32 bits, wrapping larger ones
 * (count = 20000000000 arrives as -1474836480).  We reject NULs with
 * their line, and append the L suffix to every integer literal that does
 * not fit in 32 bits, so the range checks see the number as written.
 * And it calls a file whose last line is a comment without a newline,
 * or one that starts with a UTF-8 byte-order mark (as Windows editors
 * write), a syntax error: the mark is left out and a newline added.
 * Line numbers are unchanged.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include <libconfig.h>

#include "scene/cfgtext.h"
#include "base/mem.h"
#include "base/sink.h"

/* Length of the comment or string at p, or 0 if none starts there. */
static size_t
skip_inert(const char *p, const char *end)
{
	const char *q = p;

	if (*p == '#' || (*p == '/' && p + 1 < end && p[1] == '/')) {
		while (q < end && *q != '\n')
			q++;
	} else if (*p == '/' && p + 1 < end && p[1] == '*') {
		for (q = p + 2; q < end; q++)
			if (*q == '*' && q + 1 < end && q[1] == '/') {
				q += 2;
				break;
			}
		if (q > end)
			q = end;
	} else if (*p == '"') {
		for (q = p + 1; q < end && *q != '"'; q++)
			if (*q == '\\' && q + 1 < end)
				q++;
		if (q < end)
			q++;
	}
	return (size_t)(q - p);
}

/* How many of the characters in [p, end) are in set, from the start. */
static size_t
span(const char *p, const char *end, const char *set)
{
	const char *q = p;

	while (q < end && strchr(set, *q) != NULL)
		q++;
	return (size_t)(q - p);
}

/* Does the integer literal of n characters at p fit in a C int? */
static int
fits_int(const char *p, size_t n)
{
	char buf[64];
	long long v;

	if (n >= sizeof(buf))
		return 0;
	memcpy(buf, p, n);
	buf[n] = '\0';
	errno = 0;
	v = strtoll(buf, NULL, 0);
	return errno == 0 && v <= INT_MAX;
}

char *
cfgtext_prepare(const char *text, size_t len, int *nul_line)
{
	const char *p = text, *end = text + len;
	char *out = xmalloc(len + len / 2 + 3), *o = out;
	int line = 1;

	*nul_line = 0;
	for (const char *q = text; q < end; q++) {
		if (*q == '\0') {
			*nul_line = line;
			free(out);
			return NULL;
		}
		line += *q == '\n';
	}
	if (len >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
		p += 3;
	while (p < end) {
		size_t n = skip_inert(p, end);

		if (n > 0) {
			memcpy(o, p, n);
			o += n;
			p += n;
			continue;
		}
		/* A number starts at a digit not inside a word. */
		if (isdigit((unsigned char)*p) && (p == text ||
		    !(isalnum((unsigned char)p[-1]) || p[-1] == '_' ||
		    p[-1] == '.'))) {
			const char *q = p;

			int hex = end - p > 1 && p[0] == '0' &&
			    (p[1] == 'x' || p[1] == 'X');

			while (q < end && (isalnum((unsigned char)*q) ||
			    *q == '_' || *q == '.' || ((*q == '-' ||
			    *q == '+') && (q[-1] == 'e' || q[-1] == 'E') &&
			    !hex)))
				q++;
			memcpy(o, p, (size_t)(q - p));
			o += q - p;
			/* Only plain digits, or 0x and hex digits, are integers. */
			if (span(p, q, "0123456789") == (size_t)(q - p) ||
			    (hex && q - p > 2 && span(p + 2, q,
			    "0123456789abcdefABCDEF") == (size_t)(q - p - 2)))
				if (!fits_int(p, (size_t)(q - p)))
					*o++ = 'L';
			p = q;
			continue;
		}
		*o++ = *p++;
	}
	if (o > out && o[-1] != '\n')
		*o++ = '\n';
	*o = '\0';
	return out;
}

/* A setting's string value fit for a one-line message. */
void
cfgtext_quote(char *dst, size_t sz, const char *s)
{
	static const char hex[] = "0123456789abcdef";
	size_t i = 0;

	for (; *s != '\0' && i + 5 < sz; s++) {
		unsigned char c = (unsigned char)*s;

		if (c >= 0x20 && c < 0x7f && c != '\\')
			dst[i++] = (char)c;
		else {
			dst[i++] = '\\';
			dst[i++] = 'x';
			dst[i++] = hex[c >> 4];
			dst[i++] = hex[c & 15];
		}
	}
	if (*s != '\0' && i + 3 < sz) {
		memcpy(dst + i, "...", 3);
		i += 3;
	}
	dst[i] = '\0';
}

/*
 * Locating a string value in the text, for messages that point into an
 * expression.  libconfig tells only the line of a setting's name, and
 * gives its value unescaped and joined ("a" "b" is "ab"), so the column
 * of a character in the value is found again here, by walking the text
 * as libconfig's scanner does.
 */

/* Whitespace and comments from p on. */
static const char *
skip_blank(const char *p, const char *end)
{
	while (p < end) {
		if (isspace((unsigned char)*p))
			p++;
		else if (*p != '"' && skip_inert(p, end) > 0)
			p += skip_inert(p, end);
		else
			break;
	}
	return p;
}

static int
name_char(char c)
{
	return isalnum((unsigned char)c) || c == '_' || c == '-' || c == '*';
}

/* One value: a string sequence, a bracketed aggregate, or a word. */
static const char *
skip_value(const char *p, const char *end)
{
	int depth = 0;

	do {
		p = skip_blank(p, end);
		if (p >= end)
			return end;
		if (*p == '"') {
			while (p < end && *p == '"')
				p = skip_blank(p + skip_inert(p, end), end);
			continue;
		}
		if (strchr("[({", *p) != NULL)
			depth++;
		else if (strchr("])}", *p) != NULL)
			depth--;
		else if (depth == 0) {
			while (p < end && !strchr(",;])}", *p) &&
			    !isspace((unsigned char)*p))
				p++;
			return p;
		}
		p++;
	} while (depth > 0);
	return p;
}

/* One source character of a string literal: its length, and its byte. */
static size_t
literal_char(const char *p, const char *end, char *c)
{
	static const char from[] = "nrtf\\\"", to[] = "\n\r\t\f\\\"";
	const char *e;

	if (*p != '\\' || p + 1 >= end) {
		*c = *p;
		return 1;
	}
	if ((e = strchr(from, p[1])) != NULL && p[1] != '\0') {
		*c = to[e - from];
		return 2;
	}
	if (p[1] == 'x' && end - p >= 4 && isxdigit((unsigned char)p[2]) &&
	    isxdigit((unsigned char)p[3])) {
		char hex[3] = { p[2], p[3], '\0' };

		*c = (char)strtol(hex, NULL, 16);
		return 4;
	}
	*c = '\\';
	return 1;
}

/*
 * The string sequence at p: whether it reads want, and where byte k of
 * it starts (or its closing quote, k being its length).
 */
static int
string_is(const char *p, const char *end, const char *want, size_t k,
    const char **at)
{
	size_t i = 0, n = strlen(want);

	*at = NULL;
	while (p < end && *p == '"') {
		for (p++; p < end && *p != '"'; i++) {
			char c;

			if (i == k)
				*at = p;
			p += literal_char(p, end, &c);
			if (i >= n || c != want[i])
				return 0;
		}
		if (p >= end)
			return 0;
		if (i == k && *at == NULL && i == n)
			*at = p;
		p = skip_blank(p + 1, end);
	}
	return i == n && *at != NULL;
}

int
cfgtext_locate(const char *text, size_t len, const char *name, int elem,
    const char *want, size_t k, int *line, int *col)
{
	const char *end = text + len, *p = text, *eol, *at;
	size_t nlen = strlen(name);
	int here = 1;

	/* From the start of its line: libconfig's line is the name's. */
	for (; here < *line && p < end; p++)
		if (*p == '\n')
			here++;
	if (here != *line)
		return -1;
	if ((eol = memchr(p, '\n', (size_t)(end - p))) == NULL)
		eol = end;
	while (p < eol) {
		const char *v;
		size_t inert = skip_inert(p, end);

		if (inert > 0) {
			p += inert;
			continue;
		}
		if ((size_t)(end - p) < nlen || strncmp(p, name, nlen) != 0 ||
		    (p > text && name_char(p[-1])) ||
		    (p + nlen < end && name_char(p[nlen]))) {
			p++;
			continue;
		}
		v = skip_blank(p + nlen, end);
		p += nlen;
		if (v >= end || (*v != '=' && *v != ':'))
			continue;
		v = skip_blank(v + 1, end);
		if (elem >= 0) {
			if (v >= end || (*v != '[' && *v != '('))
				continue;
			v++;
			for (int i = 0; i < elem && v < end; i++) {
				v = skip_blank(skip_value(v, end), end);
				v += v < end && *v == ',';
			}
			v = skip_blank(v, end);
		}
		if (v < end && *v == '"' && string_is(v, end, want, k, &at)) {
			/* A string may run over lines: count them to at. */
			for (; p < at; p++)
				*line += *p == '\n';
			for (*col = 1; at > text && at[-1] != '\n'; at--)
				(*col)++;
			return 0;
		}
	}
	return -1;
}

/* A number as few digits as read back the same, and a float stays one. */
static void
put_float(struct sink *s, double x)
{
	char buf[40];

	for (int digits = 15; digits <= 17; digits++) {
		snprintf(buf, sizeof(buf), "%.*g", digits, x);
		if (strtod(buf, NULL) == x)
			break;
	}
	sink_puts(s, buf);
	if (strpbrk(buf, ".en") == NULL)
		sink_puts(s, ".0");
}

static void
put_string(struct sink *s, const char *v)
{
	static const char hex[] = "0123456789abcdef";

	sink_putc(s, '"');
	for (; *v != '\0'; v++) {
		unsigned char c = (unsigned char)*v;

		if (c == '"' || c == '\\') {
			sink_putc(s, '\\');
			sink_putc(s, (char)c);
		} else if (c == '\n')
			sink_puts(s, "\\n");
		else if (c == '\t')
			sink_puts(s, "\\t");
		else if (c < 0x20 || c == 0x7f) {
			sink_puts(s, "\\x");
			sink_putc(s, hex[c >> 4]);
			sink_putc(s, hex[c & 15]);
		} else
			sink_putc(s, (char)c);
	}
	sink_putc(s, '"');
}

static void
put_value(struct sink *s, const config_setting_t *v)
{
	int type = config_setting_type(v), n = config_setting_length(v);
	char num[32];

	switch (type) {
	case CONFIG_TYPE_INT:
	case CONFIG_TYPE_INT64:
		snprintf(num, sizeof(num), "%lld", config_setting_get_int64(v));
		sink_puts(s, num);
		/* libconfig keeps an integer past 32 bits only so marked. */
		if (type == CONFIG_TYPE_INT64)
			sink_putc(s, 'L');
		return;
	case CONFIG_TYPE_FLOAT:
		put_float(s, config_setting_get_float(v));
		return;
	case CONFIG_TYPE_STRING:
		put_string(s, config_setting_get_string(v));
		return;
	case CONFIG_TYPE_BOOL:
		sink_puts(s, config_setting_get_bool(v) ? "true" : "false");
		return;
	}
	sink_puts(s, type == CONFIG_TYPE_GROUP ? "{ " :
	    type == CONFIG_TYPE_ARRAY ? "[" : "(");
	for (int i = 0; i < n; i++) {
		const config_setting_t *e = config_setting_get_elem(v,
		    (unsigned)i);

		if (type == CONFIG_TYPE_GROUP) {
			sink_puts(s, config_setting_name(e));
			sink_puts(s, " = ");
			put_value(s, e);
			sink_puts(s, "; ");
		} else {
			if (i > 0)
				sink_puts(s, ", ");
			put_value(s, e);
		}
	}
	sink_puts(s, type == CONFIG_TYPE_GROUP ? "}" :
	    type == CONFIG_TYPE_ARRAY ? "]" : ")");
}

char *
cfgtext_value(const config_setting_t *v)
{
	struct sink s;
	char *text;

	sink_init(&s, NULL);
	put_value(&s, v);
	sink_putc(&s, '\0');
	text = s.buf;		/* the sink keeps everything: take it */
	s.buf = NULL;
	sink_free(&s);
	return text;
}

/*
 * Writing a setting into the text (--cfg): the scene's own file, its
 * comments and layout kept, with the value of one setting changed or
 * added.  Walked as libconfig reads it: a group's members are "name =
 * value" or "name: value", ended by ';', ',' or nothing.
 */
struct member {
	const char	*name, *value, *value_end;
	size_t		 nlen;
	const char	*end;		/* past its terminator, if any */
	int		 ended;		/* it has one */
};

/* The member at p in a group ending at end, or NULL at its close. */
static const char *
next_member(const char *p, const char *end, struct member *m)
{
	const char *q;

	p = skip_blank(p, end);
	if (p >= end || *p == '}' || !name_char(*p))
		return NULL;
	m->name = p;
	while (p < end && name_char(*p))
		p++;
	m->nlen = (size_t)(p - m->name);
	p = skip_blank(p, end);
	if (p >= end || (*p != '=' && *p != ':'))
		return NULL;
	m->value = skip_blank(p + 1, end);
	m->value_end = skip_value(m->value, end);
	q = skip_blank(m->value_end, end);
	m->ended = q < end && (*q == ';' || *q == ',');
	m->end = m->ended ? q + 1 : m->value_end;
	return m->end;
}

/* The inside of the bracketed value at v: [*from, *to). */
static void
inside(const char *v, const char *end, const char **from, const char **to)
{
	*from = v + 1;
	*to = skip_value(v, end) - 1;
}

/* text with [at, at + cut) made ins; allocated. */
static char *
splice(const char *text, size_t len, const char *at, size_t cut,
    const char *ins, size_t *newlen)
{
	size_t pre = (size_t)(at - text), n = strlen(ins);
	char *out = xmalloc(len - cut + n + 1);

	memcpy(out, text, pre);
	memcpy(out + pre, ins, n);
	memcpy(out + pre + n, at + cut, len - pre - cut);
	*newlen = len - cut + n;
	out[*newlen] = '\0';
	return out;
}

/*
 * "name = value;" for the rest of a path, the groups it needs made
 * around it: "planar = { scale = 0.1; };".  NULL where the rest steps
 * into a list's entries, which cannot be made so.
 */
static char *
made(const char *rest, const char *value)
{
	struct sink s;
	const char *dot;
	int open = 0;
	char *out;

	sink_init(&s, NULL);
	for (; (dot = strchr(rest, '.')) != NULL; rest = dot + 1, open++) {
		if (isdigit((unsigned char)*rest)) {
			sink_free(&s);
			return NULL;
		}
		sink_write(&s, rest, (size_t)(dot - rest));
		sink_puts(&s, " = { ");
	}
	if (isdigit((unsigned char)*rest)) {
		sink_free(&s);
		return NULL;
	}
	sink_puts(&s, rest);
	sink_puts(&s, " = ");
	sink_puts(&s, value);
	sink_putc(&s, ';');
	while (open-- > 0)
		sink_puts(&s, " };");
	sink_putc(&s, '\0');
	out = s.buf;
	s.buf = NULL;
	sink_free(&s);
	return out;
}

/*
 * Add member text at the end of the group [from, to) (the whole file
 * when top): on a line of its own, indented as the last member, where
 * the group takes several lines; else after the last member.
 */
static char *
add_member(const char *text, size_t len, const char *from, const char *to,
    const struct member *last, int top, const char *member,
    size_t *newlen)
{
	char *ins, *out;
	const char *at = last != NULL ? last->end : from, *ls;
	int lines = memchr(from, '\n', (size_t)(to - from)) != NULL;
	size_t indent = 0;

	if (top) {
		/* After everything, trailing comments too. */
		ins = xmalloc(strlen(member) + 3);
		sprintf(ins, "%s%s\n", len > 0 && text[len - 1] != '\n' ? "\n" :
		    "", member);
		out = splice(text, len, text + len, 0, ins, newlen);
		free(ins);
		return out;
	}
	if (lines && last != NULL) {
		for (ls = last->name; ls > text && ls[-1] != '\n'; ls--)
			;
		while (ls + indent < last->name && (ls[indent] == ' ' ||
		    ls[indent] == '\t'))
			indent++;
	} else
		ls = NULL;
	ins = xmalloc(strlen(member) + indent + 4);
	sprintf(ins, "%s%s%.*s%s", last != NULL && !last->ended ? ";" : "",
	    lines && ls != NULL ? "\n" : " ", (int)indent, ls != NULL ? ls : "",
	    member);
	out = splice(text, len, at, 0, ins, newlen);
	free(ins);
	return out;
}

/*
 * Where the setting at path stands in the text, as cfgtext_splice() and
 * cfgtext_cut() walk to it.  1: found, *m the member; 0: a group on the
 * way lacks the rest of the path, *rest, to be added in the group
 * [*from, *to) (the whole text when *top) after *last (NULL if empty);
 * -1: the text cannot hold the path (a list entry it lacks, a value
 * where the path goes on).
 */
struct place {
	struct member	 m, last;
	const char	*from, *to, *rest;
	int		 top, any;
};

static int
find_member(const char *text, size_t len, const char *path,
    struct place *pl)
{
	const char *end = text + len, *dot;
	char name[128];

	pl->from = text;
	if (len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0)
		pl->from += 3;	/* a byte-order mark, kept */
	pl->to = end;
	pl->top = 1;
	for (const char *c = path; ; c = dot + 1) {
		const char *p = pl->from;
		size_t n;

		dot = strchr(c, '.');
		n = dot != NULL ? (size_t)(dot - c) : strlen(c);
		if (n >= sizeof(name) || isdigit((unsigned char)*c))
			return -1;
		memcpy(name, c, n);
		name[n] = '\0';
		pl->any = 0;
		for (;;) {
			if ((p = next_member(p, pl->to, &pl->m)) == NULL) {
				pl->rest = c;
				return 0;
			}
			pl->any = 1;
			pl->last = pl->m;
			if (pl->m.nlen == n && strncmp(pl->m.name, name, n) == 0)
				break;
		}
		if (dot == NULL)
			return 1;
		pl->top = 0;
		if (*pl->m.value == '{') {
			inside(pl->m.value, end, &pl->from, &pl->to);
			continue;
		}
		if (*pl->m.value != '(' || !isdigit((unsigned char)dot[1]))
			return -1;
		/* An entry of a list, by number, then into its group. */
		{
			char *after;
			long k = strtol(dot + 1, &after, 10);
			const char *e = skip_blank(pl->m.value + 1, end);

			for (long i = 0; i < k && e < end; i++) {
				e = skip_blank(skip_value(e, end), end);
				if (e >= end || *e != ',')
					return -1;
				e = skip_blank(e + 1, end);
			}
			if (e >= end || *e != '{' || *after != '.')
				return -1;
			inside(e, end, &pl->from, &pl->to);
			dot = after;
		}
	}
}

char *
cfgtext_splice(const char *text, size_t len, const char *path,
    const char *value, size_t *newlen)
{
	struct place pl;
	char *member, *out;

	switch (find_member(text, len, path, &pl)) {
	case 1:
		return splice(text, len, pl.m.value, (size_t)(pl.m.value_end -
		    pl.m.value), value, newlen);
	case 0:
		if ((member = made(pl.rest, value)) == NULL)
			return NULL;
		out = add_member(text, len, pl.from, pl.to, pl.any ? &pl.last :
		    NULL, pl.top, member, newlen);
		free(member);
		return out;
	}
	return NULL;
}

char *
cfgtext_cut(const char *text, size_t len, const char *path,
    size_t *newlen)
{
	const char *end = text + len, *from, *to;
	struct place pl;

	if (find_member(text, len, path, &pl) != 1)
		return NULL;
	from = pl.m.name;
	to = pl.m.end;
	/* The blanks after it too, to the next member or the line's end. */
	while (to < end && (*to == ' ' || *to == '\t'))
		to++;
	if (to == end || *to == '\n') {
		/* Alone on its line: the line goes, else only its blanks. */
		const char *ls = from;

		while (ls > text && (ls[-1] == ' ' || ls[-1] == '\t'))
			ls--;
		if (ls == text || ls[-1] == '\n') {
			from = ls;
			to += to < end;
		} else
			from = ls;
	}
	return splice(text, len, from, (size_t)(to - from), "", newlen);
}
