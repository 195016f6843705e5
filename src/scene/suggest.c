/*
 * suggest.c - "did you mean": the nearest word by edit distance
 * (Damerau's: insert, delete, change, or swap two neighbours), so that
 * 'planar.scael' or "hemisphere" for "hemisphare" gets its correction;
 * else the one word it begins ("gauss" for "gaussian").
 * A suggestion never changes what is accepted: the caller's message is
 * still an error.
 */
#include <string.h>

#include "scene/suggest.h"

#define WORD_MAX	96	/* longer words get no suggestion */

static size_t
min3(size_t a, size_t b, size_t c)
{
	size_t m = a < b ? a : b;

	return m < c ? m : c;
}

/* The distance between a and b, or more than limit (then exact no more). */
static size_t
distance(const char *a, const char *b, size_t limit)
{
	size_t la = strlen(a), lb = strlen(b);
	size_t d[3][WORD_MAX + 1];	/* rows i - 2, i - 1, i */

	if (la > WORD_MAX || lb > WORD_MAX)
		return limit + 1;
	if ((la > lb ? la - lb : lb - la) > limit)
		return limit + 1;
	for (size_t j = 0; j <= lb; j++)
		d[0][j] = j;
	for (size_t i = 1; i <= la; i++) {
		/* Three rows in turn: row i, and rows i - 1 and i - 2. */
		size_t *row = d[i % 3], *prev = d[(i + 2) % 3];
		size_t *prev2 = d[(i + 1) % 3], best;

		row[0] = best = i;
		for (size_t j = 1; j <= lb; j++) {
			size_t cost = a[i - 1] != b[j - 1];

			row[j] = min3(prev[j] + 1, row[j - 1] + 1,
			    prev[j - 1] + cost);
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] &&
			    a[i - 2] == b[j - 1] && prev2[j - 2] + 1 < row[j])
				row[j] = prev2[j - 2] + 1;
			if (row[j] < best)
				best = row[j];
		}
		if (best > limit)
			return limit + 1;
	}
	return d[la % 3][lb];
}

/*
 * The one word that typed begins, as "gauss" begins "gaussian": a
 * shortening is too far from its word by edit distance, yet says which
 * is meant where no other word begins the same.  Three letters at least.
 */
static const char *
only_extension(const char *typed, const char *const *words, size_t n)
{
	size_t len = strlen(typed);
	const char *found = NULL;

	if (len < 3)
		return NULL;
	for (size_t i = 0; i < n; i++)
		if (words[i] != NULL && strncmp(words[i], typed, len) == 0) {
			if (found != NULL)
				return NULL;	/* two: no telling */
			found = words[i];
		}
	return found;
}

const char *
suggest(const char *typed, const char *const *words, size_t n)
{
	size_t limit = strlen(typed) / 3, best = (size_t)-1;
	const char *nearest = NULL;

	if (limit < 1)
		limit = 1;
	for (size_t i = 0; i < n; i++) {
		size_t d;

		if (words[i] == NULL || strcmp(words[i], typed) == 0)
			continue;
		d = distance(typed, words[i], limit);
		if (d <= limit && d < best) {
			best = d;
			nearest = words[i];
		}
	}
	return nearest != NULL ? nearest : only_extension(typed, words, n);
}
