/* The FFTW planning policy every transform in noiselab shares.
 *
 * Small transforms are planned with FFTW_ESTIMATE (planning is free, the
 * transform is cheap). From NL_FFTW_MEASURE_MIN samples on, FFTW_MEASURE plans
 * are 2-7x faster but cost seconds to make, so they are kept as FFTW wisdom in
 * $XDG_CACHE_HOME/noiselab/fftw-wisdom (~/.cache/... by default): the first
 * run at a size pays for planning, later runs reuse the plan. Either plan gives
 * the same result to rounding (tests/test_fft_props.c, the test comparing
 * the two planners).
 *
 * NOISELAB_FFTW=estimate or =measure overrides the policy for every size.
 * FFTW_MEASURE overwrites the arrays it plans on: callers plan before they
 * fill their input (or plan on scratch arrays and use the new-array execute).
 *
 * Thread safety.  FFTW's planner is not reentrant: plans must be made (and
 * destroyed) from one thread at a time, although executing a finished plan
 * on its own arrays is thread-safe.  Functions of the library that plan (and
 * so must not run concurrently with each other or with the caller's own FFTW
 * planning): nl_fftw_flags itself (first call: FFTW threads and wisdom),
 * nl_wk_acf_to_spectrum, nl_wk_spectrum_to_acf, nl_wk_sample_acf of a
 * spectral model, nl_wk_sample_spectrum of a non-spectral one,
 * nl_wk_sample_spectrum_half of a non-spectral one, nl_autocorr_sums, and the
 * plan_alloc functions and estimators of synth/ and analysis/ that use FFTs
 * (see their headers).  Neither function below returns a status. */
#ifndef NL_FFTW_PLAN_H
#define NL_FFTW_PLAN_H

#include <stddef.h>

#define NL_FFTW_MEASURE_MIN ((size_t)1 << 18)
#define NL_FFTW_THREADS_MIN ((size_t)1 << 16)

/* Planner flags for a transform of `count` samples (FFTW_ESTIMATE or
 * FFTW_MEASURE, as above); the plan made next uses nl_threads_max() threads
 * from NL_FFTW_THREADS_MIN samples on, else one (a process-wide FFTW
 * setting: call it right before planning).  The first call sets up FFTW's
 * threads and loads the wisdom cache.  Not thread-safe (see above). */
unsigned nl_fftw_flags(size_t count);

/* Threads per online processor at most (nl_threads_max). */
#define NL_THREADS_PER_CPU 4

/* The number of threads to use: OpenMP's (OMP_NUM_THREADS or
 * omp_set_num_threads) capped at NL_THREADS_PER_CPU times the online
 * processors, and at least 1, so that an absurd OMP_NUM_THREADS (10^5) costs
 * no thread-creation failure.  Thread-safe. */
int nl_threads_max(void);

/* Writes the wisdom cache if plans were measured since it was loaded; a
 * no-op otherwise.  Failure to write a cache is silent (it is only a cache);
 * the file is written under a temporary name and renamed.  Not thread-safe
 * (reads FFTW's wisdom, which planning writes). */
void nl_fftw_save(void);

#endif
