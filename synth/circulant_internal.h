/* What the one-process and the distributed circulant embeddings share
 * (mpi/circulant.c); internal: not installed, not part of the public API. */
#ifndef NL_SYNTH_CIRCULANT_INTERNAL_H
#define NL_SYNTH_CIRCULANT_INTERNAL_H

#include "circulant.h"
#include "method.h"

#include <stddef.h>

/* The embedding search both plans share: from nl_synth_circulant_size per
 * axis, try_plan(ctx, m, &fi) plans periodic synthesis of the model on m
 * (clamping allowed: NL_SYNTH_FFT_CLAMP) and reports its info, keeping
 * the plan in ctx (freeing the previous one); m is doubled while clamping
 * would change the covariance by more than NL_SYNTH_FFT_CLAMP_TOL and
 * every axis stays within max_factor n.  Fills *info.  NL_OK (the last
 * plan is the one to use), try_plan's status, or the NL_ENOTPD refusal
 * (unless flags holds NL_SYNTH_FFT_CLAMP). */
typedef int nl_synth_circulant_try_fn(void *ctx, const size_t *m, nl_synth_fft_info *fi);
int nl_synth_circulant_embed(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                             int max_factor, nl_synth_circulant_try_fn *try_plan, void *ctx,
                             nl_synth_circulant_info *info);

/* Its pieces: a spectral model's variance_loss for a synthesised variance
 * (0 for lag models, NaN when R(0) is not known); the NL_ENOTPD refusal of
 * an embedding mm that could not be doubled further (info's eigenvalues,
 * doublings, clamp_error).  Pure. */
double nl_synth_circulant_loss(const nl_model *m, int dim, double variance);
int nl_synth_circulant_refuse(const nl_model *m, const nl_synth_circulant_info *info, const size_t *mm);

/* circulant's report (synth/method.h) from its plan's info, one process's
 * or the distributed plan's (mpi/fft.h), for model m in dim: method, flags,
 * sd (sqrt R(0), or 1) and json of r. */
int nl_synth_circulant_report(const nl_synth_circulant_info *info, const nl_model *m, int dim,
                              nl_method_report *r);

#endif
