/* The spectrum of an isotropic R times a Gaussian taper on a periodic
 * lattice: a test of positive definiteness that is exact in sign whatever
 * R's decay (core/taper.c).  Used by the model checks (analysis/check.c)
 * and by synthesis methods that would otherwise not see a model that is
 * not positive definite (synth/subdiv_plan.c). */
#ifndef NL_TAPER_INTERNAL_H
#define NL_TAPER_INTERNAL_H

#include "model.h"

#include <stddef.h>

/* The spectrum of R exp(-(r/T)^2): its extremes (spectrum units,
 * variance times length^dim), |k| of the minimum (cycles per unit), the
 * Nyquist frequency, T, and the rounding bound below which a negative
 * value proves nothing. */
typedef struct {
    double min, max, min_k, kmax, taper, rounding;
} nl_taper_result;

/* L0: the first lag (steps of 5% from 1e-6 to 2^20) where R departs from
 * R(0+) (no nugget) by half of it, or by 1% when it never does (R tends
 * to a positive constant); 0 when neither (R is flat over 2^20 lags). */
double nl_taper_scale(const nl_model *m, int dim);

/* The lattice for the near-origin scale L0 (coarse: the smaller one): n
 * points per axis, spacing h, taper T. */
void nl_taper_grid(int dim, double L0, int coarse, size_t *n, double *h, double *T);

/* For m isotropic in dim (1..3; any m in 1D: R is read along x); min and
 * max NAN when R is not finite at some lag of the lattice.  Codes:
 * NL_OK, NL_ENOMEM, those of nl_wk_acf_to_spectrum.  Not thread-safe
 * (plans FFTW). */
int nl_taper_spectrum(const nl_model *m, int dim, double L0, int coarse, nl_taper_result *out);

/* Compactly supported isotropic R (support within [0, L], 0 on [L, 5 L])
 * whose edge singularity outweighs its behaviour at lag 0, so that its
 * spectrum takes negative values at high |k| beyond any sampling
 * (core/model_edge.c: Askey's (1-r)_+^nu below nu = (d+1)/2): 1, else 0. */
int nl_model_edge_invalid(const nl_model *m, int dim, double L);

/* A power-law tail R ~ -c r^-b (c > 0) with b <= d, read from 1e2 L0 to
 * 1e5 L0 (core/model_edge.c): the integral of R over R^d is -infinity, so
 * S(0) is; 1, else 0. */
int nl_model_negative_tail(const nl_model *m, int dim, double L0);

/* The test every synthesis method runs before planning (the registry,
 * synth/method_plan.c; --clamp skips it): for a model defined by R and
 * isotropic in dim (any in 1D; not an exemplar), the tapered spectrum at
 * R's near-origin scale and 8 and 64 times coarser, a negative power-law
 * tail, and the edge asymptotics of a compactly supported R.  NL_OK, or NL_ENOTPD with a
 * message beginning "what: spec: not positive definite in dD" (a model
 * `noiselab check` finds invalid by these tests), or the codes of
 * nl_taper_spectrum.  Exact in sign: never refuses a positive definite
 * model.  Not thread-safe (plans FFTW). */
int nl_model_sign_check(const nl_model *m, int dim);

#endif
