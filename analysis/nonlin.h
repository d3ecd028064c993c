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
 * 400 nodes); the variance left out by K terms, Var(y) - sum_{n<K} c_n^2 n!,
 * is reported as the truncation error. */
#ifndef NL_NONLIN_H
#define NL_NONLIN_H

#include "../core/dist.h"

#define NL_HERMITE_MAX 64

typedef struct {
    int terms;                    /* K */
    double c[NL_HERMITE_MAX];     /* c_0 .. c_{K-1} */
    double variance;              /* Var(y), by the same quadrature */
    double truncation;            /* Var(y) - sum_{1<=n<K} c_n^2 n! */
} nl_hermite;

int nl_hermite_expand(const nl_dist *to, int terms, nl_hermite *h);

/* Output covariance at input correlation rho (|rho| <= 1). */
double nl_hermite_cov(const nl_hermite *h, double rho);

/* Inverse: the input correlation rho in [-1, 1] whose output covariance is
 * `cov` (bisection; the series is increasing in rho for rho >= 0); NAN when
 * cov is out of the attainable range. */
double nl_hermite_invert(const nl_hermite *h, double cov);

/* Design (GI '86: "in theory it should be possible to design the spectrum
 * of the undistorted noise so that a desired spectrum is achieved after
 * distortion"): given the wanted output covariance `target` on a periodic
 * 1D grid (wrapped order, n samples; it is rescaled so that target[0] is
 * the output variance of g), find the input correlation lag by lag with
 * nl_hermite_invert, then project onto valid spectra: the input's spectrum
 * (core/wk.h, spacing h) with negative values set to 0 and its variance
 * back to 1.  rho[] (n) receives the designed input correlation, S[] (n,
 * may be NULL) its spectrum; *err the largest |predicted output - target|
 * relative to the output variance after projection; *unreachable the lags
 * whose target lies outside the output covariances g can produce. */
int nl_nonlin_design(const nl_hermite *h, const double *target, size_t n, double spacing, double *rho, double *S,
                     double *err, size_t *unreachable);

#endif
