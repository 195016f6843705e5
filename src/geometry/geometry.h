/* geometry.h - small geometric facts shared by the models: frames, angles. */
#ifndef GEOMETRY_H
#define GEOMETRY_H

#include <stddef.h>

#include "result/organ.h"

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
/*
 * The same on a head whose centre stands dome above its rim, a circle
 * of radius rim, as a paraboloid: z = dome (1 - (rho / rim)^2), the
 * tip at the centre.  A flat head has dome 0.
 */
void	frame_dome(struct organ *, double phi, double rho, double rim,
	    double dome);

/* Stretch the result along x, y, z: positions, frames, heights. */
void	stretch_apply(struct result *, const double k[3]);

/* Whether deg lines count organs up on q rays, deg/360 being near p/q. */
int	divergence_rays(double deg, size_t count, long long *p, long long *q);

/* n * deg reduced to [0, 360), without the rounding of the product. */
double	angle_mod360(double n, double deg);

#endif
