/* Log-log regression of a spectrum. */
#include "slope.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdlib.h>

/* Least squares of y on x (m points): slope, 95% interval from the
 * residuals, eq. (16). */
static int fit(const double *x, const double *y, size_t m, int E, nl_slope *out)
{
    double c0, c1, cov00, cov01, cov11, ss;
    if (m < 3)
        return NL_ERROR(NL_EINVAL, "slope: expected at least 3 frequencies in the band, got %zu", m);
    nl_gsl_enter();
    gsl_fit_linear(x, 1, y, 1, m, &c0, &c1, &cov00, &cov01, &cov11, &ss);
    out->slope = c1;
    out->ci95 = gsl_cdf_tdist_Qinv(0.025, (double)(m - 2)) * sqrt(cov11);
    nl_gsl_leave();
    out->points = m;
    /* eq. (16) takes d of a 1D profile; the spectrum of an isotropic E-D
     * field falls as f^-(d + E - 1) (Voss 1985) */
    out->fractal_dim = E + (3 - (-c1 - (E - 1))) / 2;
    return NL_OK;
}

int nl_psd_slope_grid(const nl_field *P, double fmin, double fmax, nl_slope *out)
{
    double *x = malloc(P->count * sizeof *x), *y = malloc(P->count * sizeof *y);
    size_t m = 0;
    int st;
    if (!x || !y) {
        free(x), free(y);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t k = 0; k < P->n[2]; k++)
        for (size_t j = 0; j < P->n[1]; j++)
            for (size_t i = 0; i < P->n[0]; i++) {
                size_t lin = (k * P->n[1] + j) * P->n[0] + i;
                size_t mir = (((P->n[2] - k) % P->n[2]) * P->n[1] + (P->n[1] - j) % P->n[1]) * P->n[0] +
                             (P->n[0] - i) % P->n[0];
                double fx = (double)nl_wrap(i, P->n[0]) / ((double)P->n[0] * P->h[0]);
                double fy = (double)nl_wrap(j, P->n[1]) / ((double)P->n[1] * P->h[1]);
                double fz = (double)nl_wrap(k, P->n[2]) / ((double)P->n[2] * P->h[2]);
                double f = sqrt(fx * fx + fy * fy + fz * fz), v = P->data[lin];
                if (mir < lin || f < fmin || f > fmax || f <= 0 || !(v > 0) || !isfinite(v))
                    continue;
                x[m] = log(f), y[m++] = log(v);
            }
    st = fit(x, y, m, P->dim, out);
    free(x), free(y);
    return st;
}

int nl_psd_slope(const double *f, const double *psd, size_t n, double fmin, double fmax, int E, nl_slope *out)
{
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y);
    size_t m = 0;
    int st;
    if (!x || !y) {
        free(x), free(y);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < n; i++)
        if (f[i] >= fmin && f[i] <= fmax && f[i] > 0 && psd[i] > 0 && isfinite(psd[i]))
            x[m] = log(f[i]), y[m++] = log(psd[i]);
    st = fit(x, y, m, E, out);
    free(x), free(y);
    return st;
}

int nl_slope_fractal_range(const nl_slope *s, int E)
{
    double d;
    if (!s || E < 1 || E > 3)
        return 0;
    d = -s->slope - (E - 1);
    if (d + s->ci95 < 1)
        return -1;
    if (d - s->ci95 > 3)
        return 1;
    return 0;
}
