/* The AVX-512 path of the Gaussian fill: eight lanes of core/rng_kernel_internal.h. */
#include "rng_internal.h"

#if defined(__x86_64__) && defined(__GNUC__)
#pragma GCC target("avx512f")
#include <immintrin.h>

typedef double vd8 __attribute__((vector_size(64)));
typedef uint64_t vu8 __attribute__((vector_size(64)));
typedef long long vi8 __attribute__((vector_size(64)));

#define RK_W 8
#define RK_VD vd8
#define RK_VU_ZERO ((vu8){0, 0, 0, 0, 0, 0, 0, 0})
#define RK_VU vu8
#define RK_MUL(a, b) ((vu8)_mm512_mul_epu32((__m512i)(a), _mm512_set1_epi64(b)))
#define RK_ASU(x) ((vu8)(x))
#define RK_ASD(x) ((vd8)(x))
#define RK_SQRT(x) ((vd8)_mm512_sqrt_pd((__m512d)(x)))
#define RK_ZIP(g0, g1, lo, hi)                                                                                     \
    ((lo) = __builtin_shuffle(g0, g1, (vi8){0, 8, 1, 9, 2, 10, 3, 11}),                                            \
     (hi) = __builtin_shuffle(g0, g1, (vi8){4, 12, 5, 13, 6, 14, 7, 15}))
#define RK_(name) rk_avx512_##name
#include "rng_kernel_internal.h"

void nl_rng_fill_avx512(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    rk_avx512_fill(seed, stream, first, n, out);
}

#else

void nl_rng_fill_avx512(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    nl_rng_fill_scalar(seed, stream, first, n, out);
}

#endif
