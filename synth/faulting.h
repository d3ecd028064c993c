/* Poisson faulting (Mandelbrot 1975): a sum of randomly placed steps.
 *
 * 1D: faults at Poisson positions of rate `density` per sample over the
 * n samples, each adding a N(0, 1) height to every sample at or after it;
 * the result is a random walk with spectrum f^-2.
 * 2D: random lines, a Poisson number of mean density * (nx + ny), with
 * direction uniform in [0, pi) and signed distance from the grid centre
 * uniform over half the diagonal; each adds a N(0, 1) height on one side.
 * The surface is a Brownian (Levy) surface: radial spectrum k^-3, f^-2
 * along a transect.
 * Every fault is drawn from the counter-based RNG keyed by (seed,
 * NL_SYNTH_FAULT_STREAM, fault index); the count by inversion of the Poisson
 * CDF with nl_rng_uniform(seed, NL_SYNTH_FAULT_STREAM + 1, 0). */
#ifndef NL_SYNTH_FAULTING_H
#define NL_SYNTH_FAULTING_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stdint.h>

#define NL_SYNTH_FAULT_STREAM 300u

/* Fills f (1D or 2D, f->n and f->h as allocated; samples in units of the
 * N(0, 1) fault heights) and writes the number of faults to *count.  Pure
 * in (seed, density, f's size): bit-identical for equal arguments;
 * thread-safe (uses no shared state).  Returns NL_OK, or
 *   NL_EINVAL  f not 1D or 2D, density not positive;
 *   NL_ETOOBIG more than 1e8 faults expected;
 *   NL_ENOMEM  out of memory for the faults. */
int nl_synth_faulting(uint64_t seed, double density, nl_field *f, size_t *count);

/* The number of faults nl_synth_faulting(seed, density, f, ...) draws (its
 * *count), without drawing them; 0 for arguments it refuses.  Reads only
 * f's dim and n.  Pure; thread-safe. */
size_t nl_synth_faulting_count(uint64_t seed, double density, const nl_field *f);

#ifdef __cplusplus
}
#endif

#endif
