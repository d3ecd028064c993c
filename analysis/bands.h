/* The spread of the spectrum and histogram estimates when a model is true:
 * the bands a card draws around the model (the ACF's is nl_acf_model_band,
 * analysis/acf.h).
 *
 * Thread safety: reentrant, but for nl_hist_model_band, which is as
 * thread-safe as the model (core/model.h) and, for a spectral model, calls
 * the FFTW planner (core/wk.h). */
#ifndef NL_BANDS_H
#define NL_BANDS_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/model.h"

#include <stddef.h>

/* The 95% band of an estimate distributed as S chi-square_nu / nu (nu
 * equivalent degrees of freedom, nu > 0): *lo = q(0.025) / nu and *hi =
 * q(0.975) / nu, q the chi-square_nu quantiles, so that the band is
 * [S lo, S hi].  One periodogram ordinate (0 < f < Nyquist) has nu = 2:
 * [-ln 0.975, -ln 0.025] = [0.0253, 3.689]; the mean of K independent
 * ones nu = 2K.  Returns NL_OK or NL_EINVAL (nu not positive and finite). */
int nl_band_chisq(double nu, double *lo, double *hi);

/* The equivalent degrees of freedom of Welch's estimate (analysis/welch.h:
 * Hann windows w, segments of S samples per axis every S/2) of a dim-D
 * (1 or 2) field of n[0..dim-1] samples, at frequencies away from 0 and
 * Nyquist, for a spectrum flat over the window's main lobe:
 *     nu = 2 K^2 / sum_{i,j} rho(i - j),
 * summed over the K segments, with rho the correlation of two segments'
 * periodograms, |sum_t w_t w_{t+d}|^2 / (sum_t w_t^2)^2 for segments d
 * samples apart (a product over the axes in 2D; Welch 1967, eq. (5);
 * Percival and Walden 1993, eq. (292b)).  For this window rho = 1/36 for
 * neighbours and 0 beyond, so in 1D nu = 2K / (1 + (K - 1) / (18 K)).
 * Returns NL_OK or NL_EINVAL (dim not 1 or 2, S < 4 or above an axis). */
int nl_welch_edf(int dim, const size_t *n, size_t S, double *nu);

/* The histogram of a Gaussian field of the model (mean 0, variance R(0))
 * with dim (1..3) axes of n[0..dim-1] samples of spacing h (NULL: unit),
 * on bins [edges[b], edges[b+1]) (bins + 1 increasing edges): density[b]
 * = p_b / width_b, p_b the bin's probability under N(0, R(0)), the
 * expectation of count_b / (N width_b); sd[b] its standard deviation,
 * from the variance of the count
 *     Var count_b = N p_b (1 - p_b) + sum_{v != 0} n(v) Cov(1_b(x_0), 1_b(x_v)),
 * n(v) = prod_a (n_a - |v_a|) the ordered pairs v apart, and Mehler's
 * expansion of the bivariate Gaussian (Kibble 1945):
 *     Cov(1_b(x_0), 1_b(x_v)) = sum_{m >= 1} rho(v)^m c_m^2,
 *     c_m = [phi(t) He_{m-1}(t)]_{t = beta}^{t = alpha} / sqrt(m!),
 * rho = R(v) / R(0), alpha, beta the standardised edges, He the Hermite
 * polynomials; summed to m = 400 (at most rho^401 of the bin's p left).
 * White noise gives the binomial N p (1 - p); correlation widens it, the
 * reason a field's histogram wanders far more than N independent draws'.
 * Edges may be infinite.  Costs O(2^dim N) model values and 400 passes
 * over them.  Returns NL_OK, NL_EINVAL (dim, bins 0, edges not
 * increasing, the model not defined in dim, not stationary, or R(0) not
 * positive), NL_ETOOBIG / NL_ENOMEM, or the codes of nl_wk_sample_acf. */
int nl_hist_model_band(const nl_model *m, int dim, const size_t *n, const double *h, const double *edges,
                       size_t bins, double *density, double *sd);

#ifdef __cplusplus
}
#endif

#endif
