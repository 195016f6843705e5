/*
 * measured_csv.h - the measured model's points file: CSV whose header
 * names the columns x and y, and optionally z, n (a known order) and
 * radius; other columns are ignored, # starts a comment.
 */
#ifndef MEASURED_CSV_H
#define MEASURED_CSV_H

#include <stddef.h>

#define POINTS_MAX	1000000		/* points a file may hold */
#define POINTS_MIN	10		/* fewer say nothing of spirals */
#define POINTS_LINE_MAX	65536		/* bytes in one line */

struct points {
	double		(*p)[3];	/* x, y, z as read; z 0 without one */
	double		*radius;	/* NULL: no radius column */
	long long	*n;		/* NULL: no n column */
	int		*line;		/* where each point was read */
	size_t		 count, cap;
	int		 has_z;
	int		 header_line;
};

/*
 * The points in the file at path: 0, or -1 after a diagnostic naming
 * the file and line (a read error: a system error).  The file is read
 * line by line and refused at its first bad line, so a large file of
 * anything else costs one line.
 */
int	points_read(struct points *, const char *path);

/* The same from text in memory, as if read from file (the fuzzer's). */
int	points_parse(struct points *, const char *file, const char *text,
	    size_t len);

void	points_free(struct points *);

#endif
