/*
 * template.c - the template engine behind --pov and --blender.
 *
 * A template is the output file with @NAME@ placeholders, and blocks
 * repeated per organ object or per organ:
 *
 *	#declare @NAME@ = union {
 *	@@organs
 *	  object { @OBJECT@ matrix @MATRIX@ }
 *	@@end
 *	}
 *
 * A compound structure is written by a @@structures block, once for
 * each of its structures (the parts first, so each is declared before
 * it is used; frame by frame for --blender --frames), with @@part and
 * @@main blocks written only for a part or only for the main one.
 *
 * Lines starting with @@ are directives (those blocks, @@end, and
 * @@# comments) and are not copied; "@@" within a line writes one "@";
 * any other "@" is copied as it is.  The template is parsed once and
 * every placeholder checked before anything is written.  Every value a
 * placeholder gives is a number or a validated identifier, so no scene
 * file can put code into the output.  The placeholders every template
 * has are template_vars.c's; a writer adds its own.
 *
 * Why our own: the Debian template engines are for web pages (ctemplate
 * is C++, mustache implementations escape for HTML); ours is one small
 * file with error lines, and a per-organ loop that costs nothing.
 */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat/compat.h"
#include "base/diag.h"
#include "result/flatten.h"
#include "base/inputs.h"
#include "base/mem.h"
#include "base/phyllo.h"
#include "scene/suggest.h"
#include "writers/template.h"


enum seg_kind { SEG_TEXT, SEG_VAR, SEG_BEGIN, SEG_END };

/* The blocks: three loops and two conditions. */
enum block { B_STRUCTURES, B_OBJECTS, B_ORGANS, B_PART, B_MAIN };

static const char *const block_words[] = {
	[B_STRUCTURES] = "structures", [B_OBJECTS] = "objects",
	[B_ORGANS] = "organs", [B_PART] = "part", [B_MAIN] = "main"
};
#define NBLOCKS	(sizeof(block_words) / sizeof(block_words[0]))
#define NEST_MAX	4	/* structures > part > organs > main, at most */

struct seg {
	enum seg_kind		 kind;
	const char		*text;		/* SEG_TEXT */
	size_t			 len;
	const struct tmpl_var	*var;		/* SEG_VAR */
	enum block		 block;		/* SEG_BEGIN */
	size_t			 end;		/* SEG_BEGIN: its SEG_END */
};

struct tmpl {
	char		*text;		/* owned; segments point into it */
	struct seg	*segs;
	size_t		 nsegs, cap;
	int		 structures;	/* its @@structures blocks */
	size_t		 body;		/* the first one's SEG_BEGIN */
};

/* The blocks open while parsing, outermost first. */
struct open {
	size_t		 seg[NEST_MAX];
	int		 line[NEST_MAX];
	int		 n;
};

static const struct tmpl_var *
var_find(const struct tmpl_var *extra, const char *name, size_t len)
{
	const struct tmpl_var *lists[2] = { extra, tmpl_common };

	for (int i = 0; i < 2; i++)
		for (const struct tmpl_var *v = lists[i]; v && v->name; v++)
			if (strlen(v->name) == len &&
			    strncmp(v->name, name, len) == 0)
				return v;
	return NULL;
}

static struct seg *
seg_add(struct tmpl *t, enum seg_kind kind)
{
	if (t->nsegs == t->cap)
		t->segs = xreallocarray(t->segs, t->cap = t->cap * 2 + 16,
		    sizeof(*t->segs));
	t->segs[t->nsegs] = (struct seg){ .kind = kind };
	return &t->segs[t->nsegs++];
}

/* Copy text through; neighbouring runs become one segment. */
static void
text_add(struct tmpl *t, const char *p, size_t len)
{
	struct seg *last = t->nsegs ? &t->segs[t->nsegs - 1] : NULL;

	if (len == 0)
		return;
	if (last != NULL && last->kind == SEG_TEXT &&
	    last->text + last->len == p) {
		last->len += len;
		return;
	}
	last = seg_add(t, SEG_TEXT);
	last->text = p;
	last->len = len;
}

/* The placeholders' scope inside the open blocks: the innermost loop's. */
static int
scope_of(const struct tmpl *t, const struct open *o)
{
	for (int i = o->n - 1; i >= 0; i--) {
		enum block b = t->segs[o->seg[i]].block;

		if (b == B_ORGANS)
			return TS_ORGAN;
		if (b == B_OBJECTS)
			return TS_OBJECT;
	}
	return TS_GLOBAL;
}

/*
 * A directive line: a block's start (@@structures, @@objects, @@organs,
 * @@part, @@main), @@end, or an @@# comment.  @@structures stands only
 * at the top; @@objects and @@organs not inside each other.
 */
static int
directive(struct tmpl *t, const char *file, int line, const char *p,
    size_t len, struct open *o)
{
	const char *w = p + 2;
	size_t wl = len - 2, b;

	while (wl > 0 && isspace((unsigned char)w[wl - 1]))
		wl--;
	if (wl > 0 && w[0] == '#')
		return 0;
	if (wl == 3 && strncmp(w, "end", 3) == 0) {
		if (o->n == 0) {
			diag(ST_SCENE, file, line, 0, "@@end without a block "
			    "to end");
			return -1;
		}
		t->segs[o->seg[--o->n]].end = t->nsegs;
		seg_add(t, SEG_END);
		return 0;
	}
	for (b = 0; b < NBLOCKS; b++)
		if (strlen(block_words[b]) == wl &&
		    strncmp(w, block_words[b], wl) == 0)
			break;
	if (b == NBLOCKS) {
		const char *words[NBLOCKS + 1], *near;
		char typed[48];

		for (b = 0; b < NBLOCKS; b++)
			words[b] = block_words[b];
		words[NBLOCKS] = "end";
		snprintf(typed, sizeof(typed), "%.*s", (int)(wl > 40 ? 40 : wl),
		    w);
		near = suggest(typed, words, NBLOCKS + 1);
		diag(ST_SCENE, file, line, 0, "unknown directive '@@%s'%s%s%s: "
		    "@@structures, @@objects, @@organs, @@part, @@main, @@end "
		    "or an @@# comment", typed, near ? " (did you mean @@" : "",
		    near ? near : "", near ? "?)" : "");
		return -1;
	}
	if ((b == B_STRUCTURES && o->n > 0) ||
	    ((b == B_OBJECTS || b == B_ORGANS) && scope_of(t, o) !=
	    TS_GLOBAL) || o->n == NEST_MAX) {
		diag(ST_SCENE, file, line, 0, "@@%s inside @@%s: %s",
		    block_words[b], block_words[t->segs[o->seg[o->n - 1]].block],
		    b == B_STRUCTURES ? "@@structures stands only at the top" :
		    o->n == NEST_MAX ? "blocks nested too deeply" :
		    "@@objects and @@organs do not nest");
		return -1;
	}
	if (b == B_STRUCTURES && t->structures++ == 0)
		t->body = t->nsegs;
	o->seg[o->n] = t->nsegs;
	o->line[o->n++] = line;
	seg_add(t, SEG_BEGIN)->block = (enum block)b;
	return 0;
}

/* "unknown placeholder @NAMEE@ (did you mean @NAME@?)" */
static void
unknown_var(const char *file, int line, const char *name, size_t len,
    const struct tmpl_var *extra)
{
	const struct tmpl_var *lists[2] = { extra, tmpl_common };
	const char *words[128], *near;
	char typed[48];
	size_t n = 0;

	for (int i = 0; i < 2; i++)
		for (const struct tmpl_var *v = lists[i]; v && v->name &&
		    n < 128; v++)
			words[n++] = v->name;
	snprintf(typed, sizeof(typed), "%.*s", (int)(len > 40 ? 40 : len),
	    name);
	near = suggest(typed, words, n);
	diag(ST_SCENE, file, line, 0, "unknown placeholder @%s@%s%s%s", typed,
	    near ? " (did you mean @" : "", near ? near : "", near ? "@?)" :
	    "");
}

/* One line of text: copy it, with placeholders and "@@" resolved. */
static int
text_line(struct tmpl *t, const char *file, int line, const char *p,
    const char *next, int scope, const struct tmpl_var *extra)
{
	const char *q = p, *from = p;

	while (q < next) {
		const char *r = q + 1;
		const struct tmpl_var *v;

		if (*q != '@') {
			q++;
			continue;
		}
		if (r < next && *r == '@') {		/* "@@": one "@" */
			text_add(t, from, (size_t)(r - from));
			from = q = r + 1;
			continue;
		}
		while (r < next && (isupper((unsigned char)*r) ||
		    isdigit((unsigned char)*r) || *r == '_'))
			r++;
		if (r == q + 1 || r == next || *r != '@' ||
		    !isupper((unsigned char)q[1])) {
			q++;
			continue;
		}
		if ((v = var_find(extra, q + 1, (size_t)(r - q - 1))) == NULL) {
			unknown_var(file, line, q + 1, (size_t)(r - q - 1),
			    extra);
			return -1;
		}
		if (!(v->scopes & scope)) {
			diag(ST_SCENE, file, line, 0, "@%s@ stands only inside "
			    "%s", v->name, v->scopes == TS_ORGAN ? "@@organs" :
			    v->scopes == TS_OBJECT ? "@@objects" :
			    "@@objects or @@organs");
			return -1;
		}
		text_add(t, from, (size_t)(q - from));
		seg_add(t, SEG_VAR)->var = v;
		from = q = r + 1;
	}
	text_add(t, from, (size_t)(next - from));
	return 0;
}

struct tmpl *
tmpl_parse(const char *file, const char *text, size_t len,
    const struct tmpl_var *extra)
{
	struct tmpl *t = xcalloc(1, sizeof(*t));
	struct open o = { { 0 }, { 0 }, 0 };
	int line = 1;
	const char *p, *end;

	if (memchr(text, '\0', len) != NULL) {
		diag(ST_SCENE, file, 0, 0, "NUL byte in template");
		free(t);
		return NULL;
	}
	t->text = xmalloc(len + 1);
	memcpy(t->text, text, len);
	t->text[len] = '\0';
	for (p = t->text, end = p + len; p < end; line++) {
		const char *nl = memchr(p, '\n', (size_t)(end - p));
		const char *next = nl != NULL ? nl + 1 : end;
		int rc = next - p >= 2 && p[0] == '@' && p[1] == '@' ?
		    directive(t, file, line, p, (size_t)((nl ? nl : end) - p),
		    &o) :
		    text_line(t, file, line, p, next, scope_of(t, &o), extra);

		if (rc < 0) {
			tmpl_free(t);
			return NULL;
		}
		p = next;
	}
	if (o.n > 0) {
		diag(ST_SCENE, file, o.line[o.n - 1], 0, "@@%s is not closed "
		    "by @@end", block_words[t->segs[o.seg[o.n - 1]].block]);
		tmpl_free(t);
		return NULL;
	}
	return t;
}

struct tmpl *
tmpl_load(const char *path, const struct tmpl_var *extra)
{
	FILE *fp = sys_fopen(path, "rb");
	struct tmpl *t;
	char *buf;
	size_t len;

	if (fp == NULL) {
		diag(ST_SCENE, path, 0, 0, "cannot read template: %s",
		    strerror(errno));
		return NULL;
	}
	buf = xmalloc(TMPL_BYTES_MAX + 1);
	len = fread(buf, 1, TMPL_BYTES_MAX + 1, fp);
	if (ferror(fp) || len > TMPL_BYTES_MAX) {
		if (ferror(fp))
			diag(ST_SCENE, path, 0, 0, "cannot read template: %s",
			    strerror(errno));
		else
			diag(ST_SCENE, path, 0, 0, "template is larger than "
			    "%d bytes", TMPL_BYTES_MAX);
		fclose(fp);
		free(buf);
		return NULL;
	}
	fclose(fp);
	t = tmpl_parse(path, buf, len, extra);
	free(buf);
	return t;
}

/* A template compiled into the program, by its file name in templates/. */
struct tmpl *
tmpl_builtin(const char *name, const struct tmpl_var *extra)
{
	char file[64];

	for (const struct builtin_template *b = builtin_templates;
	    b->name != NULL; b++)
		if (strcmp(b->name, name) == 0) {
			snprintf(file, sizeof(file), "<built-in %s>", name);
			return tmpl_parse(file, (const char *)b->text, b->len,
			    extra);
		}
	diag(ST_SYSTEM, NULL, 0, 0, "no built-in template %s", name);
	return NULL;
}

void
tmpl_shipped_inputs(void)
{
	char path[4096];

	for (const struct builtin_template *b = builtin_templates;
	    b->name != NULL; b++) {
		/* A program that travels (SHAREDIR empty) has none. */
		if (SHAREDIR[0] != '\0') {
			snprintf(path, sizeof(path), "%s/%s", SHAREDIR, b->name);
			input_add(path, "a template phyllo-export installs");
		}
		input_add(b->source, "a template phyllo-export is built "
		    "from");
	}
}

static void	write_run(const struct tmpl *, size_t from, size_t to,
		    struct sink *, struct tmpl_ctx *);

/* An @@organs block being written for each organ result_each() gives. */
struct organs_block {
	const struct tmpl *t;
	size_t		 from, to;
	struct sink	*s;
	struct tmpl_ctx	*in;
};

static void
organ_block(void *ctx, const struct organ *o)
{
	struct organs_block *b = ctx;

	b->in->o = o;
	write_run(b->t, b->from, b->to, b->s, b->in);
	b->in->organ++;
}

/* Organs an estimate writes of an @@organs block: the rest is scaled. */
#define SAMPLE	64

struct sampled {
	struct organs_block b;
	size_t		 k;
	double		 weights, bytes;
};

static void
sample_block(void *ctx, const struct organ *o, double weight)
{
	struct sampled *S = ctx;
	size_t count = S->b.in->r->count;
	double before = sink_bytes(S->b.s);

	/* The index it stands for, so that @N@ has its digits. */
	S->b.in->organ = (size_t)(((double)S->k++ + 0.5) * (double)count /
	    SAMPLE);
	S->b.in->o = o;
	write_run(S->b.t, S->b.from, S->b.to, S->b.s, S->b.in);
	S->weights += weight;
	S->bytes += weight * (sink_bytes(S->b.s) - before);
}

/* A block starting at segment i, in context c. */
static void
write_block(const struct tmpl *t, size_t i, struct sink *s,
    struct tmpl_ctx *c)
{
	const struct seg *g = &t->segs[i];
	struct tmpl_ctx in = *c;
	size_t n;

	switch (g->block) {
	case B_STRUCTURES:
		for (size_t k = 0; k < c->nall; k++) {
			in.r = c->all[k];
			write_run(t, i + 1, g->end, s, &in);
		}
		return;
	case B_PART:
	case B_MAIN:
		if ((g->block == B_PART) == (c->r->part != 0))
			write_run(t, i + 1, g->end, s, &in);
		return;
	case B_OBJECTS:
		in.scope = TS_OBJECT;
		for (n = 0; n < c->r->nobjects; n++) {
			in.object = n;
			write_run(t, i + 1, g->end, s, &in);
		}
		return;
	case B_ORGANS: {
		struct organs_block b = { t, i + 1, g->end, s, &in };
		struct sampled S = { b, 0, 0, 0 };
		double before = sink_bytes(s);

		in.scope = TS_ORGAN;
		in.organ = 0;
		if (!c->estimate || c->r->count <= SAMPLE) {
			result_each(c->r, RESULT_ALL, organ_block, &b);
			return;
		}
		/* The sample is written: add the rest of the mean times count. */
		result_sample(c->r, SAMPLE, sample_block, &S);
		if (S.weights > 0)
			sink_add(s, S.bytes / S.weights * (double)c->r->count -
			    (sink_bytes(s) - before));
		return;
	}
	}
}

/* Segments [from, to): text, placeholders and whole blocks. */
static void
write_run(const struct tmpl *t, size_t from, size_t to, struct sink *s,
    struct tmpl_ctx *c)
{
	for (size_t i = from; i < to; i++) {
		const struct seg *g = &t->segs[i];

		if (g->kind == SEG_TEXT)
			sink_write(s, g->text, g->len);
		else if (g->kind == SEG_VAR && c->estimate && g->var->size)
			sink_add(s, g->var->size(c));
		else if (g->kind == SEG_VAR)
			g->var->put(s, c);
		else if (g->kind == SEG_BEGIN) {
			write_block(t, i, s, c);
			i = g->end;
		}
	}
}

/* Segments [from, to) of the piece. */
static void
piece_segs(const struct tmpl *t, enum tmpl_piece piece, size_t *from,
    size_t *to)
{
	size_t b = t->structures ? t->body : t->nsegs;
	size_t e = t->structures ? t->segs[b].end + 1 : t->nsegs;

	*from = piece == TMPL_ALL || piece == TMPL_HEAD ? 0 :
	    piece == TMPL_BODY ? b : e;
	*to = piece == TMPL_ALL || piece == TMPL_TAIL ? t->nsegs :
	    piece == TMPL_HEAD ? b : e;
}

static void
write_piece(const struct tmpl *t, enum tmpl_piece piece, struct sink *s,
    const struct result *const *all, size_t nall, unsigned opts,
    int estimate)
{
	struct tmpl_ctx c = { all[nall - 1], opts, TS_GLOBAL, 0, 0, NULL,
	    all, nall, estimate };
	size_t from, to;

	piece_segs(t, piece, &from, &to);
	write_run(t, from, to, s, &c);
}

void
tmpl_write(const struct tmpl *t, struct sink *s,
    const struct result *const *all, size_t nall, unsigned opts)
{
	write_piece(t, TMPL_ALL, s, all, nall, opts, 0);
}

void
tmpl_write_piece(const struct tmpl *t, enum tmpl_piece piece,
    struct sink *s, const struct result *const *all, size_t nall,
    unsigned opts)
{
	write_piece(t, piece, s, all, nall, opts, 0);
}

double
tmpl_bytes(const struct tmpl *t, enum tmpl_piece piece,
    const struct result *const *all, size_t nall, unsigned opts)
{
	struct sink s;
	double n;

	sink_init_count(&s);
	write_piece(t, piece, &s, all, nall, opts, 1);
	n = sink_bytes(&s);
	sink_free(&s);
	return n;
}

int
tmpl_structures(const struct tmpl *t)
{
	return t->structures;
}

void
tmpl_free(struct tmpl *t)
{
	if (t == NULL)
		return;
	free(t->text);
	free(t->segs);
	free(t);
}
