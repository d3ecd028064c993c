/* The FFTW planning policy every transform in noiselab shares.
 *
 * Small transforms are planned with FFTW_ESTIMATE (planning is free, the
 * transform is cheap). From NL_FFTW_MEASURE_MIN samples on, FFTW_MEASURE plans
 * are 2-7x faster but cost seconds to make, so they are kept as FFTW wisdom in
 * $XDG_CACHE_HOME/noiselab/fftw-wisdom (~/.cache/... by default): the first
 * run at a size pays for planning, later runs reuse the plan. Either plan gives
 * the same result to rounding (tests/test_fftw_plan.c).
 *
 * NOISELAB_FFTW=estimate or =measure overrides the policy for every size.
 * FFTW_MEASURE overwrites the arrays it plans on: callers plan before they
 * fill their input (or plan on scratch arrays and use the new-array execute).
 * Planning is not thread-safe: plan from one thread. */
#ifndef NL_FFTW_PLAN_H
#define NL_FFTW_PLAN_H

#include <stddef.h>

#define NL_FFTW_MEASURE_MIN ((size_t)1 << 18)
#define NL_FFTW_THREADS_MIN ((size_t)1 << 16)

/* Planner flags for a transform of `count` samples; the plan made next uses
 * as many threads as OpenMP would from NL_FFTW_THREADS_MIN samples on, else one. The first call sets up FFTW's threads and
 * loads the wisdom cache. */
unsigned nl_fftw_flags(size_t count);

/* Writes the wisdom cache if plans were measured since it was loaded; a
 * no-op otherwise. Failure to write a cache is silent (it is only a cache). */
void nl_fftw_save(void);

#endif
