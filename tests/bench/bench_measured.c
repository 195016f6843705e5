/*
 * bench_measured.c - the measured model's order-free analysis: its
 * success over many seeds at each distortion of measuring a real plant
 * (the trials the note reports; test_measured.c runs a few of each),
 * and its speed on a large head, phase by phase.
 *
 *	bench_measured trials [SEEDS [ONLY]]
 *					a table: structure, distortion,
 *					heads read as in order, of SEEDS
 *					(the structures named ONLY...)
 *	bench_measured csv N [SEED]	a photograph-like head, N florets
 *					clicked (jittered 15%, 5% missed),
 *					x,y CSV
 *	bench_measured speed FILE	read FILE and measure it: seconds
 *					a phase, best of three
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/axis.h"
#include "analysis/parastichy.h"
#include "analysis/unordered.h"
#include "models/measured_csv.h"
#include "scene/scene.h"
#include "clock.h"
#include "scene_text.h"
#include "synth.h"


static const struct {
	const char	*name;
	int		 what;
} distortions[] = {
	{ "shuffled", 0 },
	{ "jitter 15%", D_JITTER },
	{ "5% missing", D_MISSING },
	{ "centre off 10%", D_CENTRE },
	{ "rim cut", D_CUT },
	{ "squash 10%", D_SQUASH },
	{ "all at once", D_JITTER | D_MISSING | D_CENTRE | D_CUT | D_SQUASH },
};

static const struct {
	const char	*name;
	const char	*scene;
} structures[] = {
	{ "Vogel head 600", "model = \"planar\"; count = 600;" },
	{ "Vogel head 1200", "model = \"planar\"; count = 1200;" },
	{ "Vogel head 5000", "model = \"planar\"; count = 5000;" },
	{ "pine cone 900", "model = \"cylindrical\"; count = 900;\n"
	    "cylindrical = { parastichies = [8, 13]; radius = \"1 - 0.6 * t * "
	    "t\"; };" },
	{ "collision cone", "model = \"collision\"; count = 1500;\n"
	    "collision = { receptacle = { shape = \"cone\"; radius = 1; height "
	    "= 1.5; }; radius = 0.05; };" },
};

/* One trial (synth.h), saying why it failed where BENCH_WHY is set. */
static int
trial(const struct result *r, const struct para_zone *z0, size_t nz0,
    int what, uint64_t seed, double *dev)
{
	char why[200];
	int ok = synth_trial(r, z0, nz0, what, seed, why, sizeof(why), dev);

	if (!ok && getenv("BENCH_WHY") != NULL)
		fprintf(stderr, "seed %llu: %s\n", (unsigned long long)seed, why);
	return ok;
}

static int
trials(int seeds, const char *only)
{
	printf("%-16s %-15s %9s %16s\n", "structure", "distortion",
	    "as order", "|div. dev|/err");
	for (size_t s = 0; s < sizeof(structures) / sizeof(*structures); s++) {
		struct scene sc;
		struct result r;
		struct para_zone z[64];
		size_t nz;

		if (only != NULL && strstr(structures[s].name, only) == NULL)
			continue;
		if (scene_text_run(structures[s].scene, &sc, &r) != 0)
			return 1;
		nz = para_zones(&r, NULL, z, 64);
		for (size_t d = 0; d < sizeof(distortions) /
		    sizeof(*distortions); d++) {
			double *dv = calloc((size_t)seeds + 1, sizeof(*dv));
			int good = 0, n = 0;

			if ((distortions[d].what & D_SQUASH) &&
			    distortions[d].what == D_SQUASH &&
			    r.organs[0].pos[2] != r.organs[r.count - 1].pos[2])
				continue;
			for (int k = 1; k <= seeds; k++) {
				double dev;

				good += trial(&r, z, nz, distortions[d].what,
				    (uint64_t)k, &dev);
				if (!isnan(dev))
					dv[n++] = fabs(dev);
			}
			/* The median: one alias in a hundred would swamp a mean. */
			for (int i = 1; i < n; i++)
				for (int j = i; j > 0 && dv[j] < dv[j - 1]; j--) {
					double t = dv[j];

					dv[j] = dv[j - 1];
					dv[j - 1] = t;
				}
			printf("%-16s %-15s %4d/%-4d %8.2f median\n",
			    structures[s].name, distortions[d].name, good,
			    seeds, n ? dv[n / 2] : NAN);
			free(dv);
			fflush(stdout);
		}
		result_free(&r);
		scene_free(&sc);
	}
	return 0;
}

/* A head as a photograph gives it: Vogel's, jittered, some missed. */
static int
csv(long n, uint64_t seed)
{
	double alpha = 360 * (2 - (1 + sqrt(5)) / 2) * M_PI / 180;
	double sp = sqrt(2 * M_PI / sqrt(3));
	uint64_t rng = seed;

	printf("x,y\n");
	/* n points read: florets on past the n-th for those missed. */
	for (long k = 1, got = 0; got < n; k++) {
		double r = sqrt((double)k), a = (double)k * alpha;

		if (synth_uniform(&rng) < 0.05)
			continue;
		got++;
		printf("%.4f,%.4f\n", 1000 + r * cos(a) + 0.106 * sp *
		    synth_gauss(&rng), 1000 + r * sin(a) + 0.106 * sp *
		    synth_gauss(&rng));
	}
	return 0;
}

static int
speed(const char *file)
{
	double t[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
	size_t count = 0;

	for (int round = 0; round < 3; round++) {
		struct points P;
		struct axis A;
		struct axis_point *ap;
		struct unordered *U;
		double t0 = now(), t1, t2, t3;

		if (points_read(&P, file) != 0)
			return 1;
		t1 = now();
		axis_find(&A, (const double (*)[3])P.p, P.count, P.has_z, NULL);
		ap = calloc(P.count, sizeof(*ap));
		axis_points(&A, (const double (*)[3])P.p, P.count, ap);
		t2 = now();
		U = unordered_measure(&A, ap, (const double (*)[3])P.p, P.count,
		    0);
		t3 = now();
		t[0] = fmin(t[0], t1 - t0);
		t[1] = fmin(t[1], t2 - t1);
		t[2] = fmin(t[2], t3 - t2);
		count = P.count;
		free(U);
		free(ap);
		axis_free(&A);
		points_free(&P);
	}
	printf("%zu points: read %.3f s, axis %.3f s, parastichies %.3f s, "
	    "together %.3f s\n", count, t[0], t[1], t[2], t[0] + t[1] + t[2]);
	return 0;
}

int
main(int argc, char **argv)
{
	if (argc >= 2 && strcmp(argv[1], "trials") == 0)
		return trials(argc > 2 ? atoi(argv[2]) : 100, argc > 3 ?
		    argv[3] : NULL);
	if (argc >= 3 && strcmp(argv[1], "csv") == 0)
		return csv(atol(argv[2]), argc > 3 ? strtoull(argv[3], NULL,
		    10) : 1);
	if (argc >= 3 && strcmp(argv[1], "speed") == 0)
		return speed(argv[2]);
	fprintf(stderr, "usage: bench_measured trials [SEEDS [ONLY]] | csv N [SEED] "
	    "| speed FILE\n");
	return 2;
}
