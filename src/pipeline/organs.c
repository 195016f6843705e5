/*
 * organs.c - the organ vocabulary, applied after a model has placed the
 * organs: which object each organ is (by index range, with weighted
 * random variants), and its scale, altitude, tilt and roll from
 * expressions.  Ranges are checked here, once the count is known (the
 * collision model finds its own).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/diag.h"
#include "base/mem.h"
#include "pipeline/pipeline.h"

/* Keys the choice among variants apart from every rand(k) of the user. */
#define VARIANT_SALT	0x76617269616e7473ull	/* "variants" */

struct span {
	const struct organ_range *rg;
	long long from, to;
};

static int
span_cmp(const void *a, const void *b)
{
	const struct span *x = a, *y = b;

	return x->from < y->from ? -1 : x->from > y->from;
}

/*
 * Resolve every entry to [from, to] within 0..N-1, sorted; entries
 * that start past the last organ are dropped, so that lowering count
 * needs no edits.  Overlaps and gaps are errors.
 */
static struct span *
spans_resolve(const struct scene *sc, long long N, size_t *nspans)
{
	struct span *sp = xcalloc(sc->nranges, sizeof(*sp));
	size_t n = 0;

	for (size_t i = 0; i < sc->nranges; i++) {
		const struct organ_range *rg = &sc->ranges[i];
		long long to = rg->to < 0 ? N - 1 : rg->to;

		if (rg->to >= 0 && rg->from > rg->to) {
			diag(ST_SCENE, sc->file, rg->at.line, 0, "organs entry "
			    "runs backwards: from %lld is after to %lld",
			    rg->from, rg->to);
			free(sp);
			return NULL;
		}
		if (rg->from > N - 1)
			continue;
		sp[n++] = (struct span){ rg, rg->from, to < N ? to : N - 1 };
	}
	qsort(sp, n, sizeof(*sp), span_cmp);
	for (size_t i = 0; i <= n; i++) {
		long long next = i < n ? sp[i].from : N;
		long long prev = i > 0 ? sp[i - 1].to : -1;

		if (i < n && i > 0 && next <= prev) {
			diag(ST_SCENE, sc->file, sp[i].rg->at.line, 0, "organs "
			    "entry overlaps the entry at line %d from organ "
			    "%lld", sp[i - 1].rg->at.line, next);
			free(sp);
			return NULL;
		}
		if (next > prev + 1 && n == 0) {
			diag(ST_SCENE, sc->file, sc->ranges[0].at.line, 0,
			    "organs 0 to %lld are in no organs entry: every "
			    "entry starts after the last organ", N - 1);
			free(sp);
			return NULL;
		}
		if (next > prev + 1) {
			const struct organ_range *at = i < n ? sp[i].rg :
			    sp[i - 1].rg;

			diag(ST_SCENE, sc->file, at->at.line, 0, "organs %lld to "
			    "%lld are in no organs entry (%s this one)",
			    prev + 1, next - 1, i < n ? "before" : "after");
			free(sp);
			return NULL;
		}
	}
	*nspans = n;
	return sp;
}

static int
weights_check(const struct scene *sc, const struct organ_range *rg)
{
	double total = 0;

	if (rg->weights == NULL)
		return 0;
	if (rg->nweights != rg->nnames) {
		diag(ST_SCENE, sc->file, rg->given[RG_WEIGHTS], 0, "organs.weights "
		    "has %zu numbers for %zu objects", rg->nweights,
		    rg->nnames);
		return -1;
	}
	for (size_t i = 0; i < rg->nweights; i++)
		total += rg->weights[i];
	if (!(total > 0)) {
		diag(ST_SCENE, sc->file, rg->given[RG_WEIGHTS], 0,
		    "organs.weights are all zero");
		return -1;
	}
	return 0;
}

/* Which variant organ n gets: weighted, a pure function of (seed, n). */
static unsigned
variant(const struct organ_range *rg, uint64_t seed, long long n)
{
	double u = expr_rand(seed ^ VARIANT_SALT, n, 0), total = 0, acc = 0;
	size_t last = rg->nnames - 1;

	if (rg->nnames == 1)
		return rg->ids[0];
	if (rg->weights == NULL)
		return rg->ids[(size_t)(u * (double)rg->nnames)];
	for (size_t i = 0; i < rg->nweights; i++)
		total += rg->weights[i];
	for (size_t i = 0; i < last; i++) {
		acc += rg->weights[i];
		if (u * total < acc)
			return rg->ids[i];
	}
	/* Rounding must not hand the last place to a zero weight. */
	while (last > 0 && rg->weights[last] == 0)
		last--;
	return rg->ids[last];
}

/* Evaluate a setting for organ n; def when it is not given. */
static int
eval(const struct scene *sc, const struct expr_setting *es,
    const char *what, struct expr_env *env, double def, double *v)
{
	char path[32];

	if (es->e == NULL) {
		*v = def;
		return 0;
	}
	snprintf(path, sizeof(path), "organs.%s", what);
	return expr_setting_eval(es, sc->file, path, "organ", env, v);
}

/* Rotate a towards b by deg degrees in their plane: both stay unit. */
static void
turn(double a[3], double b[3], double deg)
{
	double c = cos(deg * (M_PI / 180)), s = sin(deg * (M_PI / 180));

	for (int i = 0; i < 3; i++) {
		double x = a[i] * c + b[i] * s, y = b[i] * c - a[i] * s;

		a[i] = x;
		b[i] = y;
	}
}

static int
apply_span(const struct scene *sc, const struct span *sp, struct result *r)
{
	const struct organ_range *rg = sp->rg;
	double len = (double)(sp->to - sp->from);
	struct expr_env env = { { 0 }, (uint64_t)sc->seed, 0 };

	for (long long n = sp->from; n <= sp->to; n++) {
		struct organ *o = &r->organs[n];
		double scale, alt, tilt, roll;

		expr_env_organ(&env, n, (long long)r->count);
		env.var[V_S] = len > 0 ? (double)(n - sp->from) / len : 0;
		env.var[V_R] = o->radius;
		env.var[V_PHI] = o->phi;
		env.var[V_H] = o->height;
		if (eval(sc, &rg->scale, "scale", &env, o->scale, &scale) < 0 ||
		    eval(sc, &rg->altitude, "altitude", &env, 0, &alt) < 0 ||
		    eval(sc, &rg->tilt, "tilt", &env, 0, &tilt) < 0 ||
		    eval(sc, &rg->roll, "roll", &env, 0, &roll) < 0)
			return -1;
		if (scale < 0) {
			diag(ST_SCENE, sc->file, rg->scale.line, 0,
			    "organs.scale is negative (%.9g) at organ %lld",
			    scale, n);
			return -1;
		}
		o->object = variant(rg, (uint64_t)sc->seed, n);
		o->scale = scale;
		for (int i = 0; i < 3; i++)
			o->pos[i] += alt * o->w[i];
		if (tilt != 0)
			turn(o->u, o->w, tilt);		/* about v */
		if (roll != 0) {
			double v[3];

			organ_v(o, v);
			turn(o->u, v, roll);		/* about w */
		}
	}
	return 0;
}

int
organs_apply(const struct scene *sc, struct result *r)
{
	struct span *sp;
	size_t nspans = 0;
	int rc = 0;

	if (sc->nranges == 0 || r->count == 0)
		return 0;
	for (size_t i = 0; i < sc->nranges; i++)
		if (weights_check(sc, &sc->ranges[i]) < 0)
			return -1;
	if ((sp = spans_resolve(sc, (long long)r->count, &nspans)) == NULL)
		return -1;
	for (size_t i = 0; i < nspans && rc == 0; i++)
		rc = apply_span(sc, &sp[i], r);
	free(sp);
	return rc;
}
