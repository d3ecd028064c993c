/* Counter-based random numbers (Random123 Philox4x32-10).
 *
 * How a seed maps to every random number: the Gaussian number for
 * (seed, stream, index) is computed from the Philox block with key = the
 * 64-bit seed and counter = (index low 32 bits, index high 32 bits, stream,
 * 0).  Its first two 64-bit halves are mapped to uniforms in (0, 1) and
 * turned into one standard normal by the Box-Muller transform (cosine
 * branch).  No state is carried between calls, so any sample of any field
 * can be recomputed on its own, in any order and with any thread count.
 *
 * nl_rng_gauss_pair returns both branches of one transform (cosine, sine):
 * two independent normals for the price of one, the first equal to
 * nl_rng_gauss of the same arguments.
 *
 * Streams in use: NL_STREAM_WHITE is the white noise under FFT synthesis
 * (samples 2k and 2k + 1 in row-major order are the pair of index k), so
 * two models synthesised with the same seed and size share it.
 *
 * No function here returns a status or allocates; all are pure functions of
 * their arguments and thread-safe. */
#ifndef NL_RNG_H
#define NL_RNG_H

#include <stdint.h>

enum { NL_STREAM_WHITE = 0 };

/* Uniform in the open interval (0, 1), 53 bits. */
double nl_rng_uniform(uint64_t seed, uint32_t stream, uint64_t index);

/* Standard normal N(0, 1). */
double nl_rng_gauss(uint64_t seed, uint32_t stream, uint64_t index);

/* The same with a fourth counter word `sub` (0 in the two above), for
 * numbers indexed by two integers such as (cell, impulse). */
double nl_rng_uniform2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub);
double nl_rng_gauss2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub);

/* Two independent N(0, 1): g[0] = nl_rng_gauss(seed, stream, index) and its
 * sine branch g[1]. */
void nl_rng_gauss_pair(uint64_t seed, uint32_t stream, uint64_t index, double g[2]);

/* Poisson(mean) by inversion of its CDF (GSL) at nl_rng_uniform2(seed,
 * stream, index, sub); 0 for mean <= 0 or NAN; mean <= 1e8 (beyond, the
 * search bound overflows).  The GSL CDF runs under the library's guard. */
unsigned long nl_rng_poisson(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, double mean);

#endif
