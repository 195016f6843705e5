/*
 * override.c - --set [OBJECT:]PATH=VALUE.  VALUE is read by libconfig
 * itself, as "v = VALUE;", so it is exactly what the scene file takes
 * (a number, a "string", an [array], a (list) or a { group }); the
 * setting it makes replaces PATH's in the scene's own settings, or is
 * added, with the groups on the way; then the loader checks the whole
 * as usual.  A path steps into groups by name and into the entries of
 * a list by index (organs.1.tilt).  Anything the command line gets
 * wrong (no '=', a bad name, a value libconfig cannot read, a path
 * through a number, an entry past the list's end) is a usage error.
 */
#include <ctype.h>
#include <libconfig.h>
#include <stdlib.h>
#include <string.h>

#include "scene/cfgtext.h"
#include "base/diag.h"
#include "base/mem.h"
#include "scene/override.h"

/* A libconfig name ([A-Za-z*][-A-Za-z0-9_*]*), or an index (digits). */
static int
component(const char *p, size_t n)
{
	int digits = 1;

	if (n == 0)
		return 0;
	for (size_t i = 0; i < n; i++) {
		unsigned char c = (unsigned char)p[i];

		if (c & 0x80)
			return 0;
		digits &= isdigit(c) != 0;
		if (!(isalnum(c) || c == '-' || c == '_' || c == '*'))
			return 0;
	}
	return digits || isalpha((unsigned char)p[0]) || p[0] == '*';
}

/* VALUE as libconfig reads "v = VALUE;": cfg's one setting, or NULL. */
static config_setting_t *
read_value(config_t *cfg, const char *value, const char **why)
{
	size_t len = strlen(value);
	char *text = xmalloc(len + 8), *ready;
	config_setting_t *root, *v = NULL;
	int nul;

	config_init(cfg);
	memcpy(text, "v = ", 4);
	memcpy(text + 4, value, len);
	memcpy(text + 4 + len, ";\n", 3);
	if ((ready = cfgtext_prepare(text, len + 6, &nul)) == NULL)
		*why = "a NUL byte in the value";
	else if (config_read_string(cfg, ready) != CONFIG_TRUE)
		*why = "not a value in scene-file syntax (a number, a "
		    "\"string\", an [array], a (list) or a { group })";
	else if (config_setting_length(root = config_root_setting(cfg)) != 1 ||
	    (v = config_setting_get_member(root, "v")) == NULL)
		*why = "more than one value";
	free(ready);
	free(text);
	return v;
}

int
override_parse(const char *arg, struct override *o)
{
	const char *eq = strchr(arg, '='), *colon, *p;
	config_t cfg;
	const char *why;
	size_t len;

	*o = (struct override){ .arg = arg };
	if (eq == NULL || eq == arg) {
		diag(ST_USAGE, NULL, 0, 0, "--set %s: give PATH=VALUE, as "
		    "planar.scale=0.05 or Floret:count=30", arg);
		return -1;
	}
	o->value = eq + 1;
	colon = memchr(arg, ':', (size_t)(eq - arg));
	p = colon != NULL ? colon + 1 : arg;
	if (colon != NULL) {
		len = (size_t)(colon - arg);
		if (len == 0 || len > NAME_LEN || !component(arg, len) ||
		    !isalpha((unsigned char)arg[0])) {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: '%.*s' is not an "
			    "organ object's name", arg, (int)(len > 40 ? 40 :
			    len), arg);
			return -1;
		}
		memcpy(o->object, arg, len);
		o->object[len] = '\0';
	}
	len = (size_t)(eq - p);
	if (len == 0 || len >= PATH_LEN) {
		diag(ST_USAGE, NULL, 0, 0, "--set %s: %s", arg, len == 0 ?
		    "no setting named before '='" : "the path is too long");
		return -1;
	}
	for (const char *c = p; c < eq; ) {
		const char *dot = memchr(c, '.', (size_t)(eq - c));
		const char *e = dot != NULL ? dot : eq;

		if (!component(c, (size_t)(e - c))) {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: '%.*s' is not a "
			    "setting's name or an entry's number", arg,
			    (int)(e - c > 40 ? 40 : e - c), c);
			return -1;
		}
		c = dot != NULL ? dot + 1 : eq;
		if (dot != NULL && c == eq) {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: the path ends in "
			    "'.'", arg);
			return -1;
		}
	}
	memcpy(o->path, p, len);
	o->path[len] = '\0';
	if (read_value(&cfg, o->value, &why) == NULL) {
		diag(ST_USAGE, NULL, 0, 0, "--set %s: %s", arg, why);
		config_destroy(&cfg);
		return -1;
	}
	config_destroy(&cfg);
	return 0;
}

/* A copy of src as member name of parent (NULL name: an element). */
static config_setting_t *
copy(config_setting_t *parent, const char *name, const config_setting_t *src,
    unsigned line)
{
	int type = config_setting_type(src);
	config_setting_t *dst = config_setting_add(parent, name, type);

	if (dst == NULL)
		return NULL;
	dst->line = line;
	config_setting_set_format(dst, config_setting_get_format(src));
	switch (type) {
	case CONFIG_TYPE_INT:
		config_setting_set_int(dst, config_setting_get_int(src));
		break;
	case CONFIG_TYPE_INT64:
		config_setting_set_int64(dst, config_setting_get_int64(src));
		break;
	case CONFIG_TYPE_FLOAT:
		config_setting_set_float(dst, config_setting_get_float(src));
		break;
	case CONFIG_TYPE_STRING:
		config_setting_set_string(dst, config_setting_get_string(src));
		break;
	case CONFIG_TYPE_BOOL:
		config_setting_set_bool(dst, config_setting_get_bool(src));
		break;
	default:
		for (int i = 0; i < config_setting_length(src); i++) {
			const config_setting_t *e = config_setting_get_elem(src,
			    (unsigned)i);

			if (copy(dst, config_setting_name(e), e, line) == NULL)
				return NULL;
		}
	}
	return dst;
}

static const char *
name_of(const config_setting_t *s)
{
	return config_setting_name(s) != NULL ? config_setting_name(s) :
	    config_setting_parent(s) != NULL ? "an entry" : "the scene";
}

/* Put one override into root; 0, or -1 after a usage error. */
static int
apply(config_setting_t *root, const struct override *o, unsigned line)
{
	char path[PATH_LEN], *c, *next;
	config_setting_t *at = root, *v, *made = NULL;
	config_t cfg;
	const char *why;

	snprintf(path, sizeof(path), "%s", o->path);
	for (c = path; (next = strchr(c, '.')) != NULL; c = next + 1) {
		config_setting_t *in;

		*next = '\0';
		if (!isdigit((unsigned char)*c)) {
			if (!config_setting_is_group(at))
				goto through;
			if ((in = config_setting_get_member(at, c)) == NULL) {
				made = in = config_setting_add(at, c,
				    CONFIG_TYPE_GROUP);
				in->line = line;
			}
		} else if (at == made) {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: the scene has no "
			    "%s to number: give the whole list, as %s=({ ... "
			    "})", o->arg, name_of(at), name_of(at));
			return -1;
		} else if (!config_setting_is_list(at)) {
			goto through;
		} else if ((in = config_setting_get_elem(at,
		    (unsigned)strtol(c, NULL, 10))) == NULL) {
			diag(ST_USAGE, NULL, 0, 0, "--set %s: %s has %d "
			    "entries, numbered from 0", o->arg, name_of(at),
			    config_setting_length(at));
			return -1;
		}
		at = in;
		if (!config_setting_is_aggregate(at))
			goto through;
	}
	if (!isdigit((unsigned char)*c) && !config_setting_is_group(at))
		goto through;
	if (isdigit((unsigned char)*c)) {
		diag(ST_USAGE, NULL, 0, 0, "--set %s: set a whole entry, array "
		    "or list by its name (stretch=[1.0, 2.0, 1.0]), or a "
		    "setting inside an entry (organs.1.tilt=30)", o->arg);
		return -1;
	}
	if ((v = read_value(&cfg, o->value, &why)) != NULL) {
		config_setting_remove(at, c);
		v = copy(at, c, v, line);
	}
	config_destroy(&cfg);
	return v != NULL ? 0 : -1;
through:
	diag(ST_USAGE, NULL, 0, 0, "--set %s: the path goes through %s, which "
	    "is %s", o->arg, name_of(at), config_setting_is_list(at) ||
	    config_setting_is_array(at) ? "a list: step into its entries by "
	    "number (organs.0.scale)" : config_setting_is_group(at) ?
	    "a group: name a setting in it (planar.scale)" : "one value, not "
	    "a group");
	return -1;
}

int
override_apply(config_setting_t *root, struct override *set, int n,
    const char *object)
{
	for (int k = 0; k < n; k++) {
		if (strcmp(set[k].object, object) != 0)
			continue;
		if (apply(root, &set[k], (unsigned)(DIAG_LINE_SET + k)) != 0)
			return -1;
		set[k].used = 1;
	}
	return 0;
}
