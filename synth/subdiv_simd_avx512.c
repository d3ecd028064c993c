/* The AVX-512 path of the subdivision stencils: eight lanes, see
 * subdiv_simd_internal.h. */
#include "subdiv_simd_internal.h"

#if defined(__x86_64__) && defined(__GNUC__)
#pragma GCC target("avx512f")
#include <string.h>

typedef double sk_vd8 __attribute__((vector_size(64)));
typedef long long sk_vi8 __attribute__((vector_size(64)));

static inline sk_vd8 sk_load8(const double *p)
{
    sk_vd8 v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void sk_store8(double *p, sk_vd8 v) { memcpy(p, &v, sizeof v); }

#define SK_W 8
#define SK_VD sk_vd8
#define SK_ZERO ((sk_vd8){0, 0, 0, 0, 0, 0, 0, 0})
#define SK_SET1(x) ((sk_vd8){(x), (x), (x), (x), (x), (x), (x), (x)})
#define SK_LOAD(p) sk_load8(p)
#define SK_STORE(p, v) sk_store8(p, v)
#define SK_LO(e, o) __builtin_shuffle(e, o, (sk_vi8){0, 8, 1, 9, 2, 10, 3, 11})
#define SK_HI(e, o) __builtin_shuffle(e, o, (sk_vi8){4, 12, 5, 13, 6, 14, 7, 15})
#define SK_EVEN(a, b) __builtin_shuffle(a, b, (sk_vi8){0, 2, 4, 6, 8, 10, 12, 14})
#define SK_ODD(a, b) __builtin_shuffle(a, b, (sk_vi8){1, 3, 5, 7, 9, 11, 13, 15})
#define SK_(name) sk_avx512_##name
#define SK_NAME nl_subdiv_pairs_avx512
#include "subdiv_simd_internal.h"

#else

void nl_subdiv_pairs_avx512(const row_job *r, long i0, long i1, const double *g, long k0)
{
    nl_subdiv_pairs_scalar(r, i0, i1, g, k0);
}

#endif
