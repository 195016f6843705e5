/*
 * synth.h - synthetic measured heads and cones for the order-free
 * analysis's tests and its trials (bench_measured.c): a model's organs
 * with the distortions of measuring a real plant (a click's jitter,
 * organs missed, a centre guessed, rows shuffled, a rim cut by the
 * photograph's frame, an oblique view), measured as the measured model
 * measures them, and held against parastichy.c's reading of the same
 * organs in their order.
 */
#ifndef SYNTH_H
#define SYNTH_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/axis.h"
#include "analysis/kdtree.h"
#include "analysis/parastichy.h"
#include "analysis/unordered.h"
#include "result/organ.h"

/* A plain, seeded stream: the trials are the same on every machine. */
static inline double
synth_uniform(uint64_t *s)
{
	*s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
	return ((double)(*s >> 11) + 0.5) / 9007199254740992.0;
}

static inline double
synth_gauss(uint64_t *s)
{
	double u = synth_uniform(s), v = synth_uniform(s);

	return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

/*
 * A model's organs as measured: positions by organ (jittered, some
 * gone), then the points a measurement reads (the gone left out, the
 * view squashed, the rows shuffled, the lot moved off the origin), with
 * the organ each point was.
 */
struct synth {
	double		(*q)[3];	/* by organ */
	char		*gone;		/* missed or cut off */
	size_t		 count;		/* organs */
	double		(*p)[3];	/* the points read */
	size_t		*id;		/* each one's organ */
	size_t		 n;
	double		*spacing;	/* by organ, before distortion */
	double		 radius;	/* the largest distance from the axis */
	int		 has_z;
};

static inline void
synth_init(struct synth *S, const struct result *r)
{
	struct kd T;

	memset(S, 0, sizeof(*S));
	S->count = r->count;
	S->q = calloc(S->count, sizeof(*S->q));
	S->gone = calloc(S->count + 1, 1);
	S->spacing = calloc(S->count, sizeof(*S->spacing));
	for (size_t i = 0; i < S->count; i++) {
		memcpy(S->q[i], r->organs[i].pos, sizeof(S->q[i]));
		S->radius = fmax(S->radius, hypot(S->q[i][0], S->q[i][1]));
		S->has_z |= S->q[i][2] != S->q[0][2];
	}
	kd_init_points(&T, (const double (*)[3])S->q, S->count);
	for (size_t i = 0; i < S->count; i++) {
		struct kd_near nb;

		kd_nearest(&T, S->q[i], i, 0, &nb);
		S->spacing[i] = nb.n > 0 ? sqrt(nb.d2[0]) / nb.inv : 0;
	}
	kd_free(&T);
}

static inline void
synth_free(struct synth *S)
{
	free(S->q);
	free(S->gone);
	free(S->p);
	free(S->id);
	free(S->spacing);
}

/*
 * Each organ moved at random by frac of its spacing, root mean square
 * (in the plane of a head, in space on a surface).
 */
static inline void
synth_jitter(struct synth *S, double frac, uint64_t *rng)
{
	int dims = S->has_z ? 3 : 2;

	for (size_t i = 0; i < S->count; i++)
		for (int k = 0; k < dims; k++)
			S->q[i][k] += synth_gauss(rng) * frac * S->spacing[i] /
			    sqrt((double)dims);
}

/* A share of the organs missed, at random. */
static inline void
synth_drop(struct synth *S, double share, uint64_t *rng)
{
	for (size_t i = 0; i < S->count; i++)
		S->gone[i] |= synth_uniform(rng) < share;
}

/* The organs beyond a straight line at share of the radius, cut off. */
static inline void
synth_cut(struct synth *S, double share, double angle)
{
	for (size_t i = 0; i < S->count; i++)
		S->gone[i] |= S->q[i][0] * cos(angle) + S->q[i][1] *
		    sin(angle) > share * S->radius;
}

/*
 * parastichy.c's reading of the organs as they are now, in their
 * order (the gone far away, where nothing has them for a neighbour):
 * each organ's pair into ref, its zones into z; how many.
 */
static inline size_t
synth_order(const struct synth *S, const struct result *r, int (*ref)[2],
    struct para_zone *z, size_t zmax)
{
	struct result o = *r;
	size_t nz;

	o.organs = calloc(r->count, sizeof(*o.organs));
	memcpy(o.organs, r->organs, r->count * sizeof(*o.organs));
	for (size_t i = 0; i < r->count; i++) {
		memcpy(o.organs[i].pos, S->q[i], sizeof(S->q[i]));
		if (S->gone[i])
			o.organs[i].pos[0] = 1e6 * S->radius * (double)(i + 1);
	}
	para_pairs(&o, ref);
	nz = para_zones(&o, NULL, z, zmax);
	free(o.organs);
	return nz;
}

/*
 * The points a measurement reads: the organs not gone, the view
 * squashed to factor along angle (1: not), the rows shuffled, the lot
 * moved off the origin.
 */
static inline void
synth_view(struct synth *S, double factor, double angle, uint64_t *rng)
{
	double c = cos(angle), s = sin(angle);

	free(S->p);
	free(S->id);
	S->p = calloc(S->count + 1, sizeof(*S->p));
	S->id = calloc(S->count + 1, sizeof(*S->id));
	S->n = 0;
	for (size_t i = 0; i < S->count; i++) {
		double u, v;

		if (S->gone[i])
			continue;
		memcpy(S->p[S->n], S->q[i], sizeof(S->q[i]));
		u = S->q[i][0] * c + S->q[i][1] * s;
		v = -S->q[i][0] * s + S->q[i][1] * c;
		u *= factor;
		S->p[S->n][0] = u * c - v * s;
		S->p[S->n][1] = u * s + v * c;
		S->id[S->n++] = i;
	}
	for (size_t i = S->n; i > 1; i--) {
		size_t j = (size_t)(synth_uniform(rng) * (double)i), k;
		double t[3];

		memcpy(t, S->p[i - 1], sizeof(t));
		memcpy(S->p[i - 1], S->p[j], sizeof(t));
		memcpy(S->p[j], t, sizeof(t));
		k = S->id[i - 1];
		S->id[i - 1] = S->id[j];
		S->id[j] = k;
	}
	for (size_t i = 0; i < S->n; i++) {
		S->p[i][0] += 3.25 * S->radius;
		S->p[i][1] -= 1.5 * S->radius;
	}
}

/* Measured as the measured model does, from a centre guessed or not. */
static inline struct unordered *
synth_measure(const struct synth *S, const double *guess, int older_out)
{
	struct axis A;
	struct axis_point *ap = calloc(S->n + 1, sizeof(*ap));
	struct unordered *U;

	axis_find(&A, (const double (*)[3])S->p, S->n, S->has_z, guess);
	axis_points(&A, (const double (*)[3])S->p, S->n, ap);
	U = unordered_measure(&A, ap, (const double (*)[3])S->p, S->n,
	    older_out);
	axis_free(&A);
	free(ap);
	return U;
}

/* The zone organ i lies in, by where along the curve it is; or nzones. */
static inline size_t
synth_zone_of(const struct unordered *U, size_t i)
{
	for (size_t z = 0; z < U->nzones; z++)
		if (U->zone[z].s <= U->c[i].s && U->c[i].s <= U->zone[z].s_end)
			return z;
	return U->nzones;
}

/* The measured pair of organ i, smaller first; 0 0 for none. */
static inline void
synth_pair(const struct unordered *U, size_t i, int p[2])
{
	const struct uorgan *o = &U->c[i];

	p[0] = p[1] = 0;
	if (o->prev[0] < 0 || o->prev[1] < 0)
		return;
	p[0] = o->dk[0] < o->dk[1] ? o->dk[0] : o->dk[1];
	p[1] = o->dk[0] < o->dk[1] ? o->dk[1] : o->dk[0];
}

/*
 * Whether the measurement agrees with parastichy.c's reading of the
 * same organs in their order, ref[] each organ's pair and z[0 .. nz)
 * the zones (the rim last or first): wherever it says a pair holds,
 * (1) the organs there have the pairs the order gives them, nine in
 * ten of those both read (share), and (2) most of them have the zone's
 * pair in the order too; (3) at the rim or base, where the order gives
 * two in three of the organs of the measurement's last zone one pair,
 * it says that pair there, or the order's at the rim of the whole (or,
 * if unclear_rim, that no one pair is clear there); where the order
 * flickers between pairs it may say a transition; (4) it says a pair
 * for at least cover of the organs, so that no head passes by saying
 * transition throughout; (5) the divergence within four of its errors
 * of alpha (degrees; NAN: any).  id[i]: point i's organ (NULL: the
 * same).  Why not into why.
 */
static inline int
synth_agrees(const struct unordered *U, const size_t *id, const int (*ref)[2],
    const struct para_zone *z, size_t nz, int rim_last, double alpha,
    double share, double cover, int unclear_rim, char *why, size_t sz)
{
	const struct uzone *rim = unordered_rim(U);
	const struct para_zone *zr = NULL;
	size_t *held = calloc(U->nzones + 1, sizeof(*held));
	size_t *read = calloc(U->nzones + 1, sizeof(*read));
	size_t *zat = calloc(U->count + 1, sizeof(*zat));
	size_t same = 0, both = 0, paired = 0, rz = U->nzones, rread = 0;
	int ok = 1, mode[2] = { 0, 0 }, mcount = 0;

	for (size_t k = 0; k < nz && zr == NULL; k++)
		if (z[rim_last ? nz - 1 - k : k].m > 0)
			zr = &z[rim_last ? nz - 1 - k : k];
	if (rim != NULL)
		rz = (size_t)(rim - U->zone);
	for (size_t i = 0; i < U->count; i++)
		zat[i] = synth_zone_of(U, i);
	/* The pair the order gives most of the rim zone's organs. */
	for (size_t i = 0; i < U->count && rz < U->nzones; i++) {
		size_t o = id != NULL ? id[i] : i;
		int c = 0;

		if (zat[i] != rz || ref[o][0] == 0)
			continue;
		rread++;
		for (size_t j = 0; j < U->count; j++) {
			size_t q = id != NULL ? id[j] : j;

			c += zat[j] == rz && ref[q][0] == ref[o][0] &&
			    ref[q][1] == ref[o][1];
		}
		if (c > mcount) {
			mcount = c;
			mode[0] = ref[o][0];
			mode[1] = ref[o][1];
		}
	}
	for (size_t i = 0; i < U->count; i++) {
		size_t at = zat[i], o = id != NULL ? id[i] : i;
		const struct uzone *u = &U->zone[at];
		int p[2];

		if (at == U->nzones || u->kind != UZ_PAIR)
			continue;
		paired++;
		if (ref[o][0] == 0)
			continue;
		synth_pair(U, i, p);
		read[at]++;
		held[at] += ref[o][0] == u->m && ref[o][1] == u->n;
		if (p[0] == 0)
			continue;
		both++;
		same += p[0] == ref[o][0] && p[1] == ref[o][1];
	}
	if ((double)same < share * (double)both) {
		snprintf(why, sz, "%zu of %zu organs' pairs as in order", same,
		    both);
		ok = 0;
	}
	for (size_t k = 0; k < U->nzones && ok; k++)
		if (U->zone[k].kind == UZ_PAIR && 2 * held[k] < read[k]) {
			snprintf(why, sz, "%d/%d from rho %.3g: the order gives "
			    "%zu of its %zu organs that pair", U->zone[k].m,
			    U->zone[k].n, U->zone[k].rho, held[k], read[k]);
			ok = 0;
		}
	if (ok && !(unclear_rim && rim != NULL && rim->kind != UZ_PAIR) &&
	    (rim == NULL || (3 * (size_t)mcount >= 2 * rread ? rim->kind !=
	    UZ_PAIR || ((rim->m != mode[0] || rim->n != mode[1]) &&
	    (zr == NULL || rim->m != zr->m || rim->n != zr->n)) : 0))) {
		snprintf(why, sz, "rim %d/%d, the order's %d/%d (%d of %zu "
		    "organs there)", rim != NULL ? rim->m : 0,
		    rim != NULL ? rim->n : 0, mode[0], mode[1], mcount, rread);
		ok = 0;
	}
	if (ok && (double)paired < cover * (double)U->count) {
		snprintf(why, sz, "a pair for %zu of %zu organs", paired,
		    U->count);
		ok = 0;
	}
	if (ok && !isnan(alpha) && (isnan(U->divergence) ||
	    fabs(remainder(U->divergence - alpha, 360)) >
	    4 * U->divergence_err + 1e-9)) {
		snprintf(why, sz, "divergence %.6f +- %.6f, not %.6f",
		    U->divergence, U->divergence_err, alpha);
		ok = 0;
	}
	free(held);
	free(read);
	free(zat);
	return ok;
}

/* What a trial does to a head before measuring it: flags. */
enum { D_JITTER = 1, D_MISSING = 2, D_CENTRE = 4, D_CUT = 8, D_SQUASH = 16 };

/*
 * One trial; 1 if it agrees with parastichy.c's reading of the same
 * organs, jittered, missed and cut alike, in their order (the pair each
 * organ shows is its own contacts', not the model's before they moved;
 * the view's squash is not in that reading: the measurement undoes it),
 * and at the rim says the pair of the head as the model made it (z0).
 * why says what failed; *dev is how far the divergence measured is from
 * the model's, in its errors (NAN: none measured).
 */
static inline int
synth_trial(const struct result *r, const struct para_zone *z0, size_t nz0,
    int what, uint64_t seed, char *why, size_t sz, double *dev)
{
	struct synth S;
	struct unordered *U;
	struct para_zone z[64];
	int (*ref)[2] = calloc(r->count, sizeof(*ref));
	uint64_t rng = seed * 0x9e3779b97f4a7c15ULL + 1;
	double guess[2], a = 2 * M_PI * synth_uniform(&rng);
	int ok;

	synth_init(&S, r);
	if (what & D_JITTER)
		synth_jitter(&S, 0.15, &rng);
	if (what & D_MISSING)
		synth_drop(&S, 0.05, &rng);
	/* The photograph's frame: a cap of the head a sixth deep. */
	if (what & D_CUT)
		synth_cut(&S, S.has_z ? 0.5 : 0.7, a);
	synth_order(&S, r, ref, z, 64);
	synth_view(&S, (what & D_SQUASH) && !S.has_z ? 0.9 : 1, a + 1, &rng);
	guess[0] = 3.25 * S.radius + 0.1 * S.radius * cos(a + 2);
	guess[1] = -1.5 * S.radius + 0.1 * S.radius * sin(a + 2);
	U = synth_measure(&S, (what & D_CENTRE) ? guess : NULL,
	    !r->rim_last);
	ok = synth_agrees(U, S.id, (const int (*)[2])ref, z0, nz0,
	    r->rim_last, r->divergence, 0.9, 2.0 / 3, 0, why, sz);
	*dev = isnan(U->divergence) ? NAN : remainder(U->divergence -
	    r->divergence, 360) / U->divergence_err;
	free(U);
	free(ref);
	synth_free(&S);
	return ok;
}

#endif
