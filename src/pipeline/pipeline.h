/*
 * pipeline.h - a loaded scene run: made into what its model sees, the
 * model run, the organs dressed by the organs entries, and a compound's
 * parts composed into the structures that place them.  Above the loader
 * (scene/), which only reads and checks.
 */
#ifndef PIPELINE_H
#define PIPELINE_H

#include "scene/compound.h"

struct model_ctx;

/* What the scene's model sees (model.h); progress may be NULL. */
void	 scene_model_ctx(const struct scene *, struct model_ctx *,
	    void (*progress)(long long done, int last));
/*
 * Run the scene's model, then apply its organs entries, leaving a
 * result that carries everything writers need (organ.h); progress, if
 * not NULL, is told of a long placement.  0, or -1 after a diagnostic.
 */
int	 scene_run(const struct scene *, struct result *,
	    void (*progress)(long long done, int last));
/* Apply the scene's organs entries to placed organs (organs.c); 0 or -1. */
int	 organs_apply(const struct scene *, struct result *);
/*
 * Run every scene of a compound, parts first, and link the parts;
 * progress, if not NULL, is told of long placements (model.h).  0 or -1.
 */
int	 compound_run(struct compound *, const struct frame *fr,
	    void (*progress)(long long done, int last));

#endif
