/* Thinning a correlated field for a goodness-of-fit test of its marginal
 * distribution, with an effective sample size for what correlation is left.
 *
 * The Kolmogorov-Smirnov and chi-square tests of analysis/gof.h assume
 * independent samples.  Neighbours of a correlated field are nearly copies
 * of each other: a 128 x 128 field of correlation length 8 holds some
 * hundred independent samples' worth of its marginal, not 16384, and the
 * plain tests reject correctly shaped fields at p ~ 1e-7.  An effective
 * sample size alone does not mend them: the deviation of a strongly
 * correlated field's empirical CDF is dominated by a few slow modes, so its
 * supremum is not that of a Brownian bridge of the same variance and the
 * KS test turns far too cautious.  Here the field is thinned instead to
 * the sub-lattice of every s-th sample per axis, s the first whole radius
 * (in samples) at which the radial mean of the autocorrelation of the
 * median indicator 1{F(x) <= 1/2} falls to NL_GOF_THIN_RHO or below (F the
 * tested distribution; the biased FFT estimate of analysis/acf.h, sample
 * mean removed).  What correlation is left between kept samples is
 * counted as usual: the integrated autocorrelation over the kept lattice
 *     tau = sum over kept lags l (|l| < r0) of rho(l) >= 1,
 * summed to r0, the first radius where the radial mean of rho is <= 0
 * (beyond it the estimate is noise, and the complete sum of an estimate
 * with its mean removed is 0), gives n_eff = kept / tau: the KS p-value
 * counts n_eff samples and chi-square is divided by tau (the first-order
 * correction of Rao and Scott 1981 with one design effect for every bin).
 * The median indicator is the most correlated one (its correlation is
 * (2/pi) asin(rho) for a Gaussian field), so its s and tau serve every
 * threshold.  Radii are at most a quarter of the shortest axis.
 *
 * Thread safety: plans FFTW (analysis/acf.h), so not thread-safe; d is
 * only read. */
#ifndef NL_GOF_DEP_H
#define NL_GOF_DEP_H

#ifdef __cplusplus
extern "C" {
#endif

#include "gof.h"
#include "../core/dist.h"
#include "../core/field.h"

#include <stddef.h>

/* Largest autocorrelation of the median indicator between kept samples. */
#define NL_GOF_THIN_RHO 0.05

typedef struct {
    size_t n;          /* samples of the field */
    size_t stride;     /* s: every s-th sample per axis is kept (1: all) */
    size_t kept;       /* samples kept, prod_a ceil(n_a / s) */
    double rho_stride; /* radial mean of the median indicator's autocorrelation at radius s */
    double radius;     /* r0: lags shorter than this (in samples) entered tau */
    double tau;        /* integrated autocorrelation over the kept lattice (>= 1) */
    double n_eff;      /* kept / tau */
} nl_gof_dep;

/* The thinning of x (1 to 3D, at least 2 samples) for a test against d.
 * A field whose median indicator is constant (every sample on one side of
 * the median of d: far from d, the test will say so) is kept whole with
 * tau = 1.  Returns NL_OK, NL_EINVAL (fewer than 2 samples), NL_ETOOBIG /
 * NL_ENOMEM (the padded grid of 2^d N values does not fit), NL_EFAIL
 * (FFTW); *out is untouched on failure. */
int nl_gof_dependence(const nl_field *x, const nl_dist *d, nl_gof_dep *out);

/* The kept samples of x for a stride (>= 1), in row-major order, into out
 * (prod_a ceil(n_a / stride) values, the caller's); returns their number. */
size_t nl_gof_thin(const nl_field *x, size_t stride, double *out);

/* The test of noiselab hist --against on K >= 1 fields (an ensemble's
 * realizations are independent of each other): every field thinned by its
 * own nl_gof_dependence, the kept samples pooled and tested by
 * nl_gof_test_dep with n_eff the sum of the fields' and chi-square on
 * min(bins, n_eff / 5) (at least 2) equal-probability bins, each kept
 * sample counted once.  *sum receives the totals: n, kept, n_eff, tau =
 * kept / n_eff, stride the largest stride (*smin, may be NULL, the
 * smallest), rho_stride and radius those of the last field.  Returns NL_OK
 * and the codes of nl_gof_dependence and nl_gof_test_dep (NL_EINVAL also
 * for K = 0, or fewer than 2 samples kept in all), NL_ENOMEM. */
int nl_gof_test_thinned(const nl_field *const *x, size_t K, const nl_dist *d, size_t bins, nl_gof_dep *sum,
                        size_t *smin, nl_gof *out);

#ifdef __cplusplus
}
#endif

#endif
