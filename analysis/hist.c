/* Histogram and moments through GSL. */
#include "hist.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_histogram.h>
#include <gsl/gsl_statistics_double.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>

int nl_moments_compute(const nl_field *x, nl_moments *m)
{
    if (x->count < 2)
        return NL_ERROR(NL_EINVAL, "moments: expected at least 2 samples, got %zu", x->count);
    m->n = x->count;
    m->mean = gsl_stats_mean(x->data, 1, x->count);
    m->variance = gsl_stats_variance_m(x->data, 1, x->count, m->mean);
    m->skewness = gsl_stats_skew_m_sd(x->data, 1, x->count, m->mean, sqrt(m->variance));
    m->kurtosis = gsl_stats_kurtosis_m_sd(x->data, 1, x->count, m->mean, sqrt(m->variance));
    gsl_stats_minmax(&m->min, &m->max, x->data, 1, x->count);
    /* GSL's running mean and variance accumulate in long double; the mean
     * square deviation comes back as a double times n / (n - 1) <= 2, so
     * deviations below sqrt(DBL_MAX / 2) keep the variance finite. */
    if (!isfinite(m->mean))
        return NL_ERROR(NL_EINVAL, "moments: the samples run from %g to %g: the mean and variance overflow; expected max - min below %g",
                        m->min, m->max, DBL_MAX);
    if (!isfinite(m->variance))
        return NL_ERROR(NL_EINVAL, "moments: the samples deviate from their mean %g by up to %g: the variance overflows; "
                        "expected deviations below %.3g (sqrt(DBL_MAX / 2))", m->mean,
                        fmax(m->max - m->mean, m->mean - m->min), sqrt(DBL_MAX / 2));
    if (m->variance == 0)
        m->skewness = m->kurtosis = NAN;
    return NL_OK;
}

static int hist(const nl_field *x, size_t bins, double *edges, double *counts)
{
    double lo, hi, top;
    gsl_histogram *h;
    if (bins < 1)
        return NL_ERROR(NL_EINVAL, "bins: expected at least 1, got %zu", bins);
    gsl_stats_minmax(&lo, &hi, x->data, 1, x->count);
    if (!isfinite(lo) || !isfinite(hi))
        return NL_ERROR(NL_EINVAL, "histogram: expected finite samples, got range [%g, %g]", lo, hi);
    if (!isfinite(hi - lo))
        return NL_ERROR(NL_EINVAL, "histogram: the samples run from %g to %g, whose width overflows", lo, hi);
    if (!(hi > lo))
        hi = lo + 1;
    /* beyond 2^53, v + 1 rounds to v: a width of 2^-20 |v| (2^32 ulps) toward zero */
    if (!(hi > lo) && lo < 0)
        hi = lo - lo * 0x1p-20;
    else if (!(hi > lo))
        lo = hi - hi * 0x1p-20;
    {   /* bins narrower than a few ulps would share edges (width 0), and
         * narrower than 2^-1000 would make densities overflow: widen */
        double mag = fmax(fabs(lo), fabs(hi)), minw = (double)bins * fmax(4 * (nextafter(mag, INFINITY) - mag), 0x1p-1000);
        if (hi - lo < minw && isfinite(minw)) {
            if (isfinite(lo + minw))
                hi = lo + minw;
            else
                lo = hi - minw;
        }
    }
    h = gsl_histogram_alloc(bins);
    if (!h)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu bins", bins);
    /* nudge the upper edge so that the maximum is counted in the last bin;
     * above DBL_MAX there is no edge: its samples are counted there by hand */
    top = nextafter(hi, INFINITY);
    if (isinf(top))
        top = hi;
    gsl_histogram_set_ranges_uniform(h, lo, top);
    for (size_t i = 0; i < x->count; i++)
        if (x->data[i] >= top)
            h->bin[bins - 1] += 1;
        else
            gsl_histogram_increment(h, x->data[i]);
    for (size_t b = 0; b <= bins; b++)
        edges[b] = h->range[b];
    for (size_t b = 0; b < bins; b++)
        counts[b] = h->bin[b];
    gsl_histogram_free(h);
    return NL_OK;
}

int nl_hist_density(const nl_field *x, const nl_moments *mo, size_t bins, double *mid, double *density, double *gauss)
{
    double *edges = malloc((bins + 1) * sizeof *edges), *counts = malloc((bins ? bins : 1) * sizeof *counts);
    int st;
    if (!edges || !counts)
        st = NL_ERROR(NL_ENOMEM, "out of memory for %zu bins", bins);
    else if (!(st = nl_hist(x, bins, edges, counts)))
        for (size_t b = 0; b < bins; b++) {
            double w = edges[b + 1] - edges[b];
            mid[b] = 0.5 * edges[b] + 0.5 * edges[b + 1]; /* no overflow at +-DBL_MAX; exact halves */
            density[b] = counts[b] / ((double)x->count * w);
            gauss[b] = mo->variance > 0 ? exp(-0.5 * (mid[b] - mo->mean) * (mid[b] - mo->mean) / mo->variance) /
                                              sqrt(2 * M_PI * mo->variance)
                                        : 0;
        }
    free(edges), free(counts);
    return st;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_hist(const nl_field *x, size_t bins, double *edges, double *counts)
{
    int st;
    nl_gsl_enter();
    st = hist(x, bins, edges, counts);
    nl_gsl_leave();
    return st;
}

int nl_hist_count(const nl_field *x, const double *edges, size_t bins, double *counts)
{
    if (bins < 1)
        return NL_ERROR(NL_EINVAL, "bins: expected at least 1, got %zu", bins);
    for (size_t b = 0; b < bins; b++)
        counts[b] = 0;
    for (size_t i = 0; i < x->count; i++) {
        size_t lo = 0, hi = bins; /* the last edge <= v, by bisection: edges[lo] <= v < edges[hi] */
        while (hi - lo > 1) {
            size_t mid = lo + (hi - lo) / 2;
            if (x->data[i] >= edges[mid])
                lo = mid;
            else
                hi = mid;
        }
        counts[lo] += 1;
    }
    return NL_OK;
}
