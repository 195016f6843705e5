/* cfgtext.h - scene text made safe for libconfig 1.5, and values quoted for messages. */
#ifndef CFGTEXT_H
#define CFGTEXT_H

#include <stddef.h>

/* A copy ready to parse, or NULL with *nul_line set to a NUL's line. */
char	*cfgtext_prepare(const char *text, size_t len, int *nul_line);
void	 cfgtext_quote(char *dst, size_t sz, const char *s);

#endif
