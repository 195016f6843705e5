/*
 * unordered.h - contact parastichies, the divergence and the spacing
 * measured on points whose order nobody knows: florets clicked on a
 * photograph, scales from a scan, or any model's organs shuffled.
 */
#ifndef UNORDERED_H
#define UNORDERED_H

#include <stddef.h>
#include <stdint.h>

#include "analysis/axis.h"
#include "analysis/parastichy.h"
#include "result/organ.h"

#define UZONES_MAX	64
#define UZ_SEEN		3

enum uzone_kind {
	UZ_PAIR,		/* one family pair m/n holds */
	UZ_TRANSITION,		/* a lattice, no one pair: seen[] */
	UZ_UNCLEAR		/* no lattice to read a pair from */
};

/* A stretch from the tip outward. */
struct uzone {
	enum uzone_kind	 kind;
	int		 m, n;
	int		 seen[UZ_SEEN][2];
	int		 nseen;
	size_t		 from;		/* its organ nearest the tip */
	double		 s, rho, z;	/* where that lies (corrected) */
	double		 s_end;		/* where its organ farthest lies */
	size_t		 organs;	/* in it */
	size_t		 agree;		/* holding its pair */
	int		 cut;		/* some of its rings cut short */
};

/*
 * An organ as measured: its nearest earlier neighbour turning each way
 * about the axis (older_out: earlier is farther from the tip, else
 * nearer) and how many organs of the spiral lie between (the parastichy
 * number the contact shows), -1 and 0 for none; and where it lies along
 * the curve from the tip.
 */
struct uorgan {
	int32_t		 prev[2];
	int32_t		 dk[2];
	double		 s;
};

/* What was measured; one allocation (free() it). */
struct unordered {
	double		 centre[2];	/* the fit's (axis.h) */
	double		 squash, squash_deg, spacing;
	int		 surface;
	/*
	 * Degrees in [0, 360): organ k at k times it, counter-clockwise
	 * seen from +Z, k counting from the rim or base towards the tip if
	 * older_out, else from the tip out (Vogel's); NAN: none measured.
	 */
	double		 divergence, divergence_err;
	int		 divergence_bands;
	int		 counted;	/* bands whose spirals, counted
					   across whole rings, agree with
					   their turns (the others labelled
					   by angle alone) */
	int		 older_out;
	/* Heads: Vogel's c (exponent 1/2) and the exponent; else NAN. */
	double		 vogel_c, vogel_c_err, exponent, exponent_err;
	/* The area per organ over 2 pi rho: a cylinder's rise. */
	double		 rise, rise_err;
	double		 contact;	/* the shortest step, median */
	double		 unit;		/* the result's length per the
					   fit's (its lengths are the fit's) */
	struct uzone	 zone[UZONES_MAX];
	size_t		 nzones;
	size_t		 count;
	struct uorgan	 c[];		/* count of them */
};

/*
 * Measure the points (axis_points() of fit A, and as given in raw,
 * whose distances a surface's neighbours go by), the older organs
 * farther from the tip if older_out (a plant's own order, and the
 * collision model's), else nearer (Vogel's); with too few points every
 * zone is unclear.
 */
struct unordered *unordered_measure(const struct axis *A,
	    const struct axis_point *ap, const double (*raw)[3], size_t n,
	    int older_out);
/*
 * The same on a result's organ positions, the axis found from them and
 * the older organs where the result's order has them (rim_last).
 */
struct unordered *unordered_of_result(const struct result *);
/*
 * The zones as parastichy.h's, for what draws either (an unclear one a
 * transition that saw no pair); how many.
 */
size_t	unordered_para_zones(const struct unordered *, struct para_zone *,
	    size_t zmax);
/* The zone at the rim or base, the last (of any kind), or NULL. */
const struct uzone *unordered_rim(const struct unordered *);

#endif
