/*
 * inhibition.c - the divergence angle emerges (seed 003; Douady and
 * Couder 1996): primordia are born on the meristem's edge, a circle of
 * radius R0, and move outward, r -> r e^G each plastochron; each new
 * one appears where the ones already there inhibit least.
 *
 * Kernels: Douady and Couder's power law, E(th) = sum 1/d^s over the
 * distances d from the edge point at th to every primordium; and seed
 * 003's parameter-free Gaussian sum in the angle alone, each primordium
 * a bell exp(-(th - phi)^2) weighted by 1/age, so the newest counts
 * most.  Primordium 0 is at angle 0, primordium 1 opposite; the rest
 * find their angle to 1e-9 rad: candidates in the gaps between recent
 * primordia, then Newton on E' inside the best gaps.
 *
 * With the power law, a primordium whose pull on the edge varies by
 * less than 1e-12 of the nearest one's is left out: they are ever
 * farther out, so the sum has a fixed number of terms however many came
 * before.  The Gaussian kernel weighs every primordium by 1/age, which
 * never falls that low: it costs O(n) a primordium, as in the seed.
 */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "mem.h"
#include "model.h"

enum { IN_GROWTH, IN_START, IN_TRANSIENT, IN_KERNEL, IN_EXPONENT, IN_RADII,
	IN_OUTER, IN_DOME, IN__N };
enum { K_POWER, K_GAUSSIAN };
enum { RADII_GROWN, RADII_VOGEL };

struct inhibition {
	struct group_at	 at;
	int		 given[IN__N];
	struct expr_setting growth;	/* G_n: ln of r's growth before n */
	double		 start;		/* G of the young meristem */
	double		 transient;	/* primordia over which it fades */
	int		 kernel;	/* K_* */
	double		 exponent;	/* s of the power law */
	int		 radii;		/* RADII_*: how the output is laid out */
	double		 outer;		/* rescale: the oldest sits here */
	double		 dome;		/* height of the centre over the rim */
};

static const char *const kernel_names[] = { "power", "gaussian", NULL };
static const char *const radii_names[] = { "grown", "vogel", NULL };

#define I(f)	offsetof(struct inhibition, f)

static const struct row inhibition_rows[] = {
	[IN_GROWTH] = { .name = "growth", .type = T_EXPR, .off = I(growth),
	  .defstr = "0.02",
	  .vars = EXPR_VAR(V_N) | EXPR_VAR(V_COUNT) | EXPR_VAR(V_T),
	  .doc = "G: radial growth a plastochron over the meristem radius" },
	[IN_START] = { .name = "start", .type = T_FLOAT, .off = I(start),
	  .lo = 0, .hi = 100, .flags = F_LO_OPEN, .def = 2, .defstr = "2",
	  .doc = "G of the young meristem, fading to growth" },
	[IN_TRANSIENT] = { .name = "transient", .type = T_FLOAT,
	  .off = I(transient), .lo = 0, .hi = HUGE_VAL, .def = 30,
	  .defstr = "30", .doc = "primordia over which start fades; 0: none" },
	[IN_KERNEL] = { .name = "kernel", .type = T_CHOICE, .off = I(kernel),
	  .words = kernel_names, .defstr = "power",
	  .doc = "the inhibition: power (1/d^s) or gaussian (seed 003)" },
	[IN_EXPONENT] = { .name = "exponent", .type = T_FLOAT,
	  .off = I(exponent), .lo = 0, .hi = 64, .flags = F_LO_OPEN, .def = 3,
	  .defstr = "3", .doc = "s of the power law" },
	[IN_RADII] = { .name = "radii", .type = T_CHOICE, .off = I(radii),
	  .words = radii_names, .defstr = "grown",
	  .doc = "grown: where the growth took them; vogel: c sqrt(age)" },
	[IN_OUTER] = { .name = "outer", .type = T_FLOAT, .off = I(outer),
	  .lo = 0, .hi = HUGE_VAL, .flags = F_LO_OPEN, .defstr = "none",
	  .doc = "radius of the oldest primordium; the head is scaled to it" },
	[IN_DOME] = { .name = "dome", .type = T_FLOAT, .off = I(dome),
	  .lo = -HUGE_VAL, .hi = HUGE_VAL, .defstr = "0",
	  .doc = "height of the centre above the rim (paraboloid)" },
};

static const struct table inhibition_table = TABLE(inhibition_rows,
    struct inhibition);

#define R0		1.0	/* the meristem's radius: the unit */
#define AGE_MAX		700	/* e^700: the largest radius a double holds */
#define GROWTH_MIN	0.001	/* the slowest growth searched surely */

/* The primordia so far: angle, its cosine and sine; ages from n. */
struct field {
	const struct inhibition *P;
	double		*phi, *c, *s;
	size_t		 n;		/* placed */
	double		*S;		/* S[n]: G_1 + ... + G_n */
	double		*r;		/* r[k]: the radius now of the k-th
					   newest, for the far ones that count */
	size_t		 near;		/* newest looked at for candidates */
	size_t		 far;		/* power law: the newest that count */
	double		 hs;		/* s / 2 */
};

/*
 * E, E' and E'' at th over the k newest primordia (all for the
 * Gaussian), each of which has moved out once more since it was born.
 */
static void
energy(const struct field *F, double th, size_t k, double e[3])
{
	double ct = cos(th), st = sin(th);
	size_t n = F->n, first = k < n ? n - k : 0;

	e[0] = e[1] = e[2] = 0;
	if (F->P->kernel == K_GAUSSIAN) {
		for (size_t i = first; i < n; i++) {
			double w = 1.0 / (double)(n - i);	/* 1 / age */
			double x = remainder(th - F->phi[i], 2 * M_PI);

			for (int img = -1; img <= 1; img++) {
				double y = x + img * 2 * M_PI, g = w * exp(-y * y);

				e[0] += g;
				e[1] += -2 * y * g;
				e[2] += (4 * y * y - 2) * g;
			}
		}
		return;
	}
	for (size_t i = first; i < n; i++) {
		double r = F->r[n - 1 - i];
		/* d^2 = R0^2 + r^2 - 2 R0 r cos(th - phi), and its derivatives. */
		double cd = ct * F->c[i] + st * F->s[i];
		double sd = st * F->c[i] - ct * F->s[i];
		double q = R0 * R0 + r * r - 2 * R0 * r * cd;
		double q1 = 2 * R0 * r * sd, q2 = 2 * R0 * r * cd;
		double hs = F->hs, p;

		/* q^-hs, with the common s = 3 and 2 without pow(). */
		p = hs == 1.5 ? 1 / (q * sqrt(q)) : hs == 1 ? 1 / q :
		    pow(q, -hs);
		e[0] += p;
		e[1] += -hs * p / q * q1;
		e[2] += hs * (hs + 1) * p / (q * q) * q1 * q1 - hs * p / q * q2;
	}
}

/*
 * The minimum of E (over the first k newest, or all) inside [a, b],
 * from its middle: Newton on E' where E'' > 0, bisection on E''s sign
 * otherwise, to 1e-12 rad.
 */
static double	minimise_from(const struct field *, double, double, double,
		    size_t, double *);

static double
minimise(const struct field *F, double a, double b, size_t k, double *emin,
    int *end)
{
	double x, e[3], ends[2] = { a, b };

	x = minimise_from(F, a, b, (a + b) / 2, k, emin);
	/*
	 * An end of the interval may be lower than the interior's best:
	 * then the minimum lies beyond it, and *end says which way (-1, 1).
	 */
	*end = 0;
	for (int side = 0; side < 2; side++) {
		energy(F, ends[side], k, e);
		if (e[0] < *emin) {
			*emin = e[0];
			x = ends[side];
			*end = side ? 1 : -1;
		}
	}
	return x;
}

/* Newton from x inside [a, b], as minimise() without the ends. */
static double
minimise_from(const struct field *F, double a, double b, double x, size_t k,
    double *emin)
{
	double e[3];

	for (int it = 0; it < 100; it++) {
		double nx;

		energy(F, x, k, e);
		if (e[1] > 0)
			b = x;
		else
			a = x;
		nx = e[2] > 0 ? x - e[1] / e[2] : (a + b) / 2;
		if (!(nx > a && nx < b))
			nx = (a + b) / 2;
		if (fabs(nx - x) < 1e-12 || b - a < 1e-12) {
			x = nx;
			break;
		}
		x = nx;
	}
	energy(F, x, k, e);
	*emin = e[0];
	return x;
}

static int
dcmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return x < y ? -1 : x > y;
}

#define CANDIDATES	6

/*
 * The angle of least inhibition on the edge.  The circle is cut at the
 * angles of the near newest primordia; each gap's least near-energy at
 * its middle ranks it, and the best few are searched for the minimum of
 * the whole energy.
 */
static double
next_angle(struct field *F, double *gaps)
{
	size_t k = F->near < F->n ? F->near : F->n, best[CANDIDATES];
	double bestE[CANDIDATES], th = 0, emin = HUGE_VAL, ba = 0, bb = 0;
	int nb = 0;

	for (size_t i = 0; i < k; i++)
		gaps[i] = remainder(F->phi[F->n - 1 - i], 2 * M_PI) + M_PI;
	qsort(gaps, k, sizeof(*gaps), dcmp);
	gaps[k] = gaps[0] + 2 * M_PI;
	for (size_t g = 0; g < k; g++) {
		double e[3], mid = (gaps[g] + gaps[g + 1]) / 2;
		int j;

		if (gaps[g + 1] - gaps[g] < 1e-12)
			continue;
		energy(F, mid, k, e);
		/* Keep the CANDIDATES lowest, sorted. */
		for (j = nb; j > 0 && bestE[j - 1] > e[0]; j--)
			if (j < CANDIDATES) {
				bestE[j] = bestE[j - 1];
				best[j] = best[j - 1];
			}
		if (j < CANDIDATES) {
			bestE[j] = e[0];
			best[j] = g;
			if (nb < CANDIDATES)
				nb++;
		}
	}
	for (int j = 0; j < nb; j++) {
		size_t g = best[j], all = F->P->kernel == K_GAUSSIAN ? F->n :
		    F->far;
		int end, way = 0, steps = 0;
		double e, x, off = 0, a, b;

		/*
		 * Follow the slope of the near energy across gap ends into
		 * the neighbours (a turn back means the minimum is the end
		 * itself); then the whole energy from there, whose far part
		 * is smooth and small, inside the same gap.
		 */
		for (;;) {
			a = gaps[g] + off;
			b = gaps[g + 1] + off;
			x = minimise(F, a, b, k, &e, &end);
			if (end == 0 || (way != 0 && end != way) ||
			    ++steps > (int)k)
				break;
			way = end;
			if (end > 0 && ++g == k) {
				g = 0;
				off += 2 * M_PI;
			} else if (end < 0 && g-- == 0) {
				g = k - 1;
				off -= 2 * M_PI;
			}
		}
		/*
		 * The whole sum once at the near minimum: its value less
		 * E'^2 / 2E'' foretells the whole minimum there, which ranks
		 * the candidates; only the best is then refined.
		 */
		if (all > k) {
			double f[3];

			energy(F, x, all, f);
			e = f[2] > 0 ? f[0] - f[1] * f[1] / (2 * f[2]) : f[0];
		}
		if (e < emin) {
			emin = e;
			th = x;
			ba = a;
			bb = b;
		}
	}
	/*
	 * The whole sum may move the minimum a little past the near gap's
	 * end (an old, weak primordium's angle): refine with room on
	 * either side; Newton from so near stays in this minimum's well.
	 */
	if (nb > 0 && (F->P->kernel == K_GAUSSIAN ? F->n : F->far) > k)
		th = minimise_from(F, ba - (bb - ba), bb + (bb - ba), th,
		    F->P->kernel == K_GAUSSIAN ? F->n : F->far, &emin);
	return th;
}

static void
field_add(struct field *F, double th)
{
	F->phi[F->n] = th;
	F->c[F->n] = cos(th);
	F->s[F->n] = sin(th);
	F->n++;
}

/*
 * The power law's cut: how many of the newest count, those farther out
 * pulling on the edge with a variation below 1e-12 of the nearest's
 * pull.  Radii only grow, so the ones left out stay out.
 */
static size_t
far_count(const struct field *F)
{
	double s = F->P->exponent;
	double delta = R0 * (exp(F->S[F->n] - F->S[F->n - 1]) - 1);
	double nearest = pow(delta, -s);
	size_t k = F->far;

	while (k < F->n) {
		double D = R0 * (exp(F->S[F->n] - F->S[F->n - 1 - k]) - 1);

		if (D > 2 * R0 && s * R0 * pow(D, -s - 1) < 1e-12 * nearest)
			break;
		k++;
	}
	return k;
}

/*
 * Each organ's radius: half the distance to its nearest neighbour, so
 * the discs touch as the primordia did.  Neighbours in space are near
 * in index (the parastichy numbers apart), so the k on either side do.
 */
static void
contact_radii(struct result *res, size_t k)
{
	size_t N = res->count;

	for (size_t i = 0; i < N; i++) {
		struct organ *o = &res->organs[i];
		size_t lo = i > k ? i - k : 0, hi = i + k < N ? i + k : N - 1;
		double best = HUGE_VAL;

		for (size_t j = lo; j <= hi; j++) {
			const struct organ *p = &res->organs[j];
			double dx = p->pos[0] - o->pos[0], dy = p->pos[1] -
			    o->pos[1], dz = p->pos[2] - o->pos[2];
			double d = dx * dx + dy * dy + dz * dz;

			if (j != i && d < best)
				best = d;
		}
		o->radius = isinf(best) ? 1 : sqrt(best) / 2;
		o->scale = o->radius;
	}
}

/* How many recent primordia cut the circle at growth G: 3 sqrt(2 pi / G). */
static size_t
near_count(double G)
{
	double k = ceil(3 * sqrt(2 * M_PI / G));

	return k < 12 ? 12 : (size_t)k;
}

/* The settled divergence: the mean and spread of the last two thirds. */
static void
settled(const double *phi, size_t n, double *mean, double *spread)
{
	size_t from = n / 3, k = 0;
	double sum = 0, sum2 = 0;

	for (size_t i = from > 0 ? from : 1; i < n; i++, k++) {
		double d = fabs(remainder(phi[i] - phi[i - 1], 2 * M_PI)) *
		    (180 / M_PI);

		sum += d;
		sum2 += d * d;
	}
	*mean = k > 0 ? sum / (double)k : 0;
	*spread = k > 1 ? sqrt(fmax(0, sum2 / (double)k - *mean * *mean)) : 0;
}

int
inhibition_place(const struct scene *sc, struct result *res, int all_pairs)
{
	const struct inhibition *P = sc->params;
	struct field F = { .P = P, .hs = P->exponent / 2 };
	struct expr_env env = { { 0 }, (uint64_t)sc->seed, 0 };
	size_t N;
	double *gaps, mean, spread, flip = 1, rim, kdome, scale = 1, gmin;

	if (!sc->given[S_COUNT]) {
		scene_error(sc, 1, "missing setting 'count'");
		return -1;
	}
	N = (size_t)sc->count;
	if (P->kernel == K_GAUSSIAN && N > 200000) {
		scene_error(sc, GIVEN_AT(P, IN_KERNEL), "count %zu is more "
		    "than the gaussian kernel places, 200000: it weighs every "
		    "primordium, so each costs as many as came before", N);
		return -1;
	}
	F.S = xcalloc(N + 1, sizeof(*F.S));
	gmin = HUGE_VAL;
	for (size_t n = 1; n <= N; n++) {
		double g = 0.02;

		env.n = (long long)n;
		env.var[V_N] = (double)n;
		env.var[V_COUNT] = (double)N;
		env.var[V_T] = N > 1 ? (double)n / (double)(N - 1) : 0;
		if (P->growth.e != NULL && scene_eval(sc, &P->growth,
		    "inhibition.growth", "primordium", &env, &g) != 0) {
			free(F.S);
			return -1;
		}
		/*
		 * Below 0.001 the gaps among the recent primordia are too
		 * fine for the candidate search to be sure of the global
		 * minimum (the tests check down to 0.001).
		 */
		if (!(g >= GROWTH_MIN) || g > 100) {
			diag(ST_SCENE, sc->file, P->growth.line, 0,
			    "inhibition.growth is %.9g at primordium %zu; it "
			    "must be between %g and 100", g, n, GROWTH_MIN);
			free(F.S);
			return -1;
		}
		/*
		 * A young meristem is small, so it grows fast for its size:
		 * start fades into growth (geometrically, so that every
		 * scale of G gets its share), and the pattern follows the
		 * branch from alternate leaves down to the spirals, as in
		 * Douady and Couder's slowly falling G.  From the symmetric
		 * first two at a fixed small G it may lock into other modes.
		 */
		if (P->transient > 0)
			g *= pow(P->start / g, exp(-(double)n / P->transient));
		F.S[n] = F.S[n - 1] + g;
		gmin = fmin(gmin, g);
	}
	if (F.S[N - 1] > AGE_MAX) {
		scene_error(sc, GIVEN_AT(P, IN_GROWTH), "inhibition.growth "
		    "adds up to %.0f over %zu primordia: the oldest would be "
		    "e^%.0f meristem radii out; the sum must stay under %d",
		    F.S[N - 1], N, F.S[N - 1], AGE_MAX);
		free(F.S);
		return -1;
	}
	F.phi = xcalloc(N, sizeof(*F.phi));
	F.c = xcalloc(N, sizeof(*F.c));
	F.s = xcalloc(N, sizeof(*F.s));
	F.r = xcalloc(N + 1, sizeof(*F.r));
	/* Room for the most gaps any step looks at (near_count()). */
	gaps = xcalloc(near_count(gmin) + 2, sizeof(*gaps));

	for (size_t n = 0; n < N; n++) {
		/*
		 * Enough recent ones that their gaps hold one minimum each,
		 * for the growth of this plastochron: finer gaps than the
		 * field's features would rank the wrong ones.
		 */
		F.near = near_count(n > 0 ? F.S[n] - F.S[n - 1] : F.S[1]);
		if (n >= 2)
			F.far = P->kernel == K_POWER && !all_pairs ?
			    far_count(&F) : n;
		/* Moved out by the growth of every plastochron since birth. */
		if (P->kernel == K_POWER)
			for (size_t k = 0; k < n && (k < F.far || k < F.near);
			    k++)
				F.r[k] = R0 * exp(F.S[n] - F.S[n - 1 - k]);
		field_add(&F, n == 0 ? 0 : n == 1 ? M_PI : next_angle(&F,
		    gaps));
		if (model_progress != NULL && n % 16384 == 0 && n > 0)
			model_progress((long long)n, 0);
	}
	if (model_progress != NULL)
		model_progress((long long)N, 1);
	settled(F.phi, N, &mean, &spread);
	/* Turn the spiral counter-clockwise, as a positive divergence does. */
	if (N > 2) {
		double turn = 0;

		for (size_t i = N / 3 > 0 ? N / 3 : 1; i < N; i++)
			turn += remainder(F.phi[i] - F.phi[i - 1], 2 * M_PI);
		if (turn < 0)
			flip = -1;
	}
	/*
	 * Where each one is when the last is born, organ i at R0 e^(S[N-1] -
	 * S[i]); or, laid out as Vogel's, at sqrt(age + 1/2) with the angles
	 * that emerged: the growth's radii span e^(sum of G), too many
	 * orders of magnitude for a picture of a whole head.
	 */
	if (P->given[IN_OUTER])
		scale = P->outer / (P->radii == RADII_VOGEL ?
		    sqrt((double)N - 0.5) : R0 * exp(F.S[N - 1] - F.S[0]));
	rim = (P->radii == RADII_VOGEL ? sqrt((double)N - 0.5) :
	    R0 * exp(F.S[N - 1] - F.S[0])) * scale;
	kdome = rim > 0 ? 2 * P->dome / (rim * rim) : 0;

	result_init(res, N);
	res->divergence = mean;
	for (size_t i = 0; i < N; i++) {
		struct organ *o = &res->organs[i];
		/* The newest is at the edge, the oldest N - 1 plastochrons out. */
		double rho = (P->radii == RADII_VOGEL ?
		    sqrt((double)(N - 1 - i) + 0.5) :
		    R0 * exp(F.S[N - 1] - F.S[i])) * scale;
		double phi = remainder(flip * F.phi[i], 2 * M_PI) * (180 / M_PI);
		double z = rim > 0 ? P->dome * (1 - (rho / rim) * (rho / rim)) :
		    P->dome;

		if (phi < 0)
			phi += 360;
		frame_revolution(o, phi, rho, z, 1, -kdome * rho);
	}
	contact_radii(res, F.near);
	result_info(res, "settled", 2, mean, spread);
	/* 99.5016: the Lucas angle, 360 / (3 + tau^-1)... of the 1, 3 series. */
	result_info_text(res, "regime", fabs(mean - 180) < 5 ? "distichous" :
	    fabs(mean - GOLDEN_ANGLE) < 2 ? "fibonacci" :
	    fabs(mean - 99.5016) < 2 ? "lucas" : "other");
	result_info(res, "terms", 1, (double)F.far);
	free(F.phi);
	free(F.c);
	free(F.s);
	free(F.S);
	free(F.r);
	free(gaps);
	return 0;
}

static int
inhibition_run(const struct scene *sc, const void *params,
    struct result *res)
{
	(void)params;		/* inhibition_place finds them in sc */
	return inhibition_place(sc, res, 0);
}

const struct model inhibition_model = {
	.name = "inhibition",
	.help = "Douady & Couder: each primordium where the others inhibit "
	    "least; the angle emerges",
	.settings = &inhibition_table,
	.size = sizeof(struct inhibition),
	.run = inhibition_run,
	.svg = PROJ_TOP,
};
