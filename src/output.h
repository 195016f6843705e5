/* output.h - where results go: stdout, or -o FILE replaced atomically. */
#ifndef OUTPUT_H
#define OUTPUT_H

#include <stdio.h>

/* One file at a time; each stays a temporary until output_commit(). */
FILE	*output_open(const char *path);
int	 output_close(void);
int	 output_commit(void);
void	 output_abort(void);

#endif
