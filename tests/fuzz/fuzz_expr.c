/* fuzz_expr.c - libFuzzer harness for the expression compiler and evaluator. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/expr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct expr_env env = { { 3, 10, 0.3, 0.5, 0.2, 45, 1.5 }, 7, 3 };
	struct expr_error err;
	struct expr *e;
	char *src = malloc(size + 1);
	double v;

	if (src == NULL)
		return 0;
	memcpy(src, data, size);
	src[size] = '\0';
	if ((e = expr_compile(src, EXPR_ALL, &err)) != NULL) {
		for (int n = 0; n < 4; n++) {
			env.var[V_N] = n;
			env.n = n;
			expr_eval(e, &env, &v);
		}
		expr_free(e);
	} else if (err.col < 1 || (size_t)err.col > size + 1 ||
	    err.msg[0] == '\0')
		abort();	/* every error has a position and a message */
	free(src);
	return 0;
}
