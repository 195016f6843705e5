/* model.h - the models: each checks its settings and fills a result. */
#ifndef MODEL_H
#define MODEL_H

#include "organ.h"
#include "scene.h"

/* 0 on success; -1 after a diagnostic, leaving res empty. */
typedef int model_fn(const struct scene *, struct result *res);

model_fn planar_run;
model_fn cylindrical_run;
model_fn collision_run;

/* The collision model, placing as the tests and benchmarks choose. */
enum place {
	PLACE_EXACT,	/* the exact walk with the cover map: the model */
	PLACE_PLAIN,	/* the exact walk alone */
	PLACE_BRUTE	/* every earlier primordium at finely spaced t */
};
int	collision_place(const struct scene *, struct result *, int how);

/*
 * Called now and then by a long-running model with the count placed so
 * far, and once with last set at the end; NULL: nobody is watching.
 */
extern void (*model_progress)(long long done, int last);

/* Apply the scene's organs entries to placed organs; 0 or -1. */
int	organs_apply(const struct scene *, struct result *);

/* The contact parastichy numbers seen from organ k, sorted; 0 if none. */
void	parastichies(const struct result *, size_t k, int pair[2]);

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

/* n * deg reduced to [0, 360), without the rounding of the product. */
double	angle_mod360(double n, double deg);

#endif
