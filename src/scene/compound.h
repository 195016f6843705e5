/*
 * compound.h - a scene and the scenes its organs are made of.  An organs
 * entry with scene = "floret.cfg" makes its object a part: a structure
 * of its own, placed once per organ like any object.  A compound is
 * every scene of the tree, loaded and run, each part once: loaded
 * here, run by the pipeline (pipeline/pipeline.h).
 */
#ifndef COMPOUND_H
#define COMPOUND_H

#include "result/organ.h"
#include "scene/scene.h"

#define COMPOUND_DEPTH_MAX	16	/* scenes in one chain of includes */
#define COMPOUND_PARTS_MAX	256	/* parts in one compound */

struct part {
	struct scene	 sc;
	struct result	 res;
	char		*file;		/* the path opened, for messages */
	char		 object[NAME_LEN + 1];	/* it makes; "" the main */
	const char	*from;		/* the scene including it, and where */
	int		 from_line;
};

struct compound {
	struct part	**parts;	/* each after the parts it uses, the
					   main scene last */
	size_t		 n;
};

/*
 * Load the scene at path and every scene it includes as ld says (NULL:
 * frame 1 of 1, nothing changed), checking each with check (a writer's,
 * or NULL).  0, or -1 after a diagnostic; the compound is to be freed
 * either way.
 */
int	compound_load(struct compound *, const char *path,
	    const struct loading *ld, int (*check)(const struct scene *));
void	compound_free(struct compound *);
/* The part making object, or NULL: none does. */
struct part *compound_part(const struct compound *, const char *object);

static inline const struct result *
compound_main(const struct compound *c)
{
	return &c->parts[c->n - 1]->res;
}

#endif
