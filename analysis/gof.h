/* Goodness of fit of samples to a named distribution.
 *
 * Kolmogorov-Smirnov: D = sup |F_n(y) - F(y)|, with the asymptotic p-value
 * Q_KS((sqrt(n) + 0.12 + 0.11/sqrt(n)) D) (Stephens 1970), where
 * Q_KS(l) = 2 sum_{k>=1} (-1)^(k-1) exp(-2 k^2 l^2).
 * Chi-square: B bins of equal probability under F (edges F^-1(k/B)),
 * X^2 = sum (O - E)^2 / E, p = Q_chi2(X^2; B - 1).
 * Both assume independent samples; nl_gof_test_dep corrects them for
 * correlated ones with an effective sample size and a design effect
 * (analysis/gof_dep.h measures both on a field).
 * Thread safety: reentrant as long as d is not shared with a thread that
 * frees it (core/dist.h). */
#ifndef NL_GOF_H
#define NL_GOF_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/dist.h"

#include <stddef.h>

typedef struct {
    double D;        /* KS statistic */
    double p_ks;     /* KS p-value */
    double chi2;     /* chi-square statistic */
    size_t bins;     /* chi-square bins */
    double p_chi2;   /* chi-square p-value */
    double n_eff;    /* samples the KS p-value counts (n when independent) */
    double deff;     /* design effect: p_chi2 is that of chi2 / deff (1 when independent) */
} nl_gof;

/* Both tests of the n samples x against d, chi-square on `bins` bins.
 * Returns NL_OK, NL_EINVAL (n < 2 or bins < 2) or NL_ENOMEM; *out is
 * untouched on failure.  x is not modified (a sorted copy is made). */
int nl_gof_test(const double *x, size_t n, const nl_dist *d, size_t bins, nl_gof *out);

/* The same for correlated samples: the KS p-value uses n_eff (1 <= n_eff
 * <= n) in place of n, i.e. Q_KS((sqrt(n_eff) + 0.12 + 0.11/sqrt(n_eff)) D),
 * and the chi-square p-value is Q_chi2(X^2 / deff; B - 1) (deff >= 1, the
 * first-order correction of Rao and Scott 1981); D and chi2 are the
 * uncorrected statistics.  n_eff = n and deff = 1 give nl_gof_test bit for
 * bit.  Returns the codes of nl_gof_test, and NL_EINVAL for n_eff or deff
 * out of range. */
int nl_gof_test_dep(const double *x, size_t n, const nl_dist *d, size_t bins, double n_eff, double deff,
                    nl_gof *out);

/* The density d predicts per histogram bin, as the probability mass over
 * the bin width: pdf[b] = (F(edges[b+1]) - F(edges[b])) / (edges[b+1] -
 * edges[b]) for b < bins (edges holds bins + 1 entries, as nl_hist makes
 * them).  Returns NL_OK or NL_EINVAL (edges not increasing). */
int nl_gof_bin_density(const nl_dist *d, const double *edges, size_t bins, double *pdf);

#ifdef __cplusplus
}
#endif

#endif
