/* Thinning and effective sample size for goodness-of-fit tests on
 * correlated fields: the autocorrelation of the median indicator, by FFT
 * (analysis/acf.h). */
#include "gof_dep.h"
#include "acf.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

/* The lag (in samples) of index i on an axis of the full grid of m = 2 n
 * (m = 1: an unused axis), with *skip set for the unused index n. */
static long lag_of(size_t i, size_t m, int *skip)
{
    size_t n = m / 2 ? m / 2 : 1;
    *skip |= i == n && m > 1;
    return i < n ? (long)i : (long)i - (long)m;
}

/* The lags of entry k of the full grid; 0 for an unused entry. */
static int lags(const nl_field *acf, size_t k, long l[3])
{
    const size_t *m = acf->n;
    int skip = 0;
    l[0] = lag_of(k % m[0], m[0], &skip);
    l[1] = lag_of(k / m[0] % m[1], m[1], &skip);
    l[2] = lag_of(k / (m[0] * m[1]), m[2], &skip);
    return !skip;
}

static size_t whole_radius(const long l[3])
{
    return (size_t)floor(sqrt((double)(l[0] * l[0] + l[1] * l[1] + l[2] * l[2])) + 0.5);
}

/* Radial means of rho = acf / acf(0) for whole radii 0 .. nr - 1. */
static void radial_means(const nl_field *a, double *mean, size_t *cnt, size_t nr)
{
    long l[3];
    for (size_t r = 0; r < nr; r++)
        mean[r] = 0, cnt[r] = 0;
    for (size_t k = 0; k < a->count; k++) {
        size_t r;
        if (lags(a, k, l) && (r = whole_radius(l)) < nr)
            mean[r] += a->data[k] / a->data[0], cnt[r]++;
    }
    for (size_t r = 0; r < nr; r++)
        mean[r] = cnt[r] ? mean[r] / (double)cnt[r] : 0;
}

/* tau over the lattice of stride s, lags of whole radius below r0. */
static double lattice_tau(const nl_field *a, size_t s, size_t r0)
{
    long l[3];
    double tau = 0;
    for (size_t k = 0; k < a->count; k++)
        if (lags(a, k, l) && l[0] % (long)s == 0 && l[1] % (long)s == 0 && l[2] % (long)s == 0 &&
            whole_radius(l) < r0)
            tau += a->data[k] / a->data[0];
    return tau > 1 ? tau : 1;
}

/* The median indicator's full autocorrelation estimate into *acf. */
static int indicator_acf(const nl_field *x, const nl_dist *d, nl_field **acf)
{
    int st;
    nl_field *ind = nl_field_alloc(x->dim, x->n, NULL, &st);
    if (!ind)
        return st;
    for (size_t i = 0; i < x->count; i++)
        ind->data[i] = nl_dist_cdf(d, x->data[i]) <= 0.5;
    st = nl_acf_full(ind, NAN, NL_ACF_BIASED, acf);
    nl_field_free(ind);
    return st;
}

int nl_gof_dependence(const nl_field *x, const nl_dist *d, nl_gof_dep *out)
{
    nl_field *a;
    size_t shortest = x->n[0], nr, s = 1, r0 = 1, *cnt;
    double *mean;
    int st;
    if (x->count < 2)
        return NL_ERROR(NL_EINVAL, "thinning: expected at least 2 samples, got %zu", x->count);
    for (int k = 1; k < x->dim; k++)
        shortest = x->n[k] < shortest ? x->n[k] : shortest;
    nr = shortest / 4 + 1;
    if ((st = indicator_acf(x, d, &a)))
        return st;
    mean = malloc(nr * sizeof *mean), cnt = malloc(nr * sizeof *cnt);
    if (!mean || !cnt) {
        free(mean), free(cnt), nl_field_free(a);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu radii", nr);
    }
    out->rho_stride = 0, out->tau = 1;
    if (a->data[0] > 0) {
        radial_means(a, mean, cnt, nr);
        while (s + 1 < nr && mean[s] > NL_GOF_THIN_RHO)
            s++;
        while (r0 < nr && mean[r0] > 0)
            r0++;
        out->rho_stride = s < nr ? mean[s] : 0;
        out->tau = lattice_tau(a, s, r0);
    }
    out->n = x->count, out->stride = s, out->radius = (double)r0;
    out->kept = 1;
    for (int k = 0; k < x->dim; k++)
        out->kept *= (x->n[k] + s - 1) / s;
    out->n_eff = (double)out->kept / out->tau;
    free(mean), free(cnt), nl_field_free(a);
    return NL_OK;
}

size_t nl_gof_thin(const nl_field *x, size_t stride, double *out)
{
    size_t m = 0;
    for (size_t k = 0; k < x->n[2]; k += stride)
        for (size_t j = 0; j < x->n[1]; j += stride)
            for (size_t i = 0; i < x->n[0]; i += stride)
                out[m++] = x->data[(k * x->n[1] + j) * x->n[0] + i];
    return m;
}

int nl_gof_test_thinned(const nl_field *const *x, size_t K, const nl_dist *d, size_t bins, nl_gof_dep *sum,
                        size_t *smin, nl_gof *out)
{
    size_t total = 0, lo = (size_t)-1, B;
    double *pool;
    nl_gof_dep dep, s = {0};
    int st = NL_OK;
    if (K == 0)
        return NL_ERROR(NL_EINVAL, "thinned test: expected at least one field");
    for (size_t k = 0; k < K; k++)
        total += x[k]->count;
    if (!(pool = nl_alloc(total * sizeof *pool)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu samples", total);
    for (size_t k = 0; k < K && !st; k++) {
        if ((st = nl_gof_dependence(x[k], d, &dep)))
            break;
        s.kept += nl_gof_thin(x[k], dep.stride, pool + s.kept);
        s.n += dep.n, s.n_eff += dep.n_eff, s.rho_stride = dep.rho_stride, s.radius = dep.radius;
        s.stride = dep.stride > s.stride ? dep.stride : s.stride, lo = dep.stride < lo ? dep.stride : lo;
    }
    if (!st) {
        s.n_eff = s.n_eff < (double)s.kept ? s.n_eff : (double)s.kept;
        s.tau = (double)s.kept / s.n_eff;
        B = (size_t)(s.n_eff / 5) < bins ? (size_t)(s.n_eff / 5) : bins;
        st = nl_gof_test_dep(pool, s.kept, d, B < 2 ? 2 : B, s.n_eff, 1, out);
    }
    nl_free(pool);
    if (!st) {
        *sum = s;
        if (smin)
            *smin = lo;
    }
    return st;
}
