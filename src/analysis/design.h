/*
 * design.h - inverse design: the count or radius whose structure shows
 * a parastichy pair, by measuring trial structures.
 */
#ifndef DESIGN_H
#define DESIGN_H

#include <stddef.h>

#include "result/organ.h"

/* Measure the pair at the rim or base with the parameter at x; 0 or -1. */
typedef int para_measure_fn(void *ctx, double x, int pair[2]);

/*
 * Inverse design: the x in [lo, hi] (lo > 0) whose structure shows the
 * pair want, searched in log x: stepped to find where want shows, then
 * each edge of that stretch bracketed, and the geometric middle taken.
 * grows: the pair grows with x (a count) rather than shrinks (a radius).
 * Returns x, 0 when want does not show (reach then lists the pairs that
 * did, "2/3 3/5 5/8"), or -1 when measure failed (it said why).
 */
double	para_search(const int want[2], double lo, double hi, int grows,
	    para_measure_fn *, void *ctx, char *reach, size_t reachsz);

struct int_list;
struct receptacle;

/* A trial structure: made with a constant radius r, at most cap organs. */
typedef int para_trial_fn(void *arg, double r, long long cap,
    struct result *);

/*
 * Inverse design on a receptacle: the constant radius whose structure
 * shows the pair want, the parastichies of the model's group given at
 * line of the scene file (which messages name, as a model's do), at the
 * base of rc; radius_line: where the group gave its radius too (0: it
 * did not, as it must not).  Searched up to a radius whose cell fits
 * four times round the base and, with by_area, four times on the whole
 * receptacle.  trial makes a trial structure with arg.  The radius, or
 * -1 after a diagnostic.
 */
double	para_design_receptacle(const char *file, const char *group,
	    int line, int radius_line, const struct receptacle *rc,
	    const struct int_list *want, int by_area, para_trial_fn *trial,
	    void *arg);

/*
 * A pair asked for at path, given at line of file: [m, n], 0 < m < n,
 * coprime.
 */
int	para_want_check(const char *file, int line, const char *path,
	    const struct int_list *);

#endif
