/*
 * expr.c - the expression language of scene files: parse once into a
 * small stack-machine program, evaluate per organ without allocating.
 *
 * Hand-written because nothing in Debian fits: libmatheval is GPL-3 and
 * reports no error positions, tinyexpr is not packaged, and we need
 * columns in messages, our own variables and a seeded rand(k).
 *
 * Grammar, loosest first:
 *	cond  = or [ "?" cond ":" cond ]
 *	or    = and { "||" and }
 *	and   = cmp { "&&" cmp }
 *	cmp   = add { ("<" | "<=" | ">" | ">=" | "==" | "!=") add }
 *	add   = mul { ("+" | "-") mul }
 *	mul   = unary { ("*" | "/" | "%") unary }
 *	unary = ("-" | "+" | "!") unary | pow
 *	pow   = primary [ "^" unary ]		(so -2^2 = -4, 2^-1 = 0.5)
 *	primary = number | name | name "(" cond { "," cond } ")" | "(" cond ")"
 */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/diag.h"
#include "base/expr.h"
#include "base/phyllo.h"
#include "base/mem.h"


enum op {
	OP_CONST, OP_VAR, OP_NEG, OP_NOT,
	OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_MOD, OP_POW,
	OP_LT, OP_LE, OP_GT, OP_GE, OP_EQ, OP_NE, OP_AND, OP_OR,
	OP_ADDK, OP_SUBK, OP_MULK, OP_DIVK, OP_POWK,	/* x op k */
	OP_CALL,	/* arg: function */
	OP_JZ,		/* pop; if zero jump to arg */
	OP_JMP		/* jump to arg */
};

enum fn {
	F_SIN, F_COS, F_TAN, F_ASIN, F_ACOS, F_ATAN, F_ATAN2, F_SQRT, F_EXP,
	F_LOG, F_POW, F_ABS, F_MIN, F_MAX, F_FLOOR, F_CEIL, F_CLAMP, F_MIX,
	F_SMOOTHSTEP, F_STEP, F_RADIANS, F_DEGREES, F_RAND
};

static const struct {
	const char	*name;
	int		 nargs;
} fns[] = {
	[F_SIN] = { "sin", 1 }, [F_COS] = { "cos", 1 }, [F_TAN] = { "tan", 1 },
	[F_ASIN] = { "asin", 1 }, [F_ACOS] = { "acos", 1 },
	[F_ATAN] = { "atan", 1 }, [F_ATAN2] = { "atan2", 2 },
	[F_SQRT] = { "sqrt", 1 }, [F_EXP] = { "exp", 1 }, [F_LOG] = { "log", 1 },
	[F_POW] = { "pow", 2 }, [F_ABS] = { "abs", 1 }, [F_MIN] = { "min", 2 },
	[F_MAX] = { "max", 2 }, [F_FLOOR] = { "floor", 1 },
	[F_CEIL] = { "ceil", 1 }, [F_CLAMP] = { "clamp", 3 },
	[F_MIX] = { "mix", 3 }, [F_SMOOTHSTEP] = { "smoothstep", 3 },
	[F_STEP] = { "step", 2 }, [F_RADIANS] = { "radians", 1 },
	[F_DEGREES] = { "degrees", 1 }, [F_RAND] = { "rand", 1 },
};
#define NFNS	(sizeof(fns) / sizeof(fns[0]))

static const char *const var_names[V__MAX] = {
	[V_N] = "n", [V_COUNT] = "N", [V_T] = "t", [V_S] = "s", [V_R] = "r",
	[V_PHI] = "phi", [V_H] = "h",
};

struct insn {
	enum op		 op;
	int		 arg;
	double		 k;
};

struct expr {
	struct insn	*code;
	size_t		 n, cap;
	double		*stack;		/* scratch for expr_eval */
	int		 varying;	/* reads a variable or rand() */
};

struct parser {
	const char	*src, *p;
	unsigned	 vars;
	const struct expr_const *consts;	/* or NULL */
	int		 depth;
	int		 sp, spmax;	/* stack height as emitted */
	size_t		 barrier;	/* a jump lands here: no fusing */
	struct expr	*e;
	struct expr_error *err;
};

/* SplitMix64's finaliser: a good 64-bit mix, the same on every machine. */
static uint64_t
mix64(uint64_t z)
{
	z += 0x9e3779b97f4a7c15ull;
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

double
expr_rand(uint64_t seed, long long n, long long k)
{
	uint64_t h = mix64(mix64(mix64(seed) ^ (uint64_t)n) ^ (uint64_t)k);

	return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

/* Record the first error only; later ones follow from it. */
static void
fail(struct parser *P, const char *at, const char *fmt, ...)
{
	va_list ap;

	if (P->err->msg[0] != '\0')
		return;
	P->err->col = (int)(at - P->src) + 1;
	va_start(ap, fmt);
	vsnprintf(P->err->msg, sizeof(P->err->msg), fmt, ap);
	va_end(ap);
}

/*
 * A variable this setting does not have: the message names those it
 * has, so a user need not look them up ("it may use n, N, t, f and F").
 */
static void
unavailable(struct parser *P, const char *at, const char *name)
{
	const char *names[V__MAX + 8];
	char list[96] = "";
	size_t k = 0;

	for (int v = 0; v < V__MAX; v++)
		if (P->vars & EXPR_VAR(v))
			names[k++] = var_names[v];
	for (const struct expr_const *c = P->consts; c && c->name && k <
	    sizeof(names) / sizeof(names[0]); c++)
		names[k++] = c->name;
	for (size_t i = 0; i < k; i++) {
		size_t len = strlen(list);

		snprintf(list + len, sizeof(list) - len, "%s%s", i == 0 ? "" :
		    i + 1 == k ? " and " : ", ", names[i]);
	}
	if (k == 0)
		fail(P, at, "variable '%s' is not available here: this "
		    "setting takes no variables", name);
	else
		fail(P, at, "variable '%s' is not available here (it may use "
		    "%s)", name, list);
}

static int
failed(const struct parser *P)
{
	return P->err->msg[0] != '\0';
}

/* Append an instruction; push is its effect on the stack height. */
static size_t
emit(struct parser *P, enum op op, int arg, double k, int push)
{
	struct expr *e = P->e;

	if (e->n == e->cap)
		e->code = xreallocarray(e->code, e->cap = e->cap * 2 + 16,
		    sizeof(*e->code));
	e->code[e->n] = (struct insn){ op, arg, k };
	P->sp += push;
	if (P->sp > P->spmax)
		P->spmax = P->sp;
	if (op == OP_VAR || (op == OP_CALL && arg == F_RAND))
		e->varying = 1;
	return e->n++;
}

/*
 * A binary operator whose right operand is a constant becomes one
 * instruction carrying it ("x * 2" is MULK 2): a third fewer
 * dispatches in typical expressions.  Not where a jump lands between
 * the two, as after "c ? a : 2".
 */
static void
emit_binary(struct parser *P, enum op op)
{
	static const enum op fused[][2] = {
		{ OP_ADD, OP_ADDK }, { OP_SUB, OP_SUBK }, { OP_MUL, OP_MULK },
		{ OP_DIV, OP_DIVK }, { OP_POW, OP_POWK },
	};
	struct expr *e = P->e;
	struct insn *last = e->n > 0 ? &e->code[e->n - 1] : NULL;

	for (size_t i = 0; i < sizeof(fused) / sizeof(fused[0]); i++)
		if (fused[i][0] == op && last != NULL &&
		    last->op == OP_CONST && P->barrier != e->n &&
		    !(op == OP_DIV && last->k == 0)) {
			last->op = fused[i][1];
			P->sp--;
			return;
		}
	emit(P, op, 0, 0, -1);
}

static void
skip_space(struct parser *P)
{
	while (isspace((unsigned char)*P->p))
		P->p++;
}

/* Consume the operator s if it comes next (and is not a longer one). */
static int
accept(struct parser *P, const char *s)
{
	size_t len = strlen(s);

	skip_space(P);
	if (strncmp(P->p, s, len) != 0)
		return 0;
	/* "<" must not take the first half of "<=", "!" of "!=". */
	if (len == 1 && P->p[1] == '=' && strchr("<>!=", s[0]) != NULL)
		return 0;
	P->p += len;
	return 1;
}

/*
 * Nesting is bounded so that no input can exhaust the C stack: each
 * parenthesis, call, unary operator, ^ and ?: counts one level.
 */
static int
enter(struct parser *P, const char *at)
{
	if (++P->depth > EXPR_DEPTH_MAX) {
		fail(P, at, "expression nested deeper than %d",
		    EXPR_DEPTH_MAX);
		return 0;
	}
	return 1;
}

static void	cond(struct parser *);
static void	unary(struct parser *);

static void
call(struct parser *P, const char *name, size_t len, const char *at)
{
	int nargs = 0;
	size_t f;

	for (f = 0; f < NFNS; f++)
		if (strlen(fns[f].name) == len &&
		    strncmp(fns[f].name, name, len) == 0)
			break;
	if (f == NFNS) {
		fail(P, at, "unknown function '%.*s'", (int)len, name);
		return;
	}
	if (!accept(P, ")")) {
		do {
			cond(P);
			nargs++;
		} while (!failed(P) && accept(P, ","));
		if (!failed(P) && !accept(P, ")")) {
			fail(P, P->p, "expected ',' or ')' in the arguments "
			    "of '%s'", fns[f].name);
			return;
		}
	}
	if (failed(P))
		return;
	if (nargs != fns[f].nargs) {
		fail(P, at, "'%s' takes %d argument%s, not %d", fns[f].name,
		    fns[f].nargs, fns[f].nargs == 1 ? "" : "s", nargs);
		return;
	}
	emit(P, OP_CALL, (int)f, 0, 1 - nargs);
}

static void
name(struct parser *P)
{
	const char *at = P->p;
	size_t len = 0;

	while (isalnum((unsigned char)at[len]) || at[len] == '_')
		len++;
	P->p += len;
	if (accept(P, "(")) {
		if (enter(P, at)) {
			call(P, at, len, at);
			P->depth--;
		}
		return;
	}
	if (len == 2 && strncmp(at, "pi", 2) == 0) {
		emit(P, OP_CONST, 0, M_PI, 1);
		return;
	}
	if (len == 6 && strncmp(at, "golden", 6) == 0) {
		emit(P, OP_CONST, 0, GOLDEN_ANGLE, 1);
		return;
	}
	for (const struct expr_const *c = P->consts; c && c->name; c++)
		if (strlen(c->name) == len && strncmp(c->name, at, len) == 0) {
			emit(P, OP_CONST, 0, c->value, 1);
			return;
		}
	for (int v = 0; v < V__MAX; v++)
		if (strlen(var_names[v]) == len &&
		    strncmp(var_names[v], at, len) == 0) {
			if (!(P->vars & EXPR_VAR(v)))
				unavailable(P, at, var_names[v]);
			else
				emit(P, OP_VAR, v, 0, 1);
			return;
		}
	for (size_t f = 0; f < NFNS; f++)
		if (strlen(fns[f].name) == len &&
		    strncmp(fns[f].name, at, len) == 0) {
			fail(P, at, "'%s' is a function: %s(...)",
			    fns[f].name, fns[f].name);
			return;
		}
	fail(P, at, "unknown variable '%.*s'", (int)len, at);
}

static void
primary(struct parser *P)
{
	char *end;
	double v;

	skip_space(P);
	if (isdigit((unsigned char)*P->p) || (*P->p == '.' &&
	    isdigit((unsigned char)P->p[1]))) {
		v = strtod(P->p, &end);
		if (isalpha((unsigned char)*end) || *end == '_' ||
		    !isfinite(v)) {
			fail(P, P->p, "malformed number");
			return;
		}
		P->p = end;
		emit(P, OP_CONST, 0, v, 1);
	} else if (isalpha((unsigned char)*P->p) || *P->p == '_')
		name(P);
	else if (accept(P, "(")) {
		const char *open = P->p - 1;

		if (!enter(P, P->p - 1))
			return;
		cond(P);
		if (!failed(P) && !accept(P, ")"))
			fail(P, open, "'(' is not closed");
		P->depth--;
	} else if (*P->p == '\0')
		fail(P, P->p, "unexpected end of expression");
	else
		fail(P, P->p, "unexpected '%c'", *P->p);
}

static void
power(struct parser *P)
{
	primary(P);
	if (!failed(P) && accept(P, "^")) {
		if (!enter(P, P->p - 1))
			return;
		unary(P);
		emit_binary(P, OP_POW);
		P->depth--;
	}
}

static void
unary(struct parser *P)
{
	enum op op = accept(P, "-") ? OP_NEG : accept(P, "!") ? OP_NOT :
	    accept(P, "+") ? OP_CONST : OP_VAR;

	if (op == OP_VAR) {
		power(P);
		return;
	}
	if (!enter(P, P->p - 1))
		return;
	unary(P);
	if (op != OP_CONST)
		emit(P, op, 0, 0, 0);
	P->depth--;
}

static void
mul(struct parser *P)
{
	unary(P);
	while (!failed(P)) {
		enum op op = accept(P, "*") ? OP_MUL : accept(P, "/") ? OP_DIV :
		    accept(P, "%") ? OP_MOD : OP_CONST;

		if (op == OP_CONST)
			break;
		unary(P);
		emit_binary(P, op);
	}
}

static void
add(struct parser *P)
{
	mul(P);
	while (!failed(P)) {
		enum op op = accept(P, "+") ? OP_ADD : accept(P, "-") ? OP_SUB :
		    OP_CONST;

		if (op == OP_CONST)
			break;
		mul(P);
		emit_binary(P, op);
	}
}

static void
cmp(struct parser *P)
{
	static const struct { const char *s; enum op op; } ops[] = {
		{ "<=", OP_LE }, { ">=", OP_GE }, { "==", OP_EQ },
		{ "!=", OP_NE }, { "<", OP_LT }, { ">", OP_GT },
	};

	add(P);
	for (size_t i = 0; !failed(P) && i < sizeof(ops) / sizeof(ops[0]);
	    i++)
		if (accept(P, ops[i].s)) {
			add(P);
			emit(P, ops[i].op, 0, 0, -1);
			i = (size_t)-1;		/* a < b < c: left to right */
		}
}

static void
and(struct parser *P)
{
	cmp(P);
	while (!failed(P) && accept(P, "&&")) {
		cmp(P);
		emit(P, OP_AND, 0, 0, -1);
	}
}

static void
or(struct parser *P)
{
	and(P);
	while (!failed(P) && accept(P, "||")) {
		and(P);
		emit(P, OP_OR, 0, 0, -1);
	}
}

static void
cond(struct parser *P)
{
	size_t jz, jmp;

	or(P);
	if (!failed(P) && accept(P, "?")) {
		const char *q = P->p - 1;

		if (!enter(P, P->p - 1))
			return;
		jz = emit(P, OP_JZ, 0, 0, -1);
		cond(P);
		if (!failed(P) && !accept(P, ":"))
			fail(P, q, "'?' without its ':'");
		if (failed(P))
			return;
		jmp = emit(P, OP_JMP, 0, 0, -1);	/* else pushes anew */
		P->e->code[jz].arg = (int)P->e->n;
		cond(P);
		P->e->code[jmp].arg = (int)P->e->n;
		P->barrier = P->e->n;
		P->depth--;
	}
}

struct expr *
expr_constant(double v)
{
	struct expr *e = xcalloc(1, sizeof(*e));

	e->code = xmalloc(sizeof(*e->code));
	e->code[0] = (struct insn){ OP_CONST, 0, v };
	e->n = e->cap = 1;
	e->stack = xmalloc(sizeof(*e->stack));
	return e;
}

struct expr *
expr_compile(const char *src, unsigned vars, struct expr_error *err)
{
	return expr_compile_with(src, vars, NULL, err);
}

struct expr *
expr_compile_with(const char *src, unsigned vars,
    const struct expr_const *consts, struct expr_error *err)
{
	struct parser P = { src, src, vars, consts, 0, 0, 0, 0, NULL, err };
	struct expr_env env = { { 0 }, 0, 0 };
	double v;

	err->col = 0;
	err->msg[0] = '\0';
	if (strlen(src) > EXPR_LEN_MAX) {
		fail(&P, src, "expression is longer than %d bytes",
		    EXPR_LEN_MAX);
		return NULL;
	}
	P.e = xcalloc(1, sizeof(*P.e));
	cond(&P);
	skip_space(&P);
	if (!failed(&P) && *P.p != '\0')
		fail(&P, P.p, "unexpected '%c' after the expression", *P.p);
	if (failed(&P)) {
		expr_free(P.e);
		return NULL;
	}
	P.e->stack = xcalloc((size_t)P.spmax + 1, sizeof(*P.e->stack));
	if (P.e->varying)
		return P.e;

	/* A constant is worked out once, and its errors found now. */
	switch (expr_eval(P.e, &env, &v)) {
	case EXPR_OK:
		expr_free(P.e);
		return expr_constant(v);
	case EXPR_DIVZERO:
		fail(&P, src, "division by zero");
		break;
	case EXPR_NOTFINITE:
		fail(&P, src, "the value is not a finite number");
		break;
	}
	expr_free(P.e);
	return NULL;
}

int
expr_is_constant(const struct expr *e, double *value)
{
	if (e->n != 1 || e->code[0].op != OP_CONST)
		return 0;
	*value = e->code[0].k;
	return 1;
}

unsigned
expr_vars(const struct expr *e)
{
	unsigned vars = 0;

	for (size_t i = 0; i < e->n; i++)
		if (e->code[i].op == OP_VAR)
			vars |= EXPR_VAR(e->code[i].arg);
	return vars;
}

static double
smoothstep(double e0, double e1, double x)
{
	double t;

	if (e0 == e1)
		return x < e0 ? 0 : 1;
	t = fmin(fmax((x - e0) / (e1 - e0), 0), 1);
	return t * t * (3 - 2 * t);
}

/* Apply function f to the top nargs values, leaving one. */
static double
apply(enum fn f, const double *a, const struct expr_env *env)
{
	switch (f) {
	case F_SIN: return sin(a[0]);
	case F_COS: return cos(a[0]);
	case F_TAN: return tan(a[0]);
	case F_ASIN: return asin(a[0]);
	case F_ACOS: return acos(a[0]);
	case F_ATAN: return atan(a[0]);
	case F_ATAN2: return atan2(a[0], a[1]);
	case F_SQRT: return sqrt(a[0]);
	case F_EXP: return exp(a[0]);
	case F_LOG: return log(a[0]);
	case F_POW: return pow(a[0], a[1]);
	case F_ABS: return fabs(a[0]);
	case F_MIN: return fmin(a[0], a[1]);
	case F_MAX: return fmax(a[0], a[1]);
	case F_FLOOR: return floor(a[0]);
	case F_CEIL: return ceil(a[0]);
	case F_CLAMP: return fmin(fmax(a[0], a[1]), a[2]);
	case F_MIX: return a[0] + (a[1] - a[0]) * a[2];
	case F_SMOOTHSTEP: return smoothstep(a[0], a[1], a[2]);
	case F_STEP: return a[1] < a[0] ? 0 : 1;
	case F_RADIANS: return a[0] * (M_PI / 180);
	case F_DEGREES: return a[0] * (180 / M_PI);
	case F_RAND:
		/* k beyond 2^62 or NaN: any fixed key will do. */
		return expr_rand(env->seed, env->n, fabs(a[0]) < 4e18 ?
		    (long long)floor(a[0]) : 0);
	}
	return NAN;
}

enum expr_status
expr_eval(struct expr *e, const struct expr_env *env, double *result)
{
	double *st = e->stack;
	int sp = -1;

	for (size_t pc = 0; pc < e->n; pc++) {
		const struct insn *in = &e->code[pc];

		switch (in->op) {
		case OP_CONST: st[++sp] = in->k; break;
		case OP_VAR: st[++sp] = env->var[in->arg]; break;
		case OP_NEG: st[sp] = -st[sp]; break;
		case OP_NOT: st[sp] = st[sp] == 0; break;
		case OP_ADD: sp--; st[sp] += st[sp + 1]; break;
		case OP_SUB: sp--; st[sp] -= st[sp + 1]; break;
		case OP_MUL: sp--; st[sp] *= st[sp + 1]; break;
		case OP_DIV:
			if (st[sp--] == 0)
				return EXPR_DIVZERO;
			st[sp] /= st[sp + 1];
			break;
		case OP_MOD:
			if (st[sp--] == 0)
				return EXPR_DIVZERO;
			st[sp] = fmod(st[sp], st[sp + 1]);
			break;
		case OP_POW: sp--; st[sp] = pow(st[sp], st[sp + 1]); break;
		case OP_ADDK: st[sp] += in->k; break;
		case OP_SUBK: st[sp] -= in->k; break;
		case OP_MULK: st[sp] *= in->k; break;
		case OP_DIVK: st[sp] /= in->k; break;
		case OP_POWK:
			st[sp] = in->k == 2 ? st[sp] * st[sp] : pow(st[sp], in->k);
			break;
		case OP_LT: sp--; st[sp] = st[sp] < st[sp + 1]; break;
		case OP_LE: sp--; st[sp] = st[sp] <= st[sp + 1]; break;
		case OP_GT: sp--; st[sp] = st[sp] > st[sp + 1]; break;
		case OP_GE: sp--; st[sp] = st[sp] >= st[sp + 1]; break;
		case OP_EQ: sp--; st[sp] = st[sp] == st[sp + 1]; break;
		case OP_NE: sp--; st[sp] = st[sp] != st[sp + 1]; break;
		case OP_AND: sp--; st[sp] = st[sp] != 0 && st[sp + 1] != 0; break;
		case OP_OR: sp--; st[sp] = st[sp] != 0 || st[sp + 1] != 0; break;
		case OP_CALL:
			sp -= fns[in->arg].nargs - 1;
			st[sp] = apply((enum fn)in->arg, &st[sp], env);
			break;
		case OP_JZ:
			if (st[sp--] == 0)
				pc = (size_t)in->arg - 1;
			break;
		case OP_JMP:
			pc = (size_t)in->arg - 1;
			break;
		}
	}
	if (!isfinite(st[0]))
		return EXPR_NOTFINITE;
	*result = st[0];
	return EXPR_OK;
}

void
expr_env_organ(struct expr_env *env, long long n, long long N)
{
	env->n = n;
	env->var[V_N] = (double)n;
	env->var[V_COUNT] = (double)N;
	env->var[V_T] = N > 1 ? (double)n / (double)(N - 1) : 0;
}

int
expr_setting_eval(const struct expr_setting *es, const char *file,
    const char *path, const char *item, struct expr_env *env, double *v)
{
	switch (expr_eval(es->e, env, v)) {
	case EXPR_OK:
		return 0;
	case EXPR_DIVZERO:
		diag(ST_SCENE, file, es->line, 0, "%s: division by zero at "
		    "%s %lld", path, item, env->n);
		return -1;
	case EXPR_NOTFINITE:
		break;
	}
	diag(ST_SCENE, file, es->line, 0, "%s is not a finite number at "
	    "%s %lld", path, item, env->n);
	return -1;
}

void
expr_free(struct expr *e)
{
	if (e == NULL)
		return;
	free(e->code);
	free(e->stack);
	free(e);
}
