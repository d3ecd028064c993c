/* Model checks: is R a valid autocorrelation, how smooth is it, and where
 * does it become numerically singular?  (Lewis 1987, "Singular Processes",
 * "Multi-dimensional Autocorrelation and Spectrum".)
 *
 * Scale: L is the smallest lag (searched by doubling, along x) beyond which
 * |R| < 1e-8 R(0) for good.  Positive definiteness is judged on the spectrum
 * of R sampled on a periodic grid of extent 8 L (spacing L / 512 in 1D,
 * L / 32 in 2D, L / 8 in 3D): negative values below -1e-6 of its largest
 * (beyond the sampling and truncation error, which is under 1e-8 R(0) in
 * covariance) make the model not positive definite; and on the smallest
 * eigenvalue of the covariance matrix of a small grid (64 samples in 1D,
 * 16x16 in 2D, 6x6x6 in 3D) spaced L / 16.  Isotropic models must also keep
 * R >= -R(0)/D (the -1/n bound) and, in 3D, a non-increasing radial
 * spectrum.  Smoothness: the order m of mean-square differentiability is
 * the largest m with a finite spectral moment of order 2m of the 1D
 * profile (the same along any line), judged from the decay of its spectrum
 * S ~ f^-b between 16/L and 128/L: m = ceil((b - 1)/2) - 1 (with 0.05 of
 * slack for the fit), -1 meaning infinitely differentiable when the
 * spectrum falls faster than any power, and 0 whenever R has a kink at the
 * origin (R(0) - R(d) ~ d^a, a < 1.9, at d = 1e-5 L); R''(0) is libmatheval's
 * symbolic second derivative for expressions, a finite difference
 * otherwise.  singular_below_spacing is the largest spacing s = L / 2^k,
 * k <= 24, at which the 1D N = 2 subdivision matrix has condition number
 * above NL_SUBDIV_COND_MAX (0 when it never does): within 24 octaves below the
 * correlation length, smooth (singular) processes lose rank while rough
 * ones such as exp(-|t|) keep it (their matrices lose rank too, but only at
 * spacings near 1e-10 L, below any sampling that resolves them). */
#ifndef NL_CHECK_H
#define NL_CHECK_H

#include "../core/model.h"

typedef struct {
    int dim;
    double scale;            /* L */
    double min_spectrum;     /* smallest sampled spectrum value / largest */
    double min_eigenvalue;   /* smallest covariance eigenvalue / R(0) */
    int positive_definite;   /* both above their tolerances */
    int isotropic;           /* the model is isotropic in dim */
    double min_r;            /* min R / R(0) over lags */
    int isotropic_bound_ok;  /* min_r >= -1/dim (always 1 if not isotropic) */
    int monotone_3d;         /* 3D isotropic: radial spectrum non-increasing (1 if not applicable) */
    double spectral_decay;   /* b in S ~ f^-b at high frequency (INFINITY: faster) */
    int differentiable_order;/* m; -1 infinitely */
    double r2;               /* R''(0) (-INFINITY when it does not exist) */
    double singular_below;   /* spacing, or 0 */
} nl_check;

/* All checks of m in dim (1..3) dimensions into *out (zeroed first).
 * Returns NL_OK, NL_EINVAL (m not defined in dim, nl_model_check_dim, or
 * R(0) not a positive finite variance or outside [1e-200, 1e200], or a
 * spectrum without a measurable decay), NL_ENOMEM, NL_EFAIL (the
 * eigenvalues did not converge), or the codes of nl_wk_sample_spectrum and
 * nl_wk_acf_to_spectrum (core/wk.h).  "Not positive definite" is a result
 * (out->positive_definite = 0), not an error.  Thread safety: as the model
 * (core/model.h: expression models are not thread-safe); the FFTs it runs
 * plan FFTW, so not concurrently with other planning. */
int nl_check_model(const nl_model *m, int dim, nl_check *out);

#endif
