/* The statistics of the bootstrap goodness-of-fit test: KS distance to the
 * uniform in linear time (bucket sort), chi-square on equal-probability
 * bins, and the moments (analysis/gof_boot.h). */
#include "gof_boot_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

int nl_gof_boot_work_alloc(size_t n, size_t bins, nl_gof_boot_work *w)
{
    w->n = n, w->bins = bins;
    w->sorted = malloc(n * sizeof *w->sorted);
    w->start = malloc((n + 1) * sizeof *w->start);
    w->count = malloc(bins * sizeof *w->count);
    if (w->sorted && w->start && w->count)
        return NL_OK;
    nl_gof_boot_work_free(w);
    return NL_ERROR(NL_ENOMEM, "out of memory for the goodness-of-fit scratch of %zu samples", n);
}

void nl_gof_boot_work_free(nl_gof_boot_work *w)
{
    free(w->sorted), free(w->start), free(w->count);
    w->sorted = NULL, w->start = NULL, w->count = NULL;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sort s[0..m-1]: insertion for the one or two of a typical bucket. */
static void sort_bucket(double *s, size_t m)
{
    if (m > 32) {
        qsort(s, m, sizeof *s, cmp);
        return;
    }
    for (size_t i = 1; i < m; i++) {
        double v = s[i];
        size_t j = i;
        for (; j > 0 && s[j - 1] > v; j--)
            s[j] = s[j - 1];
        s[j] = v;
    }
}

static size_t bucket(double u, size_t n)
{
    double b = u * (double)n;
    return b <= 0 ? 0 : b >= (double)(n - 1) ? n - 1 : (size_t)b;
}

/* D = max_i max(i/n - u_(i), u_(i) - (i-1)/n): n buckets of width 1/n hold
 * one sample on average, so the sort is linear in n. */
static double ks_uniform(const double *u, nl_gof_boot_work *w)
{
    size_t n = w->n, *s = w->start;
    double D = 0;
    for (size_t b = 0; b <= n; b++)
        s[b] = 0;
    for (size_t i = 0; i < n; i++)
        s[bucket(u[i], n) + 1]++;
    for (size_t b = 0; b < n; b++)
        s[b + 1] += s[b];
    for (size_t i = 0; i < n; i++)
        w->sorted[s[bucket(u[i], n)]++] = u[i];
    /* s[b] is now the end of bucket b */
    for (size_t b = 0, lo = 0; b < n; lo = s[b++])
        sort_bucket(w->sorted + lo, s[b] - lo);
    for (size_t i = 0; i < n; i++) {
        double v = w->sorted[i];
        D = fmax(D, fmax((double)(i + 1) / (double)n - v, v - (double)i / (double)n));
    }
    return D;
}

static double chi_square(const double *u, nl_gof_boot_work *w, double *half)
{
    size_t B = w->bins, below = 0;
    double e = (double)w->n / (double)B, X = 0;
    for (size_t b = 0; b < B; b++)
        w->count[b] = 0;
    for (size_t i = 0; i < w->n; i++) {
        size_t b = (size_t)(u[i] * (double)B);
        w->count[b < B ? b : B - 1]++;
        below += u[i] <= 0.5;
    }
    for (size_t b = 0; b < B; b++)
        X += ((double)w->count[b] - e) * ((double)w->count[b] - e) / e;
    *half = (double)below / (double)w->n - 0.5;
    return X;
}

/* Mean, variance (n - 1), skewness and excess kurtosis with GSL's
 * definitions (standardised by the sample sd), two passes. */
static void moments(const double *x, size_t n, double *T)
{
    double m = 0, c2 = 0, c3 = 0, c4 = 0, sd;
    for (size_t i = 0; i < n; i++)
        m += x[i];
    m /= (double)n;
    for (size_t i = 0; i < n; i++) {
        double e = x[i] - m, e2 = e * e;
        c2 += e2, c3 += e2 * e, c4 += e2 * e2;
    }
    T[NL_GOF_MEAN] = m;
    T[NL_GOF_VARIANCE] = c2 / (double)(n - 1);
    sd = sqrt(T[NL_GOF_VARIANCE]);
    T[NL_GOF_SKEWNESS] = c3 / (double)n / (sd * sd * sd);
    T[NL_GOF_KURTOSIS] = c4 / (double)n / (sd * sd * sd * sd) - 3;
}

void nl_gof_boot_stats(const double *u, const double *x, const int *want, nl_gof_boot_work *w, double *T,
                       double *half)
{
    T[NL_GOF_KS] = ks_uniform(u, w);
    T[NL_GOF_CHI2] = chi_square(u, w, half);
    if (x)
        moments(x, w->n, T);
    for (int s = NL_GOF_MEAN; s < NL_GOF_NSTATS; s++)
        if (!want[s])
            T[s] = NAN;
}
