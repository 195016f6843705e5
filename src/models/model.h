/* model.h - the seam between a scene and the models: what a model sees. */
#ifndef MODEL_H
#define MODEL_H

#include "compat/compat.h"
#include "result/organ.h"
#include "base/expr.h"
#include "base/table.h"

/*
 * What a model sees of the scene: the top-level settings it uses, its
 * own group's settings, and where to send messages and progress.  The
 * pipeline builds it (scene_model_ctx(), pipeline/); a model never sees the
 * scene itself.
 */
struct model_ctx {
	const void	*params;	/* its group, as its table describes */
	const char	*file;		/* the scene file, named in messages */
	long long	 count;		/* organs asked for, if given */
	int		 count_line;	/* where count was given; 0: not */
	long long	 seed;
	double		 divergence;	/* degrees: given, or the default */
	int		 divergence_line;	/* 0: not given */
	/*
	 * Told now and then by a long placement of the count placed so
	 * far, and once with last set at the end; NULL: nobody watches.
	 */
	void		(*progress)(long long done, int last);
};

/*
 * A model: its name in the scene file, its group of settings (a table
 * over its own parameter struct, which the loader allocates, fills with
 * defaults and frees), and make, the function that places the organs.
 * Adding a model is its file, defining one of these, and a line in
 * models.c.
 */
struct model {
	const char	*name;
	const char	*help;		/* a line for --help */
	const struct table *settings;	/* its group, name = { ... } */
	size_t		 size;		/* of its parameter struct */
	/*
	 * 0 on success, res filled and its svg and rim_last set; -1
	 * after a diagnostic, leaving res empty.
	 */
	int		(*make)(const struct model_ctx *, struct result *);
	int		 needs_count;	/* the scene must give count, ... */
	const char	*count_else;	/* ... or this setting of the group */
	int		 emerges;	/* the angles are found, not given: the
					   model sets rays itself (and divergence
					   does not apply) */
	int		 counts_itself;	/* its organs are its input's, which
					   count_else names: count does
					   not apply */
	/*
	 * Why row k of its table does not apply to params as given, its
	 * other settings leaving it unused ("with inhibition.kernel
	 * \"gaussian\", which has no exponent"); NULL where it applies.
	 * NULL: every row always applies.
	 */
	const char	*(*unused)(const void *params, size_t k);
	/*
	 * The files its settings name and it reads, each given to add()
	 * with what it is, so that -o never names one; params as loaded
	 * from scene (their names are relative to it).  NULL: none.
	 */
	void		(*inputs)(const void *params, const char *scene,
			    void (*add)(const char *path, const char *what));
};

/* Every model, NULL-terminated (models.c); at most MODELS_MAX. */
#define MODELS_MAX	16
extern const struct model *const models[];

const struct model *model_find(const char *name);

/*
 * Run model m as ctx says, once count is there if m needs it; 0, or
 * -1 after a diagnostic.
 */
int	model_run(const struct model *m, const struct model_ctx *,
	    struct result *);

/* A problem with the scene at line (0: at its start); as scene_error(). */
void	model_error(const struct model_ctx *, int line, const char *fmt, ...)
	    PRINTFLIKE(3, 4)
	    ;

/* Evaluate a setting of the group at path for the item ("organ") env->n. */
int	model_eval(const struct model_ctx *, const struct expr_setting *,
	    const char *path, const char *item, struct expr_env *, double *v);

#endif
