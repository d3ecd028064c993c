/* Exact simulation of the intrinsic power-variogram field (core/model.h,
 * Intrinsic models: powvar, gamma(h) = c |h|^alpha, the fractional Brownian
 * field of Hurst index alpha/2) on 1D and 2D grids.
 *
 * 1D (Davies and Harte 1987; Wood and Chan 1994): the n - 1 increments
 * X_i = Z(i h) - Z((i-1) h) are fractional Gaussian noise, stationary with
 *     Cov(X_i, X_i+k) = c h^alpha (|k+1|^alpha - 2 |k|^alpha + |k-1|^alpha),
 * synthesised exactly by circulant embedding (the FFT synthesis of
 * synth/fft.h on a period M >= 2 (n - 2)) and summed: Z(0) = 0.  Exact for
 * every 0 < alpha <= 2 (the embedding's eigenvalues are non-negative for
 * fractional Gaussian noise: Craigmile 2003 for alpha <= 1, Dietrich and
 * Newsam 1997 above; measured, and refused otherwise as in 2D).
 *
 * 2D (Stein 2002, "Fast and exact simulation of fractional Brownian
 * surfaces", JCGS 11:587-599; Gneiting, Sevcikova, Percival, Schlather and
 * Jiang 2006, JCGS 15:483-501, sec. 3): with s = |lag| / D, D the grid's
 * largest lag, Stein's cut-off covariance
 *     phi(s) = c0 - s^alpha + c2 s^2      0 <= s <= 1
 *            = beta (R - s)^3 / s          1 <= s <= R
 *            = 0                           s >= R
 * is positive definite in R^2 for R = 1, beta = 0, c2 = alpha/2,
 * c0 = 1 - alpha/2 when alpha <= 1.5 and for R = 2 with
 *     beta = alpha (2 - alpha) / (3 R (R^2 - 1)),
 *     c2 = (alpha - beta (R - 1)^2 (R + 2)) / 2,   c0 = beta (R - 1)^3 + 1 - c2
 * when 1.5 < alpha < 2 (Stein 2002; Gneiting et al. 2006, sec. 3, where
 * R = 2 is shown to suffice for alpha up to 2).  The constants are those
 * that make phi, phi' and phi'' continuous at s = 1 (rederived so here;
 * R = 1 is the case beta = 0).  The plan measures the embedding's
 * eigenvalues and refuses a negative one rather than trust this.  Being compactly supported, phi is embedded exactly in a
 * periodic grid of m_a >= n_a - 1 + R D / h_a samples per axis, whose
 * eigenvalues (the DFT of the periodized phi) are then non-negative
 * (Poisson summation of its non-negative spectrum).  On the grid, where s
 * <= 1, the field Y with covariance phi has the variogram s^alpha - c2 s^2;
 * adding the independent random plane sqrt(2 c2) (X1 x + X2 y) / D, X1, X2
 * standard normals, restores s^alpha exactly (Stein 2002, sec. 2), and the
 * factor sqrt(c) D^(alpha/2) makes it c |lag|^alpha.  Z(0, 0) = 0.
 *
 * A nugget is added as independent white noise of its variance per sample.
 * Only isotropic models are simulated (an angle or ratio would need the
 * embedding on a sheared grid). */
#ifndef NL_SYNTH_INTRINSIC_H
#define NL_SYNTH_INTRINSIC_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

typedef struct {
    size_t m[2];           /* embedding size per axis (1D: m[1] = 1) */
    double min_eigenvalue; /* smallest eigenvalue of the embedding's covariance matrix */
    double max_eigenvalue; /* largest */
    double cutoff;         /* 2D: Stein's R (1 or 2); 1D: 0 */
    double c2;             /* 2D: the plane's coefficient c2; 1D: 0 */
    double diameter;       /* 2D: D, the grid's largest lag (model units); 1D: 0 */
} nl_synth_intrinsic_info;

/* Eigenvalues above -NL_SYNTH_INTRINSIC_EIG_TOL times the largest are taken
 * as rounding (the FFT of M values has an error near 1e-16 sqrt(log M) of
 * the largest) and set to 0; below it the plan is refused. */
#define NL_SYNTH_INTRINSIC_EIG_TOL 1e-10

typedef struct nl_synth_intrinsic_plan nl_synth_intrinsic_plan;

/* Plan for the intrinsic model m on a dim-D grid (1 or 2) of n[] samples
 * (each >= 2) at spacing h[] (NULL: unit).  Plans FFTW: not thread-safe.
 * Returns NL_OK and *out, or (*out = NULL)
 *   NL_EINVAL  m not intrinsic, anisotropic in 2D, dim not 1 or 2, a size
 *              below 2, a spacing that is not positive and finite;
 *   NL_ENOTPD  an embedding eigenvalue below -NL_SYNTH_INTRINSIC_EIG_TOL of
 *              the largest (the message gives it; not seen for these
 *              constants);
 *   NL_ETOOBIG, NL_ENOMEM, NL_EFAIL  sizes, memory, FFTW. */
int nl_synth_intrinsic_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                                  nl_synth_intrinsic_plan **out);

void nl_synth_intrinsic_plan_info(const nl_synth_intrinsic_plan *p, nl_synth_intrinsic_info *info);

/* The realization for `seed` into out (the plan's dim and n; row-major, x
 * fastest).  The white noise of the embedding is synth/fft.h's stream; the
 * plane's two normals and the nugget's noise are drawn from
 * NL_SYNTH_INTRINSIC_STREAM.  Only reads the plan: one plan may serve
 * several threads.  NL_OK, NL_EINVAL (out does not match), NL_ENOMEM,
 * NL_ETOOBIG. */
#define NL_SYNTH_INTRINSIC_STREAM 0x1497u
int nl_synth_intrinsic_execute(const nl_synth_intrinsic_plan *p, uint64_t seed, nl_field *out);

/* Frees the plan (NULL: no-op); not thread-safe (FFTW). */
void nl_synth_intrinsic_plan_free(nl_synth_intrinsic_plan *p);

#ifdef __cplusplus
}
#endif

#endif
