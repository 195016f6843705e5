/*
 * collision_cover.c - the cover map: which parts of the receptacle are
 * already covered, so the walk need not look there.
 *
 * Without epsilon every primordium starts its walk at the base, and the
 * walk would pass all the rings below the front: O(sqrt N) steps each.
 * But a point p with clearance F(p) = min_i (|p - Q_i| - r_i) below r
 * is covered for a primordium of radius r, and F is 1-Lipschitz, so a
 * cell whose points all lie within d of its middle point m has
 * F <= F(m) + d throughout.  cover_add lowers that bound in the cells
 * around each new primordium; a cell bounded below r is skipped whole.
 * A packing of circles of radius r leaves no point further than about
 * 1.15 r from a centre, so cells a little over r/2 a side (d about
 * 0.6 r) are mostly covered as soon as their neighbours are placed;
 * the front and true holes are not, and loose packings leave some
 * cells to refine (collision.c) or to look at exactly.  A bound under
 * most of the smallest radius still to come (cover_floor()) covers a
 * cell for every walk to come: such a cell needs no closer look and no
 * lowering again.
 *
 * Each column also remembers how many rows from the base are covered,
 * and the largest bound among them, so a walk jumps over all of them
 * at once; that prefix stays valid for every radius above that bound
 * and is rebuilt when radii shrink below it.
 *
 * Falling radii cost more, and the map is why: below the front lie
 * gaps between earlier, larger primordia whose clearance is a little
 * under the present radius.  Mostly nothing fits there, but a cell's
 * bound (the least of single primordia's, over a cell about r_min a
 * side) can lie up to a cell's size above the gap's clearance, so the
 * walk stops and looks.  Measured on the hemisphere with r falling
 * 0.003 -> 0.0005: 2.7 such stops a walk (the dome: 0.02), nine in ten
 * at gaps within r_min of r that fit nothing.  Five in six cells that
 * walks stop in are stopped in once or twice in all, so a closer proof
 * made at a stop (refine()) is seldom used before the radius falls
 * past it: a column comes round again only after some cols walks
 * (21,000 at the base there), and by then r has fallen 9% (early) to
 * 33% (late).  Sampled finely, the cells of the stops more than 32
 * rows below the head (2.2 a walk) had a clearance under 0.8 r in 31%
 * of stops, 0.8 r to r in 50%, and fitted r, off the walk's meridian,
 * in 19%: a proof exact to the clearance, made at a cell's first stop
 * (273,000 cells for 432,000 such stops), could spare at most the
 * later 37%, and would cost more than a look to make.
 *
 * Measured again on the sphere, r falling 0.0003 -> 0.00006 (bands of
 * 100,000 and 300,000): 6.6 and 8.8 looks a walk, 2 of them at the
 * column's head and the rest above it, a few hundred rows up, at cells
 * that the falling radius has just uncovered; cover_skip() read 320 and
 * 490 rows a walk, nearly all from those looks up to the next open
 * cell, not from prefixes started again (kept in four parts and cut
 * back only to the parts still covered, they read 470 on the larger).
 * A proof (refine()) at each look above the head spared 7% of looks;
 * going back to the head after passing it, as below_head() does for
 * one radius, made looks above the head looks at it, no fewer.
 *
 * cover_add() costs more there too (27% of the time on the sphere's
 * 300,000): a call visits 44 cells on the dome, 21 of them under final
 * and 1.7 taking farthest(), and 202 on that sphere, 50 under final,
 * 14 past reach, 18 spared by the check against h, 59 near and 60
 * far; 65 instructions and 0.6 mispredicted branches a cell
 * (callgrind, its band of 100,000).  Tried there, and not kept:
 * rows in runs of columns on vectors (AVX2 clones), both bounds worked
 * out for every column and the near or far one chosen, the square roots
 * in a loop of their own, then the byte checks without branches: 15%
 * slower in all (best of 5), the vector part alone 16% of the time;
 * the runs are short (some 10 columns a row) and every cell pays for
 * the far bound.  And the cells of a row within (final - 3) steps less
 * d of the middle (2.0M of 10M on the 100,000), found by angle and set
 * to final - 1 without the distance: no bound under final counts for
 * any walk, but the near bound was cheap already, 11% more instructions
 * in cover_add() for 5% fewer mispredictions, time within 2%.  The
 * cell tests in one branch, not four: 6% slower.  Asking for the
 * patch's tiles before the writes: no faster.
 *
 * What a closer map or a better walk could win at most, measured by a
 * replay: a run's t and rows recorded, then the run again with one
 * look a walk, at its answer (CLI, CSV written, best of 3, us a
 * primordium).  With cover_add() kept, the falling rows cost 1.5 to
 * 2.1 (the dome 0.96; the whole run 1.31); without it, 0.7 to 0.9 (the
 * dome 0.67).  On the sphere's 300,000, 5.5 -> 2.1 -> 0.8, the
 * hemisphere's 3.0 -> 2.0 -> 0.9, the disk to the tip 4.8 -> 1.7 ->
 * 0.7.  So with cells of 0.6 r_min the map's upkeep alone, 0.7 to 1.35
 * us (the dome's 0.29) where early radii are five times r_min, is up to
 * the dome's whole time, and three rows (the sphere's and hemisphere's
 * 300,000, the sphere to the tip) stay over 1.5 times the dome with
 * every needless look spared: the looks are not the only cost.
 *
 * So rows need not all be r_min high.  With a falling radius the rows
 * the front crosses early, under large primordia, are as high as
 * CELL_FRAC of the radius expected there (runs of 8 rows, each run's
 * bounds in steps of its own q, a power of 2 times the lowest rows';
 * its columns as much wider): cover_add() then writes some 20 to 45
 * cells a primordium, as on the dome, where cells of 0.6 r_min had it
 * write up to 200.  Used where the walks start near the front
 * (epsilon); a walk from the base crosses those rows later, at a
 * radius their bounds are far too coarse for.  Its start row is then
 * often not covered where the walk starts, and it looks at the row's
 * start before working its start out (collision_walk.c).  Measured,
 * instructions a primordium (callgrind), falling radius and epsilon r,
 * 100,000 / 300,000 / to the tip: disk 10,570 / 13,570 / 14,367 ->
 * 8,101 / 9,038 / 10,453, hemisphere 10,608 / 12,149 / 13,699 -> 8,076
 * / 8,862 / 10,065, sphere 15,278 / 14,449 / 14,914 -> 10,606 / 10,370
 * / 10,140 (the dome: 7,606 -> 7,647).  Rows of 0.5 or 0.45 of the
 * radius, or columns as wide as the rows are high, cost more.
 *
 * For the walks from the base, the rows below the front would need
 * their room kept otherwise than in bounds.  Tried, and kept on the
 * branch collision53-holes, not here: each primordium's cell of the
 * power diagram weighted (r + c)^2, c under every radius to come, cut
 * as a polygon in its tangent plane once its neighbours hem it in (in
 * it, room for r >= c is exactly where it is r_m + r from m), tiles
 * marked by primordia not yet closed, and walks that look, below the
 * rows no open primordium can reach, only where a cell's polygon cut
 * to their meridian's strip reaches r_m + r.  Exact (the reference and
 * the plain walk agree; a check that every point with room lies in a
 * hole catches polygons shrunk 3%), but the falling sphere's 100,000
 * took 2.09 s against 0.44 s: the packing is loose enough that 68-91%
 * of the final cells hold room for the least radius (sphere 100,000,
 * hemisphere 300,000, disk to the tip), so a late walk's meridian
 * crosses some 80 cells whose room may hold it (78 read a walk, 25.6
 * within their angles, 7.7 whose polygon reaches r on the strip: the
 * bound at c is loose at r beside larger neighbours), and closing a
 * primordium (a grid query of up to 150 late on, and the cuts) costs
 * about what the looks it spares do.
 *
 * cover_skip() on that sphere (a map of 32 MB; 55 MB to the tip, the
 * dome's 17 MB): 5.5 calls a walk, 103 tile words read, and two thirds
 * of its samples (perf) on the first word's load.  Kept per tile and
 * column, the largest of its bounds (not known once one is lowered),
 * side by side up the column, so that a word was eight tiles: tile
 * reads fell from 29.6M to 4.4M, but the time did not (the samples
 * moved to the first of the new words), and to the tip the disk and
 * the hemisphere were 6% and 10% slower, best of 5.  Asking for the
 * next tiles up the column while scanning, or for f, the exceptions
 * and the next tile with the head's (cover_ahead()): no faster.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "models/collision_cover.h"
#include "base/mem.h"

#define CELL_FRAC	0.6	/* row height, as a fraction of r_min */
#define CELLS_MIN	(1 << 12)
#define CELLS_MAX	(1 << 26)
#define U_NONE		UINT8_MAX
#define U_STEPS		64	/* steps of the bound per row height: up to 4 rows */
#define TIGHT		0.95	/* of r_min: bounds under it cover a cell for good */
#define GROW		1.05	/* the largest next radius worth a bound, per r */

/*
 * Cells are stored in tiles of 8 rows by 8 columns, a cache line each:
 * cover_add writes a patch of cells around a primordium and a walk
 * reads up a column, and either way few lines are touched.  Row k's
 * column jz counts among its own row's cols >> z.
 */
static inline uint8_t *
cell_z(const struct cover *cv, int32_t k, int32_t jz)
{
	int32_t b = k >> 3;
	size_t tile = cv->bbase[b] + (size_t)(jz >> 3) * (size_t)cv->bstride[b];

	return &cv->u[tile * 64 + (size_t)((jz & 7) << 3 | (k & 7))];
}

/* The cell of row k that column j of the widest rows passes through. */
static inline uint8_t *
cell(const struct cover *cv, int32_t k, int32_t j)
{
	return cell_z(cv, k, j >> cv->bz[k >> 3]);
}

static inline uint8_t
cell_u(const struct cover *cv, int32_t k, int32_t j)
{
	return *cell(cv, k, j);
}

/* The level of row k: its height is a 2^level. */
static inline int
level(const struct cover *cv, int32_t k)
{
	return cv->be[k >> 3];
}

/* Is bound u of a cell of level e under r? */
static inline int
covered(const struct cover *cv, int e, uint8_t u, double r)
{
	return u != U_NONE && u * cv->q[e] < r;
}

/* The least bound in steps of level e that is not covered for r. */
static inline uint8_t
threshold(const struct cover *cv, int e, double r)
{
	double s = ceil(r * cv->inv_q[e]);
	int u = s < U_NONE ? (int)s : U_NONE;

	/* As covered() decides, rounding and all. */
	while (u > 0 && !covered(cv, e, (uint8_t)(u - 1), r))
		u--;
	while (u < U_NONE && covered(cv, e, (uint8_t)u, r))
		u++;
	return (uint8_t)u;
}

/* Start column j's prefix again: radii fell below what it proved. */
static void
column_reset(struct cover *cv, int32_t j)
{
	cv->head[j] = 0;
	cv->f[j] = 0;
	cv->first[j] = cv->last[j] = -1;
}

/*
 * Each row's kappa: the distance within which the squared distance to
 * a point is a convex function along the row, the least of the pieces'
 * it runs through (all of one segment, so one polynomial, convex on
 * each piece and so on all of them).  A row across a joint of two
 * segments, where the curve may turn a corner, gets 0.
 */
static void
row_kappa(struct cover *cv, const struct curve *c)
{
	size_t i = 0;

	for (int32_t k = 0; k < cv->rows; k++) {
		double t0 = cv->t_row[k], t1 = cv->t_row[k + 1], kap = HUGE_VAL;

		while (i + 1 < c->npc && c->pc[i].t1 <= t0)
			i++;
		for (size_t n = i; n < c->npc && c->pc[n].t0 < t1; n++)
			kap = fmin(kap, c->pc[n].kappa);
		if (floor(t0) < ceil(t1) - 1)
			kap = 0;	/* an integer t, a joint, inside */
		cv->kappa[k] = kap;
	}
}

/*
 * The map's cells' side, and the band's length *L and widest ring's
 * circumference *W (cover_init()).
 */
static double
cover_side(const struct curve *c, double r_min, double s_band,
    double cells_most, double *L, double *W)
{
	double a = CELL_FRAC * r_min, cells;
	double most = fmin(fmax(cells_most, CELLS_MIN), CELLS_MAX);

	/*
	 * Only the band the primordia can reach is mapped: a small count
	 * of small primordia covers a strip at the base, and a map of the
	 * whole receptacle at their size would not fit.  Its columns are
	 * as wide as the band's widest ring needs.
	 */
	*L = fmin(c->length, s_band);
	*W = 0;
	for (int i = 0; i <= 64; i++) {
		double p[2];

		curve_eval(c, curve_t(c, *L * i / 64), p, NULL);
		*W = fmax(*W, p[0]);
	}
	*W = 2 * M_PI * fmin(*W + *L / 64, c->rho_max);
	/*
	 * Fewer, larger cells if there would be too many: coarser skips.
	 * A receptacle narrower than a cell has one column, and then
	 * only the rows count.
	 */
	cells = ceil(*L / a) * fmax(1, ceil(*W / a));
	if (cells > most) {
		a = sqrt(*L * *W / most) * 1.01;
		if (!(*W > a))
			a = *L / most * 1.01;
	}
	return a;
}

double
cover_rows(const struct curve *c, double r_min, double s_band,
    double cells_most)
{
	double L, W, a = cover_side(c, r_min, s_band, cells_most, &L, &W);

	return fmax(1, ceil(L / a));
}

/*
 * How high a row from arc length s0 up may be, a the least: CELL_FRAC
 * (frac) of the radius that r_front expects there, looked up at the
 * row's middle.
 */
static double
row_height(double a, double frac, double s0, double L, const double *r_front,
    int n_est)
{
	double h = a;

	for (int i = 0; i < 2; i++) {
		int k = (int)((s0 + h / 2) / L * n_est);

		h = fmax(a, frac * r_front[k < 0 ? 0 : k < n_est ? k : n_est - 1]);
	}
	return fmin(h, a * (double)(1 << (COVER_E - 1)));
}

void
cover_init(struct cover *cv, const struct curve *c, double r_min,
    double s_band, double cells_most, const double *r_est,
    const double *r_front, int n_est)
{
	double L, W, a;
	size_t n = 0;
	int32_t blocks;
	int zcap, zmax = 0;

	memset(cv, 0, sizeof(*cv));
	a = cover_side(c, r_min, s_band, cells_most, &L, &W);
	cv->band = L < c->length;
	cv->tight = TIGHT * r_min;
	if (r_front != NULL) {
		/*
		 * Runs of 8 rows, each as high as its level, up to L, the
		 * lowest CELL_FRAC r_min high; larger, if that would make
		 * more than most cells (counted as if every row were as wide
		 * as the widest, as cover_side() does, and its cells as
		 * narrow as they may be).
		 */
		double most = fmin(fmax(cells_most, CELLS_MIN), CELLS_MAX), cells;
		double frac = CELL_FRAC, a_one = a;	/* a: cover_side()'s */
		size_t cap = 64;
		int varied = 0;

		/*
		 * Rows no lower than one height's map would have, capped:
		 * the columns' tables (some 45 bytes a column of the lowest
		 * rows) would grow as the rows shrink, and on a wide thin
		 * band (the hemisphere's rim, 100,000) outgrow the cells
		 * saved.
		 */
		cv->s_row = xcalloc(cap + 1, sizeof(*cv->s_row));
		cv->be = xcalloc(cap / 8, sizeof(*cv->be));
		for (int tries = 0; tries < 8; tries++) {
			cv->rows = 0;
			cv->levels = 0;
			cells = 0;
			varied = 0;
			while (cv->rows == 0 || cv->s_row[cv->rows] < L) {
				double h[8], s0 = cv->s_row[cv->rows], most_h = a;
				int e = 0, nr = 0;

				if ((size_t)cv->rows + 8 > cap) {
					cap *= 2;
					cv->s_row = xreallocarray(cv->s_row, cap + 1,
					    sizeof(*cv->s_row));
					cv->be = xreallocarray(cv->be, cap / 8,
					    sizeof(*cv->be));
				}
				/* 8 rows (fewer at the end), then their level. */
				for (; nr < 8 && (nr == 0 || s0 < L); nr++) {
					h[nr] = row_height(a, frac, s0, L, r_front,
					    n_est);
					varied |= h[nr] > a;
					most_h = fmax(most_h, h[nr]);
					s0 += h[nr];
				}
				while (a * (double)(1 << e) < most_h)
					e++;
				cv->be[cv->rows / 8] = (uint8_t)e;
				cv->levels = e + 1 > cv->levels ? e + 1 :
				    cv->levels;
				for (int i = 0; i < nr; i++, cv->rows++) {
					cv->s_row[cv->rows + 1] =
					    cv->s_row[cv->rows] + h[i];
					/* Columns may be h / sqrt 2 wide. */
					cells += fmax(1, ceil(W / h[i] * M_SQRT2));
				}
			}
			if (cells <= most)
				break;
			a *= sqrt(cells / most) * 1.01;
			frac *= sqrt(cells / most) * 1.01;
		}
		if (!varied) {	/* all of one height after all */
			free(cv->s_row);
			free(cv->be);
			a = a_one;
		}
	}
	cv->a = a;
	cv->cols = (int32_t)fmax(1, ceil(W / a));
	/* Halvings down to 16 columns at most. */
	for (zcap = 0; zcap + 1 < COVER_Z && cv->cols >> (zcap + 5) > 0; zcap++)
		;
	if (cv->levels <= 1) {
		/* Every row a high: the rows' ends are k a, exactly. */
		cv->rows = (int32_t)fmax(1, ceil(L / a));
		cv->be = xcalloc((size_t)(cv->rows + 7) / 8, sizeof(*cv->be));
		cv->s_row = xcalloc((size_t)cv->rows + 1, sizeof(*cv->s_row));
		for (int32_t k = 0; k <= cv->rows; k++)
			cv->s_row[k] = k * a;
		cv->levels = 1;
	}
	blocks = (cv->rows + 7) / 8;
	for (int e = 0; e < cv->levels; e++) {
		cv->q[e] = a * (double)(1 << e) / U_STEPS;
		cv->inv_q[e] = U_STEPS / (a * (double)(1 << e));
		cv->final[e] = 0;
	}
	cover_floor(cv, r_min);
	cv->t_row = xcalloc((size_t)cv->rows + 1, sizeof(*cv->t_row));
	cv->rho_c = xcalloc((size_t)cv->rows, sizeof(*cv->rho_c));
	cv->z_c = xcalloc((size_t)cv->rows, sizeof(*cv->z_c));
	cv->d = xcalloc((size_t)cv->rows, sizeof(*cv->d));
	cv->h = xcalloc((size_t)cv->rows, sizeof(*cv->h));
	cv->start = xcalloc((size_t)cv->rows, sizeof(*cv->start));
	cv->kappa = xcalloc((size_t)cv->rows, sizeof(*cv->kappa));
	for (int32_t k = 0; k <= cv->rows; k++)
		cv->t_row[k] = k == cv->rows && !cv->band ? c->tmax :
		    curve_t(c, fmin(cv->s_row[k], c->length));
	for (int32_t k = 0; k < cv->rows; k++) {
		double s0 = cv->s_row[k], s1 = fmin(cv->s_row[k + 1], c->length);
		double p[2];

		/* Walks look here first when they come to a row. */
		curve_eval(c, cv->t_row[k], cv->start[k], cv->start[k] + 2);
		curve_eval(c, curve_t(c, (s0 + s1) / 2), p, NULL);
		cv->rho_c[k] = p[0];
		cv->z_c[k] = p[1];
		cv->h[k] = (s1 - s0) / 2;
	}
	row_kappa(cv, c);
	cv->bz = xcalloc((size_t)blocks, sizeof(*cv->bz));
	cv->bbase = xcalloc((size_t)blocks, sizeof(*cv->bbase));
	cv->bstride = xcalloc((size_t)blocks, sizeof(*cv->bstride));
	for (int32_t b = 0; b < blocks; b++) {
		double rho = 0, wide = a / 2, ab = 0;
		int z = 0;

		/*
		 * Rows higher than a: as many fewer columns, as if a were
		 * their height (the mean of the block's, to a power of 2).
		 */
		if (cv->levels > 1) {
			int32_t k1 = 8 * b + 8 < cv->rows ? 8 * b + 8 : cv->rows;

			ab = (cv->s_row[k1] - cv->s_row[8 * b]) / (k1 - 8 * b);
			while (z < zcap && a * (double)(2 << z) <= ab * M_SQRT2)
				z++;
			wide = a * (double)(1 << z) / 2;
		}

		/*
		 * The block's widest ring, rho within h of each middle, in
		 * cells at most half a row wide: halving further saves
		 * cover_add little and costs bounds slack (measured).
		 */
		for (int32_t k = 8 * b; k < 8 * b + 8 && k < cv->rows; k++)
			rho = fmax(rho, cv->rho_c[k] + cv->h[k]);
		/*
		 * Or as wide as cells sized for the least radius expected
		 * to walk there, if that is wider: a rising radius walks
		 * high up only when it has grown, and cells of r_min a side
		 * there had cover_add() write (2 r / a)^2 of them for each
		 * primordium.
		 */
		if (r_est != NULL) {
			int i0 = (int)(8 * b * a / L * n_est), i1 = (int)(fmin(
			    (8 * b + 8) * a, L) / L * n_est);
			double least = HUGE_VAL;

			for (int i = i0 < 0 ? 0 : i0; i <= i1 && i < n_est; i++)
				least = fmin(least, r_est[i]);
			if (least < HUGE_VAL)
				wide = fmax(wide, CELL_FRAC * least);
		}
		while (z < zcap && (cv->cols >> (z + 1)) * wide >= 2 * M_PI *
		    rho)
			z++;
		cv->bz[b] = (uint8_t)z;
		zmax = z > zmax ? z : zmax;
	}
	/*
	 * So that the columns nest, cols is a multiple of 2^zmax: at most
	 * a sixteenth more, and none more where no row is halved.
	 */
	cv->cols = (cv->cols + (1 << zmax) - 1) >> zmax << zmax;
	/* The tiles: a run of blocks of one z, column by column. */
	for (int32_t b0 = 0, b1; b0 < blocks; b0 = b1) {
		int32_t groups = ((cv->cols >> cv->bz[b0]) + 7) / 8;

		for (b1 = b0 + 1; b1 < blocks && cv->bz[b1] == cv->bz[b0]; b1++)
			;
		for (int32_t b = b0; b < b1; b++) {
			cv->bbase[b] = n + (size_t)(b - b0);
			cv->bstride[b] = b1 - b0;
		}
		n += (size_t)groups * (size_t)(b1 - b0);
	}
	cv->sub = xcalloc((size_t)cv->rows * COVER_SUB, sizeof(*cv->sub));
	for (int32_t k = 0; k < cv->rows; k++) {
		double s0 = cv->s_row[k], s1 = fmin(cv->s_row[k + 1], c->length);
		int32_t ncol = cv->cols >> cv->bz[k >> 3];

		for (int i = 0; i < COVER_SUB; i++) {
			double *sp = cv->sub[k * COVER_SUB + i];

			curve_eval(c, curve_t(c, s0 + (s1 - s0) * (i + 0.5) /
			    COVER_SUB), sp, NULL);
			sp[2] = (s1 - s0) / (2 * COVER_SUB) + (sp[0] + (s1 - s0) /
			    (2 * COVER_SUB)) * M_PI / ((double)ncol * COVER_SUB);
		}
		/*
		 * Along the curve a point is at most (s1 - s0)/2 away (a
		 * chord is no longer than its arc); about the axis at most
		 * rho pi / cols, rho at most half a row more than here.
		 */
		cv->d[k] = cv->h[k] + (cv->rho_c[k] + cv->h[k]) * M_PI / ncol;
	}
	for (int32_t b = 0; b < blocks; b++) {
		int z = cv->bz[b];
		int32_t ncol = cv->cols >> z;

		if (cv->mid[z] != NULL)
			continue;	/* only the z in use */
		for (int i = 0; i < COVER_SUB; i++) {
			double off = ((i + 0.5) / COVER_SUB - 0.5) * 2 * M_PI /
			    ncol;

			cv->sub_turn[z][i][0] = cos(off);
			cv->sub_turn[z][i][1] = sin(off);
		}
		cv->mid[z] = xcalloc(2 * (size_t)ncol, sizeof(double));
		cv->edge[z] = xcalloc(2 * (size_t)ncol + 2, sizeof(double));
		for (int32_t j = 0; j <= ncol; j++) {
			double phi = j * 2 * M_PI / ncol;

			cv->edge[z][2 * j] = cos(phi);
			cv->edge[z][2 * j + 1] = sin(phi);
			if (j == ncol)
				break;
			phi = (j + 0.5) * 2 * M_PI / ncol;
			cv->mid[z][2 * j] = cos(phi);
			cv->mid[z][2 * j + 1] = sin(phi);
		}
	}
	n *= 64;
	cv->u = xcalloc_big(n, 1);
	memset(cv->u, U_NONE, n);
	cv->head = xcalloc((size_t)cv->cols, sizeof(*cv->head));
	cv->f = xcalloc((size_t)cv->cols, sizeof(*cv->f));
	cv->first = xcalloc((size_t)cv->cols, sizeof(*cv->first));
	cv->last = xcalloc((size_t)cv->cols, sizeof(*cv->last));
	for (int32_t j = 0; j < cv->cols; j++)
		column_reset(cv, j);
	cv->lim_r = 0;		/* no walk yet */
}

void
cover_floor(struct cover *cv, double r_floor)
{
	/*
	 * The steps under TIGHT r_floor: 0 .. final - 1, never fewer.  A
	 * final cell keeps its bound where it would have been lowered,
	 * but both are under every radius to come, so no walk can tell.
	 * tight, under which row_add() takes the simple bound, stays as
	 * made for r_min: moved up with the floor, it gave some cells
	 * bounds looser than they had (neither bound is always the
	 * lower), walks looked there, and the exits worked out from
	 * those looks moved placements by rounding (up to 5e-13 on the
	 * hemisphere, radius rising, to the tip).
	 */
	for (int e = 0; e < cv->levels; e++)
		while (cv->final[e] < U_NONE && (cv->final[e] + 1) * cv->q[e] <
		    TIGHT * r_floor)
			cv->final[e]++;
}

void
cover_free(struct cover *cv)
{
	free(cv->be);
	free(cv->s_row);
	free(cv->t_row);
	free(cv->start);
	free(cv->rho_c);
	free(cv->z_c);
	free(cv->d);
	free(cv->h);
	free(cv->kappa);
	free(cv->sub);
	free(cv->bz);
	free(cv->bbase);
	free(cv->bstride);
	for (int z = 0; z < COVER_Z; z++) {
		free(cv->mid[z]);
		free(cv->edge[z]);
	}
	free(cv->u);
	free(cv->head);
	free(cv->f);
	free(cv->first);
	free(cv->last);
	free(cv->ex);
}

int32_t
cover_col(const struct cover *cv, double phi)
{
	int32_t j = (int32_t)(phi / (2 * M_PI) * cv->cols);

	return j < 0 ? 0 : j >= cv->cols ? cv->cols - 1 : j;
}

double
cover_angles(const struct cover *cv, int32_t k, int32_t j, double *phi0)
{
	int z = cv->bz[k >> 3];
	int32_t ncol = cv->cols >> z;

	*phi0 = (j >> z) * 2 * M_PI / ncol;
	return 2 * M_PI / ncol;
}

void
cover_dirs(const struct cover *cv, int32_t k, int32_t j, double mid[2],
    double sub[COVER_SUB][2])
{
	int z = cv->bz[k >> 3];
	const double *m = &cv->mid[z][2 * (j >> z)];

	mid[0] = m[0];
	mid[1] = m[1];
	/* The middle turned by each sub-column's offset from it. */
	for (int i = 0; i < COVER_SUB; i++) {
		const double *o = cv->sub_turn[z][i];

		sub[i][0] = m[0] * o[0] - m[1] * o[1];
		sub[i][1] = m[1] * o[0] + m[0] * o[1];
	}
}

/* The last row in [lo, hi] that starts at or before t, else lo. */
static int32_t
row_within(const struct cover *cv, double t, int32_t lo, int32_t hi)
{
	while (lo < hi) {
		int32_t mid = (lo + hi + 1) / 2;

		if (cv->t_row[mid] <= t)
			lo = mid;
		else
			hi = mid - 1;
	}
	return lo;
}

int32_t
cover_row(const struct cover *cv, double t)
{
	return row_within(cv, t, 0, cv->rows - 1);
}

/*
 * The row holding t, at or past row k, which starts at or before t: a
 * walk moves up a few rows a stop, so strides doubling from k find it
 * in a few steps where a search of every row takes a dozen or more.
 */
static int32_t
row_from(const struct cover *cv, double t, int32_t k)
{
	int32_t step = 1;

	while (k + step < cv->rows && cv->t_row[k + step] <= t) {
		k += step;
		step *= 2;
	}
	return row_within(cv, t, k, k + step < cv->rows ? k + step - 1 :
	    cv->rows - 1);
}

static inline void
lower_at(uint8_t *u, double inv_q, double U)
{
	/* Rounded up, and a step more: a bound must never shrink. */
	double steps = U * inv_q + 2;

	if (steps < *u)
		*u = steps > 0 ? (uint8_t)steps : 0;
}

void
cover_lower(struct cover *cv, int32_t k, int32_t j, double U)
{
	lower_at(cell(cv, k, j), cv->inv_q[level(cv, k)], U);
}

/*
 * How far the points of column jz at radius rho_a lie from (x, y) at
 * radius rho, at most: the squared distance is rho_a^2 + rho^2 - 2
 * rho_a m, m the least of x cos + y sin over the column's angles.
 * The distance grows with the angle from (x, y), so m is at an edge,
 * or -rho when the opposite meridian is inside the column.
 */
static inline double
least_proj(const struct cover *cv, int z, int32_t jz, double x, double y,
    double rho, int opp)
{
	const double *e = &cv->edge[z][2 * jz];
	double a = x * e[0] + y * e[1], b = x * e[2] + y * e[3];

	/*
	 * Opposite (x, y) inside the column (narrower than pi): sines say.
	 * Asked only where the caller's columns reach round to it (opp).
	 */
	if (opp && (cv->cols >> z) >= 3 && -(e[0] * y - e[1] * x) >= 0 &&
	    -(x * e[3] - y * e[2]) >= 0)
		return -rho;
	return a < b ? a : b;
}

/*
 * How far the points of cell (k, jz) lie from (x, y, z), at most: each
 * lies within h[k] / COVER_SUB of the middle arc of its sub-row, along
 * its own meridian (a chord is no longer than its arc), so the farthest
 * of those arcs' points, plus that, bounds it.  One middle arc for the
 * row and h[k] left the bound of cells beside a large primordium a
 * quarter of r_min loose: with a falling radius, walks stopped there.
 *
 * Sub-row s at (rho_s, z_s) is at squared distance rho_s^2 + rho^2 +
 * (z_s - z)^2 - 2 rho_s m from (x, y, z), m the projection, so a row
 * keeps A_s (all but the last term) and B_s = 2 rho_s: what is left
 * for a cell is the least m and four products.
 */
struct subs {
	double	 A[COVER_SUB], B[COVER_SUB];
	int	 n;		/* how many to try: 2 (the ends) or all */
};

_Static_assert(COVER_SUB >= 2, "farthest() tries at least two sub-rows");

/*
 * With m fixed, A_s - B_s m is |C_s - (m, z)|^2 + rho^2 - m^2: the
 * squared distance from a point of the meridian plane to the sub-row's
 * point C_s on the generating curve, and a constant.  Where the curve
 * bends gently enough for the distances at hand (ends_only), that is a
 * convex function along the row, and the end sub-rows are the
 * farthest: only they are tried.
 */
static void
subs_of(const struct cover *cv, int32_t k, double z, double rho,
    int ends_only, struct subs *sb)
{
	int step = ends_only ? COVER_SUB - 1 : 1;

	sb->n = 0;
	for (int sa = 0; sa < COVER_SUB; sa += step) {
		const double *sp = cv->sub[k * COVER_SUB + sa];
		double dz = sp[1] - z;

		sb->A[sb->n] = sp[0] * sp[0] + dz * dz + rho * rho;
		sb->B[sb->n++] = 2 * sp[0];
	}
}

static inline double
farthest(const struct cover *cv, int zk, int32_t jz, double x, double y,
    double rho, const struct subs *sb, double hk, int opp)
{
	double m = least_proj(cv, zk, jz, x, y, rho, opp);
	double far = sb->A[0] - sb->B[0] * m, f = sb->A[1] - sb->B[1] * m;

	far = f > far ? f : far;
	for (int sa = 2; sa < sb->n; sa++) {
		f = sb->A[sa] - sb->B[sa] * m;
		far = f > far ? f : far;
	}
	return sqrt(far) + hk / COVER_SUB;
}

/*
 * What cover_add knows while it works along a row: the new primordium,
 * the row's middle ring and reach, and the sub-row terms once a cell
 * needs them.
 */
struct row_add {
	double		 x, y, z, r, rho;	/* the primordium */
	int32_t		 k;
	int		 zk;
	double		 rk, dz;		/* the row's middle */
	double		 reach2, near2, dk, hk, q, inv_q;
	uint8_t		 final;
	int		 opp;			/* the row's cells reach the
						   opposite meridian */
	int		 ends_only;		/* the end sub-rows are the
						   farthest */
	const double	*mid;
	int		 have_sb;
	struct subs	 sb;
};

/* Lower cell j of the row, at *up, to what the new primordium proves. */
static inline void
cell_add(const struct cover *cv, struct row_add *ra, int32_t j, uint8_t *up)
{
	double dx, dy, D2, U;
	uint8_t u;

	/* Covered for every radius already: nothing to gain. */
	if ((u = *up) < ra->final)
		return;
	dx = ra->rk * ra->mid[2 * j] - ra->x;
	dy = ra->rk * ra->mid[2 * j + 1] - ra->y;
	D2 = dx * dx + dy * dy + ra->dz * ra->dz;
	if (D2 >= ra->reach2)
		return;
	/*
	 * No square root where the bound would drop by less than h at
	 * most (both bounds are at least the middle's distance less r):
	 * taking those too changed no walk's stops, measured.
	 */
	if (u != U_NONE) {
		double L = (u - 2) * ra->q + ra->r - ra->hk;

		if (L <= 0 || D2 >= L * L)
			return;
	}
	/*
	 * Near the middle, the middle's distance and the cell's size will
	 * do; farther out, only the sub-rows' farthest points bound it
	 * closely enough to matter.
	 */
	if (D2 < ra->near2)
		U = sqrt(D2) - ra->r + ra->dk;
	else {
		if (!ra->have_sb) {
			subs_of(cv, ra->k, ra->z, ra->rho, ra->ends_only,
			    &ra->sb);
			ra->have_sb = 1;
		}
		U = farthest(cv, ra->zk, j, ra->x, ra->y, ra->rho, &ra->sb,
		    ra->hk, ra->opp) - ra->r;
	}
	lower_at(up, ra->inv_q, U);
}

/* The cells of row k within reach of the primordium, column jphi's. */
static void
row_add(struct cover *cv, struct row_add *ra, int32_t k, int32_t jphi)
{
	double reach = GROW * ra->r - cv->d[k] + ra->r, m, wf, lim;
	/* Within this of the middle, the simple bound is under tight. */
	double near = cv->tight + ra->r - cv->d[k];
	int zk = cv->bz[k >> 3];
	int32_t ncol = cv->cols >> zk, jc = jphi >> zk, w, lo, hi, run[2][2];
	/* The row's cells, as cell_z() finds them. */
	uint8_t *tiles = &cv->u[cv->bbase[k >> 3] * 64 + (size_t)(k & 7)];
	size_t stride = (size_t)cv->bstride[k >> 3] * 64;
	int nrun = 0;

	ra->k = k;
	ra->zk = zk;
	if (cv->levels > 1) {	/* else cover_add() has set them */
		ra->q = cv->q[level(cv, k)];
		ra->inv_q = cv->inv_q[level(cv, k)];
		ra->final = cv->final[level(cv, k)];
	}
	ra->rk = cv->rho_c[k];
	ra->dz = cv->z_c[k] - ra->z;
	ra->reach2 = reach * reach;
	ra->near2 = near > 0 ? near * near : 0;
	ra->dk = cv->d[k];
	ra->hk = cv->h[k];
	ra->mid = cv->mid[zk];
	ra->have_sb = 0;
	lim = ra->reach2 - ra->dz * ra->dz - (ra->rk - ra->rho) * (ra->rk -
	    ra->rho);
	m = 4 * ra->rk * ra->rho;
	if (lim <= 0)
		return;
	/*
	 * |P - Q|^2 = (rk - rho)^2 + 4 rk rho sin^2(dphi / 2) + dz^2 (near
	 * a dome's top rows differ in rho more than in z), and the middle
	 * of column jc + dj is at least |dj| - 1/2 columns from the
	 * primordium's angle: out of reach past dphi/2 = asin(x), x^2 =
	 * lim / m, which is at most x / sqrt(1 - x^2) (its tangent), close
	 * for the small x of most rows and without asin().
	 */
	wf = m > lim ? sqrt(lim / (m - lim)) / M_PI * ncol + 0.5 : ncol;
	/* Rounded up; ceil() is a call. */
	w = wf < ncol ? (int32_t)wf + ((int32_t)wf < wf) : ncol;
	/*
	 * Columns jc - w .. jc + w round the ring: at most two runs of
	 * columns in order, a cell's place one step on from the last's.
	 */
	lo = jc - w;
	hi = jc + w;
	if (2 * w + 1 >= ncol) {	/* the whole ring, once */
		lo = 0;
		hi = ncol - 1;
	} else if (lo < 0) {		/* the part before 0, from the end */
		run[nrun][0] = lo + ncol;
		run[nrun++][1] = ncol - 1;
		lo = 0;
	} else if (hi >= ncol) {	/* the part past the end, from 0 */
		run[nrun][0] = 0;
		run[nrun++][1] = hi - ncol;
		hi = ncol - 1;
	}
	run[nrun][0] = lo;
	run[nrun++][1] = hi;
	/*
	 * The meridian opposite the primordium lies in column jc + ncol / 2,
	 * give or take one, and no point of columns jc - w .. jc + w is
	 * further round than w + 1 columns from it: only 2 w + 3 >= ncol
	 * can reach it.  Elsewhere the least projection is at an edge.
	 */
	ra->opp = 2 * w + 3 >= ncol;
	/* No cell point is further than reach + d from the primordium. */
	ra->ends_only = reach + cv->d[k] < cv->kappa[k];
	for (int i = 0; i < nrun; i++) {
		int32_t j = run[i][0];
		uint8_t *up = tiles + (size_t)(j >> 3) * stride + (size_t)((j &
		    7) << 3);

		for (; j <= run[i][1]; j++, up += (j & 7) != 0 ? 8 : stride - 56)
			cell_add(cv, ra, j, up);
	}
}

void
cover_add(struct cover *cv, double t, int32_t row, double phi, double x,
    double y, double z, double r)
{
	/* Rows as far as the bound can bring a cell under GROW r. */
	int32_t kq = row >= 0 ? row : cover_row(cv, t), span, k0, k1, jphi;
	double rows = ceil(GROW * r / cv->a);
	/*
	 * The row's constants live here, not in *cv: the cells' writes
	 * (bytes, which may alias anything) would have them read again
	 * after each cell.
	 */
	struct row_add ra = { .x = x, .y = y, .z = z, .r = r,
	    .rho = sqrt(x * x + y * y), .q = cv->q[0], .inv_q = cv->inv_q[0],
	    .final = cv->final[0] };

	if (cv->levels == 1) {
		span = rows < cv->rows ? (int32_t)rows : cv->rows;
		k0 = kq - span - 1 < 0 ? 0 : kq - span - 1;
		k1 = kq + span + 1 >= cv->rows ? cv->rows - 1 : kq + span + 1;
	} else {
		/* Rows of many heights: as far in arc length, and one more. */
		double reach = GROW * r;

		for (k0 = kq; k0 > 0 && cv->s_row[kq] - cv->s_row[k0] <= reach;
		    k0--)
			;
		for (k1 = kq; k1 + 1 < cv->rows && cv->s_row[k1 + 1] -
		    cv->s_row[kq + 1] <= reach; k1++)
			;
	}
	jphi = cover_col(cv, phi);
	for (int32_t k = k0; k <= k1; k++)
		row_add(cv, &ra, k, jphi);
}

void
cover_ahead(const struct cover *cv, double phi)
{
	int32_t j = cover_col(cv, phi), k = cv->head[j];

	if (k < cv->rows)
		PREFETCH(cell(cv, k & ~7, j));
}

/* The row where t moves next in column j, below its head: an exception or the head. */
static int32_t
prefix_next(struct cover *cv, int32_t j, int32_t k, double r)
{
	int32_t *link = &cv->first[j], prev = -1;

	while (*link >= 0) {
		struct except *e = &cv->ex[*link];
		uint8_t u = cell_u(cv, e->row, j);
		int lv = level(cv, e->row);

		if (covered(cv, lv, u, r)) {
			/* Covered since: into the prefix with the rest. */
			unsigned u0 = (unsigned)u << lv;

			if (u0 > cv->f[j])
				cv->f[j] = u0 < U_NONE ? (uint8_t)u0 : U_NONE;
			if (cv->last[j] == *link)
				cv->last[j] = prev;
			*link = e->next;
			continue;
		}
		if (e->row >= k)
			return e->row;
		prev = *link;
		link = &e->next;
	}
	return cv->head[j];
}

/*
 * Move the walk to the start of row k: past the tip if there is none,
 * to the band's end, where no row is, if the map ends below the tip.
 */
static int
move_to(const struct cover *cv, double *t, int32_t *row, int32_t k)
{
	*t = k == cv->rows && !cv->band ? HUGE_VAL : cv->t_row[k];
	*row = k < cv->rows ? k : -1;
	return 1;
}

/*
 * Eight bounds read as one word: are all of them under L (0 .. 256)?
 * Each byte gets a 16-bit lane of its own and 256 - L added (lanes(L)),
 * so a byte of L or more, and only such, carries into its lane's bit 8
 * (at most 511: no lane spills into the next).  The order of the bytes
 * in the word does not matter.
 */
static inline uint64_t
lanes(unsigned L)
{
	return (uint64_t)(256 - L) * 0x0001000100010001u;
}

static inline int
all_below(uint64_t x, uint64_t add)
{
	const uint64_t lo = 0x00FF00FF00FF00FFu, carry = 0x0100010001000100u;

	return ((((x & lo) + add) | (((x >> 8) & lo) + add)) & carry) == 0;
}

/*
 * Column j's eight cells of the tile above run's, row e its first: in
 * a run of blocks of one z the tiles of a group of columns lie one
 * after another (cover_init), so the next is 64 bytes on.
 */
static inline const uint8_t *
column_up(const struct cover *cv, const uint8_t *run, int32_t e, int32_t j)
{
	if (e >= cv->rows)
		return run;	/* the scan ends: never read */
	return cv->bz[e >> 3] == cv->bz[(e >> 3) - 1] ? run + 64 :
	    cell(cv, e, j);
}

/*
 * Column j's prefix grows by n rows, the largest bound among them most
 * steps of q[0] (U_NONE: that many or more).
 */
static void
prefix_grow(struct cover *cv, int32_t j, int32_t n, uint8_t most)
{
	cv->head[j] += n;
	if (most > cv->f[j])
		cv->f[j] = most;
}

int
cover_skip(struct cover *cv, double *t, int32_t j, double r, int32_t *row)
{
	/* Walks mostly step a row at a time: try the next row first. */
	int32_t k = *row, h, e;
	int moved = 0, lv, varied = cv->levels > 1;
	uint8_t lim, most = 0;
	uint64_t below_lim, below_most;
	const uint8_t *run;
	unsigned most0 = 0;	/* in steps of q[0], rows of other levels */

	if (cv->band && *t >= cv->t_row[cv->rows]) {
		*row = -1;	/* unmapped: the walk goes on alone */
		return 0;
	}
	if (cv->f[j] * cv->q[0] >= r || (varied && cv->f[j] == U_NONE))
		column_reset(cv, j);
	if (k < 0 || k >= cv->rows || !(cv->t_row[k] <= *t))
		/* Most walks start at the base: search up from it. */
		k = *t >= cv->t_row[0] ? row_from(cv, *t, 0) : 0;
	else if (k + 1 < cv->rows && !(*t < cv->t_row[k + 1]))
		k = row_from(cv, *t, k);
	*row = k;
	h = cv->head[j];
	if (k < h) {
		e = prefix_next(cv, j, k, r);
		if (e < h || h >= cv->rows)
			return e == k ? 0 : move_to(cv, t, row, e);
		/* To the head, and on up from it now, not in another call. */
		moved = move_to(cv, t, row, h);
		k = h;
	}
	/*
	 * At or past the head: every covered row from here in one go,
	 * a tile's eight rows of the column at a time (they lie side by
	 * side), and the prefix grows by them when the walk is at its head.
	 */
	if (r != cv->lim_r) {	/* once a walk */
		for (int l = 0; l < cv->levels; l++)
			cv->lim[l] = threshold(cv, l, r);
		cv->lim_r = r;
	}
	lv = level(cv, k);
	lim = cv->lim[lv];
	below_lim = lanes(lim);
	below_most = lanes(1);
	run = cell(cv, k & ~7, j);
	for (e = k; e < cv->rows; ) {
		int i = e & 7, end = cv->rows - (e & ~7) < 8 ?
		    cv->rows - (e & ~7) : 8;

		if (varied && i == 0 && level(cv, e) != lv) {
			/*
			 * Rows of another height: the largest bound so far
			 * as a length, and this level's steps from here.
			 */
			unsigned m0 = (unsigned)most << lv;

			most0 = m0 > most0 ? m0 : most0;
			lv = level(cv, e);
			lim = cv->lim[lv];
			below_lim = lanes(lim);
			/* lim >= 1: a bound of 0 is under any radius. */
			most = (most0 >> lv) < lim ? (uint8_t)(most0 >> lv) :
			    (uint8_t)(lim - 1);
			below_most = lanes(most + 1u);
		}
		/*
		 * A tile's eight rows at once where all are covered (a reset
		 * column's long scan is mostly such), and the largest bound
		 * worked out only where one of them exceeds the largest yet.
		 */
		if (i == 0 && end == 8) {
			uint64_t x;

			memcpy(&x, run, sizeof(x));
			if (all_below(x, below_most))
				i = 8;
			else if (all_below(x, below_lim)) {
				for (int b = 0; b < 8; b++)
					most = run[b] > most ? run[b] : most;
				below_most = lanes(most + 1u);
				i = 8;
			}
		}
		for (; i < end && run[i] < lim; i++)
			most = run[i] > most ? run[i] : most;
		e = (e & ~7) + i;
		if (i < end)
			break;
		run = column_up(cv, run, e, j);
	}
	if (e == k)
		return moved;
	if (k == h) {
		unsigned m0 = (unsigned)most << lv;

		m0 = m0 > most0 ? m0 : most0;
		prefix_grow(cv, j, e - k, m0 < U_NONE ? (uint8_t)m0 : U_NONE);
	}
	return move_to(cv, t, row, e);
}

long long
cover_check(const struct cover *cv, const struct curve *c, double r,
    int every, int (*near)(void *, const double p[3], double U), void *ctx)
{
	long long misses = 0, seen = 0;

	for (int32_t k = 0; k < cv->rows; k++) {
		int z = cv->bz[k >> 3], lv = level(cv, k);
		int32_t ncol = cv->cols >> z;
		double s0 = cv->s_row[k], s1 = fmin(cv->s_row[k + 1], c->length);
		double rz[3][2];

		for (int i = 0; i < 3; i++)
			curve_eval(c, curve_t(c, s0 + (s1 - s0) * i / 2), rz[i],
			    NULL);
		for (int32_t jz = 0; jz < ncol; jz++) {
			uint8_t u = *cell_z(cv, k, jz);
			/* Its edges' and middle's angles. */
			const double *e = &cv->edge[z][2 * jz],
			    *m = &cv->mid[z][2 * jz], *cs[3] = { e, m, e + 2 };

			if (!covered(cv, lv, u, r) || seen++ % every != 0)
				continue;
			for (int i = 0; i < 3; i++)
				for (int b = 0; b < 3; b++) {
					double p[3] = { rz[i][0] * cs[b][0],
					    rz[i][0] * cs[b][1], rz[i][1] };

					misses += !near(ctx, p, u * cv->q[lv]);
				}
		}
	}
	return misses;
}

void
cover_passed(struct cover *cv, int32_t j, int32_t k)
{
	struct except *e;

	if (k != cv->head[j])
		return;
	if (cv->nex == cv->exmax) {
		cv->exmax = cv->exmax ? 2 * cv->exmax : 1024;
		cv->ex = xreallocarray(cv->ex, cv->exmax, sizeof(*cv->ex));
	}
	e = &cv->ex[cv->nex];
	e->row = k;
	e->next = -1;
	if (cv->last[j] >= 0)
		cv->ex[cv->last[j]].next = (int32_t)cv->nex;
	else
		cv->first[j] = (int32_t)cv->nex;
	cv->last[j] = (int32_t)cv->nex++;
	cv->head[j] = k + 1;
}
