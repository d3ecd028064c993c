/* Kolmogorov-Smirnov and chi-square tests (GSL for sorting and the
 * chi-square distribution; the Kolmogorov series is summed here, GSL has
 * no KS test). */
#include "gof.h"
#include "gof_boot_internal.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sort.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Q_KS(l), the Kolmogorov tail (analysis/gof_boot_internal.h). */
double nl_gof_ks_tail(double l)
{
    double s = 0, sign = 1;
    if (l < 0.2)
        return 1.0;
    for (int k = 1; k <= 100; k++) {
        double t = sign * exp(-2.0 * k * k * l * l);
        s += t;
        if (fabs(t) < 1e-16 * fabs(s))
            break;
        sign = -sign;
    }
    return fmin(fmax(2 * s, 0), 1);
}

static int gof_test(const double *x, size_t n, const nl_dist *d, size_t bins, double n_eff, double deff,
                    nl_gof *out)
{
    double *s, D = 0, en;
    size_t *count;
    if (n < 2 || bins < 2)
        return NL_ERROR(NL_EINVAL, "goodness of fit: expected at least 2 samples and 2 bins");
    s = malloc(n * sizeof *s);
    count = calloc(bins, sizeof *count);
    if (!s || !count) {
        free(s), free(count);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    memcpy(s, x, n * sizeof *s);
    gsl_sort(s, 1, n);
    for (size_t i = 0; i < n; i++) {
        double F = nl_dist_cdf(d, s[i]);
        D = fmax(D, fmax((double)(i + 1) / (double)n - F, F - (double)i / (double)n));
        size_t b = (size_t)(F * (double)bins);
        count[b < bins ? b : bins - 1]++;
    }
    en = sqrt(n_eff);
    out->D = D;
    out->p_ks = nl_gof_ks_tail((en + 0.12 + 0.11 / en) * D);
    out->chi2 = 0;
    for (size_t b = 0; b < bins; b++) {
        double e = (double)n / (double)bins;
        out->chi2 += ((double)count[b] - e) * ((double)count[b] - e) / e;
    }
    out->bins = bins;
    out->p_chi2 = gsl_cdf_chisq_Q(deff == 1 ? out->chi2 : out->chi2 / deff, (double)(bins - 1));
    out->n_eff = n_eff, out->deff = deff;
    free(s);
    free(count);
    return NL_OK;
}

int nl_gof_bin_density(const nl_dist *d, const double *edges, size_t bins, double *pdf)
{
    for (size_t b = 0; b < bins; b++)
        if (!(edges[b + 1] > edges[b]))
            return NL_ERROR(NL_EINVAL, "bin density: expected increasing edges, got %g then %g at bin %zu", edges[b],
                            edges[b + 1], b);
    /* probability mass over the bin width */
    for (size_t b = 0; b < bins; b++)
        pdf[b] = (nl_dist_cdf(d, edges[b + 1]) - nl_dist_cdf(d, edges[b])) / (edges[b + 1] - edges[b]);
    return NL_OK;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_gof_test(const double *x, size_t n, const nl_dist *d, size_t bins, nl_gof *out)
{
    int st;
    nl_gsl_enter();
    st = gof_test(x, n, d, bins, (double)n, 1, out);
    nl_gsl_leave();
    return st;
}

int nl_gof_test_dep(const double *x, size_t n, const nl_dist *d, size_t bins, double n_eff, double deff,
                    nl_gof *out)
{
    int st;
    if (!(n_eff >= 1 && n_eff <= (double)n && deff >= 1 && isfinite(deff)))
        return NL_ERROR(NL_EINVAL, "goodness of fit: expected 1 <= effective n <= %zu and a design effect >= 1, got "
                        "%g and %g", n, n_eff, deff);
    nl_gsl_enter();
    st = gof_test(x, n, d, bins, n_eff, deff, out);
    nl_gsl_leave();
    return st;
}
