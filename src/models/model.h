/* model.h - the models: each checks its settings and fills a result. */
#ifndef MODEL_H
#define MODEL_H

#include "result/organ.h"
#include "scene/scene.h"

/*
 * A model: its name in the scene file, its group of settings (a table
 * over its own parameter struct, which the loader allocates, fills with
 * defaults and frees), and the function that places the organs.  Adding
 * a model is its file, defining one of these, and a line in models.c.
 */
struct receptacle;

struct model {
	const char	*name;
	const char	*help;		/* a line for --help */
	const struct table *settings;	/* its group, name = { ... } */
	size_t		 size;		/* of its parameter struct */
	/* 0 on success; -1 after a diagnostic, leaving res empty. */
	int		(*run)(const struct scene *, const void *params,
			    struct result *);
	enum projection	 svg;
	int		 rim_last;	/* the rim or base is the last organs
					   (planar), not the first */
	int		 emerges;	/* the angles are found, not given: the
					   model sets rays itself */
};

/* Every model, NULL-terminated (models.c); at most MODELS_MAX. */
#define MODELS_MAX	16
extern const struct model *const models[];

const struct model *model_find(const char *name);

/*
 * Run the scene's model and apply its organs entries, leaving a result
 * that carries everything writers need; 0, or -1 after a diagnostic.
 */
int	model_run(const struct scene *, struct result *);

/* The collision model, placing as the tests and benchmarks choose. */
enum place {
	PLACE_EXACT,	/* the exact walk with the cover map: the model */
	PLACE_PLAIN,	/* the exact walk alone */
	PLACE_BRUTE,	/* every earlier primordium at finely spaced t */
	PLACE_CHECK	/* PLACE_EXACT, and --info's "cover misses" counts
			   points of the cover map's cells further from
			   every primordium than their cell's bound (the
			   tests': it must be 0) */
};
int	collision_place(const struct scene *, struct result *, int how);
/*
 * The inhibition model.  how: 0, or INHIB_ALL_PAIRS: the power law
 * summed one by one, no far field (the bench's reference); and/or
 * INHIB_CHECK_BOUNDS: every gap searched too, and --info's "bound
 * misses" counts the gap bounds above the least E found in their gap
 * (the tests': it must be 0).
 */
enum { INHIB_ALL_PAIRS = 1, INHIB_CHECK_BOUNDS = 2 };
int	inhibition_place(const struct scene *, struct result *, int how);

/* The receptacle a collision scene gave, for the tests. */
const struct receptacle *collision_receptacle(const struct scene *);

/*
 * Called now and then by a long-running model with the count placed so
 * far, and once with last set at the end; NULL: nobody is watching.
 */
extern void (*model_progress)(long long done, int last);

/* Apply the scene's organs entries to placed organs; 0 or -1. */
int	organs_apply(const struct scene *, struct result *);

/*
 * Place an organ on a surface of revolution about Z: at angle phi
 * (degrees), radius rho, height z, where the generating curve's tangent
 * pointing away from the tip is (t_rho, t_z).  Then u is that tangent,
 * w the outward normal (the tangent turned a right angle towards the
 * outside), and v = w x u turns counter-clockwise.
 */
void	frame_revolution(struct organ *, double phi, double rho, double z,
	    double t_rho, double t_z);
/* The same with phi's cosine and sine at hand. */
void	frame_revolution_cs(struct organ *, double phi, double c, double s,
	    double rho, double z, double t_rho, double t_z);

/* Stretch the result along x, y, z: positions, frames, heights. */
void	stretch_apply(struct result *, const double k[3]);

/* Whether deg lines count organs up on q rays, deg/360 being near p/q. */
int	divergence_rays(double deg, size_t count, long long *p, long long *q);

/* n * deg reduced to [0, 360), without the rounding of the product. */
double	angle_mod360(double n, double deg);

#endif
