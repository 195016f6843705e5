/*
 * sink.c - buffered output for the writers.  A sink either flushes to a
 * stream in 64 KiB blocks or, with no stream, keeps everything in memory
 * (used by tests and fuzzing), or only counts (estimating a size).  The
 * first write error is remembered and reported once by sink_finish(), so
 * writers need not check each call.  A block that would take a run past
 * its budget's limit is not written: the error is EFBIG, budget->over.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "base/mem.h"
#include "base/numfmt.h"
#include "base/sink.h"

#define SINK_BLOCK (64 * 1024)

void
sink_init(struct sink *s, FILE *fp)
{
	*s = (struct sink){ .fp = fp, .cap = SINK_BLOCK };
	s->buf = xmalloc(s->cap);
}

void
sink_init_count(struct sink *s)
{
	sink_init(s, NULL);
	s->counting = 1;
}

static void
sink_flush(struct sink *s)
{
	struct budget *b = s->budget;

	if (s->counting) {
		s->counted += (double)s->len;
		s->len = 0;
	}
	if (s->fp == NULL || s->len == 0)
		return;
	if (s->err == 0 && b != NULL && b->limit > 0 &&
	    b->used + (double)s->len > b->limit) {
		b->over = 1;
		s->err = EFBIG;
	}
	if (s->err == 0 && fwrite(s->buf, 1, s->len, s->fp) != s->len)
		s->err = errno ? errno : EIO;
	if (s->err == 0 && b != NULL) {
		b->used += (double)s->len;
		if (b->told != NULL)
			b->told(b);
	}
	s->len = 0;
}

/* Make room for n more bytes. */
static void
sink_reserve(struct sink *s, size_t n)
{
	if (s->cap - s->len >= n)
		return;
	sink_flush(s);
	if (s->cap - s->len >= n)
		return;
	while (s->cap - s->len < n)
		s->cap *= 2;
	s->buf = xreallocarray(s->buf, s->cap, 1);
}

void
sink_write(struct sink *s, const char *p, size_t n)
{
	sink_reserve(s, n);
	memcpy(s->buf + s->len, p, n);
	s->len += n;
}

void
sink_puts(struct sink *s, const char *p)
{
	sink_write(s, p, strlen(p));
}

void
sink_putc(struct sink *s, char c)
{
	sink_reserve(s, 1);
	s->buf[s->len++] = c;
}

void
sink_num(struct sink *s, double x)
{
	sink_reserve(s, NUMFMT_MAX);
	s->len += num_format(s->buf + s->len, x);
}

void
sink_uint(struct sink *s, unsigned long long v)
{
	char tmp[24];
	size_t i = sizeof(tmp);

	do
		tmp[--i] = (char)('0' + v % 10);
	while ((v /= 10) != 0);
	sink_write(s, tmp + i, sizeof(tmp) - i);
}

void
sink_add(struct sink *s, double n)
{
	s->counted += n;
}

double
sink_bytes(const struct sink *s)
{
	return s->counted + (double)s->len;
}

/* Flush everything; 0, or -1 with errno set to the first failure. */
int
sink_finish(struct sink *s)
{
	sink_flush(s);
	if (s->fp != NULL && s->err == 0 && fflush(s->fp) != 0)
		s->err = errno ? errno : EIO;
	if (s->fp != NULL && s->err == 0 && ferror(s->fp))
		s->err = EIO;
	if (s->err != 0) {
		errno = s->err;
		return -1;
	}
	return 0;
}

void
sink_free(struct sink *s)
{
	free(s->buf);
	s->buf = NULL;
}
