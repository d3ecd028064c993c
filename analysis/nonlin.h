/* Memoryless nonlinearities of Gaussian noise: Beckmann's Hermite series
 * (Lewis GI '86, section 4.1).
 *
 * For a zero-mean Gaussian input of variance s^2 and normalised ACF rho,
 * and the shaping g(x) = F_y^-1(Phi(x / s)) of synth/shape.h, write
 * G(z) = g(s z) = sum_n c_n He_n(z) (probabilists' Hermite polynomials,
 * E[He_m He_n] = n! delta_mn), c_n = E[G(Z) He_n(Z)] / n!.  Then
 *     E[y] = c_0,   Cov(y(t), y(t + tau)) = sum_{n>=1} c_n^2 n! rho(tau)^n,
 * and by the convolution theorem the output spectrum is the matching sum
 * of n-fold self-convolutions of the normalised input spectrum.  An odd g
 * (a symmetric target density) has only odd n: a narrow band at f0 spreads
 * to 3 f0, 5 f0, ... (GI '86 Fig. 7).
 * The c_n are computed by Gauss-Hermite quadrature (GSL fixed quadrature,
 * 400 nodes) for a distribution, by adaptive quadrature (GSL QAGS) for an
 * expr: nonlinearity G(z) (core/dist.h: any memoryless g, GI '86 section 4,
 * e.g. z^2, exp(z), sign), whose jumps and kinks fixed nodes resolve
 * slowly; the variance left out by K terms, Var(y) - sum_{n<K} c_n^2 n!,
 * is reported as the truncation error. */
#ifndef NL_NONLIN_H
#define NL_NONLIN_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/dist.h"
#include "../core/field.h"

#include <stddef.h>

#define NL_HERMITE_MAX 64

typedef struct {
    int terms;                    /* K */
    double c[NL_HERMITE_MAX];     /* c_0 .. c_{K-1} */
    double variance;              /* Var(y), by the same quadrature */
    double truncation;            /* Var(y) - sum_{1<=n<K} c_n^2 n! */
} nl_hermite;

/* Every function here is reentrant (the caller owns every array; inputs
 * are only read) except nl_nonlin_verify, which plans FFTW (not
 * thread-safe, core/fftw_plan.h).  Nothing returned needs freeing. */

/* The first `terms` coefficients c_n of g = F_to^-1 o Phi into *h.
 * NL_EINVAL: terms outside 2..NL_HERMITE_MAX, an expansion that is not
 * finite (a distribution near the overflow threshold), an output that is
 * constant to rounding (variance <= 0), or a quadrature
 * variance more than 1% from the distribution's closed-form variance
 * (tails too heavy, e.g. lognormal with sigma >= 3); NL_ENOMEM. */
int nl_hermite_expand(const nl_dist *to, int terms, nl_hermite *h);

/* Output covariance at input correlation rho (|rho| <= 1). */
double nl_hermite_cov(const nl_hermite *h, double rho);

/* Inverse: the input correlation rho in [-1, 1] whose output covariance is
 * `cov`: of the roots on the side of 0 of cov's sign, the one nearest 0, else
 * the one nearest 0 on the other side (a scan outward from rho = 0 in steps
 * of 1/512, then bisection; the series need not be monotone: an even g such
 * as x^2 gives an even covariance, 2 rho^2, and a positive cov has the root
 * sqrt(cov / 2) > 0).  NAN when no rho in [-1, 1] gives cov. */
double nl_hermite_invert(const nl_hermite *h, double cov);

/* Design (GI '86: "in theory it should be possible to design the spectrum
 * of the undistorted noise so that a desired spectrum is achieved after
 * distortion"): given the wanted output covariance `target` on a periodic
 * 1D grid (wrapped order, n samples; it is rescaled so that target[0] is
 * the output variance of g), find the input correlation lag by lag with
 * nl_hermite_invert (a lag out of reach gets the rho whose output is
 * nearest its target), then project onto valid spectra: the input's spectrum
 * (core/wk.h, spacing h) with negative values set to 0 and its variance
 * back to 1.  rho[] (n) receives the designed input correlation, S[] (n,
 * may be NULL) its spectrum; *err the largest |predicted output - target|
 * relative to the output variance after projection; *unreachable the lags
 * whose target lies outside the output covariances g can produce. */
int nl_nonlin_design(const nl_hermite *h, const double *target, size_t n, double spacing, double *rho, double *S,
                     double *err, size_t *unreachable);
/* Errors of nl_nonlin_design: NL_EINVAL for target[0] <= 0 or n = 0 or a
 * spacing that is not positive; NL_ENOMEM. */

/* The predicted output covariance (Beckmann's series) at every lag of an
 * input covariance: out[i] = nl_hermite_cov(h, clamp(acf[i] / r0, -1, 1)),
 * i < n (r0 the input variance; 1 for a correlation). */
void nl_nonlin_output_acf(const nl_hermite *h, const double *acf, size_t n, double r0, double *out);

/* Check a design by simulation: `realizations` Gaussian fields from the 1D
 * spectrum S (nl_synth_fft_plan_spectrum, negative values clamped, seeds
 * 1..realizations), each shaped by d (nl_synth_shape) and its unbiased ACF
 * about the sample mean measured (nl_acf_full); meas[i] (nlags doubles,
 * i < nlags <= S->n[0]) receives the mean over the realizations at lag i.
 * Errors: NL_EINVAL for S not 1D, no realization or too many lags; those
 * of the synthesis, shaping and ACF (NL_ENOMEM, NL_EINVAL). */
int nl_nonlin_verify(const nl_field *S, const nl_dist *d, size_t realizations, size_t nlags, double *meas);

/* max_i |meas[i] - target[i] scale| / var over i < n (0 for n = 0): the
 * measured error relative to the output variance. */
double nl_nonlin_max_deviation(const double *meas, const double *target, size_t n, double scale, double var);

#ifdef __cplusplus
}
#endif

#endif
