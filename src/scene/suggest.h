/* suggest.h - "did you mean": the nearest of a set of words. */
#ifndef SUGGEST_H
#define SUGGEST_H

#include <stddef.h>

/*
 * The word of words[0 .. n-1] nearest to typed, if near enough to be a
 * slip (an edit distance of at most a third of its length, and at least
 * one), else NULL.  Adjacent letters swapped count as one edit.
 */
const char	*suggest(const char *typed, const char *const *words, size_t n);

#endif
