/*
 * ppmstat.c - facts about a binary PPM (P6) picture, for the render
 * tests.  Usage:
 *	ppmstat FILE R G B TOL	pixels within TOL of (R, G, B) in each
 *				channel: "count total cx cy" (centroid)
 *	ppmstat FILE at COL ROW	the colour of one pixel: "R G B"
 *	ppmstat FILE diff OTHER	pixels whose colour differs from OTHER's,
 *				of the same size: "count total maxdiff"
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The next header number, past white space and # comments. */
static int
number(FILE *fp)
{
	int c, v = 0;

	while ((c = fgetc(fp)) == '#' || c == ' ' || c == '\n' || c == '\r' ||
	    c == '\t')
		if (c == '#')
			while ((c = fgetc(fp)) != '\n' && c != EOF)
				continue;
	if (c < '0' || c > '9')
		return -1;
	for (; c >= '0' && c <= '9'; c = fgetc(fp))
		v = v * 10 + (c - '0');
	return v;	/* the one white space after it is consumed */
}

static unsigned char *
load(const char *path, int *w, int *h)
{
	FILE *fp = fopen(path, "rb");
	unsigned char *px;
	int max;

	if (fp == NULL || fgetc(fp) != 'P' || fgetc(fp) != '6' ||
	    (*w = number(fp)) <= 0 || (*h = number(fp)) <= 0 ||
	    (max = number(fp)) != 255) {
		fprintf(stderr, "ppmstat: %s: not an 8-bit P6 picture\n", path);
		exit(2);
	}
	px = malloc((size_t)*w * (size_t)*h * 3);
	if (px == NULL || fread(px, 3, (size_t)*w * (size_t)*h, fp) !=
	    (size_t)*w * (size_t)*h) {
		fprintf(stderr, "ppmstat: %s: short picture\n", path);
		exit(2);
	}
	fclose(fp);
	return px;
}

int
main(int argc, char *argv[])
{
	unsigned char *px;
	int w, h;

	if (argc == 5 && strcmp(argv[2], "at") == 0) {
		int c = atoi(argv[3]), r = atoi(argv[4]);

		const unsigned char *p;

		px = load(argv[1], &w, &h);
		if (c < 0 || r < 0 || c >= w || r >= h) {
			free(px);
			return 2;
		}
		p = px + ((size_t)r * (size_t)w + (size_t)c) * 3;
		printf("%d %d %d\n", p[0], p[1], p[2]);
		free(px);
		return 0;
	}
	if (argc == 4 && strcmp(argv[2], "diff") == 0) {
		unsigned char *other;
		int w2, h2, most = 0;
		long n = 0;

		px = load(argv[1], &w, &h);
		other = load(argv[3], &w2, &h2);
		if (w != w2 || h != h2) {
			free(px);
			free(other);
			return 2;
		}
		for (size_t i = 0; i < (size_t)w * (size_t)h; i++) {
			int d = 0;

			for (int k = 0; k < 3; k++)
				if (abs(px[3 * i + k] - other[3 * i + k]) > d)
					d = abs(px[3 * i + k] - other[3 * i + k]);
			n += d > 0;
			most = d > most ? d : most;
		}
		printf("%ld %ld %d\n", n, (long)w * h, most);
		free(px);
		free(other);
		return 0;
	}
	if (argc == 6) {
		int want[3] = { atoi(argv[2]), atoi(argv[3]), atoi(argv[4]) };
		int tol = atoi(argv[5]);
		double cx = 0, cy = 0;
		long n = 0;

		px = load(argv[1], &w, &h);
		for (int r = 0; r < h; r++)
			for (int c = 0; c < w; c++) {
				const unsigned char *p =
				    px + ((size_t)r * (size_t)w + (size_t)c) * 3;

				if (abs(p[0] - want[0]) <= tol &&
				    abs(p[1] - want[1]) <= tol &&
				    abs(p[2] - want[2]) <= tol) {
					n++;
					cx += c + 0.5;
					cy += r + 0.5;
				}
			}
		printf("%ld %ld %.2f %.2f\n", n, (long)w * h,
		    n ? cx / (double)n : -1, n ? cy / (double)n : -1);
		free(px);
		return 0;
	}
	fprintf(stderr, "usage: ppmstat FILE R G B TOL | ppmstat FILE at COL "
	    "ROW | ppmstat FILE diff OTHER\n");
	return 2;
}
