/* Ensemble ACF check shared by the statistical tests of exact methods
 * (the numbers: analysis/verdict.h).
 *
 * Property: a zero-mean Gaussian field with covariance C has unbiased
 * lag-product estimates r(l) = (1/P) sum_j x_j x_{j+l} (known mean 0, P
 * pairs) with E r(l) = C(l).
 * Tolerance, derived: by Isserlis' theorem, grouping products by offset d,
 *     Var r(l) = (1/P^2) sum_d prod_a (n_a - l_a - |d_a|) [C(d)^2 + C(d+l) C(d-l)],
 * exactly; the ensemble mean of M realizations has variance Var r(l) / M
 * and z(l) = (mean - R(l)) / sqrt(Var r(l) / M) is close to N(0, 1) (CLT).
 * L lags at a family-wise false-alarm rate of 1e-3 (Bonferroni):
 *     z_crit = Phi^-1(1 - 1e-3 / (2 L)).
 * C is R at the wrapped lag for periodic methods, R itself otherwise. */
#ifndef NL_TEST_STAT_H
#define NL_TEST_STAT_H

#include "../core/field.h"

#include <stddef.h>
#include <stdint.h>

typedef double (*stat_profile)(double x, double y);
typedef int (*stat_synth)(void *ctx, uint64_t seed, nl_field *out);

/* Synthesise M realizations (seeds 1..M) with fn on an n[0] x n[1] grid
 * (n[1] = 1: 1D) and assert that the ensemble-mean ACF at the L lags is
 * within z_crit of R.  Returns the largest |z|. */
double stat_check_acf(const char *name, stat_synth fn, void *ctx, const size_t *n, stat_profile R, int periodic,
                      size_t M, const long (*lags)[2], size_t L);

/* Standard lag sets: 1D 0..32; 2D x 0..10, y 1..10, diagonal 1..10. */
size_t stat_lags_1d(long (*lags)[2]);
size_t stat_lags_2d(long (*lags)[2]);

#endif
