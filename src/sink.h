/* sink.h - the buffered output every writer writes into; errors are sticky. */
#ifndef SINK_H
#define SINK_H

#include <stddef.h>
#include <stdio.h>

struct sink {
	FILE	*fp;		/* NULL: everything stays in buf */
	char	*buf;
	size_t	 len, cap;
	int	 err;		/* errno of the first failed write, or 0 */
};

void	sink_init(struct sink *, FILE *);
void	sink_write(struct sink *, const char *, size_t);
void	sink_puts(struct sink *, const char *);
void	sink_putc(struct sink *, char);
void	sink_num(struct sink *, double);
void	sink_uint(struct sink *, unsigned long long);
int	sink_finish(struct sink *);
void	sink_free(struct sink *);

#endif
