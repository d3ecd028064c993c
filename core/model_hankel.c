/* R(r) of the power-law spectrum by quadrature: the inverse Fourier
 * transform in 1D and the Hankel transform of Lewis 1987, eq. (13), for
 * isotropic spectra in 2D and 3D:
 *     1D  R(t) = 2 int S(f) cos(2 pi f t) df
 *     2D  R(r) = 2 pi int S(k) J0(2 pi k r) k dk
 *     3D  R(r) = 4 pi int S(k) sin(2 pi k r) / (2 pi k r) k^2 dk
 * over the band fmin <= k <= fmax (GSL QAWO for the trigonometric weights,
 * QAG for the Bessel one). */
#include "model_internal.h"

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>

struct arg {
    const nl_model *m;
    int dim;
    double r;
};

static double s_of(const nl_model *m, int dim, double k)
{
    double f[3] = {k, 0, 0};
    return nl_model_spectrum(m, dim, f);
}

static double integrand_plain(double k, void *p)
{
    const struct arg *a = p;
    double s = s_of(a->m, a->dim, k);
    if (a->dim == 1) return 2 * s;
    if (a->dim == 2) return 2 * M_PI * s * k;
    return 4 * M_PI * s * k * k;
}

static double integrand_j0(double k, void *p)
{
    const struct arg *a = p;
    return 2 * M_PI * s_of(a->m, 2, k) * k * gsl_sf_bessel_J0(2 * M_PI * k * a->r);
}

static double integrand_sinc3(double k, void *p)
{
    const struct arg *a = p;
    return 4 * M_PI * s_of(a->m, 3, k) * k / (2 * M_PI * a->r);
}

double nl_model_power_acf(const nl_model *m, int dim, double r)
{
    struct arg a = {m, dim, fabs(r)};
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(2000);
    double lo = m->fmin, hi = m->fmax, val = NAN, err;
    gsl_function F;
    int st;
    if (!w)
        return NAN;
    F.params = &a;
    if (a.r == 0) {
        F.function = integrand_plain;
        st = gsl_integration_qag(&F, lo, hi, 0, 1e-11, 2000, GSL_INTEG_GAUSS61, w, &val, &err);
    } else if (dim == 2) {
        F.function = integrand_j0;
        st = gsl_integration_qag(&F, lo, hi, 0, 1e-11, 2000, GSL_INTEG_GAUSS61, w, &val, &err);
    } else {
        gsl_integration_qawo_table *t =
            gsl_integration_qawo_table_alloc(2 * M_PI * a.r, hi - lo, dim == 1 ? GSL_INTEG_COSINE : GSL_INTEG_SINE, 50);
        F.function = dim == 1 ? integrand_plain : integrand_sinc3;
        st = t ? gsl_integration_qawo(&F, lo, 0, 1e-11, 2000, w, t, &val, &err) : -1;
        gsl_integration_qawo_table_free(t);
    }
    gsl_integration_workspace_free(w);
    return st == 0 ? val : NAN;
}
