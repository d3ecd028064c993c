/* The Gaussian kernel, written once for every code path: Philox4x32-10
 * (Salmon et al. 2011, the Random123 algorithm) and the Box-Muller
 * transform with our own log and sincos.  A path includes this file after
 * defining
 *   RK_VD, RK_VU     its lane types (double and uint64_t: scalars or vectors)
 *   RK_MUL(a, b)     the 64-bit product of the low 32 bits of a by b < 2^32
 *   RK_ASU, RK_ASD   bit casts double <-> uint64_t
 *   RK_SQRT(x)       the correctly rounded square root
 *   RK_VU_ZERO       the zero of RK_VU
 *   RK_(name)        the name under which this path's functions are made
 * Every step is an integer operation, a bit cast or one IEEE-754 basic
 * operation (+ - * / sqrt, correctly rounded) in one fixed order, and the
 * files are compiled with -ffp-contract=off (no fused multiply-add), so every
 * lane width gives the same bits for the same counter (tests/test_rng_simd.c).
 *
 * Accuracy (measured against long double logl, sinl and cosl over 10^7
 * draws of the uniforms, tests/test_rng_simd.c checks the bounds over 10^6):
 * log within 1 ulp (fdlibm's algorithm, below 1 ulp by its analysis; 0.84
 * measured); sin and cos of 2 pi u within 2 ulp (1.63 measured) of their
 * value after an exact reduction (Taylor polynomials in r, |r| <= 1/8,
 * truncation below 0.03 ulp).  The Gaussian numbers differ from those of
 * libm's log, sin and cos by 2.7e-15 at most in 4 million draws (a relative
 * 1e-12 near the zeros of cos and sin, where libm's argument 2 pi u carried
 * the rounding of the product): a float32 file rarely changes. */
#ifndef NL_RNG_KERNEL_INTERNAL_H
#define NL_RNG_KERNEL_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define RK_M32 0xffffffffu
#define RK_EXP52 0x4330000000000000u  /* the bits of 2^52 */

/* The 10 round keys of Philox4x32-10 for `seed` in every lane: the key
 * bumped r times by the Weyl constants (Random123's philox4x32bumpkey). */
static inline void RK_(keys)(uint64_t seed, RK_VU k0[10], RK_VU k1[10])
{
    uint32_t a = (uint32_t)seed, b = (uint32_t)(seed >> 32);
    RK_VU zero = RK_VU_ZERO;
    for (int r = 0; r < 10; r++, a += 0x9E3779B9u, b += 0xBB67AE85u)
        k0[r] = zero + a, k1[r] = zero + b;
}

/* Philox4x32-10 of the counter (c0, c1, c2, c3), each lane holding 32 bits:
 * Random123's philox4x32round, ten times.  The low halves of the products
 * keep their high 32 bits until the end: they only reach c0 and c2, whose
 * high bits RK_MUL ignores. */
static inline void RK_(philox)(RK_VU c[4], const RK_VU k0[10], const RK_VU k1[10])
{
    RK_VU c0 = c[0], c1 = c[1], c2 = c[2], c3 = c[3];
#pragma GCC unroll 10
    for (int r = 0; r < 10; r++) {
        RK_VU p0 = RK_MUL(c0, 0xD2511F53u), p1 = RK_MUL(c2, 0xCD9E8D57u);
        c0 = (p1 >> 32) ^ c1 ^ k0[r];
        c1 = p1;
        c2 = (p0 >> 32) ^ c3 ^ k1[r];
        c3 = p0;
    }
    c[0] = c0 & RK_M32, c[1] = c1 & RK_M32, c[2] = c2 & RK_M32, c[3] = c3 & RK_M32;
}

/* Random123's u01fixedpt_open_open_64_double of the 64 bits hi:lo,
 * (0.5 + (bits >> 12)) 2^-52, without an integer conversion: 2^52 + m is the
 * double with mantissa m, and both differences are exact. */
static inline RK_VD RK_(u01)(RK_VU lo, RK_VU hi)
{
    RK_VU m = (hi << 20) | (lo >> 12);
    return (RK_ASD(m | RK_EXP52) - (0x1p52 - 0.5)) * 0x1p-52;
}

/* log(u) for a normal u > 0, fdlibm's e_log.c: u = 2^k (1 + f) with
 * sqrt(2)/2 <= 1 + f < sqrt(2), log(1 + f) = f - s (f - R(s^2)) with
 * s = f / (2 + f), in its order of operations. */
static inline RK_VD RK_(log)(RK_VD u)
{
    RK_VU b = RK_ASU(u), e = b >> 52, mant = b & 0x000fffffffffffffu;
    RK_VU i = (mant + 0x00095f6400000000u) & 0x0010000000000000u;
    RK_VD f = RK_ASD(mant | (i ^ 0x3ff0000000000000u)) - 1.0;
    RK_VD k = RK_ASD(RK_EXP52 | (e + (i >> 52))) - (0x1p52 + 1023.0);
    RK_VD s = f / (2.0 + f), z = s * s, w = z * z;
    RK_VD t1 = w * (3.999999999940941908e-01 + w * (2.222219843214978396e-01 + w * 1.531383769920937332e-01));
    RK_VD t2 = z * (6.666666666666735130e-01 +
                    w * (2.857142874366239149e-01 + w * (1.818357216161805012e-01 + w * 1.479819860511658591e-01)));
    RK_VD R = t2 + t1, hfsq = 0.5 * f * f;
    return k * 6.93147180369123816490e-01 - ((hfsq - (s * (hfsq + R) + k * 1.90821492927058770002e-10)) - f);
}

/* cos and sin of 2 pi u for u in (0, 1).  q = round(4u) by the 1.5 2^52
 * rounding constant and r = u - q/4 are exact (u is a multiple of 2^-53 and
 * 4u never a half-integer), |r| <= 1/8; the Taylor series of sin(2 pi r) to
 * r^17 and cos(2 pi r) to r^16; then the quadrant q by swaps and signs. */
static inline void RK_(sincos)(RK_VD u, RK_VD *c, RK_VD *s)
{
    RK_VD t = u * 4.0 + 0x1.8p52, r = u - (t - 0x1.8p52) * 0.25, r2 = r * r;
    RK_VU q = RK_ASU(t), swap = -(q & 1), sc = ((q + 1) & 2) << 62, ss = (q & 2) << 62;
    RK_VD sn = r * (0x1.921fb54442d18p+2 +
                    r2 * (-0x1.4abbce625be53p+5 +
                          r2 * (0x1.466bc6775aae2p+6 +
                                r2 * (-0x1.32d2cce62bd86p+6 +
                                      r2 * (0x1.50783487ee782p+5 +
                                            r2 * (-0x1.e3074fde8871fp+3 +
                                                  r2 * (0x1.e8f434d018d63p+1 +
                                                        r2 * (-0x1.6fadb9f155744p-1 + r2 * 0x1.aaec32af93359p-4))))))));
    RK_VD cs = 1.0 + r2 * (-19.739208802178716 +
                           r2 * (64.9393940226683 +
                                 r2 * (-85.45681720669373 +
                                       r2 * (60.24464137187666 +
                                             r2 * (-26.4262567833744 +
                                                   r2 * (7.903536371318469 +
                                                         r2 * (-1.714390711088672 + r2 * 0.28200596845579123)))))));
    RK_VU sb = RK_ASU(sn), cb = RK_ASU(cs);
    *c = RK_ASD(((sb & swap) | (cb & ~swap)) ^ sc);
    *s = RK_ASD(((cb & swap) | (sb & ~swap)) ^ ss);
}

/* The pair of one Philox block: the uniforms of its 64-bit halves, then Box
 * and Muller (1958), cosine branch g0 and sine branch g1. */
static inline void RK_(gauss)(RK_VU c[4], const RK_VU k0[10], const RK_VU k1[10], RK_VD *g0, RK_VD *g1)
{
    RK_VD co, si, rad;
    RK_(philox)(c, k0, k1);
    rad = RK_SQRT(-2.0 * RK_(log)(RK_(u01)(c[0], c[1])));
    RK_(sincos)(RK_(u01)(c[2], c[3]), &co, &si);
    *g0 = rad * co;
    *g1 = rad * si;
}

#ifdef RK_W
/* The fill of a vector path of RK_W lanes (see rng_internal.h), which also
 * defines RK_ZIP(g0, g1, lo, hi): lo, hi = g0[0] g1[0] g0[1] g1[1] ... */
static inline void RK_(fill)(uint64_t seed, uint32_t stream, uint64_t first, size_t n, double *out)
{
    RK_VU k0[10], k1[10], lane, zero = RK_VU_ZERO;
    for (int a = 0; a < RK_W; a++)
        lane[a] = (uint64_t)a;
    RK_(keys)(seed, k0, k1);
    for (size_t j = 0; j < n; j += 2 * RK_W) {
        RK_VU idx = (first + j / 2) + lane, c[4] = {idx & RK_M32, idx >> 32, zero + stream, zero};
        RK_VD g0, g1, lo, hi;
        RK_(gauss)(c, k0, k1, &g0, &g1);
        RK_ZIP(g0, g1, lo, hi);
        if (j + 2 * RK_W <= n) {
            memcpy(out + j, &lo, sizeof lo);
            memcpy(out + j + RK_W, &hi, sizeof hi);
        } else {
            double t[2 * RK_W];
            memcpy(t, &lo, sizeof lo);
            memcpy(t + RK_W, &hi, sizeof hi);
            memcpy(out + j, t, (n - j) * sizeof *t);
        }
    }
}
#endif

#endif
