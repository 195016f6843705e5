/* sink.h - the buffered output every writer writes into; errors are sticky. */
#ifndef SINK_H
#define SINK_H

#include <stddef.h>
#include <stdio.h>

/*
 * What one run may write, shared by its files: a limit (--max-output),
 * the bytes written so far, and who is told as blocks go out.
 */
struct budget {
	double		 limit;		/* bytes; 0: none */
	double		 expected;	/* the estimate, for progress */
	double		 used;
	void		(*told)(const struct budget *);	/* or NULL */
	int		 over;		/* a block would have passed limit */
};

struct sink {
	FILE	*fp;		/* NULL: everything stays in buf */
	char	*buf;
	size_t	 len, cap;
	int	 err;		/* errno of the first failed write, or 0 */
	int	 counting;	/* only count: nothing is kept */
	double	 counted;	/* bytes counted, and added by sink_add() */
	struct budget *budget;	/* or NULL */
};

void	sink_init(struct sink *, FILE *);
/* A sink that only counts what is written into it (sink_bytes()). */
void	sink_init_count(struct sink *);
void	sink_write(struct sink *, const char *, size_t);
void	sink_puts(struct sink *, const char *);
void	sink_putc(struct sink *, char);
void	sink_num(struct sink *, double);
void	sink_uint(struct sink *, unsigned long long);
/* A counting sink: n bytes more than were written (a scaled sample). */
void	sink_add(struct sink *, double n);
double	sink_bytes(const struct sink *);
int	sink_finish(struct sink *);
void	sink_free(struct sink *);

#endif
