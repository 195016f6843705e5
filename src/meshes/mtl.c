/*
 * mtl.c - the materials of a Wavefront .mtl file, as far as glTF's base
 * colour goes: newmtl, Kd and d.  The rest (Ka, Ks, maps, and what each
 * program adds) is skipped.
 */
#include <stdlib.h>
#include <string.h>

#include "base/diag.h"
#include "base/mem.h"
#include "meshes/mtl.h"
#include "meshes/objtext.h"

/* The rest of the line, without blanks at its ends, as a name. */
static void
rest_name(char *dst, size_t sz, const char *p, const char *end)
{
	size_t n;

	p = objtext_skip(p, end);
	while (end > p && objtext_blank(end[-1]))
		end--;
	n = (size_t)(end - p) < sz - 1 ? (size_t)(end - p) : sz - 1;
	memcpy(dst, p, n);
	dst[n] = '\0';
}

/* Kd r g b (or one grey), d alpha; a number from 0 to 1 each. */
static int
mtl_numbers(struct objtext *O, const char *p, const char *end, float *out,
    int want)
{
	double x[3];
	int n = objtext_numbers(O, p, end, x, 1, want, want == 3 ? "Kd" : "d");

	if (n < 0)
		return -1;
	if (want == 3 && n == 2)
		return objtext_fail(O, "Kd takes 1 or 3 numbers, not 2");
	for (int k = 0; k < want; k++) {
		double c = x[n == 1 ? 0 : k];

		/* Some programs write colours past 1; glTF's end there. */
		out[k] = (float)(c < 0 ? 0 : c > 1 ? 1 : c);
	}
	return 0;
}

int
mtl_parse(struct mtl_material **mats, size_t *nmats, const char *file,
    const char *text, size_t len)
{
	struct objtext O = { file, 0 };
	struct mtl_material *cur = NULL;
	const char *p, *end, *nl;
	char *copy;
	int at = objtext_nul_line(text, len), rc = 0;

	if (at > 0) {
		diag(ST_SCENE, file, at, 0, "NUL byte: a material library is "
		    "text");
		return -1;
	}
	copy = xmalloc(len + 1);
	memcpy(copy, text, len);
	copy[len] = '\0';
	end = copy + len;
	for (p = copy, O.line = 1; p < end && rc == 0; p = nl + 1, O.line++) {
		const char *s, *w;

		if ((nl = memchr(p, '\n', (size_t)(end - p))) == NULL)
			nl = end;
		s = objtext_skip(p, nl);
		w = objtext_word_end(s, nl);
		if (w - s == 6 && memcmp(s, "newmtl", 6) == 0) {
			*mats = xreallocarray(*mats, *nmats + 1,
			    sizeof(**mats));
			cur = &(*mats)[(*nmats)++];
			*cur = (struct mtl_material){ "", { 1, 1, 1, 1 }, 0 };
			rest_name(cur->name, sizeof(cur->name), w, nl);
		} else if ((w - s == 2 && memcmp(s, "Kd", 2) == 0) ||
		    (w - s == 1 && *s == 'd')) {
			const char *v = objtext_skip(w, nl);

			if (cur == NULL)
				rc = objtext_fail(&O, "%.*s before the first "
				    "newmtl",
				    (int)(w - s), s);
			/* Kd spectral FILE and Kd xyz X Y Z: not an RGB. */
			else if (w - s == 2 && v < nl &&
			    (*v == 's' || *v == 'x'))
				continue;
			else if (w - s == 2) {
				rc = mtl_numbers(&O, w, nl, cur->color, 3);
				cur->has_kd = rc == 0;
			} else
				rc = mtl_numbers(&O, w, nl, &cur->color[3], 1);
		}
		/* The rest of .mtl (Ka, Ks, maps, ...) glTF's base colour
		 * does without, and programs add their own: skipped. */
	}
	free(copy);
	return rc;
}
