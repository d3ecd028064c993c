/* Philox4x32-10 counter-based Gaussian numbers: the scalar path and the
 * choice of path for bulk fills. */
#include "rng.h"
#include "rng_internal.h"
#include "gsl_guard_internal.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

static inline uint64_t asu(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline double asd(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

#define RK_VD double
#define RK_VU uint64_t
#define RK_VU_ZERO 0
#define RK_MUL(a, b) (((a) & 0xffffffffu) * (uint64_t)(b))
#define RK_ASU asu
#define RK_ASD asd
#define RK_SQRT sqrt
#define RK_(name) rk_scalar_##name
#include "rng_kernel_internal.h"

/* The block of counter (index, stream, sub) under key seed. */
static void block(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, uint64_t c[4], uint64_t k0[10],
                  uint64_t k1[10])
{
    c[0] = index & RK_M32, c[1] = index >> 32, c[2] = stream, c[3] = sub;
    rk_scalar_keys(seed, k0, k1);
}

void nl_rng_philox_block(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, uint32_t out[4])
{
    uint64_t c[4];
    uint64_t k0[10], k1[10];
    block(seed, stream, index, sub, c, k0, k1);
    rk_scalar_philox(c, k0, k1);
    for (int a = 0; a < 4; a++)
        out[a] = (uint32_t)c[a];
}

double nl_rng_kernel_log(double u) { return rk_scalar_log(u); }

void nl_rng_kernel_sincos(double u, double *c, double *s) { rk_scalar_sincos(u, c, s); }

double nl_rng_uniform(uint64_t seed, uint32_t stream, uint64_t index)
{
    return nl_rng_uniform2(seed, stream, index, 0);
}

double nl_rng_gauss(uint64_t seed, uint32_t stream, uint64_t index)
{
    return nl_rng_gauss2(seed, stream, index, 0);
}

double nl_rng_uniform2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub)
{
    uint64_t c[4];
    uint64_t k0[10], k1[10];
    block(seed, stream, index, sub, c, k0, k1);
    rk_scalar_philox(c, k0, k1);
    return rk_scalar_u01(c[0], c[1]);
}

double nl_rng_gauss2(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub)
{
    uint64_t c[4];
    uint64_t k0[10], k1[10];
    double g[2];
    block(seed, stream, index, sub, c, k0, k1);
    rk_scalar_gauss(c, k0, k1, &g[0], &g[1]);
    return g[0];
}

void nl_rng_gauss_pair(uint64_t seed, uint32_t stream, uint64_t index, double g[2])
{
    uint64_t c[4];
    uint64_t k0[10], k1[10];
    block(seed, stream, index, 0, c, k0, k1);
    rk_scalar_gauss(c, k0, k1, &g[0], &g[1]);
}

void nl_rng_fill_scalar(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    uint64_t k0[10], k1[10];
    rk_scalar_keys(seed, k0, k1);
    for (size_t j = 0; j < n; j += 2) {
        uint64_t idx = first + j / 2, c[4] = {idx & RK_M32, idx >> 32, stream, 0};
        double g0, g1;
        rk_scalar_gauss(c, k0, k1, &g0, &g1);
        out[j] = g0;
        if (j + 1 < n)
            out[j + 1] = g1;
    }
}

int nl_rng_path_available(int path)
{
    if (path == NL_RNG_SCALAR)
        return 1;
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init();
    if (path == NL_RNG_AVX2)
        return __builtin_cpu_supports("avx2") != 0;
    if (path == NL_RNG_AVX512)
        return __builtin_cpu_supports("avx512f") != 0;
#endif
    return 0;
}

int nl_rng_path_choose(const char *env)
{
    static const char *const name[NL_RNG_NPATH] = {"scalar", "avx2", "avx512"};
    int top = NL_RNG_NPATH - 1;
    for (int p = 0; env && p < NL_RNG_NPATH; p++)
        if (strcmp(env, name[p]) == 0)
            top = p;
    while (top > 0 && !nl_rng_path_available(top))
        top--;
    return top;
}

static int path_in_use(void)
{
    static int chosen = -1;
    int p = __atomic_load_n(&chosen, __ATOMIC_RELAXED);
    if (p < 0) {
        p = nl_rng_path_choose(getenv("NOISELAB_SIMD"));
        __atomic_store_n(&chosen, p, __ATOMIC_RELAXED);
    }
    return p;
}

const char *nl_rng_simd(void)
{
    static const char *const name[NL_RNG_NPATH] = {"scalar", "avx2", "avx512"};
    return name[path_in_use()];
}

void nl_rng_gauss_fill_path(int path, uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    if (path == NL_RNG_AVX512)
        nl_rng_fill_avx512(seed, stream, first, n, out);
    else if (path == NL_RNG_AVX2)
        nl_rng_fill_avx2(seed, stream, first, n, out);
    else
        nl_rng_fill_scalar(seed, stream, first, n, out);
}

void nl_rng_gauss_fill(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    const size_t B = NL_RNG_FILL_BLOCK, nb = (n + B - 1) / B;
    const int path = path_in_use();
    if (n < NL_RNG_FILL_PARALLEL || omp_in_parallel()) {
        nl_rng_gauss_fill_path(path, seed, stream, first, n, out);
        return;
    }
#pragma omp parallel for schedule(static)
    for (size_t b = 0; b < nb; b++)
        nl_rng_gauss_fill_path(path, seed, stream, first + b * (B / 2), b + 1 < nb ? B : n - b * B, out + b * B);
}

unsigned long nl_rng_poisson(uint64_t seed, uint32_t stream, uint64_t index, uint32_t sub, double mean)
{
    double u = nl_rng_uniform2(seed, stream, index, sub);
    unsigned long lo = 0, hi = (unsigned long)(mean + 20 * sqrt(mean) + 20);
    if (!(mean > 0))
        return 0;
    nl_gsl_enter();
    while (lo < hi) {
        unsigned long mid = lo + (hi - lo) / 2;
        if (gsl_cdf_poisson_P((unsigned)mid, mean) < u)
            lo = mid + 1;
        else
            hi = mid;
    }
    nl_gsl_leave();
    return lo;
}
