/* output.h - where results go: stdout, or -o FILE replaced atomically. */
#ifndef OUTPUT_H
#define OUTPUT_H

#include <stdio.h>

/*
 * 0 if -o path names no input (base/inputs.h) and may be written; else
 * -1 after a usage error.
 */
int	 output_check(const char *path);

/*
 * One file at a time; each stays a temporary until output_commit().
 * Through a symbolic link the link's target is written; an existing
 * file keeps its permissions.
 */
FILE	*output_open(const char *path);
int	 output_close(void);
int	 output_commit(void);
void	 output_abort(void);

/*
 * The file of frame F: pattern with its one %d (flags 0, a width) made
 * F, and %% made %.  buf NULL: only check the pattern.  0, or -1 after
 * a usage error.
 */
int	 output_frame_path(const char *pattern, int F, char *buf, size_t sz);

#endif
