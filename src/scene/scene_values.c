/* scene_values.c - one setting's value, read and checked by its row's type. */
#include <ctype.h>
#include <libconfig.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/cfgtext.h"
#include "base/diag.h"
#include "base/mem.h"
#include "models/model.h"
#include "scene/load.h"
#include "scene/scene.h"
#include "base/table.h"
#include "scene/suggest.h"

static const char *
file_of(const struct load *L, const config_setting_t *s)
{
	const char *f = config_setting_source_file(s);

	return f != NULL ? f : L->file;
}

void
load_err_at(const struct load *L, const config_setting_t *s,
    const char *fmt, ...)
{
	char msg[512];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	diag(ST_SCENE, file_of(L, s), load_line(s), 0, "%s", msg);
}

/*
 * An error at byte col (from 1) of setting s's string value, as a
 * compiler gives it: at the line and column of that byte in the file,
 * so that an editor jumps to it.  Where the file does not show the
 * value plainly (an @include), at the setting's line.
 */
static void
err_in_string(const struct load *L, const config_setting_t *s, int col,
    const char *path, const char *msg, const char *hint)
{
	const config_setting_t *named = s;
	int elem = -1, line, at = 0;

	if (config_setting_name(s) == NULL &&
	    (named = config_setting_parent(s)) != NULL)
		elem = config_setting_index(s);
	line = named != NULL ? load_line(named) : 0;
	if (named == NULL || config_setting_name(named) == NULL ||
	    strcmp(file_of(L, s), L->file) != 0 || col < 1 ||
	    cfgtext_locate(L->text, L->len, config_setting_name(named), elem,
	    config_setting_get_string(s), (size_t)col - 1, &line, &at) != 0) {
		line = load_line(s);
		at = 0;
	}
	diag(ST_SCENE, file_of(L, s), line, at, "%s: %s%s", path, msg, hint);
}

static int
ident_valid(const char *s)
{
	if (!isalpha((unsigned char)s[0]) || (s[0] & 0x80))
		return 0;
	for (; *s != '\0'; s++)
		if (!(isalnum((unsigned char)*s) || *s == '_') ||
		    (*s & 0x80))
			return 0;
	return 1;
}

/* Store an identifier; names reach POV-Ray and Python, so check hard. */
static int
set_ident(struct load *L, const config_setting_t *s, const char *path,
    char *dst)
{
	const char *v = config_setting_get_string(s);

	if (v == NULL) {
		load_err_at(L, s, "%s must be a string", path);
		return -1;
	}
	if (strlen(v) > NAME_LEN) {
		load_err_at(L, s, "%s is longer than %d characters", path,
		    NAME_LEN);
		return -1;
	}
	if (!ident_valid(v)) {
		char q[64];

		cfgtext_quote(q, sizeof(q), v);
		load_err_at(L, s, "%s \"%s\" is not an identifier "
		    "(a letter, then letters, digits or _)", path, q);
		return -1;
	}
	memcpy(dst, v, strlen(v) + 1);
	return 0;
}

/* "must be between 1 and 10000000", "must be greater than 0", ... */
static void
range_words(const struct row *r, char *buf, size_t sz)
{
	const char *lo = r->flags & F_LO_OPEN ? "greater than" : "at least";

	if (isinf(r->hi) && isinf(r->lo))
		snprintf(buf, sz, "must be finite");
	else if (isinf(r->hi))
		snprintf(buf, sz, "must be %s %.15g", lo, r->lo);
	else if (r->flags & F_LO_OPEN)
		snprintf(buf, sz, "must be greater than %.15g and at most "
		    "%.15g", r->lo, r->hi);
	else
		snprintf(buf, sz, "must be between %.15g and %.15g",
		    r->lo, r->hi);
}

static int
in_range(const struct row *r, double v)
{
	if (r->flags & F_LO_OPEN ? v <= r->lo : v < r->lo)
		return 0;
	return v <= r->hi;
}

/*
 * A number given as an expression string: it may read only the frame's
 * f and F, so it is a constant by the time it is compiled.  An integer
 * setting takes the nearest integer, so "100 + 900 * f" counts smoothly.
 */
static int
set_number_expr(struct load *L, const config_setting_t *s,
    const struct row *r, const char *path, void *dst)
{
	struct expr_error err;
	struct expr *e = expr_compile_with(config_setting_get_string(s), 0,
	    L->consts, &err);
	char range[128];
	double v = 0;

	if (e == NULL) {
		err_in_string(L, s, err.col, path, err.msg,
		    strstr(err.msg, "unknown variable") ?
		    " (a number's expression may use only f and F)" : "");
		return -1;
	}
	expr_is_constant(e, &v);
	expr_free(e);
	if (r->type == T_INT || r->type == T_INTS)
		v = floor(v + 0.5);
	if (!in_range(r, v) || fabs(v) > 9007199254740992.0) {
		range_words(r, range, sizeof(range));
		load_err_at(L, s, "%s %.15g is out of range: %s", path, v,
		    range);
		return -1;
	}
	if (r->type == T_INT || r->type == T_INTS)
		*(long long *)dst = (long long)v;
	else
		*(double *)dst = v;
	return 0;
}

static int
set_number(struct load *L, const config_setting_t *s, const struct row *r,
    const char *path, void *dst)
{
	char range[128];
	int type = config_setting_type(s);
	double v;

	if (type == CONFIG_TYPE_STRING)
		return set_number_expr(L, s, r, path, dst);
	if (type != CONFIG_TYPE_INT && type != CONFIG_TYPE_INT64 &&
	    type != CONFIG_TYPE_FLOAT) {
		load_err_at(L, s, "%s must be %s", path,
		    r->type == T_INT || r->type == T_INTS ? "an integer" :
		    "a number");
		return -1;
	}
	if ((r->type == T_INT || r->type == T_INTS) &&
	    type == CONFIG_TYPE_FLOAT) {
		v = config_setting_get_float(s);
		if (v != floor(v) || fabs(v) > 9007199254740992.0) {
			load_err_at(L, s, "%s must be an integer, not %.15g",
			    path, v);
			return -1;
		}
	} else if (type == CONFIG_TYPE_FLOAT)
		v = config_setting_get_float(s);
	else
		v = (double)config_setting_get_int64(s);

	if (!isfinite(v) || !in_range(r, v)) {
		range_words(r, range, sizeof(range));
		if (type == CONFIG_TYPE_FLOAT)
			load_err_at(L, s, "%s %.15g is out of range: %s", path,
			    v, range);
		else
			load_err_at(L, s, "%s %lld is out of range: %s", path,
			    config_setting_get_int64(s), range);
		return -1;
	}
	if (r->type == T_INT || r->type == T_INTS)
		*(long long *)dst = type == CONFIG_TYPE_FLOAT ?
		    (long long)v : config_setting_get_int64(s);
	else
		*(double *)dst = v;
	return 0;
}

/* "disk cone hemisphere ...": a word list for messages. */
void
load_words_join(char *buf, size_t sz, const char *const *words)
{
	size_t len = 0;

	buf[0] = '\0';
	for (; *words != NULL && len < sz; words++)
		len += (size_t)snprintf(buf + len, sz - len, "%s%s",
		    len ? " " : "", *words);
}

static int
set_choice(struct load *L, const config_setting_t *s, const char *path,
    const char *const *words, int *dst)
{
	const char *v = config_setting_get_string(s);
	char q[64], list[256];

	if (v == NULL) {
		load_err_at(L, s, "%s must be a string", path);
		return -1;
	}
	size_t n = 0;
	const char *near;

	for (; words[n] != NULL; n++)
		if (strcmp(v, words[n]) == 0) {
			*dst = (int)n;
			return 0;
		}
	cfgtext_quote(q, sizeof(q), v);
	load_words_join(list, sizeof(list), words);
	near = suggest(v, words, n);
	load_err_at(L, s, "%s \"%s\" is not one of: %s%s%s%s", path, q, list,
	    near ? " (did you mean " : "", near ? near : "", near ? "?)" : "");
	return -1;
}

/* [x, y, z]: three finite numbers in the row's range. */
static int
set_vec3(struct load *L, const config_setting_t *s, const struct row *r,
    const char *path, double *dst)
{
	if ((config_setting_type(s) != CONFIG_TYPE_ARRAY &&
	    config_setting_type(s) != CONFIG_TYPE_LIST) ||
	    config_setting_length(s) != 3) {
		load_err_at(L, s, "%s must be an array of 3 numbers, "
		    "[x, y, z]", path);
		return -1;
	}
	for (int i = 0; i < 3; i++)
		if (set_number(L, config_setting_get_elem(s, (unsigned)i), r,
		    path, &dst[i]) < 0)
			return -1;
	return 0;
}

/* [m, n] or [m, n, k]: positive integers, stored with their count. */
static int
set_ints(struct load *L, const config_setting_t *s, const struct row *r,
    const char *path, struct int_list *dst)
{
	int n = config_setting_length(s);

	if ((config_setting_type(s) != CONFIG_TYPE_ARRAY &&
	    config_setting_type(s) != CONFIG_TYPE_LIST) || n < 2 || n > 3) {
		load_err_at(L, s, "%s must be an array of 2 or 3 integers: "
		    "[8, 13] or [8, 13, 21]", path);
		return -1;
	}
	for (int i = 0; i < n; i++) {
		long long v;

		if (set_number(L, config_setting_get_elem(s, (unsigned)i),
		    r, path, &v) < 0)
			return -1;
		dst->v[i] = (int)v;
	}
	dst->n = n;
	return 0;
}

/* ((x0, y0), (x1, y1), ...): finite numbers, x at least 0. */
static int
set_points(struct load *L, const config_setting_t *s, const char *path,
    struct point_list *dst)
{
	int n = config_setting_length(s);

	if (config_setting_type(s) != CONFIG_TYPE_LIST &&
	    config_setting_type(s) != CONFIG_TYPE_ARRAY) {
		load_err_at(L, s, "%s must be a list of points: ((1, 0), "
		    "(0.7, 0.2), (0.3, 0.4), (0, 0.5))", path);
		return -1;
	}
	if (n > PROFILE_POINTS_MAX) {
		load_err_at(L, s, "%s has %d points, more than %d", path, n,
		    PROFILE_POINTS_MAX);
		return -1;
	}
	free(dst->p);
	dst->p = xcalloc((size_t)n + 1, sizeof(*dst->p));
	dst->n = n;
	for (int i = 0; i < n; i++) {
		config_setting_t *e = config_setting_get_elem(s, (unsigned)i);

		if ((config_setting_type(e) != CONFIG_TYPE_LIST &&
		    config_setting_type(e) != CONFIG_TYPE_ARRAY) ||
		    config_setting_length(e) != 2) {
			load_err_at(L, e, "%s: point %d must be a pair "
			    "(radius, height)", path, i + 1);
			return -1;
		}
		for (int k = 0; k < 2; k++) {
			config_setting_t *x = config_setting_get_elem(e,
			    (unsigned)k);
			double v;

			if (!config_setting_is_number(x)) {
				load_err_at(L, x, "%s: point %d must be two "
				    "numbers (radius, height)", path, i + 1);
				return -1;
			}
			v = config_setting_type(x) == CONFIG_TYPE_FLOAT ?
			    config_setting_get_float(x) :
			    (double)config_setting_get_int64(x);
			if (!isfinite(v) || (k == 0 && v < 0)) {
				load_err_at(L, x, "%s: point %d has %s %.15g; "
				    "it must be %s", path, i + 1, k ? "height" :
				    "radius", v, k ? "finite" :
				    "finite and at least 0");
				return -1;
			}
			dst->p[i][k] = v;
		}
	}
	return 0;
}

/* A number, or a string holding an expression, compiled now. */
static int
set_expr(struct load *L, const config_setting_t *s, const struct row *r,
    const char *path, struct expr_setting *dst)
{
	struct expr_error err;
	const char *src;

	dst->line = load_line(s);
	if (config_setting_is_number(s)) {
		double v = config_setting_type(s) == CONFIG_TYPE_FLOAT ?
		    config_setting_get_float(s) :
		    (double)config_setting_get_int64(s);

		dst->e = expr_constant(v);
		return 0;
	}
	if ((src = config_setting_get_string(s)) == NULL) {
		load_err_at(L, s, "%s must be a number or an expression string",
		    path);
		return -1;
	}
	if ((dst->e = expr_compile_with(src, r->vars, L->consts,
	    &err)) == NULL) {
		err_in_string(L, s, err.col, path, err.msg, "");
		return -1;
	}
	return 0;
}

/* One identifier, or an array of them: the entry's object variants. */
static int
set_names(struct load *L, const config_setting_t *s, const char *path,
    struct organ_range *rg)
{
	int list = config_setting_type(s) == CONFIG_TYPE_ARRAY ||
	    config_setting_type(s) == CONFIG_TYPE_LIST;
	int n = list ? config_setting_length(s) : 1;

	if (!list && config_setting_type(s) != CONFIG_TYPE_STRING) {
		load_err_at(L, s, "%s must be a name or an array of names",
		    path);
		return -1;
	}
	if (n == 0 || n > VARIANTS_MAX) {
		load_err_at(L, s, "%s must list 1 to %d names, not %d", path,
		    VARIANTS_MAX, n);
		return -1;
	}
	free(rg->names);
	rg->names = xcalloc((size_t)n, sizeof(*rg->names));
	rg->nnames = (size_t)n;
	for (int i = 0; i < n; i++) {
		const config_setting_t *e = list ?
		    config_setting_get_elem(s, (unsigned)i) : s;

		if (set_ident(L, e, path, rg->names[i]) < 0)
			return -1;
	}
	return 0;
}

/* A file's name, or an array of them: one for each variant. */
static int
set_files(struct load *L, const config_setting_t *s, const char *path,
    struct file_list *fl)
{
	int list = config_setting_type(s) == CONFIG_TYPE_ARRAY ||
	    config_setting_type(s) == CONFIG_TYPE_LIST;
	int n = list ? config_setting_length(s) : 1;

	if (!list && config_setting_type(s) != CONFIG_TYPE_STRING) {
		load_err_at(L, s, "%s must be a file name or an array of them",
		    path);
		return -1;
	}
	if (n == 0 || n > VARIANTS_MAX) {
		load_err_at(L, s, "%s must list 1 to %d files, not %d", path,
		    VARIANTS_MAX, n);
		return -1;
	}
	fl->v = xcalloc((size_t)n, sizeof(*fl->v));
	fl->n = (size_t)n;
	for (int i = 0; i < n; i++) {
		const config_setting_t *e = list ?
		    config_setting_get_elem(s, (unsigned)i) : s;
		const char *v = config_setting_get_string(e);

		if (v == NULL || *v == '\0' || strlen(v) > SCENE_PATH_MAX) {
			load_err_at(L, e, "%s must be %s", path, v == NULL ?
			    "a file name in quotes" : *v == '\0' ?
			    "a file name, not \"\"" : "a shorter file name");
			return -1;
		}
		fl->v[i] = xstrdup(v);
	}
	return 0;
}

static int
set_weights(struct load *L, const config_setting_t *s, const struct row *r,
    const char *path, struct organ_range *rg)
{
	int n = config_setting_length(s);

	if (config_setting_type(s) != CONFIG_TYPE_ARRAY &&
	    config_setting_type(s) != CONFIG_TYPE_LIST) {
		load_err_at(L, s, "%s must be an array of numbers: [1, 2]",
		    path);
		return -1;
	}
	if (n > VARIANTS_MAX) {
		load_err_at(L, s, "%s lists more than %d numbers", path,
		    VARIANTS_MAX);
		return -1;
	}
	rg->weights = xcalloc((size_t)n, sizeof(*rg->weights));
	rg->nweights = (size_t)n;
	for (int i = 0; i < n; i++)
		if (set_number(L, config_setting_get_elem(s, (unsigned)i), r,
		    path, &rg->weights[i]) < 0)
			return -1;
	return 0;
}

/* The registry's names, NULL-terminated, as a word list for set_choice. */
void
load_model_names(const char *words[MODELS_MAX + 1])
{
	size_t n = 0;

	for (const struct model *const *m = models; *m != NULL &&
	    n < MODELS_MAX; m++)
		words[n++] = (*m)->name;
	words[n] = NULL;
}

/* model = "...": one of the registry's names. */
int
load_model(struct load *L, const config_setting_t *s, const char *path,
    const struct model **dst)
{
	const char *words[MODELS_MAX + 1];
	int i;

	load_model_names(words);
	if (set_choice(L, s, path, words, &i) < 0)
		return -1;
	*dst = models[i];
	return 0;
}

int
load_setting_as(struct load *L, const config_setting_t *s, const char *path,
    const struct row *r, void *base)
{
	void *dst = (char *)base + r->off;

	switch (r->type) {
	case T_GROUP:
		if (!config_setting_is_group(s)) {
			load_err_at(L, s, "%s must be a group: %s = { ... };",
			    path, path);
			return -1;
		}
		return load_group(L, s, path, r->sub, dst);
	case T_INT:
	case T_FLOAT:
		return set_number(L, s, r, path, dst);
	case T_IDENT:
		return set_ident(L, s, path, dst);
	case T_CHOICE:
		return set_choice(L, s, path, r->words, dst);
	case T_EXPR:
		return set_expr(L, s, r, path, dst);
	case T_NAMES:
		return set_names(L, s, path, base);
	case T_WEIGHTS:
		return set_weights(L, s, r, path, base);
	case T_FILES:
		return set_files(L, s, path, dst);
	case T_INTS:
		return set_ints(L, s, r, path, dst);
	case T_POINTS:
		return set_points(L, s, path, dst);
	case T_RANGES:
		return load_ranges(L, s, path, r->sub);
	case T_MODEL:
		return load_model(L, s, path, dst);
	case T_VEC3:
		return set_vec3(L, s, r, path, dst);
	}
	return -1;
}
