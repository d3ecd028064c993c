/* What the one-process and the distributed FFT plans share (mpi/fft.c);
 * internal: not installed, not part of the public API. */
#ifndef NL_SYNTH_FFT_INTERNAL_H
#define NL_SYNTH_FFT_INTERNAL_H

#include "fft.h"
#include "method.h"

#include <stddef.h>

/* The plan's verdict on a sampled spectrum, from its sums over the full
 * grid (lambda as densities S / cell): sum of the non-negative values, neg
 * = minus the sum of the negative ones; info's min_lambda, max_lambda and
 * negatives set by the caller.  Sets variance and clamp_error, and returns
 * NL_OK, or NL_ENOTPD (no positive part; clamping above
 * NL_SYNTH_FFT_CLAMP_TOL without NL_SYNTH_FFT_CLAMP in flags) with the
 * message `name` leads. */
int nl_synth_fft_verdict(const char *name, size_t count, double sum, double neg, unsigned flags,
                         nl_synth_fft_info *info);

/* fft's report (synth/method.h) from its plan's info, one process's or the
 * distributed plan's (mpi/fft.h): method, flags, sd and json of r. */
int nl_synth_fft_report(const nl_synth_fft_info *info, nl_method_report *r);

#endif
