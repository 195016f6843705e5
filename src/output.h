/* output.h - where the result goes: stdout, or -o FILE replaced atomically. */
#ifndef OUTPUT_H
#define OUTPUT_H

#include <stdio.h>

FILE	*output_open(const char *path);
int	 output_commit(void);
void	 output_abort(void);

#endif
