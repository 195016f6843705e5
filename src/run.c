/*
 * run.c - one run: every frame of the scene made and written.
 *
 * Before a byte is written the run knows about how much it will write:
 * the first and the last frame are made and their sizes estimated
 * (plan_bytes()), and the frames between are taken to lie between them,
 * as they do when a count or a radius grows with f.  An output over
 * --max-output is refused then, with the estimate.  While writing, the
 * limit holds whatever the estimate said: a block that would pass it is
 * not written (sink.c), and the run stops.
 *
 * Memory holds one frame.  A format that writes each frame to its own
 * file writes a frame and frees it.  One that writes every frame into
 * one file (the Blender script) writes its template's head, then each
 * frame's @@structures block as the frame is made, then the tail.  The
 * head and tail speak of the last frame (the script's first lines give
 * the final organ count), so the last frame is made first, for them and
 * for the estimate, and again in its turn.
 *
 * -o never names what the run reads: the scene, its parts' scenes, the
 * template, the organ meshes, a model's own input (a points file); that
 * is checked before anything is written.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene/compound.h"
#include "base/diag.h"
#include "base/inputs.h"
#include "meshes/meshes.h"
#include "models/model.h"
#include "writers/output.h"
#include "scene/override.h"
#include "pipeline/pipeline.h"
#include "writers/plan.h"
#include "run.h"

/* A frame made: its structures, and what its writer writes of them. */
struct made {
	struct compound	 c;
	struct plan	 p;
	struct meshes	 ms;		/* for writers reading meshes */
};

#define MADE_NONE	{ { NULL, 0 }, { NULL, 0, NULL, 0 }, { NULL, 0, 0 } }

static int
make(const struct job *j, int F, struct made *m)
{
	struct frame fr = { F, j->frames };
	struct loading ld = { .frame = j->frames ? &fr : NULL, .set = j->set,
	    .nset = j->nset };
	char what[96];
	int rc;

	/* A message must say which frame, or "count -100" is a riddle. */
	if (j->frames > 1) {
		snprintf(what, sizeof(what), "frame %d of %d (f = %.9g)", F,
		    j->frames, (double)(F - 1) / (j->frames - 1));
		diag_context(what);
	}
	m->p = (struct plan){ NULL, 0, NULL, 0 };
	rc = compound_load(&m->c, j->scene, &ld, j->writer->check) != 0 ? -1 :
	    compound_run(&m->c, j->frames ? &fr : NULL, j->placed);
	diag_context(NULL);
	/*
	 * The meshes are the same in every frame, so their messages name
	 * none, and the first frame made (the last, or the only) says
	 * which objects have none.
	 */
	if (rc == 0 && (j->writer->opts & (TO_MESHES | TO_SIZES)))
		rc = meshes_load(&m->ms, &m->c, (j->writer->opts & TO_MESHES ?
		    0 : MESH_SIZES) | ((j->writer->opts & TO_MESHES) &&
		    F == (j->frames ? j->frames : 1) ? MESH_WARN : 0));
	if (rc == 0)
		plan_make(&m->p, j->writer, j->tmpl, compound_main(&m->c));
	return rc;
}

/* Every --set OBJECT:PATH must have found its part. */
static int
overrides_used(const struct job *j, const struct compound *c)
{
	char parts[256];
	size_t len = 0;

	for (int k = 0; k < j->nset; k++) {
		if (j->set[k].used)
			continue;
		parts[0] = '\0';
		for (size_t i = 0; i < c->n && len < sizeof(parts); i++)
			if (c->parts[i]->object[0] != '\0')
				len += (size_t)snprintf(parts + len,
				    sizeof(parts) - len, "%s%s", len ? ", " : "",
				    c->parts[i]->object);
		diag(ST_USAGE, NULL, 0, 0, "--set %s: no organ object \"%s\" "
		    "is made of a scene (%s%s)", j->set[k].arg,
		    j->set[k].object, len ? "the parts: " : "this structure "
		    "has no parts", parts);
		return -1;
	}
	return 0;
}

/*
 * A divergence given so near a fraction p/q of a turn that organs line
 * up on q rays instead of spirals is rarely what was meant (137.5 is
 * 55/144): said once a run, whatever the format, where the user looks.
 * One that emerged (the inhibition model's 180 degrees, alternate
 * leaves) is the model's answer, not a slip.
 */
static void
warn_rays(const struct compound *c, int *warned)
{
	const struct part *main = c->parts[c->n - 1];
	const struct result *r = &main->res;

	if (*warned || r->rays == 0 || !main->sc.given[S_DIVERGENCE])
		return;
	*warned = 1;
	diag(ST_OK, main->sc.file, main->sc.given[S_DIVERGENCE], 0,
	    "divergence %.9g is %lld/%lld of a turn: from organ %lld on, "
	    "organs line up on %lld rays instead of spirals", r->divergence,
	    r->rays_p, r->rays, r->rays, r->rays);
}

/* Free a frame; again is harmless. */
static void
unmake(struct made *m)
{
	plan_free(&m->p);
	meshes_free(&m->ms);
	compound_free(&m->c);
}

static const char *
scene_name(const struct job *j)
{
	return strcmp(j->scene, "-") == 0 ? "<stdin>" : j->scene;
}

void
run_size_words(char *buf, size_t sz, double bytes)
{
	static const char *const units[] = { "bytes", "KiB", "MiB", "GiB",
	    "TiB", "PiB", "EiB" };
	int u = 0;

	while (bytes >= 1024 && u < 6) {
		bytes /= 1024;
		u++;
	}
	/* Three digits at most, and no trailing zeros: "4 GiB", "3.7 GiB". */
	snprintf(buf, sz, "%.*f", u == 0 || bytes >= 100 ? 0 :
	    bytes >= 10 ? 1 : 2, bytes);
	if (strchr(buf, '.') != NULL) {
		size_t n = strlen(buf);

		while (buf[n - 1] == '0')
			buf[--n] = '\0';
		if (buf[n - 1] == '.')
			buf[n - 1] = '\0';
	}
	snprintf(buf + strlen(buf), sz - strlen(buf), " %s", units[u]);
}

/* The --max-output that lets bytes through: "952G". */
static void
allowing(char *buf, size_t sz, double bytes)
{
	int u = 0;

	while (bytes >= 1024 && u < 6) {
		bytes /= 1024;
		u++;
	}
	snprintf(buf, sz, "%.0f%.*s", ceil(bytes * 1.0001), u > 0,
	    &"KMGTPE"[u > 0 ? u - 1 : 0]);
}

/* An output over the limit, refused before a byte of it is written. */
static int
within_limit(const struct job *j, double bytes)
{
	char est[32], lim[32], need[32], frames[32] = "";

	if (j->max_output <= 0 || bytes <= j->max_output)
		return 0;
	run_size_words(est, sizeof(est), bytes);
	run_size_words(lim, sizeof(lim), j->max_output);
	allowing(need, sizeof(need), bytes);
	if (j->frames > 1)
		snprintf(frames, sizeof(frames), " in %d frames", j->frames);
	diag(ST_SCENE, scene_name(j), 0, 0, "the output would be about "
	    "%s%s, over the limit of %s: --max-output %s allows it", est,
	    frames, lim, need);
	return -1;
}

/* What the run reads, which -o must not name. */
static void
inputs(const struct job *j, const struct compound *c)
{
	char what[NAME_LEN + 48];

	if (strcmp(j->scene, "-") != 0)
		input_add(j->scene, "the scene file");
	if (j->template_path != NULL)
		input_add(j->template_path, "the template in use");
	tmpl_shipped_inputs();
	for (size_t i = 0; i < c->n; i++) {
		if (c->parts[i]->object[0] == '\0')
			continue;
		snprintf(what, sizeof(what), "the scene of organ object \"%s\"",
		    c->parts[i]->object);
		input_add(c->parts[i]->file, what);
	}
	/* A model's own inputs (the measured model's points file). */
	for (size_t i = 0; i < c->n; i++)
		if (c->parts[i]->sc.model->inputs != NULL)
			c->parts[i]->sc.model->inputs(c->parts[i]->sc.params,
			    c->parts[i]->file, input_add);
	meshes_inputs(c);
}

/* Every file the run writes: none of them may be an input. */
static int
outputs_clear(const struct job *j, int each_frame)
{
	char path[4096];

	if (!each_frame)
		return output_check(j->output);
	for (int F = 1; F <= j->frames; F++)
		if (output_frame_path(j->output, F, path, sizeof(path)) != 0 ||
		    output_check(path) != 0)
			return -1;
	return 0;
}

/* End a file: 0, or -1 after a diagnostic with everything removed. */
static int
finish(const struct job *j, struct sink *s, const char *path)
{
	char lim[32], est[32], need[32];

	if (sink_finish(s) == 0)
		return output_close();
	if (s->budget != NULL && s->budget->over) {
		run_size_words(lim, sizeof(lim), s->budget->limit);
		run_size_words(est, sizeof(est), s->budget->expected);
		allowing(need, sizeof(need), 2 * s->budget->limit);
		diag(ST_SCENE, scene_name(j), 0, 0, "the output passed the "
		    "limit of %s while being written (it was estimated at %s), "
		    "so it was stopped: --max-output %s allows more", lim, est,
		    need);
	} else
		diag(ST_SYSTEM, path != NULL ? path : "<stdout>", 0, 0, "%s",
		    strerror(errno));
	output_abort();
	return -1;
}

/* Frame m as a whole file at path (NULL: standard output). */
static int
write_whole(const struct job *j, const char *path, const struct made *m,
    struct budget *b)
{
	FILE *fp = output_open(path);
	struct sink s;
	int rc;

	if (fp == NULL)
		return -1;
	sink_init(&s, fp);
	s.budget = b;
	if (j->tmpl != NULL)
		tmpl_write(j->tmpl, &s, m->p.all, m->p.n, j->opts);
	else
		j->writer->write(&s, m->p.all[m->p.n - 1], j->opts);
	rc = finish(j, &s, path);
	sink_free(&s);
	return rc;
}

/* Each frame to its own file; first is frame 1, made already. */
static int
write_each(const struct job *j, struct made *first, struct budget *b)
{
	char path[4096];
	int N = j->frames ? j->frames : 1;

	for (int F = 1; F <= N; F++) {
		struct made m = MADE_NONE;
		struct made *now = F == 1 ? first : &m;
		int rc = F > 1 ? make(j, F, &m) : 0;

		if (rc == 0 && j->frames)
			rc = output_frame_path(j->output, F, path,
			    sizeof(path));
		if (rc == 0)
			rc = write_whole(j, j->frames ? path : j->output, now, b);
		unmake(now);
		if (rc != 0)
			return -1;
	}
	return 0;
}

/*
 * Every frame into one file: the head, each frame's @@structures block
 * as it is made, the tail.  first is frame 1, made already.
 */
static int
write_together(const struct job *j, struct made *first,
    const struct sink *head, const struct sink *tail, struct budget *b)
{
	FILE *fp = output_open(j->output);
	struct sink s;
	int rc = 0;

	if (fp == NULL)
		return -1;
	sink_init(&s, fp);
	s.budget = b;
	sink_write(&s, head->buf, head->len);
	for (int F = 1; F <= j->frames && rc == 0 && s.err == 0; F++) {
		struct made m = MADE_NONE;
		struct made *now = F == 1 ? first : &m;

		if ((rc = F > 1 ? make(j, F, &m) : 0) == 0)
			tmpl_write_piece(j->tmpl, TMPL_BODY, &s, now->p.all,
			    now->p.n, j->opts);
		unmake(now);
	}
	if (rc != 0) {
		output_abort();
		sink_free(&s);
		return -1;
	}
	sink_write(&s, tail->buf, tail->len);
	rc = finish(j, &s, j->output);
	sink_free(&s);
	return rc;
}

/* The head and tail of one file of every frame, from frame m. */
static void
head_and_tail(const struct job *j, const struct made *m, struct sink *head,
    struct sink *tail)
{
	tmpl_write_piece(j->tmpl, TMPL_HEAD, head, m->p.all, m->p.n, j->opts);
	tmpl_write_piece(j->tmpl, TMPL_TAIL, tail, m->p.all, m->p.n, j->opts);
}

/*
 * A format of the scenes as read (--settings, --cfg): the compound is
 * loaded, keeping every setting as written, and nothing is placed.
 */
static int
run_scenes(const struct job *j)
{
	struct loading ld = { .set = j->set, .nset = j->nset, .record = 1,
	    .listing = (j->writer->opts & TO_LISTING) != 0 };
	struct compound c;
	struct sink mem, s;
	FILE *fp;
	int rc;

	sink_init(&mem, NULL);
	rc = compound_load(&c, j->scene, &ld, NULL);
	if (rc == 0)
		rc = overrides_used(j, &c);
	if (rc == 0) {
		inputs(j, &c);
		rc = outputs_clear(j, 0);
	}
	if (rc == 0)
		rc = j->writer->scenes(&mem, &c, j->set, j->nset);
	if (rc == 0 && (fp = output_open(j->output)) == NULL)
		rc = -1;
	if (rc == 0) {
		sink_init(&s, fp);
		sink_write(&s, mem.buf, mem.len);
		rc = finish(j, &s, j->output);
		sink_free(&s);
	}
	if (rc == 0)
		rc = output_commit();
	else
		output_abort();
	compound_free(&c);
	sink_free(&mem);
	return rc;
}

int
run(const struct job *j)
{
	int N = j->frames ? j->frames : 1;
	int together = j->frames && (j->writer->opts & TO_ANIMATE) &&
	    j->tmpl != NULL;
	enum tmpl_piece piece = together ? TMPL_BODY : TMPL_ALL;
	struct made first = MADE_NONE, last = first;
	struct sink head, tail;
	struct budget b = { j->max_output, 0, 0, j->told, 0 };
	double bytes_last = 0, bytes;
	int rc = -1, warned = 0;

	if (j->writer->scenes != NULL)
		return run_scenes(j);
	if (together && tmpl_structures(j->tmpl) > 1) {
		diag(ST_SCENE, j->template_path != NULL ? j->template_path :
		    j->writer->tmpl, 0, 0, "%d @@structures blocks: with "
		    "--frames a template has one, written frame by frame",
		    tmpl_structures(j->tmpl));
		return -1;
	}
	sink_init(&head, NULL);
	sink_init(&tail, NULL);
	if (N > 1) {
		if (make(j, N, &last) != 0)
			goto out;
		warn_rays(&last.c, &warned);
		bytes_last = plan_bytes(&last.p, j->writer, j->tmpl, piece,
		    j->opts);
		if (together)
			head_and_tail(j, &last, &head, &tail);
		unmake(&last);
	}
	if (make(j, 1, &first) != 0 || overrides_used(j, &first.c) != 0)
		goto out;
	warn_rays(&first.c, &warned);
	if (together && N == 1)
		head_and_tail(j, &first, &head, &tail);
	if (j->tmpl != NULL && !tmpl_structures(j->tmpl) &&
	    compound_main(&first.c)->sub != NULL)
		diag(ST_OK, NULL, 0, 0, "the template has no @@structures "
		    "block: the parts of the structure are written as "
		    "placeholders");
	bytes = plan_bytes(&first.p, j->writer, j->tmpl, piece, j->opts);
	if (N > 1)
		bytes = N * (bytes + bytes_last) / 2;
	bytes += (double)(head.len + tail.len);
	b.expected = bytes;
	inputs(j, &first.c);
	if (outputs_clear(j, j->frames && !together) != 0)
		goto out;
	if (within_limit(j, bytes) != 0)
		goto out;
	rc = together ? write_together(j, &first, &head, &tail, &b) :
	    write_each(j, &first, &b);
	if (rc == 0)
		rc = output_commit();
out:
	if (rc != 0)
		output_abort();
	unmake(&last);
	unmake(&first);
	sink_free(&head);
	sink_free(&tail);
	meshes_forget();
	return rc;
}
