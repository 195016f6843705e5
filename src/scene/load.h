/*
 * load.h - what the scene loader's files share: struct load, one load
 * under way, and the functions that cross them (scene.c loads a file
 * as a whole, scene_tables.c walks a settings table over its struct,
 * scene_values.c reads one value by its row's type).
 */
#ifndef SCENE_LOAD_H
#define SCENE_LOAD_H

#include <libconfig.h>
#include <stddef.h>

#include "compat/compat.h"
#include "models/model.h"
#include "base/expr.h"
#include "base/table.h"

struct scene;

struct load {
	struct scene	*sc;
	const char	*file;
	const char	*text;		/* the file as written, for columns */
	size_t		 len;
	struct expr_const consts[3];	/* f and F, for every expression */
	const char	*object;	/* the part it makes, or "" */
	int		 record;	/* keep each setting as written */
	int		 listing;	/* keep a given one left unused */
	int		 overridden;	/* --set given */
	int		 alone;		/* the file without it: 1 loads, -1
					   does not, 0 not tried yet */
};

static inline int
load_line(const config_setting_t *s)
{
	return (int)config_setting_source_line(s);
}

/* scene_values.c */
void	 load_err_at(const struct load *, const config_setting_t *,
	    const char *fmt, ...)
	    PRINTFLIKE(3, 4)
	    ;
void	 load_words_join(char *buf, size_t sz, const char *const *words);
void	 load_model_names(const char *words[MODELS_MAX + 1]);
int	 load_model(struct load *, const config_setting_t *,
	    const char *path, const struct model **dst);
int	 load_setting_as(struct load *, const config_setting_t *,
	    const char *path, const struct row *, void *base);

/* scene_tables.c */
void	 load_defaults(const struct table *, void *base);
void	 load_paths(const struct table *, void *base, const char *path);
void	 load_free_settings(const struct table *, void *base);
void	 load_record(struct load *, const config_setting_t *);
int	 load_group(struct load *, const config_setting_t *,
	    const char *path, const struct table *, void *base);
int	 load_ranges(struct load *, const config_setting_t *,
	    const char *path, const struct table *);
int	 load_check_applies(struct load *);

#endif
