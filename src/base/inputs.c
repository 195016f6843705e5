/*
 * inputs.c - the files a run reads, by identity, so that -o's check
 * (output.c) knows another path or a link to one for the same file.
 * Here, below the loader, the models and the meshes that find them.
 */
#include <stdlib.h>

#include "base/inputs.h"
#include "base/mem.h"
#include "compat/compat.h"

/* A file read, by identity: another path or a link is the same file. */
struct input {
	struct sys_id	 id;
	char		*path, *what;
};

static struct input *inputs;
static size_t ninputs;

static void
free_inputs(void)
{
	for (size_t i = 0; i < ninputs; i++) {
		free(inputs[i].path);
		free(inputs[i].what);
	}
	free(inputs);
	inputs = NULL;
	ninputs = 0;
}

void
input_add(const char *path, const char *what)
{
	struct sys_stat st;

	if (sys_stat(path, &st) != 0)
		return;
	if (inputs == NULL)
		atexit(free_inputs);
	inputs = xreallocarray(inputs, ninputs + 1, sizeof(*inputs));
	inputs[ninputs++] = (struct input){ st.id, xstrdup(path),
	    xstrdup(what) };
}

int
input_find(const struct sys_id *id, const char **path, const char **what)
{
	for (size_t i = 0; i < ninputs; i++)
		if (SYS_SAME(inputs[i].id, *id)) {
			*path = inputs[i].path;
			*what = inputs[i].what;
			return 1;
		}
	return 0;
}
