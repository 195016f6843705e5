/* phyllo.h - facts of the whole program, each said once. */
#ifndef PHYLLO_H
#define PHYLLO_H

/* The Makefile passes the version from its VERSION line. */
#ifndef VERSION
#define VERSION		"0.0"
#endif

/* Where make install puts the templates: the Makefile passes it. */
#ifndef SHAREDIR
#define SHAREDIR	"/usr/local/share/phyllo-export"
#endif

/* 360 (2 - tau), tau the golden ratio: the default divergence, degrees. */
#define GOLDEN_ANGLE	137.50776405003785

#define NAME_LEN	32	/* longest name or organ object name */

/*
 * The hue of organ object k in every preview (SVG, POV-Ray and Blender
 * placeholders), degrees: a golden angle apart, so any number of
 * objects stay told apart.
 */
#define OBJECT_HUE(k)	(40 + GOLDEN_ANGLE * (double)(k) - \
	360 * (double)(unsigned long long)((40 + GOLDEN_ANGLE * (double)(k)) / 360))

#endif
