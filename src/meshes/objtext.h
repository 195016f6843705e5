/*
 * objtext.h - the lines, words and numbers of Wavefront OBJ and .mtl
 * text, the messages about them, and reading their files.
 */
#ifndef OBJTEXT_H
#define OBJTEXT_H

#include <stddef.h>

#include "compat/compat.h"

/* Where a message points: the file, and the line being read. */
struct objtext {
	const char	*file;
	int		 line;
};

/* Space within a line: blanks, tabs and a CRLF's CR. */
int	 objtext_blank(char);
const char *objtext_skip(const char *p, const char *end);
/* The end of the word at p. */
const char *objtext_word_end(const char *p, const char *end);
/* An error at the line being read; always -1. */
int	 objtext_fail(const struct objtext *, const char *fmt, ...)
	    PRINTFLIKE(2, 3)
	    ;
/* The text from p to end (a few words at most), quoted for a message. */
void	 objtext_quote(char *dst, size_t sz, const char *p, const char *end);
/*
 * The number at *p, if one is there before the line's end or a comment:
 * 1 and *p past it, 0 if none, or -1 after a diagnostic.  The text must
 * end in a NUL.  Numbers are finite, and so as floats (glTF's).
 */
int	 objtext_number(const struct objtext *, const char **p,
	    const char *end, double *x);
/* lo to hi numbers to the line's end: how many, or -1. */
int	 objtext_numbers(const struct objtext *, const char *p,
	    const char *end, double *x, int lo, int hi, const char *what);
/* The line of the first NUL in text, or 0. */
int	 objtext_nul_line(const char *text, size_t len);
/*
 * The whole file at path, up to max bytes, ending in a NUL: 0, or -1
 * after a diagnostic (too large: exit 1; I/O: exit 3).
 */
int	 objtext_read(const char *path, long max, const char *what,
	    char **text, size_t *len);

#endif
