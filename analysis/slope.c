/* Log-log regression of a spectrum. */
#include "slope.h"
#include "../core/nl_error.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdlib.h>

int an_psd_slope(const double *f, const double *psd, size_t n, double fmin, double fmax, int E, an_slope *out)
{
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), c0, c1, cov00, cov01, cov11, ss;
    size_t m = 0;
    if (!x || !y) {
        free(x), free(y);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < n; i++)
        if (f[i] >= fmin && f[i] <= fmax && f[i] > 0 && psd[i] > 0 && isfinite(psd[i]))
            x[m] = log(f[i]), y[m++] = log(psd[i]);
    if (m < 3) {
        free(x), free(y);
        return NL_ERROR(NL_EINVAL, "slope: expected at least 3 frequencies in [%g, %g], got %zu", fmin, fmax, m);
    }
    gsl_fit_linear(x, 1, y, 1, m, &c0, &c1, &cov00, &cov01, &cov11, &ss);
    out->slope = c1;
    out->ci95 = gsl_cdf_tdist_Qinv(0.025, (double)(m - 2)) * sqrt(cov11);
    out->points = m;
    /* eq. (16) takes d of a 1D profile; the radial average of an E-D spectrum
     * of an isotropic field falls as f^-(d + E - 1) (Voss 1985) */
    out->fractal_dim = E + (3 - (-c1 - (E - 1))) / 2;
    free(x), free(y);
    return NL_OK;
}
