/* Named one-dimensional distributions: density, CDF and quantile (GSL).
 *
 *   gauss[:mean=0,sd=1]        normal
 *   uniform[:a=0,b=1]          flat on [a, b]
 *   laplace[:a=1]              density exp(-|y|/a) / (2a)
 *   hyperbolic                 hyperbolic secant: density sech(pi y / 2) / 2,
 *                              CDF (2/pi) atan(exp(pi y / 2)), variance 1
 *   lognormal[:zeta=0,sigma=1] exp of a normal(zeta, sigma)
 *   chi2-1                     the squared standard Gaussian (chi-square, 1
 *                              degree of freedom; GI '86, section 4)
 *   power:p=P                  U^P for U uniform on [0, 1] (y <- y^P of the
 *                              paper's terrains, applied to the uniform rank)
 *   table:FILE                 a quantile table: TSV with header, columns u y,
 *                              u increasing from 0 to 1, y non-decreasing;
 *                              linear interpolation
 *   expr:G                     not a distribution but a memoryless
 *                              nonlinearity: y = g(x) of the standardised
 *                              Gaussian input x (core/expr_internal.h syntax, e.g.
 *                              expr:x^2, expr:exp(x), expr:sgn(x)); g must be
 *                              finite for |x| <= NL_DIST_XMAX.  Its CDF, density,
 *                              quantile, mean and variance are NAN (unknown in
 *                              closed form); nl_dist_transform evaluates it.
 *
 * nl_dist_parse returns NL_OK and a new distribution in *out (release it
 * with nl_dist_free; NULL is a no-op), or NL_EINVAL (unknown name or key, a
 * parameter that is not a number or out of range, or parameters whose
 * quantile at u = 1e-300 or 1 - 1e-16, or the span between, is infinite,
 * e.g. laplace:a=1e308), NL_EINPUT (table: file
 * missing, a row that is not two numbers, u not increasing from 0 to 1 or y
 * decreasing, fewer than two rows) or NL_ENOMEM.  The other functions return
 * values, no status: quantile(u) for u in [0, 1] (infinite tails at 0 and 1
 * where the support is), NAN where GSL's chi-square inverse fails (it runs
 * under the library's GSL guard, core/nl_error.h).  All are thread-safe; a
 * distribution is read-only after parsing. */
#ifndef NL_DIST_H
#define NL_DIST_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

typedef struct nl_dist nl_dist;

int nl_dist_parse(const char *spec, nl_dist **out);
void nl_dist_free(nl_dist *d);
const char *nl_dist_spec(const nl_dist *d);  /* owned by d */

double nl_dist_cdf(const nl_dist *d, double y);
double nl_dist_pdf(const nl_dist *d, double y);  /* NAN for table: */
double nl_dist_quantile(const nl_dist *d, double u);

/* The memoryless map of a standard Gaussian input x onto d (Lewis GI '86,
 * section 4): g(x) = F^-1(Phi(x)) for a distribution, with Phi(x) kept in
 * [1e-300, 1 - 1e-16] so that the quantile is finite; the expression's g(x)
 * for expr:.  Thread-safe for distributions; for expr: as thread-safe as
 * the compiled expression (not: one thread per nl_dist). */
double nl_dist_transform(const nl_dist *d, double x);

/* 1 for an expr: nonlinearity (no CDF: not a target for goodness of fit or
 * rank shaping), 0 for a distribution. */
int nl_dist_is_function(const nl_dist *d);

/* Half-width of the input range over which expr: nonlinearities must be
 * finite (that of shaping's table, synth/shape.h, and beyond the Hermite
 * quadrature's effective nodes). */
#define NL_DIST_XMAX 8.5

/* Mean and variance (NAN where not finite or not known in closed form). */
double nl_dist_mean(const nl_dist *d);
double nl_dist_variance(const nl_dist *d);

/* Skewness E[(Y - mean)^3] / variance^1.5 and excess kurtosis
 * E[(Y - mean)^4] / variance^2 - 3 (0 and 0 for the Gaussian; NAN where not
 * finite or not known in closed form: table:, expr:). */
double nl_dist_skewness(const nl_dist *d);
double nl_dist_kurtosis(const nl_dist *d);

#ifdef __cplusplus
}
#endif

#endif
