/* Counter-based random numbers (Random123 Philox4x32-10).
 *
 * How a seed maps to every random number: the Gaussian number for
 * (seed, stream, index) is computed from the Philox block with key = the
 * 64-bit seed and counter = (index low 32 bits, index high 32 bits, stream,
 * 0).  Its first two 64-bit halves are mapped to uniforms in (0, 1) and
 * turned into one standard normal by the Box-Muller transform (cosine
 * branch), with our own log and sincos (core/rng_kernel_internal.h: within
 * 2 ulp) so that the scalar, AVX2 and AVX-512 code paths give the same bits
 * on every machine.  No state is carried between calls, so any sample of
 * any field can be recomputed on its own, in any order and with any thread
 * count.  (Before version 0.2 the transform used libm's log, sin and cos:
 * numbers differ from those by about 1e-15, 2.7e-15 at most in 4 million
 * draws.)
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

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>
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

/* Bulk fill, the same numbers as nl_rng_gauss_pair: out[j], j < n, is
 * g[j % 2] of nl_rng_gauss_pair(seed, stream, first + j / 2, g) (the last
 * sine branch is dropped when n is odd; the index is 64-bit, with carry).
 * From NL_RNG_FILL_PARALLEL numbers on, and outside any OpenMP parallel
 * region, blocks of NL_RNG_FILL_BLOCK run on OpenMP threads; every thread
 * count and every code path gives the same bits.  The code path is the
 * fastest this CPU has (AVX-512, AVX2 or scalar) unless the environment
 * variable NOISELAB_SIMD = scalar, avx2 or avx512 lowers it (read once; any
 * other value is ignored).  out holds n doubles.  Thread-safe. */
#define NL_RNG_FILL_PARALLEL ((size_t)1 << 16)
#define NL_RNG_FILL_BLOCK ((size_t)1 << 14)
void nl_rng_gauss_fill(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out);

/* The code path of nl_rng_gauss_fill: "scalar", "avx2" or "avx512" (a
 * static string).  Thread-safe. */
const char *nl_rng_simd(void);

/* Poisson(mean) by inversion of its CDF (GSL) at nl_rng_uniform2(seed,
 * stream, index, sub); 0 for mean <= 0 or NAN; mean <= 1e8 (beyond, the
 * search bound overflows).  The GSL CDF runs under the library's guard. */
unsigned long nl_rng_poisson(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, double mean);

#ifdef __cplusplus
}
#endif

#endif
