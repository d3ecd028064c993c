/* The FFTW planning policy every transform in noiselab shares.
 *
 * Transforms are planned with FFTW_ESTIMATE, which costs no time and, where
 * FFTW holds measured wisdom for the transform, returns the measured plan
 * (FFTW_ESTIMATE accepts wisdom of greater rigour): a first run at a new
 * size never waits for planning (FFTW_MEASURE costs seconds at 4096^2,
 * several times the transform).  Measured wisdom is loaded, on the first
 * call, from FFTW's system wisdom (/etc/fftw/wisdom), the wisdom installed
 * with noiselab (NL_WISDOM_FILE, made by `make wisdom` for the common
 * power-of-two sizes and installed by `make install`), the file named by
 * $NOISELAB_WISDOM, and the user's cache $XDG_CACHE_HOME/noiselab/fftw-wisdom
 * (~/.cache/... by default).  NOISELAB_FFTW=measure plans every size with
 * FFTW_MEASURE and keeps the plans in that cache (nl_fftw_save), so later
 * runs at those sizes use them; NOISELAB_FFTW=estimate plans as a machine
 * without any wisdom does (none is loaded; the tests use it).
 * Either plan gives the same result to rounding (tests/test_fft_props.c,
 * tests/test_fftw_wisdom.c).
 *
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

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

#define NL_FFTW_THREADS_MIN ((size_t)1 << 16)

/* Planner flags for a transform of `count` samples (FFTW_ESTIMATE, or
 * FFTW_MEASURE under NOISELAB_FFTW=measure); the plan made next uses nl_threads_max() threads
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

#ifdef __cplusplus
}
#endif

#endif
