/*
 * override.h - settings given on the command line, --set
 * [OBJECT:]PATH=VALUE, put into each scene file as it is read, so that
 * the loader checks them as if they were written there.
 */
#ifndef OVERRIDE_H
#define OVERRIDE_H

#include "base/phyllo.h"
#include "base/table.h"

struct override {
	const char	*arg;			/* as given */
	char		 object[NAME_LEN + 1];	/* the part's object, or ""
						   for the main scene */
	char		 path[PATH_LEN];	/* "planar.scale", "organs.1.tilt" */
	const char	*value;			/* in scene-file syntax, in arg */
	int		 used;			/* put into some scene */
};

/* Read --set's argument; 0, or -1 after a usage error naming it. */
int	override_parse(const char *arg, struct override *);

struct config_setting_t;

/*
 * Put the overrides meant for the scene making object ("" the main one)
 * into its settings; the k-th gets line DIAG_LINE_SET + k (diag.h), so
 * that messages name it.  0, or -1 after a usage error.
 */
int	override_apply(struct config_setting_t *root, struct override *set,
	    int n, const char *object);

#endif
