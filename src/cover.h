/* cover.h - where the receptacle is provably covered: the walk's shortcut. */
#ifndef COVER_H
#define COVER_H

#include "curve.h"

struct cover {
	int	 on;
};

void	cover_init(struct cover *, const struct curve *, double r0,
	    long long count);
void	cover_free(struct cover *);
void	cover_add(struct cover *, const struct curve *, double t, double c,
	    double s, double r);
int	cover_skip(struct cover *, const struct curve *, double *t, double c,
	    double s, double r);

#endif
