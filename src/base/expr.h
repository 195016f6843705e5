/* expr.h - expressions over an organ's index and place, compiled once. */
#ifndef EXPR_H
#define EXPR_H

#include <stdint.h>

#define EXPR_LEN_MAX	4096	/* bytes in one expression */
#define EXPR_DEPTH_MAX	256	/* nesting of parentheses and operators */

/* The variables; a context allows a subset (EXPR_VAR(V_N) | ...). */
enum expr_var {
	V_N,		/* n: the organ's index */
	V_COUNT,	/* N: the number of organs */
	V_T,		/* t: n / (N - 1) */
	V_S,		/* s: 0..1 across the organ's own entry */
	V_R,		/* r: packing radius */
	V_PHI,		/* phi: angle about the axis, degrees */
	V_H,		/* h: height along the axis */
	V__MAX
};
#define EXPR_VAR(v)	(1u << (v))
#define EXPR_ALL	((1u << V__MAX) - 1)

/* What one evaluation sees. */
struct expr_env {
	double		 var[V__MAX];
	uint64_t	 seed;		/* with n, keys rand(k) */
	long long	 n;
};

/* Where and why compiling failed; col counts from 1. */
struct expr_error {
	int		 col;
	char		 msg[128];
};

enum expr_status {
	EXPR_OK,
	EXPR_DIVZERO,		/* division or modulo by zero */
	EXPR_NOTFINITE		/* the result is NaN or infinite */
};

/*
 * A name that stands for a number fixed while a scene is loaded: the
 * frame's f and F.  Lists of them end with a NULL name.
 */
struct expr_const {
	const char	*name;
	double		 value;
};

struct expr;

/* A number or expression setting (T_EXPR), and where it was given. */
struct expr_setting {
	struct expr	*e;		/* NULL: not given */
	int		 line;
};

struct expr	*expr_compile(const char *src, unsigned vars,
		    struct expr_error *);
/* The same, where the names in consts are those numbers. */
struct expr	*expr_compile_with(const char *src, unsigned vars,
		    const struct expr_const *consts, struct expr_error *);
struct expr	*expr_constant(double);
int		 expr_is_constant(const struct expr *, double *value);
/* The variables it reads, as EXPR_VAR() bits. */
unsigned	 expr_vars(const struct expr *);
enum expr_status expr_eval(struct expr *, const struct expr_env *,
		    double *result);
void		 expr_free(struct expr *);

/*
 * What organ n of N sees: n, N, and t = n / (N - 1), 0 for one organ;
 * the other variables are left as they are.
 */
void		 expr_env_organ(struct expr_env *, long long n, long long N);

/*
 * Evaluate the setting at path (as the scene file names it, given in
 * file) for env->n; an error names the item, "organ 5".  0, or -1
 * after a diagnostic.
 */
int		 expr_setting_eval(const struct expr_setting *,
		    const char *file, const char *path, const char *item,
		    struct expr_env *, double *v);

/* The uniform number in [0, 1) that rand(k) gives organ n. */
double		 expr_rand(uint64_t seed, long long n, long long k);

#endif
