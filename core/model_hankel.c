/* R(r) of the power-law spectrum by quadrature: the inverse Fourier
 * transform in 1D and the Hankel transform of Lewis 1987, eq. (13), for
 * isotropic spectra in 2D and 3D:
 *     1D  R(t) = 2 int S(f) cos(2 pi f t) df
 *     2D  R(r) = 2 pi int S(k) J0(2 pi k r) k dk
 *     3D  R(r) = 4 pi int S(k) sin(2 pi k r) / (2 pi k r) k^2 dk
 * over the band fmin <= k <= fmax (GSL QAWO for the trigonometric weights,
 * QAG for the Bessel one; at lags of over HANKEL_PERIODS periods of the band,
 * or where QAG fails, Hankel's expansion of J0 turns the 2D transform into
 * QAWO integrals too). */
#include "gsl_guard_internal.h"
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

/* Hankel's expansion of J0 for large x (Abramowitz and Stegun 9.2.5, 9.2.9,
 * 9.2.10): J0(x) = (pi x)^(-1/2) [(P + Q) cos x + (P - Q) sin x], the series
 * P, Q summed until a term falls below 1e-17; for x >= HANKEL_X0 the terms
 * fall below it before they start to grow, so the expansion is good to
 * about 1e-16 there. */
#define HANKEL_X0 40.0
/* Beyond this many periods of J0 over the band, adaptive quadrature of the
 * oscillating integrand costs tens of milliseconds per lag, or fails. */
#define HANKEL_PERIODS 1000.0

static void hankel_pq(double x, double *P, double *Q)
{
    double t = 1;
    *P = 1;
    *Q = 0;
    for (int k = 1; k < 60; k++) {
        double prev = fabs(t);
        t *= -(2.0 * k - 1) * (2.0 * k - 1) / (k * 8.0 * x);
        if (fabs(t) < 1e-17 || fabs(t) > prev)
            break;
        if (k % 2)
            *Q += (k % 4 == 1 ? 1 : -1) * t;
        else
            *P += (k % 4 == 0 ? 1 : -1) * t;
    }
}

struct asym_arg {
    const nl_model *m;
    double r;
    int sine;
};

/* 2 pi S(k) k (P +- Q) / sqrt(pi x), the amplitude of cos x (sine = 0) or of
 * sin x (sine = 1), x = 2 pi k r. */
static double integrand_asym(double k, void *p)
{
    const struct asym_arg *a = p;
    double x = 2 * M_PI * k * a->r, P, Q;
    hankel_pq(x, &P, &Q);
    return 2 * M_PI * s_of(a->m, 2, k) * k * (a->sine ? P - Q : P + Q) / sqrt(M_PI * x);
}

/* The 2D R(r) at large r: QAG with J0 below k0 = HANKEL_X0 / (2 pi r) (a few
 * periods), and above it the expansion of J0, whose cos and sin parts QAWO
 * integrates at a cost that does not grow with r. */
static double power_acf_2d_far(const nl_model *m, double r, gsl_integration_workspace *w)
{
    struct arg a = {m, 2, r};
    struct asym_arg b = {m, r, 0};
    double lo = nl_model_p(m, "fmin"), hi = nl_model_p(m, "fmax"), k0 = HANKEL_X0 / (2 * M_PI * r), near = 0, far = 0, v, err;
    gsl_function F = {integrand_j0, &a};
    if (k0 > lo) {
        if (gsl_integration_qag(&F, lo, fmin(k0, hi), 0, 1e-11, 2000, GSL_INTEG_GAUSS61, w, &near, &err))
            return NAN;
        lo = k0;
    }
    if (lo < hi) {
        F.function = integrand_asym;
        F.params = &b;
        for (b.sine = 0; b.sine < 2; b.sine++) {
            gsl_integration_qawo_table *t = gsl_integration_qawo_table_alloc(
                2 * M_PI * r, hi - lo, b.sine ? GSL_INTEG_SINE : GSL_INTEG_COSINE, 50);
            int st = t ? gsl_integration_qawo(&F, lo, 1e-13 * m->var, 1e-11, 2000, w, t, &v, &err) : -1;
            gsl_integration_qawo_table_free(t);
            if (st)
                return NAN;
            far += v;
        }
    }
    return near + far;
}

static double power_acf(const nl_model *m, int dim, double r)
{
    struct arg a = {m, dim, fabs(r)};
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(2000);
    double lo = nl_model_p(m, "fmin"), hi = nl_model_p(m, "fmax"), val = NAN, err;
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
        st = (hi - lo) * a.r > HANKEL_PERIODS ? -1
                                               : gsl_integration_qag(&F, lo, hi, 0, 1e-11, 2000, GSL_INTEG_GAUSS61, w,
                                                                     &val, &err);
        if (st && 2 * M_PI * a.r * hi > 2 * HANKEL_X0) {
            val = power_acf_2d_far(m, a.r, w);
            st = isfinite(val) ? 0 : -1;
        }
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

/* One guard per value: a quadrature costs far more than the guard. */
double nl_model_power_acf(const nl_model *m, int dim, double r)
{
    double v;
    nl_gsl_enter();
    v = power_acf(m, dim, r);
    nl_gsl_leave();
    return v;
}

/* Lewis 1987, eq. (13): the spectrum of an isotropic n-dimensional R,
 *     S(w) = 2 pi w^(1 - n/2) int_0^inf R(r) J_{n/2 - 1}(2 pi w r) r^(n/2) dr,
 * for w > 0 (J_{-1/2}(x) = sqrt(2 / (pi x)) cos x in 1D), and
 *     S(0) = (surface of the unit sphere) int_0^inf R(r) r^(n-1) dr,
 * by GSL adaptive quadrature up to the lag beyond which |R| < 1e-12 R(0)
 * (NaN when R has not fallen that low by lag 1e7). */
struct hankel_arg {
    const nl_model *m;
    int dim;   /* the model's dimension (<= 3) for R */
    int n;     /* the transform's dimension */
    double w;
};

static double hankel_integrand(double r, void *p)
{
    const struct hankel_arg *a = p;
    double lag[3] = {r, 0, 0}, R = nl_model_acf(a->m, a->dim, lag), nu = a->n / 2.0 - 1;
    if (a->w == 0)
        return R * pow(r, a->n - 1);
    double x = 2 * M_PI * a->w * r;
    double J = a->n == 1 ? (x > 0 ? sqrt(2 / (M_PI * x)) * cos(x) : 0) : gsl_sf_bessel_Jnu(nu, x);
    return R * J * pow(r, a->n / 2.0);
}

static double spectrum_iso(const nl_model *m, int dim, double w)
{
    static const double sphere[] = {0, 2, 2 * M_PI, 4 * M_PI, 2 * M_PI * M_PI};
    double zero[3] = {0, 0, 0}, r0 = nl_model_acf(m, dim < 3 ? dim : 3, zero), rmax = 1e-3, val, err;
    struct hankel_arg a = {m, dim < 3 ? dim : 3, dim, fabs(w)};
    gsl_integration_workspace *ws;
    gsl_function F = {hankel_integrand, &a};
    if (!(r0 > 0) || dim < 1 || dim > 4)
        return NAN;
    double t = 1e-3;
    for (; t < 1e7; t *= 1.25) {
        double lag[3] = {t, 0, 0};
        if (fabs(nl_model_acf(m, a.dim, lag)) >= 1e-12 * r0)
            rmax = t * 1.25;
    }
    /* R not below 1e-12 R(0) at the last lag tried (cos(t)): no transform to
     * integrate, and minutes of Bessel functions over 1e7 lags to find it */
    if (rmax >= t)
        return NAN;
    ws = gsl_integration_workspace_alloc(4000);
    if (!ws)
        return NAN;
    if (gsl_integration_qag(&F, 0, rmax, 1e-14 * r0, 1e-9, 4000, GSL_INTEG_GAUSS41, ws, &val, &err) != 0) {
        /* oscillatory tails: accept the best estimate when it is converged to 1e-6 */
        if (!(err <= 1e-6 * fabs(val) + 1e-12 * r0))
            val = NAN;
    }
    gsl_integration_workspace_free(ws);
    if (a.w == 0)
        return sphere[dim] * val;
    return 2 * M_PI * pow(a.w, 1 - dim / 2.0) * val;
}

double nl_model_spectrum_iso(const nl_model *m, int dim, double w)
{
    double v;
    nl_gsl_enter();
    v = spectrum_iso(m, dim, w);
    nl_gsl_leave();
    return v;
}
