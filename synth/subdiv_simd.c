/* The portable path of the subdivision stencils: two lanes of GCC's generic
 * vectors (SSE2 on x86-64), see subdiv_simd_internal.h. */
#include "subdiv_simd_internal.h"

#include <string.h>

typedef double sk_vd2 __attribute__((vector_size(16)));
typedef long long sk_vi2 __attribute__((vector_size(16)));

static inline sk_vd2 sk_load2(const double *p)
{
    sk_vd2 v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void sk_store2(double *p, sk_vd2 v) { memcpy(p, &v, sizeof v); }

#define SK_W 2
#define SK_VD sk_vd2
#define SK_ZERO ((sk_vd2){0, 0})
#define SK_SET1(x) ((sk_vd2){(x), (x)})
#define SK_LOAD(p) sk_load2(p)
#define SK_STORE(p, v) sk_store2(p, v)
#define SK_LO(e, o) __builtin_shuffle(e, o, (sk_vi2){0, 2})
#define SK_HI(e, o) __builtin_shuffle(e, o, (sk_vi2){1, 3})
#define SK_EVEN(a, b) __builtin_shuffle(a, b, (sk_vi2){0, 2})
#define SK_ODD(a, b) __builtin_shuffle(a, b, (sk_vi2){1, 3})
#define SK_(name) sk_scalar_##name
#define SK_NAME nl_subdiv_pairs_scalar
#include "subdiv_simd_internal.h"
