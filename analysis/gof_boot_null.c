/* The null spectrum of the bootstrap goodness-of-fit test: the windowed
 * autocorrelation of a field's normal scores on its own periodic grid
 * (analysis/gof_boot.h, steps 1 to 4). */
#include "gof_boot.h"
#include "acf.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

/* The lag of index i on an axis of the full estimate's grid of m = 2 n
 * samples (m = 1: an unused axis); *skip is set for the unused index n. */
static long full_lag(size_t i, size_t m, int *skip)
{
    size_t n = m / 2 ? m / 2 : 1;
    *skip |= i == n && m > 1;
    return i < n ? (long)i : (long)i - (long)m;
}

/* The lags of entry k of the full grid a, and its Euclidean radius; 0 for
 * the unused entries. */
static int full_lags(const nl_field *a, size_t k, long l[3], double *r)
{
    const size_t *m = a->n;
    int skip = 0;
    l[0] = full_lag(k % m[0], m[0], &skip);
    l[1] = full_lag(k / m[0] % m[1], m[1], &skip);
    l[2] = full_lag(k / (m[0] * m[1]), m[2], &skip);
    *r = sqrt((double)(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]));
    return !skip;
}

/* The normal scores Phi^-1(F(x)), F clipped to [1/(2n), 1 - 1/(2n)]. */
static nl_field *scores(const nl_field *x, const nl_dist *d, int *st)
{
    nl_field *y = nl_field_alloc(x->dim, x->n, NULL, st);
    double lo = 0.5 / (double)x->count;
    if (!y)
        return NULL;
    for (size_t i = 0; i < x->count; i++) {
        double F = fmin(fmax(nl_dist_cdf(d, x->data[i]), lo), 1 - lo);
        y->data[i] = gsl_cdf_ugaussian_Pinv(F);
    }
    return y;
}

/* r0: the first whole radius >= 1 at which the radial mean of rho = a / a(0)
 * is <= 0, at most nr - 1. */
static size_t first_zero(const nl_field *a, size_t nr, int *st)
{
    double *mean = calloc(nr, sizeof *mean), r;
    size_t *cnt = calloc(nr, sizeof *cnt), r0 = 1;
    long l[3];
    if (!mean || !cnt) {
        free(mean), free(cnt);
        *st = NL_ERROR(NL_ENOMEM, "out of memory for %zu radii", nr);
        return 0;
    }
    for (size_t k = 0; k < a->count; k++) {
        size_t w;
        if (full_lags(a, k, l, &r) && (w = (size_t)floor(r + 0.5)) < nr)
            mean[w] += a->data[k] / a->data[0], cnt[w]++;
    }
    while (r0 + 1 < nr && mean[r0] > 0)
        r0++;
    free(mean), free(cnt);
    return r0;
}

/* Politis and Romano's (1995) flat-top trapezoid, c = 1/2: 1 up to t = 1/2,
 * linear to 0 at t = 1 (t = lag / M, M = 2 r0: Politis 2003's rule). */
static double flat_top(double t) { return t <= 0.5 ? 1 : t < 1 ? 2 * (1 - t) : 0; }

/* The windowed, bias-mended correlation of the full estimate a on the
 * periodic grid R (zeroed, x's n) for lags of radius below r0; returns the
 * equivalent degrees of freedom 2 N / sum_l w(l)^2 of the window (Priestley
 * 1981, section 6.2.3, eq. (6.2.124)). */
static double window(const nl_field *a, double r0, nl_field *R)
{
    double S = 0, W = 0, V, r, w2 = 0;
    long l[3];
    for (size_t k = 0; k < a->count; k++)
        if (full_lags(a, k, l, &r) && r < r0)
            S += a->data[k] / a->data[0], W++;
    /* step 2: every lag low by Var(ybar) = (S + W V) / N */
    V = (double)R->count > W ? fmax(S / ((double)R->count - W), 0) : 0;
    for (size_t k = 0; k < a->count; k++) {
        size_t j[3];
        if (!full_lags(a, k, l, &r) || r >= r0)
            continue;
        for (int ax = 0; ax < 3; ax++)
            j[ax] = (size_t)((l[ax] % (long)R->n[ax] + (long)R->n[ax]) % (long)R->n[ax]);
        R->data[(j[2] * R->n[1] + j[1]) * R->n[0] + j[0]] = flat_top(r / r0) * (a->data[k] / a->data[0] + V) / (1 + V);
        w2 += flat_top(r / r0) * flat_top(r / r0);
    }
    return 2 * (double)R->count / w2;
}

/* Step 4 after the window: the spectrum, clipped at 0, unit variance. */
static int spectrum(const nl_field *R, nl_field *S)
{
    double mean = 0;
    int st = nl_wk_acf_to_spectrum(R, S);
    if (st)
        return st;
    for (size_t k = 0; k < S->count; k++)
        S->data[k] = fmax(S->data[k], 0), mean += S->data[k];
    mean /= (double)S->count;
    if (!(mean > 0))
        return NL_ERROR(NL_EFAIL, "bootstrap null: the windowed correlation has no positive spectrum");
    for (size_t k = 0; k < S->count; k++)
        S->data[k] /= mean;
    return NL_OK;
}

static int null_spectrum(const nl_field *x, const nl_dist *d, nl_field **S, double *radius, double *dof)
{
    nl_field *y, *a = NULL, *R = NULL;
    size_t shortest = x->n[0], r0 = 0;
    double M = 0;
    int st = NL_OK;
    for (int k = 1; k < x->dim; k++)
        shortest = x->n[k] < shortest ? x->n[k] : shortest;
    if (!(y = scores(x, d, &st)))
        return st;
    if (!(st = nl_acf_full(y, NAN, NL_ACF_UNBIASED, &a)) && (R = nl_field_alloc(x->dim, x->n, NULL, &st)) &&
        (*S = nl_field_alloc(x->dim, x->n, NULL, &st))) {
        if (a->data[0] > 0 && shortest >= 4 && (r0 = first_zero(a, shortest / 4 + 1, &st)) > 0) {
            M = fmin(2.0 * (double)r0, (double)(shortest / 4));
            *dof = window(a, M, R);
        }
        else
            R->data[0] = 1, *dof = 2 * (double)x->count; /* constant scores or a tiny axis: white */
        if (!st)
            st = spectrum(R, *S);
    }
    if (st)
        nl_field_free(*S), *S = NULL;
    else
        *radius = M;
    nl_field_free(y), nl_field_free(a), nl_field_free(R);
    return st;
}

int nl_gof_boot_spectrum(const nl_field *x, const nl_dist *d, nl_field **S, double *radius, double *dof)
{
    int st;
    *S = NULL;
    if (x->count < 2)
        return NL_ERROR(NL_EINVAL, "bootstrap null: expected at least 2 samples, got %zu", x->count);
    if (nl_dist_is_function(d))
        return NL_ERROR(NL_EINVAL, "bootstrap null: %s has no CDF (expected a distribution)", nl_dist_spec(d));
    nl_gsl_enter();
    st = null_spectrum(x, d, S, radius, dof);
    nl_gsl_leave();
    return st;
}
