/* cylindrical_lattice.h - van Iterson's circles packed on a cylinder. */
#ifndef CYL_H
#define CYL_H

/*
 * Everything on a cylinder of radius 1 (circumference 2 pi), as in
 * ABOP's Table 4.1; angles in degrees, folded into (0, 180] (a
 * divergence alpha and 360 - alpha make mirror images of one pattern).
 */

/* The encyclic numbers of a coprime pair: n dm - m dn = +-1, smallest. */
int	cyl_encyclic(int m, int n, int *dm, int *dn);

/* The triple-contact pattern (m, n, m + n): divergence, rise, diameter. */
void	cyl_triple(int m, int n, double *alpha, double *h, double *d);

/* The divergences for which (m, n) is the opposed contact pair. */
void	cyl_range(int m, int n, double *lo, double *hi);

/* Rise and diameter for (m, n) at divergence alpha; -1 if not opposed. */
int	cyl_pair(int m, int n, double alpha, double *h, double *d);

/* The opposed contact pair of the pattern (alpha, h), and its d. */
int	cyl_contacts(double alpha, double h, int *m, int *n, double *d);

/* alpha folded into (0, 180]. */
double	cyl_fold(double alpha);

#endif
