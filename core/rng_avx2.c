/* The AVX2 path of the Gaussian fill: four lanes of core/rng_kernel_internal.h. */
#include "rng_internal.h"

#if defined(__x86_64__) && defined(__GNUC__)
#pragma GCC target("avx2")
#include <immintrin.h>

typedef double vd4 __attribute__((vector_size(32)));
typedef uint64_t vu4 __attribute__((vector_size(32)));
typedef long long vi4 __attribute__((vector_size(32)));

#define RK_W 4
#define RK_VD vd4
#define RK_VU_ZERO ((vu4){0, 0, 0, 0})
#define RK_VU vu4
#define RK_MUL(a, b) ((vu4)_mm256_mul_epu32((__m256i)(a), _mm256_set1_epi64x(b)))
#define RK_ASU(x) ((vu4)(x))
#define RK_ASD(x) ((vd4)(x))
#define RK_SQRT(x) ((vd4)_mm256_sqrt_pd((__m256d)(x)))
#define RK_ZIP(g0, g1, lo, hi)                                                                                     \
    ((lo) = __builtin_shuffle(g0, g1, (vi4){0, 4, 1, 5}), (hi) = __builtin_shuffle(g0, g1, (vi4){2, 6, 3, 7}))
#define RK_(name) rk_avx2_##name
#include "rng_kernel_internal.h"

void nl_rng_fill_avx2(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    rk_avx2_fill(seed, stream, first, n, out);
}

#else

void nl_rng_fill_avx2(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    nl_rng_fill_scalar(seed, stream, first, n, out);
}

#endif
