/* numfmt.h - fast formatting of doubles with 9 significant digits. */
#ifndef NUMFMT_H
#define NUMFMT_H

#include <stddef.h>

#define NUMFMT_MAX 32	/* longest output, with the NUL */

size_t	num_format(char *out, double x);

#endif
