/*
 * inhibition_impl.h - what the inhibition model's files share: the
 * field of primordia placed so far, the circle's cuts and gaps, and
 * the functions that search them (inhibition.c runs the model,
 * inhibition_far.c keeps the power law's far field, inhibition_kernel.c
 * evaluates the energy, inhibition_min.c finds its least minimum on the
 * edge, inhibition_bounds.c bounds it in each gap).
 */
#ifndef INHIBITION_IMPL_H
#define INHIBITION_IMPL_H

#include <math.h>
#include <stddef.h>

#define R0		1.0	/* the meristem's radius: the unit */
#define MODES		80	/* of the power law's far field, at least */
#define MODES_MAX	400	/* and at most (slow growth) */
#define GMODES		14	/* of the Gaussian's: e^-(15^2/4) < 1e-24 */

/*
 * The modes the lower bounds evaluate: the others, x_far^m smaller and
 * less, are bounded by their amplitudes.
 */
#define BOUND_MODES	24

/*
 * Near primordia as the bounds want them, in order (the far field is
 * bounded apart): an array per quantity, so that the loops over them
 * take LANES at once, each lane summing its own share.
 */
struct cutv {
	double		*c, *s;		/* cos and sin of its angle */
	double		*q0, *r2;	/* R0^2 + r^2 and 2 R0 r */
	double		*fl;		/* its floor */
};

/*
 * The sums over near primordia: four partial sums side by side, which
 * the compiler runs as one vector where the CPU has them (HOT).  Their
 * order is fixed, so every build adds the same numbers the same way.
 */
#define LANES		4

/*
 * The functions that hold those sums are built twice, for AVX2 and for
 * the baseline, and the CPU picks at load time (GCC's and Clang's
 * target_clones, on x86-64 where the C library has ifunc: configure's
 * test-target_clones.c says, and mingw-w64 has none): four lanes
 * where AVX2 has them, two with SSE2 alone.  Static functions only:
 * Clang names a global clone's entry NAME.ifunc, which callers in other
 * files do not find.  FMA is left out: a*b + c is rounded twice in both
 * builds (-std=c11 contracts nothing), so both give the same bits
 * (-DNO_CLONES builds the baseline alone, to compare).
 */
#if HAVE_TARGET_CLONES && !defined(NO_CLONES)
#define HOT	__attribute__((target_clones("avx2", "default")))
#else
#define HOT
#endif

/*
 * The primordia so far: angle, its cosine and sine; ages from n.
 *
 * With the power law, the pull of a primordium at radius r on the
 * edge point at angle th is (R0^2 + r^2 - 2 R0 r cos(th - phi))^-(s/2)
 * = r^-s sum_j C_j(cos(th - phi)) x^j, x = R0 / r, with C_j the
 * Gegenbauer polynomials of order s/2 (their generating function), and
 * C_j(cos a) = sum_i w_ji cos((j - 2i) a).  So the primordia beyond
 * radius far_r (x below x_far) add up to sum_m Fc_m cos(m th) + Fs_m
 * sin(m th) over m <= nmodes, from the moments sum r^-(s+j) cos(m phi)
 * and sin(m phi); a plastochron's growth multiplies each by
 * e^-(s+j)G.  Each primordium joins the moments once and costs nothing
 * after: near ones are summed one by one, the rest in O(nmodes^2) a
 * primordium however many came before.
 *
 * The moments are kept in units that do not move: each as it was at the
 * step whose S is base (times its weight), so a plastochron changes
 * nothing stored, and the modes take the growth since base as a factor
 * per j.  The units are reset (base moved up) before those factors could
 * leave a double's range.
 */
struct field {
	double		*phi, *c, *s;
	size_t		 n;		/* placed */
	double		*S;		/* S[n]: G_1 + ... + G_n */
	double		*r;		/* r[k]: the radius now of the k-th
					   newest, for the near ones */
	size_t		 near;		/* newest that cut the circle */
	size_t		 from;		/* the oldest summed one by one; the
					   older are in the moments */
	int		 moments;	/* 0: every one by one (all pairs) */
	double		 far_r;		/* the radius where they join them */
	double		 hs;		/* s / 2 */
	double		*w;		/* per (m, j): the weight of moment
					   (j, m) in mode m */
	double		*Mc, *Ms;	/* the weighted moments at base */
	double		 base;		/* their units' S */
	size_t		 row[MODES_MAX + 2];	/* where m's moments start */
	double		 Fc[MODES_MAX + 1], Fs[MODES_MAX + 1];	/* the modes */
	int		 nmodes;	/* of the far field: GMODES, or MODES
					   and more where the cuts reach
					   inside far_r (inhib_far_init()) */
	int		 grid;		/* 0, or the points of a grid on the
					   circle where the far field is known
					   (inhib_far_least()) */
	double		*gv, *gd;	/* its E and E' there */
	double		*tw;		/* the transform's turns (fft()) */
	int		*rev;		/* j's bits reversed, j < grid */
	double		 m2;		/* sum m^2 |mode m|: E'' at most */
	double		 gerr;		/* the grid's rounding, at most */
	double		*gt;		/* Gaussian: per primordium cos and
					   sin (m phi), m <= GMODES, in rows */
	size_t		 grows;		/* for all, or a ring of the newest */
	int		 gexp;		/* exponentials of its weights, or 0 */
	double		*gdec, *gin;	/* per one: its decay a step, and the
					   weight it takes a primordium in */
	double		*gsum;		/* per exponential, and mode's cos
					   then sin: its running sum */
	double		 far_curv;	/* the far field's E'', at most */
	double		 tail[2];	/* the most its modes past BOUND_MODES
					   add to E and to E' */
	double		 far_least;	/* and its least on the circle */
	int		 check;		/* test every gap's bounds */
	long long	 misses;	/* bounds above their gap's least E */
	double		 floor;		/* the near ones' least pulls, */
	double		*fl;		/* each, indexed as r */
	struct cutv	 cp;		/* the near cuts in order, twice round */
	size_t		*cpi;		/* their primordia */
	size_t		 ncp;		/* how many */
	double		*fnear;		/* per gap: the first bound's near part
					   (inhib_first_near()) */
	size_t		*gpos;		/* per gap: the first near cut after
					   its start, in cp */
	struct cutv	 mid;		/* the near ones that are not cuts */
	size_t		 nmid;
	size_t		 ncut, cut_n;	/* how many, and n when they were cut */
};

/* The circle cut at a primordium's angle: where, which, cos and sin. */
struct cut {
	double		 th;
	size_t		 i;
	double		 c, s;
};

/* Where gap g, from cut g, ends: at the next cut, round the circle. */
static inline double
gap_end(const struct cut *cuts, size_t k, size_t g)
{
	return g + 1 < k ? cuts[g + 1].th : cuts[0].th + 2 * M_PI;
}

/* A gap's search: its bound so far, from which tier, and where to start. */
struct gap {
	double		 lb, at;
	int		 tier;
	unsigned	 live;		/* gap_bound()'s */
};

#define TIERS		4

/* The last tier's parts: each tier's parts are a number dividing it. */
#define SUBPARTS	16

/*
 * The power law's pull at squared distance q, q^-(s/2): the common
 * s = 3 and 2 without pow().
 */
static inline double
pull_at(const struct field *F, double q)
{
	return F->hs == 1.5 ? 1 / (q * sqrt(q)) : F->hs == 1 ? 1 / q :
	    pow(q, -F->hs);
}

void	inhib_cutv_alloc(struct cutv *, size_t n);
void	inhib_cutv_free(struct cutv *);

/* Entry d of v: primordium (c, s) at radius r, its floor fl. */
static inline void
cutv_set(const struct cutv *v, size_t d, double c, double s, double r,
    double fl)
{
	v->c[d] = c;
	v->s[d] = s;
	v->q0[d] = R0 * R0 + r * r;
	v->r2[d] = 2 * R0 * r;
	v->fl[d] = fl;
}

/* The far field (inhibition_far.c). */
void	inhib_far_init(struct field *, double inside);
void	inhib_far_grid(struct field *, int modes);
double	inhib_far_least(const struct field *, double lo, double hi);
void	inhib_far_step(struct field *);
void	inhib_far_summary(struct field *);
void	inhib_far_energy(const struct field *, double ct, double st,
	    int modes, double e[3]);

/* The Gaussian kernel's modes (inhibition_gauss.c). */
void	inhib_gauss_init(struct field *, size_t count, int exact);
double	*inhib_gauss_row(const struct field *, size_t i);
void	inhib_gauss_step(struct field *);
void	inhib_gauss_free(struct field *);

/* The energy (inhibition_kernel.c). */
void	inhib_energy(const struct field *, double th, double e[3]);
double	inhib_energy_only(const struct field *, double th);

/* The least minimum on the edge (inhibition_min.c). */
double	inhib_minimise(const struct field *, const struct cut *, size_t k,
	    size_t g, double x, double *emin);
double	inhib_next_angle(struct field *, struct cut *, struct gap *);

/* Lower bounds of the energy in a gap (inhibition_bounds.c). */
void	inhib_first_near(struct field *, const struct cut *, size_t k);
double	inhib_first_bound(const struct field *, const struct cut *,
	    size_t k, size_t g, double a, double b, double stop, double *at);
double	inhib_gap_bound(const struct field *, const struct cut *, size_t k,
	    size_t g, double a, double b, int tier, double stop,
	    unsigned *live, double *at);
double	inhib_end_least(const struct field *, const struct cut *, size_t k,
	    size_t g, int side);
void	inhib_check_bounds(struct field *, const struct cut *, size_t k);

#endif
