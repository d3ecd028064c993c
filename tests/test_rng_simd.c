/* The Gaussian fill (core/rng.h): the same bits on every code path and
 * thread count, Random123's Philox, the accuracy of the kernel's log and
 * sincos, and the distribution of its numbers. */
#include "../core/rng.h"
#include "../core/rng_internal.h"

#include <criterion/criterion.h>
#include <math.h>
#include <omp.h>
#include <Random123/philox.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NDRAW 1000000

/* The kernel's Philox is Random123's philox4x32 (10 rounds): its known
 * answer for counter 0 and key 0 (Random123's kat_vectors) and 10^4 counters
 * and keys spread over all four words. */
Test(rng_simd, philox_is_random123s)
{
    uint32_t b[4];
    nl_rng_philox_block(0, 0, 0, 0, b);
    cr_assert(b[0] == 0x6627e8d5u && b[1] == 0xe169c58du && b[2] == 0xbc57ac4cu && b[3] == 0x9b00dbd8u);
    for (uint64_t i = 0; i < 10000; i++) {
        uint64_t seed = i * 0x9E3779B97F4A7C15ull, index = i * 0xD1B54A32D192ED03ull;
        uint32_t stream = (uint32_t)(i * 2654435761u), sub = (uint32_t)(i >> 3);
        philox4x32_ctr_t c = {{(uint32_t)index, (uint32_t)(index >> 32), stream, sub}};
        philox4x32_key_t k = {{(uint32_t)seed, (uint32_t)(seed >> 32)}};
        philox4x32_ctr_t r = philox4x32(c, k);
        nl_rng_philox_block(seed, stream, index, sub, b);
        cr_assert(memcmp(b, r.v, sizeof b) == 0, "i=%llu", (unsigned long long)i);
    }
}

/* Every available path gives the scalar path's bits: 10^6 + 1 numbers (odd:
 * the last pair is cut) from an index whose low word carries into the high
 * one, into an output one double off the vector alignment; then every
 * length 0..40 from every start 0..9, which covers each partial block. */
Test(rng_simd, every_path_gives_the_same_bits)
{
    const size_t n = NDRAW + 1;
    const uint64_t first = 0xffffffffull - 1000;
    double *ref = malloc((n + 1) * sizeof *ref), *out = malloc((n + 1) * sizeof *out);
    cr_assert(ref && out);
    nl_rng_gauss_fill_path(NL_RNG_SCALAR, 2385, 7, first, n, ref);
    for (size_t j = 0; j < n; j += 4099) {
        double g[2];
        nl_rng_gauss_pair(2385, 7, first + j / 2, g);
        cr_assert_eq(ref[j], g[j % 2], "j=%zu", j);
    }
    for (int p = NL_RNG_AVX2; p < NL_RNG_NPATH; p++) {
        if (!nl_rng_path_available(p)) {
            cr_log_info("path %d: not on this CPU", p);
            continue;
        }
        out[n] = 1.5;
        nl_rng_gauss_fill_path(p, 2385, 7, first, n, out + 1);
        cr_assert(memcmp(out + 1, ref, n * sizeof *ref) == 0, "path %d differs from the scalar path", p);
        for (uint64_t s = 0; s < 10; s++)
            for (size_t len = 0; len <= 40; len++) {
                out[len] = 1.5;
                nl_rng_gauss_fill_path(p, 2385, 7, first + s, len, out);
                cr_assert(memcmp(out, ref + 2 * s, len * sizeof *out) == 0 && out[len] == 1.5, "path %d start %d len %zu",
                          p, (int)s, len);
            }
    }
    free(ref), free(out);
}

/* The threaded fill gives the same bits with 1, 2 and 4 threads. */
Test(rng_simd, every_thread_count_gives_the_same_bits)
{
    const size_t n = NDRAW + 1;
    const int was = omp_get_max_threads();
    double *ref = malloc(n * sizeof *ref), *out = malloc(n * sizeof *out);
    cr_assert(ref && out);
    nl_rng_gauss_fill_path(NL_RNG_SCALAR, 11, 3, 1234567, n, ref);
    for (int t = 1; t <= 4; t *= 2) {
        omp_set_num_threads(t);
        memset(out, 0, n * sizeof *out);
        nl_rng_gauss_fill(11, 3, 1234567, n, out);
        cr_assert(memcmp(out, ref, n * sizeof *out) == 0, "%d threads (path %s)", t, nl_rng_simd());
    }
    omp_set_num_threads(was);
    free(ref), free(out);
}

/* NOISELAB_SIMD names a ceiling: an unavailable path falls to the fastest
 * available below it, anything else means the fastest. */
Test(rng_simd, path_choice)
{
    int best = NL_RNG_NPATH - 1;
    while (!nl_rng_path_available(best))
        best--;
    cr_assert_eq(nl_rng_path_choose("scalar"), NL_RNG_SCALAR);
    cr_assert_eq(nl_rng_path_choose("avx2"), nl_rng_path_available(NL_RNG_AVX2) ? NL_RNG_AVX2 : NL_RNG_SCALAR);
    cr_assert_eq(nl_rng_path_choose("avx512"), best);
    cr_assert_eq(nl_rng_path_choose(NULL), best);
    cr_assert_eq(nl_rng_path_choose("AVX2 "), best);
}

/* |x - ref| in units of the last place of ref (a double's). */
static double ulps(double x, long double ref)
{
    int e;
    frexpl(ref, &e);
    return (double)(fabsl((long double)x - ref) / ldexpl(1.0L, e - 53));
}

/* The kernel's log and sincos against long double (64-bit mantissa: its own
 * error is below 0.002 of a double's ulp) at 10^6 uniforms of the generator
 * and at the edges (the smallest u, u near 1 and near the quadrant and octant
 * boundaries).  log: fdlibm's algorithm, proven below 1 ulp.  cos and sin of
 * 2 pi u, after the exact reduction to r = u - q/4: the Taylor truncation is
 * below 0.03 ulp, the rounding of the two last Horner steps at most 1 ulp
 * and the inner terms' below 0.6 ulp (measured at most 1.63 over 10^7
 * draws), so 2 ulp. */
static void check_kernel(double u)
{
    static const long double twopi = 6.283185307179586476925286766559005768L;
    double c, s;
    long double q = roundl(4.0L * u), r = (long double)u - q / 4, cr = cosl(twopi * r), sr = sinl(twopi * r);
    long double C[4] = {cr, -sr, -cr, sr}, S[4] = {sr, cr, -sr, -cr};
    int k = (int)q & 3;
    nl_rng_kernel_sincos(u, &c, &s);
    cr_assert_lt(ulps(nl_rng_kernel_log(u), logl(u)), 1.0, "log(%a)", u);
    cr_assert_lt(ulps(c, C[k]), 2.0, "cos(2 pi %a)", u);
    cr_assert_lt(ulps(s, S[k]), 2.0, "sin(2 pi %a)", u);
}

Test(rng_simd, kernel_log_and_sincos_accuracy)
{
    for (uint64_t i = 0; i < NDRAW; i++)
        check_kernel(nl_rng_uniform(5, 77, i));
    for (int m = 0; m < 2000; m++) {
        double u = (0.5 + m) * 0x1p-52;
        check_kernel(u), check_kernel(1 - u);
        for (int q = 1; q < 8; q++)
            check_kernel(q * 0.125 + u), check_kernel(q * 0.125 - u);
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double Phi(double x) { return 0.5 * erfc(-x / sqrt(2.0)); }

/* 10^6 numbers of the fill against N(0, 1), seed fixed.  Kolmogorov-
 * Smirnov: sqrt(n) D_n exceeds 1.949 with probability 0.001 under the null
 * (Kolmogorov's limit law; n = 10^6 is deep in the asymptote).  Mean and
 * variance: sd 1/sqrt(n) and sqrt(2/n), five sd.  Tails: the count beyond
 * |g| > t is Binomial(n, p = 2 Phi(-t)), five sd, for t = 3 and 4.  No number
 * can exceed sqrt(-2 log 2^-53) = 8.57 (the smallest uniform). */
Test(rng_simd, fill_is_standard_normal)
{
    const size_t n = NDRAW;
    double *g = malloc(n * sizeof *g), s1 = 0, s2 = 0, d = 0;
    size_t beyond[2] = {0, 0};
    cr_assert(g);
    nl_rng_gauss_fill(2385, 9, 0, n, g);
    for (size_t i = 0; i < n; i++) {
        cr_assert(fabs(g[i]) <= 8.58, "g[%zu] = %g", i, g[i]);
        s1 += g[i], s2 += g[i] * g[i];
        beyond[0] += fabs(g[i]) > 3, beyond[1] += fabs(g[i]) > 4;
    }
    cr_expect_leq(fabs(s1 / n), 5 / sqrt((double)n));
    cr_expect_leq(fabs(s2 / n - 1), 5 * sqrt(2.0 / n));
    for (int a = 0; a < 2; a++) {
        double p = 2 * Phi(-(3.0 + a)), mu = p * n, sd = sqrt(n * p * (1 - p));
        cr_expect_leq(fabs((double)beyond[a] - mu), 5 * sd, "|g| > %d: %zu, expected %.1f", 3 + a, beyond[a], mu);
    }
    qsort(g, n, sizeof *g, cmp_double);
    for (size_t i = 0; i < n; i++) {
        double F = Phi(g[i]);
        d = fmax(d, fmax(F - (double)i / n, (double)(i + 1) / n - F));
    }
    cr_expect_lt(sqrt((double)n) * d, 1.949, "KS sqrt(n) D = %g", sqrt((double)n) * d);
    free(g);
}
