/* The check of an intrinsic model (core/model.h, Intrinsic models: powvar,
 * gamma(h) = c |h|^alpha): is gamma a valid variogram, i.e. conditionally
 * negative definite (sum_ij w_i w_j gamma(t_i - t_j) <= 0 whenever
 * sum w_i = 0), in dim dimensions?
 *
 * By Schoenberg's theorem gamma is a variogram in R^d iff exp(-s gamma) is
 * positive definite for every s > 0; for |h|^alpha that is the stable
 * (powered exponential) family, valid in every dimension for 0 < alpha <= 2
 * and in none for alpha > 2 (Schoenberg 1938; Gneiting and Schlather 2004).
 * The evidence printed is the generalized spectral density of gamma,
 *     S(f) = s_d |f|^-(d + alpha),  gamma(h) = int (1 - cos 2 pi f.h) S(f) df,
 * (core/families/powvar.c), positive for 0 < alpha < 2, scanned on 61
 * radii from 1e-3 to 1e3 cycles per unit; at alpha = 2 the field is a
 * random plane (S all at f = 0), still valid.  alpha outside (0, 2] is
 * refused when the spec is parsed, so a parsed model is always valid: the
 * check reports the numbers.  The graph of a realization has fractal
 * (Hausdorff) dimension d + 1 - alpha/2 (Adler 1981, ch. 8); the
 * field is nowhere mean-square differentiable for alpha < 2. */
#ifndef NL_CHECK_INTRINSIC_H
#define NL_CHECK_INTRINSIC_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/model.h"

typedef struct {
    int dim;                  /* 1..3 */
    double alpha, c, nugget;  /* the model's */
    int valid;                /* conditionally negative definite in dim */
    double spectrum_coef;     /* s_d: S(f) = s_d |f|^-(d + alpha) (NAN at alpha = 2) */
    double min_spectrum;      /* smallest scanned S (positive when valid, NAN at alpha = 2) */
    double hurst;             /* alpha / 2 */
    double fractal_dimension; /* d + 1 - alpha/2 */
} nl_check_intrinsic;

/* Check the intrinsic model m in dim (1..3) into *out.  NL_OK, or NL_EINVAL
 * (m not intrinsic, dim out of range or refused by nl_model_check_dim).
 * Thread-safe. */
int nl_check_intrinsic_model(const nl_model *m, int dim, nl_check_intrinsic *out);

#ifdef __cplusplus
}
#endif

#endif
