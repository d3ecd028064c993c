/* Model spectra at integer wave vectors (Keller 2001, eq. 13), evaluated
 * once per distinct radius, or on a radial table for many radii. */
#include "rank1_model.h"
#include "../core/field.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "method.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* |k / extent|^2 in the order of operations used since the first version. */
static double freq2(const long *k, int s, double extent)
{
    double f2 = 0;
    for (int a = 0; a < s; a++)
        f2 += ((double)k[a] / extent) * ((double)k[a] / extent);
    return f2;
}

static double raw_spectrum(const nl_rank1_model_ctx *c, const long *k, int s)
{
    double f[3] = {0, 0, 0};
    for (int a = 0; a < s && a < 3; a++)
        f[a] = (double)k[a] / c->extent;
    return nl_model_is_spectral(c->m) ? nl_model_spectrum(c->m, s, f)
                                      : nl_model_spectrum_iso(c->m, s, sqrt(freq2(k, s, c->extent)));
}

double nl_rank1_model_spectrum(const long *k, int s, void *ctx)
{
    const nl_rank1_model_ctx *c = ctx;
    double v = raw_spectrum(c, k, s);
    /* quadrature leaves rounding-level negatives where the spectrum is ~0 */
    if (v < 0 && v > -1e-12 * fabs(nl_model_is_spectral(c->m) ? v : nl_model_spectrum_iso(c->m, s, 0)))
        v = 0;
    return v / pow(c->extent, s);
}

int nl_rank1_model_check(const nl_model *m, int s)
{
    if (nl_model_nugget(m) != 0) {
        char list[64];
        nl_method_names(NL_METHOD_NUGGET, NULL, ", ", " or ", list, sizeof list);
        return NL_ERROR(NL_EINVAL, "rank1: %s: a nugget is not represented by a rank-1 lattice (the Hankel "
                        "transform has no white-noise part); use %s", nl_model_spec(m), list);
    }
    for (size_t i = 0; i < nl_model_structures(m); i++) {
        const nl_family *f = nl_model_family(nl_model_structure(m, i));
        if (f->max_dim && s > f->max_dim)
            return NL_ERROR(NL_EINVAL, "rank1: %s: the %s model is positive definite up to %dD only, got %dD",
                            nl_model_spec(m), f->name, f->max_dim, s);
    }
    if (nl_model_is_spectral(m)) {
        if (s > 3)
            return NL_ERROR(NL_EINVAL, "%s: spectrum models reach 3 dimensions; in 4 give an isotropic --acf",
                            nl_model_spec(m));
        return NL_OK;
    }
    if (!nl_model_is_isotropic(m))
        return NL_ERROR(NL_EINVAL, "%s: rank-1 lattice synthesis needs a spectrum or an isotropic R (its Hankel "
                        "transform, eq. 13)", nl_model_spec(m));
    return NL_OK;
}

/* The radial table: S at w_i = w1 (exp(i h) - 1), i = 0..n-1 (fine near 0,
 * geometric further out, where spectra fall like powers or faster),
 * interpolated in u = log(1 + w / w1) by the cubic through the four nearest
 * nodes (Lagrange), mirrored at u = 0 (S is even in w, u odd). */
typedef struct {
    const nl_model *m;
    int s;
    size_t n;
    double h, w1, *v;
} radial;

static double node(const radial *t, long i)
{
    i = labs(i);
    return t->v[(size_t)i < t->n ? (size_t)i : t->n - 1];
}

/* Cubic interpolation on nodes of spacing `step` (a multiple of the table's
 * spacing: step 2 uses every other node, for the error estimate). */
static double interp(const radial *t, double w, long step)
{
    double x = log1p(w / t->w1) / (t->h * (double)step);
    long i = (long)floor(x);
    double u = x - (double)i, a = node(t, (i - 1) * step), b = node(t, i * step), c = node(t, (i + 1) * step),
           d = node(t, (i + 2) * step);
    return b + 0.5 * u * (c - a + u * (2 * a - 5 * b + 4 * c - d + u * (3 * (b - c) + d - a)));
}

/* Fill a table reaching wmax with nodes doubling from 129 to 1025 until the
 * error of the half table at the new nodes is at most 1e-6 of S(0) (the
 * convergence the quadrature itself accepts on oscillatory tails); *err
 * receives that measured error (of the coarser table: a bound for the finer
 * one, whose cubic error is about 16 times smaller), relative to S(0). */
static int radial_fill(radial *t, double wmax, double *err)
{
    size_t n = 129, have = 0;
    double *v = NULL;
    for (;;) {
        double *nv = realloc(v, n * sizeof *nv);
        if (!nv) {
            free(v);
            return NL_ERROR(NL_ENOMEM, "out of memory for a radial table of %zu nodes", n);
        }
        v = nv;
        for (size_t i = have; i-- > 0;)
            v[2 * i] = v[i];  /* the old nodes become the even ones */
        t->w1 = wmax / 1024, t->v = v, t->n = n, t->h = log1p(1.05 * wmax / t->w1) / (double)(n - 1);
        double e = 0;
        for (size_t i = 0; i < n; i++) {
            if (have && i % 2 == 0)
                continue;
            double w = t->w1 * expm1((double)i * t->h);
            v[i] = nl_model_spectrum_iso(t->m, t->s, w);
            if (!isfinite(v[i]))
                return NL_ERROR(NL_EINVAL, "%s: the spectrum (Hankel transform, eq. 13) is not finite at radial "
                                "frequency %g: the quadrature failed", nl_model_spec(t->m), w);
        }
        for (size_t i = 1; i + 2 < n; i += 2)
            e = fmax(e, fabs(interp(t, t->w1 * expm1((double)i * t->h), 2) - v[i]));
        *err = e / fabs(v[0]);
        if (*err <= 1e-6 || n >= 1025)
            return NL_OK;
        have = n, n = 2 * n - 1;
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* S for m = 0..N/2 into v, raw (before the sign rule and the cell factor):
 * one evaluation per distinct |k|^2 (bit-identical to one per wave vector)
 * when there are at most NL_RANK1_EXACT_RADII of them, else from the radial
 * table (info->nodes, info->interp_error). */
static int isotropic_values(const nl_rank1_lattice *L, const nl_rank1_model_ctx *c, double *v,
                            nl_rank1_model_info *info)
{
    size_t H = L->N / 2 + 1, u = 0;
    double *f2 = malloc(H * sizeof *f2);
    int st = NL_OK;
    if (!f2)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu radii", H);
    for (size_t m = 0; m < H; m++)
        f2[m] = freq2(L->k + m * L->s, L->s, c->extent);
    qsort(f2, H, sizeof *f2, cmp_double);
    for (size_t m = 0; m < H; m++)
        if (m == 0 || f2[m] != f2[u - 1])
            f2[u++] = f2[m];
    if (u <= NL_RANK1_EXACT_RADII) {
        double *S = malloc(u * sizeof *S);
        if (!S) {
            free(f2);
            return NL_ERROR(NL_ENOMEM, "out of memory for %zu radii", u);
        }
        for (size_t i = 0; i < u; i++)
            S[i] = nl_model_spectrum_iso(c->m, L->s, sqrt(f2[i]));
        for (size_t m = 0; m < H; m++) {
            double q = freq2(L->k + m * L->s, L->s, c->extent), *hit = bsearch(&q, f2, u, sizeof *f2, cmp_double);
            v[m] = S[hit - f2];
        }
        free(S);
    } else {
        radial t = {c->m, L->s, 0, 0, 0, NULL};
        if (!(st = radial_fill(&t, sqrt(f2[u - 1]), &info->interp_error))) {
            info->nodes = t.n;
            for (size_t m = 0; m < H; m++) {
                double w = sqrt(freq2(L->k + m * L->s, L->s, c->extent));
                v[m] = w == 0 ? t.v[0] : interp(&t, w, 1);
            }
        }
        free(t.v);
    }
    free(f2);
    return st;
}

/* The sign rule on the raw values v[0..H-1]: rounding-level negatives (at
 * most 1e-9 of S(0), the quadrature's relative tolerance) become 0; larger
 * ones are refused, or zeroed under NL_RANK1_CLAMP with the bound on the
 * change (their share of the variance) in info. */
static int sign_rule(const nl_rank1_lattice *L, const nl_model *m, double *v, unsigned flags,
                     nl_rank1_model_info *info)
{
    size_t H = L->N / 2 + 1;
    double tol = nl_model_is_spectral(m) ? 0 : 1e-9 * fabs(v[0]), neg = 0, pos = 0, lo = 0;
    for (size_t i = 0; i < H; i++) {
        double w = i == 0 || 2 * i == L->N ? 1 : 2;
        if (!isfinite(v[i]))
            return NL_ERROR(NL_EINVAL, "spectrum: expected a finite non-negative value, got %g at wave vector %zu",
                            v[i], i);
        if (v[i] < 0 && v[i] >= -tol)
            v[i] = 0;
        if (v[i] < 0)
            neg -= w * v[i], info->negatives += (size_t)w, lo = fmin(lo, v[i]);
        else
            pos += w * v[i];
    }
    info->clamp_error = neg > 0 ? (pos > 0 ? neg / pos : INFINITY) : 0;
    if (neg > 0 && (!(flags & NL_RANK1_CLAMP) || !(pos > 0)))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite on this lattice: min spectrum %.3g; zeroing the %zu "
                        "negative values would change the variance by %.2g of it (use --clamp to accept)",
                        nl_model_spec(m), lo, info->negatives, info->clamp_error);
    for (size_t i = 0; i < H; i++)
        v[i] = fmax(v[i], 0);
    return NL_OK;
}

typedef struct {
    const nl_rank1_lattice *L;
    const double *v;
} lookup_ctx;

static double lookup(const long *k, int s, void *ctx)
{
    const lookup_ctx *c = ctx;
    return c->v[(size_t)(k - c->L->k) / (size_t)s];
}

int nl_rank1_model_coefficients(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed,
                                unsigned flags, double *coef, nl_rank1_model_info *info)
{
    nl_rank1_model_ctx ctx = {m, L->s, extent};
    nl_rank1_model_info dummy;
    size_t H = L->N / 2 + 1;
    double *v;
    int st;
    if (!info)
        info = &dummy;
    memset(info, 0, sizeof *info);
    if ((st = nl_rank1_model_check(m, L->s)))
        return st;
    if (!(extent > 0) || !isfinite(extent))
        return NL_ERROR(NL_EINVAL, "extent: expected a positive finite length, got %g", extent);
    if ((st = nl_size_check(1, &L->N, 5 * sizeof(double), 1, NULL)))
        return st;
    v = malloc(H * sizeof *v);
    if (!v)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu coefficients", L->N);
    if (nl_model_is_spectral(m)) {
        for (size_t i = 0; i < H; i++)
            v[i] = raw_spectrum(&ctx, L->k + i * L->s, L->s);
        st = NL_OK;
    } else
        st = isotropic_values(L, &ctx, v, info);
    if (!st && !(st = sign_rule(L, m, v, flags, info))) {
        lookup_ctx lc = {L, v};
        for (size_t i = 0; i < H; i++)
            v[i] = v[i] / pow(extent, L->s);
        st = nl_rank1_coefficients(L, lookup, &lc, seed, coef);
    }
    free(v);
    return st;
}

int nl_rank1_model_synthesize_info(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed,
                                   unsigned flags, double *f, double *grad, double *imag, nl_rank1_model_info *info)
{
    double *coef;
    int st;
    if ((st = nl_size_check(1, &L->N, 5 * sizeof(double), 1, NULL)))
        return st;
    if (!(coef = malloc(2 * L->N * sizeof *coef)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu coefficients", L->N);
    if (!(st = nl_rank1_model_coefficients(L, m, extent, seed, flags, coef, info)))
        st = nl_rank1_synthesize(L, coef, extent, f, grad, imag);
    free(coef);
    return st;
}

int nl_rank1_model_synthesize(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed, double *f,
                              double *grad, double *imag)
{
    return nl_rank1_model_synthesize_info(L, m, extent, seed, 0, f, grad, imag, NULL);
}
