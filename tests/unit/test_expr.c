/*
 * test_expr.c - the expression language: precedence, every function,
 * every compile error with its column, run-time errors, and rand(k).
 * Prints "ok - what" / "not ok - what" lines for tests/run.sh.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/expr.h"
#include "check.h"


/* n = 7, N = 11, t = 0.7, s = 0.25, r = 0.5, phi = 90, h = 2, seed 42 */
static struct expr_env env = {
	{ [V_N] = 7, [V_COUNT] = 11, [V_T] = 0.7, [V_S] = 0.25, [V_R] = 0.5,
	  [V_PHI] = 90, [V_H] = 2 }, 42, 7
};

static void
value(const char *src, double want)
{
	struct expr_error err;
	struct expr *e = expr_compile(src, EXPR_ALL, &err);
	double got = NAN;

	if (e == NULL) {
		check(0, "%s compiles (col %d: %s)", src, err.col, err.msg);
		return;
	}
	check(expr_eval(e, &env, &got) == EXPR_OK &&
	    fabs(got - want) <= 1e-12 * fmax(1, fabs(want)),
	    "%s = %.15g (got %.15g)", src, want, got);
	expr_free(e);
}

static void
error(const char *src, unsigned vars, int col, const char *msg)
{
	struct expr_error err;
	struct expr *e = expr_compile(src, vars, &err);

	check(e == NULL && err.col == col && strcmp(err.msg, msg) == 0,
	    "\"%.40s\" fails at column %d: %s (got %d: %s)", src, col, msg,
	    err.col, e == NULL ? err.msg : "compiled");
	expr_free(e);
}

static void
runtime(const char *src, enum expr_status want)
{
	struct expr_error err;
	struct expr *e = expr_compile(src, EXPR_ALL, &err);
	double v;

	check(e != NULL && expr_eval(e, &env, &v) == want,
	    "%s gives run-time status %d", src, want);
	expr_free(e);
}

static void
test_precedence(void)
{
	value("1 + 2 * 3", 7);
	value("(1 + 2) * 3", 9);
	value("2 ^ 3 ^ 2", 512);		/* right-associative */
	value("-2 ^ 2", -4);			/* ^ binds tighter than - */
	value("2 ^ -1", 0.5);
	value("10 - 4 - 3", 3);			/* left-associative */
	value("12 / 3 / 2", 2);
	value("7 % 3", 1);
	value("1 + 2 < 4", 1);
	value("3 <= 3 && 2 > 1", 1);
	value("0 || 0", 0);
	value("!0 + !5", 1);
	value("1 == 1 != 0", 1);
	value("n > 5 ? 10 : 20", 10);
	value("n > 8 ? 1 : n > 6 ? 2 : 3", 2);	/* ?: nests to the right */
	value("0 ? 1/0 : 4", 4);		/* the branch not taken is not run */
	/* A constant right after ?: must not absorb the next operator. */
	value("n * (1 ? 3 : 2)", 21);
	value("n * (0 ? 3 : 2)", 14);
	value("(n > 5 ? 1 : 2) * 3 + 1", 4);
	value("n - 2 - 1", 4);
	value("r ^ 2", 0.25);
	value("2 ^ 0.5", M_SQRT2);
	value("--3", 3);
	value("+3", 3);
	value(".5 + 1e-1 + 2.5E1", 25.6);
	value("  n*  N  ", 77);
}

static void
test_names(void)
{
	value("n", 7);
	value("N", 11);
	value("t", 0.7);
	value("s", 0.25);
	value("r", 0.5);
	value("phi", 90);
	value("h", 2);
	value("pi", M_PI);
	value("golden", 137.50776405003785);
	value("sin(pi / 6)", 0.5);
	value("cos(0)", 1);
	value("tan(pi / 4)", 1);
	value("asin(1)", M_PI / 2);
	value("acos(1)", 0);
	value("atan(1)", M_PI / 4);
	value("atan2(1, 0)", M_PI / 2);
	value("sqrt(16)", 4);
	value("exp(0)", 1);
	value("log(exp(2))", 2);
	value("pow(2, 10)", 1024);
	value("abs(-3)", 3);
	value("min(3, 2)", 2);
	value("max(3, 2)", 3);
	value("floor(-1.5)", -2);
	value("ceil(1.2)", 2);
	value("clamp(5, 0, 1)", 1);
	value("clamp(-5, 0, 1)", 0);
	value("mix(10, 20, 0.25)", 12.5);
	value("smoothstep(0, 1, 0.5)", 0.5);
	value("smoothstep(0, 1, 2)", 1);
	value("smoothstep(1, 1, 0)", 0);
	value("step(0.5, 0.7)", 1);
	value("step(0.5, 0.3)", 0);
	value("radians(180)", M_PI);
	value("degrees(pi)", 180);
}

static void
test_errors(void)
{
	char deep[1200], big[EXPR_LEN_MAX + 8];

	error("q + 1", EXPR_ALL, 1, "unknown variable 'q'");
	error("n * foo(2)", EXPR_ALL, 5, "unknown function 'foo'");
	error("1 + min(2)", EXPR_ALL, 5, "'min' takes 2 arguments, not 1");
	error("sqrt(1, 2)", EXPR_ALL, 1, "'sqrt' takes 1 argument, not 2");
	error("1 +", EXPR_ALL, 4, "unexpected end of expression");
	error("(1 + 2", EXPR_ALL, 1, "'(' is not closed");
	error("1 + 2)", EXPR_ALL, 6, "unexpected ')' after the expression");
	error("n ? 1", EXPR_ALL, 3, "'?' without its ':'");
	error("2 $ 3", EXPR_ALL, 3, "unexpected '$' after the expression");
	error("3 * # 2", EXPR_ALL, 5, "unexpected '#'");
	error("1.5.2", EXPR_ALL, 4, "unexpected '.' after the expression");
	error("2pi", EXPR_ALL, 1, "malformed number");
	error("1e999", EXPR_ALL, 1, "malformed number");
	error("sin + 1", EXPR_ALL, 1, "'sin' is a function: sin(...)");
	error("max(1 2)", EXPR_ALL, 7,
	    "expected ',' or ')' in the arguments of 'max'");
	error("r * 2", EXPR_VAR(V_N) | EXPR_VAR(V_COUNT), 1,
	    "variable 'r' is not available here (it may use n and N)");
	error("n + 1", 0, 1, "variable 'n' is not available here: this "
	    "setting takes no variables");
	error("1 / 0", EXPR_ALL, 1, "division by zero");
	error("sqrt(-1)", EXPR_ALL, 1, "the value is not a finite number");
	error("", EXPR_ALL, 1, "unexpected end of expression");

	memset(deep, '(', 300);
	strcpy(deep + 300, "1");
	memset(deep + 301, ')', 300);
	deep[601] = '\0';
	error(deep, EXPR_ALL, 257, "expression nested deeper than 256");
	memset(deep, '-', 1000);
	strcpy(deep + 1000, "1");
	error(deep, EXPR_ALL, 257, "expression nested deeper than 256");
	memset(big, ' ', sizeof(big));
	big[sizeof(big) - 2] = '1';
	big[sizeof(big) - 1] = '\0';
	error(big, EXPR_ALL, 1, "expression is longer than 4096 bytes");
	memset(deep, '(', 200);
	strcpy(deep + 200, "1");
	memset(deep + 201, ')', 200);
	deep[401] = '\0';
	value(deep, 1);
}

static void
test_runtime(void)
{
	struct expr_error err;
	struct expr *e;
	double v = 0;

	runtime("1 / (n - 7)", EXPR_DIVZERO);
	runtime("n % (n - 7)", EXPR_DIVZERO);
	runtime("log(n - 7)", EXPR_NOTFINITE);
	runtime("sqrt(-n)", EXPR_NOTFINITE);
	runtime("exp(n * 1000)", EXPR_NOTFINITE);
	e = expr_compile("3 * 4 + 1", EXPR_ALL, &err);
	check(e != NULL && expr_is_constant(e, &v) && v == 13,
	    "a constant expression is folded to one number");
	expr_free(e);
	e = expr_compile("n + 1", EXPR_ALL, &err);
	check(e != NULL && !expr_is_constant(e, &v),
	    "an expression of n is not folded");
	expr_free(e);
}

static void
test_rand(void)
{
	struct expr_env a = env;
	struct expr_error err;
	struct expr *e = expr_compile("rand(3)", EXPR_ALL, &err);
	double x, y, sum = 0, lo = 1, hi = 0;
	int same = 1;

	expr_eval(e, &a, &x);
	expr_eval(e, &a, &y);
	check(x == y, "rand(k) is a pure function of (seed, n, k)");
	a.seed = 43;
	expr_eval(e, &a, &y);
	check(x != y, "another seed gives another rand(k)");
	a.seed = 42;
	a.n = 8;
	expr_eval(e, &a, &y);
	check(x != y, "another organ gives another rand(k)");
	expr_free(e);
	/* Uniform on [0, 1): mean near 1/2 over many organs. */
	for (long n = 0; n < 100000; n++) {
		double u = expr_rand(1, n, 0);

		sum += u;
		lo = fmin(lo, u);
		hi = fmax(hi, u);
		same &= expr_rand(1, n, 0) == expr_rand(1, n, 0);
	}
	check(lo >= 0 && hi < 1 && fabs(sum / 100000 - 0.5) < 0.005 && same,
	    "rand is uniform on [0, 1) (mean %.4f)", sum / 100000);
	/*
	 * The same numbers on every machine: the value was computed by an
	 * independent Python transcription of SplitMix64's finaliser.
	 */
	check(expr_rand(0, 0, 0) == expr_rand(0, 0, 0) &&
	    fabs(expr_rand(12345, 678, 9) - 0.6921218637) < 1e-10,
	    "rand(9) for seed 12345, organ 678 is 0.6921218637 everywhere "
	    "(got %.10f)", expr_rand(12345, 678, 9));
}

int
main(void)
{
	check_topic = "expr: ";
	test_precedence();
	test_names();
	test_errors();
	test_runtime();
	test_rand();
	return check_failures != 0;
}
