/* The code paths of the Gaussian fill (core/rng.h); not installed. */
#ifndef NL_RNG_INTERNAL_H
#define NL_RNG_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

/* Code paths, slowest first: every one gives the same bits. */
enum { NL_RNG_SCALAR, NL_RNG_AVX2, NL_RNG_AVX512, NL_RNG_NPATH };

/* One path's fill on the calling thread: out[j], j < n, is the cosine
 * (j even) or sine (j odd) branch of the pair first + j / 2, exactly as
 * nl_rng_gauss_fill.  The vector ones exist only on x86-64 and may be
 * called only where the CPU has their instructions (nl_rng_path_available). */
void nl_rng_fill_scalar(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out);
void nl_rng_fill_avx2(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out);
void nl_rng_fill_avx512(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out);

/* 1 when this CPU (and build) can run `path`, else 0.  Thread-safe. */
int nl_rng_path_available(int path);

/* The path NOISELAB_SIMD = `env` selects: "scalar", "avx2" or "avx512",
 * lowered to the fastest available one at or below it; NULL or any other
 * value: the fastest available.  Thread-safe. */
int nl_rng_path_choose(const char *env);

/* nl_rng_gauss_fill on one path, on the calling thread (path available). */
void nl_rng_gauss_fill_path(int path, uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out);

/* The Philox4x32-10 block of the counter (index low, index high, stream,
 * sub) under key seed, by the kernel of the scalar path (tested against
 * Random123's philox4x32). */
void nl_rng_philox_block(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, uint32_t out[4]);

/* The kernel's log(u) for u in (0, 1) and its cos and sin of 2 pi u, on the
 * scalar path (for the accuracy tests). */
double nl_rng_kernel_log(double u);
void nl_rng_kernel_sincos(double u, double *c, double *s);

#endif
