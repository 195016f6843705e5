/* scene.h - a scene file, loaded and checked against the settings table. */
#ifndef SCENE_H
#define SCENE_H

#include <stdio.h>

#include "compat/compat.h"
#include "base/expr.h"
#include "result/organ.h"
#include "base/table.h"

#define SCENE_BYTES_MAX	(16L * 1024 * 1024)
#define SCENE_PATH_MAX	1024		/* bytes in a sub-scene's file name */

#define RANGES_MAX	1024		/* entries in organs */

/* One entry of organs = ( ... ): an index range and what its organs are. */
enum { RG_FROM, RG_TO, RG_OBJECT, RG_WEIGHTS, RG_SCENE, RG_MESH, RG_SCALE,
	RG_ALTITUDE, RG_TILT, RG_ROLL, RG__N };

struct organ_range {
	struct group_at	 at;
	int		 given[RG__N];
	long long	 from, to;	/* inclusive; to = -1: the last */
	char		(*names)[NAME_LEN + 1];	/* object variants, owned */
	size_t		 nnames;
	unsigned	*ids;		/* names as indices into objects */
	double		*weights;	/* one per name, or NULL */
	size_t		 nweights;
	struct file_list scenes;	/* one per name, or none */
	struct file_list meshes;	/* OBJ files, one per name, or none */
	struct expr_setting scale, altitude, tilt, roll;
};

/* The top-level settings (settings.c), by row. */
enum { S_NAME, S_MODEL, S_DIVERGENCE, S_COUNT, S_SEED, S_STRETCH, S_ORGANS,
	S__N };

struct model;

struct scene {
	struct group_at	 at;
	int		 given[S__N];
	const char	*file;		/* as named in messages */
	char		 name[NAME_LEN + 1];
	const struct model *model;
	double		 divergence;	/* degrees */
	long long	 count;
	long long	 seed;
	double		 stretch[3];	/* x, y, z factors of the result */
	void		*params;	/* the model's own, owned */
	struct organ_range *ranges;	/* owned */
	size_t		 nranges;
	const char	**objects;	/* distinct organ object names */
	const char	**object_scene;	/* for each: its scene file as
					   written, or NULL (a plain object) */
	int		*object_line;	/* for each: the entry naming it */
	const char	**object_mesh;	/* for each: its OBJ file as
					   written, or NULL */
	int		*object_mesh_line;	/* for each: where given */
	size_t		 nobjects;
	double		 frame_f;	/* f: 0 .. 1 over the frames */
	int		 frame_no;	/* F: the frame's number, from 1 */
	struct written	*written;	/* with loading.record; owned */
	size_t		 nwritten;
	char		*text;		/* with loading.record: the file */
	size_t		 len;
};

/* Which frame of how many a scene is loaded for: f and F in it. */
struct frame {
	int		 number;	/* F, 1 .. count */
	int		 count;
};

struct override;

/*
 * How a run loads every scene it reads: for which frame (NULL: 1 of 1,
 * so f = 0 and F = 1), with which settings the command line changes
 * (override.h), and whether to keep each setting as written (record,
 * for --settings and --cfg).
 */
struct loading {
	const struct frame *frame;
	struct override	*set;
	int		 nset;
	int		 record;
	/*
	 * A listing (--settings): a setting given that the scene's
	 * others leave unused is kept, to be listed as such, not refused.
	 */
	int		 listing;
};

/* A setting as the scene (or --set) wrote it. */
struct written {
	char		*path;		/* "planar.scale", "organs.1.tilt" */
	char		*text;		/* its value in scene-file syntax */
	int		 line;		/* where: a line, or an override's
					   (DIAG_LINE_SET + k) */
	int		 dropped;	/* given by the file, left unused by a
					   --set: --cfg takes it out */
};

extern const struct table scene_table;

int	 scene_load(struct scene *, const char *path);
int	 scene_load_buffer(struct scene *, const char *file,
	    const char *text, size_t len);
/* The same as a run loads it, the scene making object ("" the main). */
int	 scene_load_as(struct scene *, const char *path, const char *object,
	    const struct loading *);
int	 scene_load_buffer_as(struct scene *, const char *file,
	    const char *text, size_t len, const char *object,
	    const struct loading *);
void	 scene_free(struct scene *);
/*
 * Whether row k of tab (the top level's or the model's) applies to the
 * scene as loaded; if not, why, into why[sz] ("to model \"inhibition\",
 * whose angle emerges").  Such a setting given is an error (or, made
 * so by a --set, ignored: scene_tables.c), and --settings lists it as
 * not applying.
 */
int	 scene_applies(const struct scene *, const struct table *tab,
	    size_t k, char *why, size_t sz);

void	 scene_error(const struct scene *, int line, const char *fmt, ...)
	    PRINTFLIKE(3, 4)
	    ;

#endif
