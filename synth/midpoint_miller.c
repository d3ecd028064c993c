/* Miller's square-square subdivision (Miller 1986; Lewis 1987, "Comparison
 * of Stochastic Synthesis Methods"): see synth/midpoint.h. */
#include "midpoint.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <math.h>
#include <string.h>

void nl_synth_midpoint_miller_mask(int dim, double *w)
{
    if (dim == 1)
        w[0] = 0.75, w[1] = 0.25;
    else if (dim == 2)
        w[0] = 9.0 / 16, w[1] = 3.0 / 16, w[2] = 3.0 / 16, w[3] = 1.0 / 16;
}

/* Semivariogram of fBm: gamma(h) = sigma2 |h|^(2H) / 2. */
static double gam(double sigma2, double H, double dx, double dy)
{
    return 0.5 * sigma2 * pow(hypot(dx, dy), 2 * H);
}

int nl_synth_midpoint_miller_variances(int dim, int levels, double spacing0, double H, double sigma2, double vscale,
                                       double *r0, double *v)
{
    double w[4], px[4], py[4];
    int nc = dim == 1 ? 2 : 4;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "midpoint: expected dimension 1 or 2, got %d", dim);
    if (!(H > 0 && H < 1))
        return NL_ERROR(NL_EINVAL, "midpoint: expected a Hurst exponent 0 < H < 1, got %g", H);
    if (levels < 1 || levels > NL_MILLER_MAX_LEVELS)
        return NL_ERROR(NL_EINVAL, "midpoint: levels: expected 1 to %d, got %d", NL_MILLER_MAX_LEVELS, levels);
    if (!(spacing0 > 0) || !isfinite(spacing0) || !(sigma2 > 0) || !isfinite(sigma2) || !(vscale > 0) ||
        !isfinite(vscale))
        return NL_ERROR(NL_EINVAL, "midpoint: expected a positive finite spacing, variance and variance-scale, got "
                        "%g, %g and %g", spacing0, sigma2, vscale);
    nl_synth_midpoint_miller_mask(dim, w);
    *r0 = 0.5 * sigma2 * pow(spacing0, 2 * H);
    for (int k = 0; k < levels; k++) {
        double s = ldexp(spacing0, -k), t = 0.25 * s, e = 0;
        for (int i = 0; i < nc; i++)
            px[i] = (double)(i % 2) * s, py[i] = (double)(i / 2) * s;
        for (int i = 0; i < nc; i++) {
            e += 2 * w[i] * gam(sigma2, H, t - px[i], dim == 2 ? t - py[i] : 0);
            for (int q = 0; q < nc; q++)
                e -= w[i] * w[q] * gam(sigma2, H, px[i] - px[q], py[i] - py[q]);
        }
        v[k] = e * pow(vscale, k);
        if (!isfinite(v[k]) || !(v[k] >= 0) || !isfinite(*r0))
            return NL_ERROR(NL_EINVAL, "midpoint: the variance of level %d is %g (variance-scale %g per level, "
                            "coarse spacing %g, H %g); expected a finite number: lower the variance-scale, the "
                            "levels or the spacing", k, v[k], vscale, spacing0, H);
    }
    return NL_OK;
}

static uint64_t index2(size_t i, size_t j) { return ((uint64_t)j << 32) | (uint64_t)i; }

void nl_synth_midpoint_miller_refine(int dim, const size_t *n, const double *in, double sd, uint64_t seed, int level,
                                     double *out)
{
    double w[4];
    size_t nx = n[0], ny = dim == 2 ? n[1] : 1, ox = 2 * nx;
    uint32_t stream = NL_MILLER_STREAM + 1u + (uint32_t)level;
    nl_synth_midpoint_miller_mask(dim, w);
    for (size_t j = 0; j < ny; j++) {
        size_t j1 = dim == 2 ? (j + 1) % ny : 0;
        for (size_t i = 0; i < nx; i++) {
            size_t i1 = (i + 1) % nx;
            /* corners P00, P10, P01, P11 */
            double c[4] = {in[j * nx + i], in[j * nx + i1], in[j1 * nx + i], in[j1 * nx + i1]};
            for (int b = 0; b < (dim == 2 ? 2 : 1); b++)
                for (int a = 0; a < 2; a++) {
                    size_t I = 2 * i + (size_t)a, J = dim == 2 ? 2 * j + (size_t)b : 0;
                    double x = 0;
                    if (dim == 1)
                        x = w[a] * c[0] + w[1 - a] * c[1];
                    else
                        for (int q = 0; q < 4; q++)
                            x += w[(q % 2 ^ a) + 2 * (q / 2 ^ b)] * c[q];
                    if (sd > 0)
                        x += sd * nl_rng_gauss(seed, stream, index2(I, J));
                    out[J * ox + I] = x;
                }
        }
    }
}

int nl_synth_midpoint_miller_default_levels(int dim, const size_t *n)
{
    int L = 0;
    while (L < NL_MILLER_MAX_LEVELS) {
        int ok = 1;
        for (int a = 0; a < dim; a++)
            ok &= n[a] % ((size_t)2 << L) == 0 && n[a] / ((size_t)2 << L) >= 2;
        if (!ok)
            break;
        L++;
    }
    return L;
}

static int check_size(int dim, const size_t *n, int L)
{
    for (int a = 0; a < dim; a++)
        if (L > 40 || n[a] % ((size_t)1 << L) != 0 || n[a] >> L < 2)
            return NL_ERROR(NL_EINVAL, "midpoint: --size: expected a multiple of 2^%d = %zu with at least 2 coarse "
                            "samples per axis for %d levels, got %zu", L, (size_t)1 << (L < 40 ? L : 40), L, n[a]);
    return NL_OK;
}

int nl_synth_midpoint_miller(int levels, double H, double sigma2, double vscale, uint64_t seed, nl_field *out)
{
    int dim = out->dim, L, st;
    double v[NL_MILLER_MAX_LEVELS], r0, *a, *b;
    size_t n[2], count;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "midpoint: expected a 1D or 2D field, got %dD", dim);
    if (levels < 0 || levels > NL_MILLER_MAX_LEVELS)
        return NL_ERROR(NL_EINVAL, "midpoint: levels: expected 1 to %d, got %d", NL_MILLER_MAX_LEVELS, levels);
    L = levels ? levels : nl_synth_midpoint_miller_default_levels(dim, out->n);
    if (L < 1)
        return NL_ERROR(NL_EINVAL, "midpoint: --size: expected sizes divisible by 2 with at least 4 samples, got "
                        "%zu", out->n[0]);
    if ((st = check_size(dim, out->n, L)) || (st = nl_size_check(dim, out->n, sizeof(double), 1, &count)) ||
        (st = nl_synth_midpoint_miller_variances(dim, L, ldexp(1.0, L), H, sigma2, vscale, &r0, v)))
        return st;
    if (!(a = nl_alloc(count * sizeof *a)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    n[0] = out->n[0] >> L, n[1] = dim == 2 ? out->n[1] >> L : 1;
    for (size_t j = 0; j < n[1]; j++)
        for (size_t i = 0; i < n[0]; i++)
            a[j * n[0] + i] = sqrt(r0) * nl_rng_gauss(seed, NL_MILLER_STREAM, index2(i, j));
    /* ping-pong between the scratch and the output so the last level lands in out */
    b = out->data;
    if (L % 2 == 0) {
        memcpy(b, a, n[0] * n[1] * sizeof *a);
        double *t = a;
        a = b, b = t;
    }
    for (int k = 0; k < L; k++) {
        nl_synth_midpoint_miller_refine(dim, n, a, sqrt(v[k]), seed, k, b);
        double *t = a;
        a = b, b = t;
        n[0] *= 2, n[1] = dim == 2 ? 2 * n[1] : 1;
    }
    nl_free(a == out->data ? b : a);
    return NL_OK;
}
