/* The AVX2 path of the subdivision stencils: four lanes, see
 * subdiv_simd_internal.h. */
#include "subdiv_simd_internal.h"

#if defined(__x86_64__) && defined(__GNUC__)
#pragma GCC target("avx2")
#include <string.h>

typedef double sk_vd4 __attribute__((vector_size(32)));
typedef long long sk_vi4 __attribute__((vector_size(32)));

static inline sk_vd4 sk_load4(const double *p)
{
    sk_vd4 v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void sk_store4(double *p, sk_vd4 v) { memcpy(p, &v, sizeof v); }

#define SK_W 4
#define SK_VD sk_vd4
#define SK_ZERO ((sk_vd4){0, 0, 0, 0})
#define SK_SET1(x) ((sk_vd4){(x), (x), (x), (x)})
#define SK_LOAD(p) sk_load4(p)
#define SK_STORE(p, v) sk_store4(p, v)
#define SK_LO(e, o) __builtin_shuffle(e, o, (sk_vi4){0, 4, 1, 5})
#define SK_HI(e, o) __builtin_shuffle(e, o, (sk_vi4){2, 6, 3, 7})
#define SK_EVEN(a, b) __builtin_shuffle(a, b, (sk_vi4){0, 2, 4, 6})
#define SK_ODD(a, b) __builtin_shuffle(a, b, (sk_vi4){1, 3, 5, 7})
#define SK_(name) sk_avx2_##name
#define SK_NAME nl_subdiv_pairs_avx2
#include "subdiv_simd_internal.h"

#else

void nl_subdiv_pairs_avx2(const row_job *r, long i0, long i1, const double *g, long k0)
{
    nl_subdiv_pairs_scalar(r, i0, i1, g, k0);
}

#endif
