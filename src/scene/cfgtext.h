/* cfgtext.h - scene text made safe for libconfig 1.5, and values quoted for messages. */
#ifndef CFGTEXT_H
#define CFGTEXT_H

#include <stddef.h>

/* A copy ready to parse, or NULL with *nul_line set to a NUL's line. */
char	*cfgtext_prepare(const char *text, size_t len, int *nul_line);
void	 cfgtext_quote(char *dst, size_t sz, const char *s);

/*
 * Where byte k of a string setting's value stands in the file: the
 * setting name, on line (as libconfig reports it), whose value -- or,
 * with elem >= 0, whose array's element elem -- is the string want.
 * Sets *line and *col (from 1, a tab one column); 0, or -1 when the
 * text does not show the string so (a message then gives the line).
 */
int	 cfgtext_locate(const char *text, size_t len, const char *name,
	    int elem, const char *want, size_t k, int *line, int *col);

struct config_setting_t;

/*
 * A setting's value written again in scene-file syntax (0.04, "1 + n",
 * [8, 13], { a = 1; }), such that libconfig reads it back the same;
 * allocated.
 */
char	*cfgtext_value(const struct config_setting_t *);

/*
 * text with the setting at path (dotted, numbers stepping into a list's
 * entries: "organs.1.tilt") given value, in scene-file syntax: its value
 * replaced where the text has it, else the setting added at the end of
 * the group holding it (made if need be); comments and layout as they
 * were.  Allocated, with *newlen; NULL where the text cannot take it.
 */
char	*cfgtext_splice(const char *text, size_t len, const char *path,
	    const char *value, size_t *newlen);

/*
 * text without the setting at path: "name = value;" taken out, with
 * its line where nothing else is on it (a comment after it stays);
 * every other comment and line as it was.  Allocated, with *newlen;
 * NULL where the text does not have it.
 */
char	*cfgtext_cut(const char *text, size_t len, const char *path,
	    size_t *newlen);

#endif
