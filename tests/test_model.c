/*
 * test_model.c - properties of the numeric core: the number formatter,
 * exact angles, and the planar model's geometry.  Each check prints
 * "ok - what" or "not ok - what"; tests/run.sh counts them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/geometry.h"
#include "models/model.h"
#include "analysis/parastichy.h"
#include "writers/numfmt.h"
#include "scene/scene.h"
#include "check.h"
#include "geometry/vec.h"


/* A deterministic stream of doubles for the formatter checks. */
static unsigned long long rng = 0x9e3779b97f4a7c15ull;

static double
uniform(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return (double)(rng >> 11) / 9007199254740992.0;
}

static void
test_numfmt(void)
{
	char ours[NUMFMT_MAX], ref[NUMFMT_MAX];
	double worst = 0;
	long differ = 0, n = 300000;

	for (long i = 0; i < n; i++) {
		double x = (uniform() - 0.5) * pow(10, floor(uniform() * 30) - 15);
		double back;

		num_format(ours, x);
		snprintf(ref, sizeof(ref), "%.9g", x);
		back = strtod(ours, NULL);
		if (x != 0)
			worst = fmax(worst, fabs(back - x) / fabs(x));
		differ += strcmp(ours, ref) != 0;
	}
	check(worst <= 5.0000001e-9, "numfmt: 9 significant digits "
	    "(worst relative error %.3g over %ld numbers)", worst, n);
	/* Only rounding ties may differ from printf, and they are rare. */
	check(differ * 10000 < n, "numfmt: same text as %%.9g "
	    "(%ld of %ld differ)", differ, n);
	num_format(ours, 0.0);
	check(strcmp(ours, "0") == 0, "numfmt: zero is \"0\"");
	num_format(ours, -0.0);
	check(strcmp(ours, "0") == 0, "numfmt: negative zero is \"0\"");
	num_format(ours, 1e-5);
	check(strcmp(ours, "1e-05") == 0, "numfmt: 1e-5 as %%g writes it");
	num_format(ours, 123456789.0);
	check(strcmp(ours, "123456789") == 0, "numfmt: 9-digit integer");
	num_format(ours, 0.1 + 0.2);
	check(strcmp(ours, "0.3") == 0, "numfmt: 0.1 + 0.2 is 0.3");
}

/*
 * Whether fma() rounds once and long double has 64 bits, as on real
 * hardware; valgrind emulates neither, and the exactness check below
 * would then measure the emulator.
 */
static int
exact_arithmetic(void)
{
	volatile double a = 1 + 0x1p-30, p = a * a;
	volatile long double one = 1;

	return fma(a, a, -p) == 0x1p-60 && one + 0x1p-60L != one;
}

static void
test_angle(void)
{
	const double alpha = 137.50776405003785;
	double worst = 0;

	/*
	 * The long double product carries 64 bits, enough to show the
	 * 1e-7 degree error a plain double product would make.
	 */
	for (long n = 1; n <= 10000000; n += 9973) {
		long double ref = fmodl((long double)n * (long double)alpha,
		    360.0L);
		double got = angle_mod360((double)n, alpha);

		worst = fmax(worst, fabs((double)(ref - (long double)got)));
	}
	if (exact_arithmetic())
		check(worst < 2e-10, "angle_mod360 exact to %.2g degree up "
		    "to n = 1e7", worst);
	else
		printf("ok - # SKIP angle_mod360 exactness: fma() or long "
		    "double is emulated here (valgrind?)\n");
	check(angle_mod360(3, -90) == 90, "angle_mod360 of a negative "
	    "divergence lies in [0, 360)");
}

/* Load a scene from text and run its model; 0 on success. */
static int
run(const char *text, struct scene *sc, struct result *res)
{
	*res = (struct result){0};
	if (scene_load_buffer(sc, "test.cfg", text, strlen(text)) != 0)
		return -1;
	return scene_run(sc, res, NULL);
}

static void
done(struct scene *sc, struct result *res)
{
	result_free(res);
	scene_free(sc);
}

static const char *
object_of(const struct result *r, size_t n)
{
	return r->objects[r->organs[n].object];
}

/* Largest deviation from an orthonormal right-handed frame. */
static double
frame_error(const struct organ *o)
{
	double c[3], v[3], e = 0;

	organ_v(o, v);
	e = fmax(e, fabs(vec_dot(o->u, o->u) - 1));
	e = fmax(e, fabs(vec_dot(v, v) - 1));
	e = fmax(e, fabs(vec_dot(o->w, o->w) - 1));
	e = fmax(e, fabs(vec_dot(o->u, v)));
	e = fmax(e, fabs(vec_dot(o->u, o->w)));
	e = fmax(e, fabs(vec_dot(v, o->w)));
	vec_cross(c, o->u, v);
	for (int i = 0; i < 3; i++)
		e = fmax(e, fabs(c[i] - o->w[i]));
	return e;
}

static double
angle_diff(double a, double b)
{
	double d = fmod(fabs(a - b), 360);

	return fmin(d, 360 - d);
}

static void
test_planar_vogel(void)
{
	struct scene sc;
	struct result res;
	double er = 0, ea = 0, ef = 0, eu = 0;
	const double c = 0.7, alpha = 137.3;

	if (run("model = \"planar\"; count = 5000; divergence = 137.3;\n"
	    "planar = { scale = 0.7; };", &sc, &res) != 0) {
		check(0, "planar: scene loads");
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const struct organ *o = &res.organs[n];
		double rho = hypot(o->pos[0], o->pos[1]);
		double ang = atan2(o->pos[1], o->pos[0]) * 180 / M_PI;
		double want = fmod((double)n * alpha, 360);

		er = fmax(er, fabs(rho - c * sqrt((double)n)));
		if (n > 0)
			ea = fmax(ea, angle_diff(ang, want));
		ef = fmax(ef, frame_error(o));
		/* u radially outward, w = +Z. */
		if (n > 0)
			eu = fmax(eu, fabs(o->u[0] - o->pos[0] / rho) +
			    fabs(o->u[1] - o->pos[1] / rho) + fabs(o->u[2]));
		eu = fmax(eu, fabs(o->w[2] - 1) + fabs(o->pos[2]));
	}
	check(er < 1e-12, "planar: r = c sqrt(n) (worst %.2g)", er);
	check(ea < 1e-9, "planar: angle = n alpha (worst %.2g degree)", ea);
	check(ef < 1e-12, "planar: frames orthonormal, right-handed "
	    "(worst %.2g)", ef);
	check(eu < 1e-12, "planar: u radial, w = +Z on a flat disk");
	check(res.organs[0].u[0] == 1 && res.organs[0].pos[0] == 0,
	    "planar: organ 0 at the centre facing +X");
	check(fabs(res.organs[7].radius - c * sqrt(M_PI / (2 * sqrt(3)))) <
	    1e-12, "planar: packing radius c sqrt(pi / (2 sqrt 3))");
	result_free(&res);
	scene_free(&sc);
}

static void
test_planar_variants(void)
{
	struct scene sc;
	struct result res;
	double ez = 0, en = 0, ef = 0;

	if (run("model = \"planar\"; count = 300;\n"
	    "planar = { outer = 2.5; inner = 0.5; exponent = 0.6; };",
	    &sc, &res) == 0) {
		const struct organ *o = res.organs;
		double c = 2.0 / pow(299, 0.6);

		check(fabs(hypot(o[299].pos[0], o[299].pos[1]) - 2.5) < 1e-12,
		    "planar: outer puts the last organ at the outer radius");
		check(fabs(hypot(o[0].pos[0], o[0].pos[1]) - 0.5) < 1e-12,
		    "planar: inner puts organ 0 at the inner radius");
		check(fabs(hypot(o[77].pos[0], o[77].pos[1]) -
		    (0.5 + c * pow(77, 0.6))) < 1e-12,
		    "planar: r = inner + c n^exponent");
	} else
		check(0, "planar: variants scene loads");
	result_free(&res);
	scene_free(&sc);

	if (run("model = \"planar\"; count = 800;\n"
	    "planar = { scale = 0.1; dome = 0.6; };", &sc, &res) == 0) {
		double rim = 0.1 * sqrt(799.0);

		for (size_t n = 0; n < res.count; n++) {
			const struct organ *o = &res.organs[n];
			double rho = hypot(o->pos[0], o->pos[1]);
			/* Gradient of f = z - dome (1 - rho^2/rim^2). */
			double g[3] = { 1.2 * o->pos[0] / (rim * rim),
			    1.2 * o->pos[1] / (rim * rim), 1 }, cr[3];

			ez = fmax(ez, fabs(o->pos[2] -
			    0.6 * (1 - rho * rho / (rim * rim))));
			vec_normalize(g);
			vec_cross(cr, g, o->w);
			en = fmax(en, sqrt(vec_dot(cr, cr)) +
			    fabs(vec_dot(o->u, g)));
			ef = fmax(ef, frame_error(o));
			if (n > 0 && (o->u[2] > 0 ||
			    o->u[0] * o->pos[0] + o->u[1] * o->pos[1] <= 0))
				en = 1;
		}
		check(ez < 1e-12, "planar: dome centres on the paraboloid");
		check(en < 1e-12, "planar: dome w normal, u tangent pointing "
		    "outward and down");
		check(ef < 1e-12, "planar: dome frames orthonormal");
	} else
		check(0, "planar: dome scene loads");
	result_free(&res);
	scene_free(&sc);
}

static int
is_fib_pair(int a, int b)
{
	int f0 = 1, f1 = 2;

	while (f0 < a) {
		int t = f0 + f1;

		f0 = f1;
		f1 = t;
	}
	return f0 == a && f1 == b;
}

static void
test_parastichies(void)
{
	static const char *const counts[] = { "100", "1000", "5000" };

	for (size_t i = 0; i < 3; i++) {
		char text[128];
		struct scene sc;
		struct result res;
		int pair[2] = { 0, 0 };
		struct para_zone z[64];
		size_t nz;

		snprintf(text, sizeof(text), "model = \"planar\"; count = %s;",
		    counts[i]);
		if (run(text, &sc, &res) == 0 &&
		    (nz = para_zones(&res, NULL, z, 64)) > 0) {
			pair[0] = z[nz - 1].m;
			pair[1] = z[nz - 1].n;
		}
		check(is_fib_pair(pair[0], pair[1]), "parastichies of %s "
		    "organs at the golden angle are consecutive Fibonacci "
		    "numbers (%d, %d)", counts[i], pair[0], pair[1]);
		result_free(&res);
		scene_free(&sc);
	}
}


static void
test_organ_ranges(void)
{
	struct scene sc;
	struct result res;
	int wrong = 0;

	if (run("model = \"planar\"; count = 630;\n"
	    "organs = ( { object = \"Seed\"; to = 440; },\n"
	    "  { object = \"Ray\"; from = 441; to = 565; },\n"
	    "  { object = \"Petal\"; from = 566; } );", &sc, &res) != 0) {
		check(0, "organs: ranges scene loads");
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const char *want = n <= 440 ? "Seed" : n <= 565 ? "Ray" :
		    "Petal";

		wrong += strcmp(object_of(&res, n), want) != 0;
	}
	check(wrong == 0 && res.nobjects == 3, "organs: each range gets its "
	    "object (%d wrong)", wrong);
	done(&sc, &res);

	/* Entries past the last organ are dropped, to is clipped. */
	check(run("model = \"planar\"; count = 100;\n"
	    "organs = ( { object = \"A\"; to = 440; },\n"
	    "  { object = \"B\"; from = 441; } );", &sc, &res) == 0 &&
	    strcmp(object_of(&res, 99), "A") == 0,
	    "organs: entries beyond the count are ignored");
	done(&sc, &res);
}

/* Count how often each of the objects A, B, C is chosen. */
static void
tally(const char *text, long counts[3], unsigned *choices)
{
	struct scene sc;
	struct result res;

	counts[0] = counts[1] = counts[2] = 0;
	if (run(text, &sc, &res) != 0)
		return;
	for (size_t n = 0; n < res.count; n++) {
		const char *o = object_of(&res, n);

		if (o[0] >= 'A' && o[0] <= 'C' && o[1] == '\0')
			counts[o[0] - 'A']++;
		if (choices != NULL)
			choices[n] = (unsigned)o[0];
	}
	done(&sc, &res);
}

static void
test_variants(void)
{
	static unsigned a[3000], b[3000], c[3000];
	long k[3];
	int same = 1, differ = 0, kept = 1;

	tally("model = \"planar\"; count = 3000; seed = 7;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 2, 1]; } );", k, a);
	/* 3000 draws: 4 standard deviations is about 95. */
	check(labs(k[0] - 750) < 100 && labs(k[1] - 1500) < 110 &&
	    labs(k[2] - 750) < 100, "organs: variants follow their weights "
	    "1:2:1 over 3000 organs (%ld %ld %ld)", k[0], k[1], k[2]);
	tally("model = \"planar\"; count = 3000; seed = 7;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 2, 1]; } );", k, b);
	tally("model = \"planar\"; count = 3000; seed = 8;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 2, 1]; } );", k, c);
	for (int n = 0; n < 3000; n++) {
		same &= a[n] == b[n];
		differ += a[n] != c[n];
	}
	check(same, "organs: the same seed gives the same choices");
	check(differ > 1000, "organs: another seed gives other choices "
	    "(%d of 3000 differ)", differ);
	tally("model = \"planar\"; count = 3000;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; } );", k, NULL);
	check(labs(k[0] - 1000) < 110 && labs(k[1] - 1000) < 110 &&
	    labs(k[2] - 1000) < 110, "organs: without weights variants are "
	    "equally likely (%ld %ld %ld)", k[0], k[1], k[2]);
	tally("model = \"planar\"; count = 3000;\n"
	    "organs = ( { object = [\"A\", \"B\", \"C\"]; "
	    "weights = [1, 0, 1]; } );", k, NULL);
	check(k[1] == 0 && k[0] > 0 && k[2] > 0, "organs: a zero weight is "
	    "never chosen");

	/* Changing the second range leaves the first range's choices. */
	tally("model = \"planar\"; count = 3000; seed = 3;\n"
	    "organs = ( { object = [\"A\", \"B\"]; to = 1499; },\n"
	    "  { object = \"C\"; from = 1500; } );", k, a);
	tally("model = \"planar\"; count = 3000; seed = 3;\n"
	    "organs = ( { object = [\"A\", \"B\"]; to = 1499; },\n"
	    "  { object = [\"C\", \"A\"]; weights = [3, 1]; "
	    "scale = \"rand(2)\"; from = 1500; } );", k, b);
	for (int n = 0; n < 1500; n++)
		kept &= a[n] == b[n];
	check(kept, "organs: editing one entry does not reshuffle another");
}

static void
test_transforms(void)
{
	struct scene sc, sc2;
	struct result base, res;
	double ep = 0, ef = 0, es = 0, eh = 0;

	if (run("model = \"planar\"; count = 200; planar = { dome = 1; };",
	    &sc, &base) != 0 ||
	    run("model = \"planar\"; count = 200; planar = { dome = 1; };\n"
	    "organs = ( { altitude = \"-0.1 * t\"; tilt = \"n % 90\";\n"
	    "  roll = 30; scale = \"2 * r + s\"; } );", &sc2, &res) != 0) {
		check(0, "organs: transform scenes load");
		return;
	}
	for (size_t n = 0; n < res.count; n++) {
		const struct organ *b = &base.organs[n], *o = &res.organs[n];
		double alt = -0.1 * (double)n / 199;
		double th = fmod((double)n, 90) * M_PI / 180;
		double ro = 30 * M_PI / 180;
		double u1[3], w1[3], u2[3], v2[3], bv[3], ov[3];

		organ_v(b, bv);
		organ_v(o, ov);
		for (int i = 0; i < 3; i++) {
			/* Altitude along the model's w, then tilt, then roll. */
			ep = fmax(ep, fabs(o->pos[i] - (b->pos[i] +
			    alt * b->w[i])));
			u1[i] = b->u[i] * cos(th) + b->w[i] * sin(th);
			w1[i] = b->w[i] * cos(th) - b->u[i] * sin(th);
			u2[i] = u1[i] * cos(ro) + bv[i] * sin(ro);
			v2[i] = bv[i] * cos(ro) - u1[i] * sin(ro);
			ef = fmax(ef, fabs(o->u[i] - u2[i]) +
			    fabs(ov[i] - v2[i]) + fabs(o->w[i] - w1[i]));
		}
		es = fmax(es, fabs(o->scale - (2 * b->radius +
		    (double)n / 199)));
		eh = fmax(eh, frame_error(o));
	}
	check(ep < 1e-12, "organs: altitude moves the centre along w");
	check(ef < 1e-12, "organs: tilt turns u towards w about v, roll "
	    "turns u towards v about w");
	check(eh < 1e-12, "organs: transformed frames stay orthonormal and "
	    "right-handed");
	check(es < 1e-12, "organs: scale expression sees r and s");
	check(res.organs[5].radius == base.organs[5].radius,
	    "organs: the packing radius is the model's");
	done(&sc, &base);
	done(&sc2, &res);
}

/*
 * Found by fuzz_scene: a number at the very end of a buffer that is
 * not NUL-terminated was scanned past its end.  Under check-asan an
 * over-read of this exact-size heap copy fails the run.
 */
static void
test_unterminated(void)
{
	static const char crash[] = "model 102\273\ncyli= [0";
	static const struct {
		const char	*text;
		int		 rc;
		long long	 count;	/* as read from the last bytes */
	} t[] = {
		{ crash, -1, 0 },
		{ "model = \"planar\";\ncount = 12", 0, 12 },
		{ "model = \"planar\"; count = 0x1F", 0, 31 },
	};

	for (size_t i = 0; i < sizeof(t) / sizeof(t[0]); i++) {
		size_t len = strlen(t[i].text);
		char *buf = malloc(len);
		struct scene sc;
		int rc;

		memcpy(buf, t[i].text, len);
		rc = scene_load_buffer(&sc, "t.cfg", buf, len);
		check(rc == t[i].rc && (rc != 0 || sc.count == t[i].count),
		    "scene text need not end in NUL: text %zu %s (fuzz_scene "
		    "regression)", i + 1, t[i].rc ? "refused" : "read to its "
		    "last digit");
		scene_free(&sc);
		free(buf);
	}
}

int
main(void)
{
	test_numfmt();
	test_angle();
	test_planar_vogel();
	test_planar_variants();
	test_parastichies();
	test_organ_ranges();
	test_variants();
	test_transforms();
	test_unterminated();
	return check_failures != 0;
}
