/*
 * fuzz_points.c - libFuzzer harness for the measured model's points
 * reader, and the order-free analysis of whatever points it accepts:
 * a file is read or refused (at a line within the file), never more;
 * what is read holds at least POINTS_MIN finite points, no two the
 * same; and the analysis of any such points ends, its contacts naming
 * organs that exist, its zones within bounds, its numbers finite or
 * not measured (NAN).
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/axis.h"
#include "analysis/unordered.h"
#include "base/diag.h"
#include "models/measured_csv.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void
measure(const struct points *P)
{
	struct axis A;
	struct axis_point *ap = calloc(P->count, sizeof(*ap));
	struct unordered *U;

	axis_find(&A, (const double (*)[3])P->p, P->count, P->has_z, NULL);
	axis_points(&A, (const double (*)[3])P->p, P->count, ap);
	U = unordered_measure(&A, ap, (const double (*)[3])P->p, P->count,
	    0);
	if (U->count != P->count || U->nzones > UZONES_MAX)
		abort();
	for (size_t i = 0; i < U->count; i++)
		for (int s = 0; s < 2; s++)
			if (U->c[i].prev[s] >= (int32_t)U->count ||
			    (U->c[i].prev[s] >= 0 && U->c[i].dk[s] <= 0))
				abort();
	if (!isnan(U->divergence) && !(U->divergence >= 0 &&
	    U->divergence < 360 && U->divergence_err >= 0))
		abort();
	free(U);
	free(ap);
	axis_free(&A);
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct points P;

	diag_hush(1);
	if (points_parse(&P, "fuzz.csv", (const char *)data, size) == 0) {
		if (P.count < POINTS_MIN)
			abort();
		for (size_t i = 0; i < P.count; i++)
			for (int k = 0; k < 3; k++)
				if (!isfinite(P.p[i][k]))
					abort();
		/* Few enough to measure within the fuzzer's time. */
		if (P.count <= 2000)
			measure(&P);
		points_free(&P);
	}
	diag_hush(0);
	return 0;
}
