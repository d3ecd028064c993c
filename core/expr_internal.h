/* The one door to expressions: every expression a user gives (expr:,
 * spectrum:, nonlin's expr: g, sparse's kernel and angle) is checked and
 * compiled here, by muParser (its C interface, muParserDLL.h).
 *
 * The syntax is libmatheval's, as noiselab took it before, kept exactly:
 *   numbers      12, 1.5, .5, 5., 1e-3 (read with strtod)
 *   operators    + - * / ^; unary minus binds looser than ^ and tighter
 *                than * and / (-2^2 = -4, 2^-1 = 0.5, 2*-3^2 = -18); ^ is
 *                LEFT-associative as in libmatheval (2^3^2 = 64, not 512);
 *                repeated signs are allowed (--2 = 2); a unary + is accepted
 *   constants    e pi log2e log10e ln2 ln10 pi_2 pi_4 1_pi 2_pi 2_sqrtpi
 *                sqrt2 sqrt1_2
 *   functions    exp log (natural) sqrt sin cos tan cot sec csc asin acos
 *                atan acot asec acsc sinh cosh tanh coth sech csch asinh
 *                acosh atanh acoth asech acsch abs step (0 below 0, else 1)
 *                delta (inf at 0, else 0) nandelta (NAN at 0, else 0) erf
 * and the special functions (core/expr_funcs.c; NAN outside the domain):
 *   erfc(x), sinc(x) = sin(x)/x with sinc(0) = 1 (unnormalised),
 *   gamma(x), lgamma(x) = log|Gamma(x)|,
 *   besselj(nu, x), bessely(nu, x), besselk(nu, x): J, Y, K of real order,
 *   gammainc(a, x) = P(a, x), the regularised LOWER incomplete gamma,
 *   gammaincc(a, x) = Q(a, x) = 1 - P, the regularised upper one,
 *   gammaupper(a, x) = Gamma(a, x), the non-normalised upper one, any real a.
 * Any other name is a variable; the caller says which it accepts.
 *
 * Characters outside NL_EXPR_CHARS are refused before anything else sees
 * them (libmatheval's flex scanner used to echo them to stdout and drop
 * them; the check stays so that a message names the character). */
#ifndef NL_EXPR_INTERNAL_H
#define NL_EXPR_INTERNAL_H

#include <stddef.h>

/* The characters an expression may hold. */
#define NL_EXPR_CHARS "letters, digits and _ . , + - * / ^ ( ) and spaces"

/* Index of the first character of `text` outside NL_EXPR_CHARS, or
 * strlen(text) when there is none. */
size_t nl_expr_bad_char(const char *text);

/* A compiled expression (opaque). */
typedef struct nl_expr nl_expr;

/* Compile `text` into *out.  NL_EINVAL, with a message starting "WHAT: ",
 * for a character outside NL_EXPR_CHARS (named, with its 1-based position),
 * an unknown function (named), a call with the wrong number of arguments or
 * any other malformed expression (the reason and its 1-based position);
 * NL_ENOMEM.  *out is NULL on failure.  Nothing is written to stdout.
 * Not thread-safe (muParser's C interface keeps static buffers). */
int nl_expr_create(const char *what, const char *text, nl_expr **out);

/* Release (NULL is a no-op). */
void nl_expr_free(nl_expr *e);

/* The variables the expression names, in order of first appearance. */
size_t nl_expr_nvars(const nl_expr *e);
const char *nl_expr_var(const nl_expr *e, size_t i);

/* Bind the expression's variables to names[0..n-1], the order of the values
 * nl_expr_eval takes.  Returns NULL, or the first variable of the
 * expression that is not among the names (nothing bound then). */
const char *nl_expr_bind(nl_expr *e, const char *const *names, size_t n);

/* The expression at values[0..n-1] (the names given to nl_expr_bind).
 * Not reentrant: one nl_expr is evaluated by one thread at a time (muParser
 * reads the variables from the object and evaluates on its own stack). */
double nl_expr_eval(nl_expr *e, const double *values);

/* A function of a point p[0..n-1] (n <= 3), for the two below. */
typedef double (*nl_expr_fn)(void *ctx, const double *p);

/* The limit of f at p0 (core/expr_limit.c), for an f that is not finite at
 * p0 itself (a removable singularity such as sin(r)/r at 0): approached
 * along two directions, from both sides (in 1D: both sides), by Richardson
 * extrapolation; NAN when the approaches disagree or do not converge
 * (1/r, sin(1/r), t/|t| at 0).  Up to 4 x 64 evaluations of f. */
double nl_expr_limit(nl_expr_fn f, void *ctx, const double *p0, int n);

/* f''(t) of a function of one variable by extrapolated central
 * differences; NAN where they do not converge (a kink at t). */
double nl_expr_d2(nl_expr_fn f, void *ctx, double t);

/* The function and constant tables (core/expr_funcs.c). */
typedef struct {
    const char *name;
    double (*f)(double);
} nl_expr_fun1;
typedef struct {
    const char *name;
    double (*f)(double, double);
} nl_expr_fun2;
typedef struct {
    const char *name;
    double value;
} nl_expr_const;
const nl_expr_fun1 *nl_expr_funs1(size_t *n);
const nl_expr_fun2 *nl_expr_funs2(size_t *n);
const nl_expr_const *nl_expr_consts(size_t *n);

/* "exp(x) log(x) ... besselj(a, x) ...": every function, into buf (cut at
 * size - 1 bytes). */
void nl_expr_function_names(char *buf, size_t size);

/* The text muParser compiles, made from `text` by core/expr_lex.c: numbers
 * and constants become the constants _k0, _k1, ... (values in *consts),
 * variables _v0, _v1, ... (names in *vars, first appearance first), ^ the
 * left-associative operator #, runs of unary signs one sign or none;
 * map[i] is the index in `text` that character i came from.  NL_EINVAL
 * with a "WHAT: " message for an unknown function or a stray '.'. */
typedef struct {
    char *out;         /* the rewritten text */
    size_t *map;       /* out index -> text index, strlen(out) + 1 entries */
    double *consts;    /* value of _kI */
    size_t nconsts;    /* number of _kI */
    char **vars;       /* name of _vI as written */
    size_t nvars;      /* number of _vI */
} nl_expr_lexed;
int nl_expr_lex(const char *what, const char *text, nl_expr_lexed *l);
void nl_expr_lexed_free(nl_expr_lexed *l);

#endif
