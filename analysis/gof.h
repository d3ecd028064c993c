/* Goodness of fit of samples to a named distribution.
 *
 * Kolmogorov-Smirnov: D = sup |F_n(y) - F(y)|, with the asymptotic p-value
 * Q_KS((sqrt(n) + 0.12 + 0.11/sqrt(n)) D) (Stephens 1970), where
 * Q_KS(l) = 2 sum_{k>=1} (-1)^(k-1) exp(-2 k^2 l^2).
 * Chi-square: B bins of equal probability under F (edges F^-1(k/B)),
 * X^2 = sum (O - E)^2 / E, p = Q_chi2(X^2; B - 1).
 * Both assume independent samples: for a correlated field, test a white
 * field or a decimation much sparser than the correlation length. */
#ifndef NL_GOF_H
#define NL_GOF_H

#include "../core/dist.h"

#include <stddef.h>

typedef struct {
    double D;        /* KS statistic */
    double p_ks;     /* KS p-value */
    double chi2;     /* chi-square statistic */
    size_t bins;     /* chi-square bins */
    double p_chi2;   /* chi-square p-value */
} nl_gof;

int nl_gof_test(const double *x, size_t n, const nl_dist *d, size_t bins, nl_gof *out);

#endif
