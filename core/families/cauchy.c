/* cauchy: the Cauchy correlation R = var (1 + a^2)^-gamma, a = |t|/scale
 * (RandomFields' RMcauchy; gencauchy with alpha = 2, beta = 2 gamma), a
 * normal scale mixture, so positive definite in every dimension for
 * gamma > 0 (Gneiting and Schlather 2004). */
#include "families_internal.h"
#include "../gsl_guard_internal.h"

#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>

enum { GAMMA };

static const nl_family_param params[] = {
    /* fits: gamma from 0.05 (no decay a data set sees) to 50 (a Gaussian
     * the scale absorbs) */
    {.name = "gamma", .def = NAN, .placeholder = "G", .example = "3", .range = NL_RANGE_POSITIVE, .start = 1,
     .fit_lo = 0.05, .fit_hi = 50},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return m->var * pow(1 + a * a, -m->p[GAMMA]);
}

/* (1 + r^2)^-g = int_0^inf exp(-u r^2) u^(g-1) e^-u du / Gamma(g), and the
 * d-dimensional transform of exp(-u r^2), (4 pi u)^(-d/2) exp(-k^2 / 4u)
 * (angular k), gives with nu = g - d/2 (Gradshteyn and Ryzhik 3.471.9)
 *     S(k) = 2 (4 pi)^(-d/2) / Gamma(g) (k/2)^nu K_nu(k);
 * in cycles per unit for scale s, (2 pi s)^d S(2 pi s |f|). At f = 0 the
 * limit Gamma(nu) / 2 of (k/2)^nu K_nu(k) for nu > 0, INFINITY otherwise. */
double nl_spectrum_cauchy(double var, double s, double g, int dim, double k)
{
    double nu = g - 0.5 * dim, q = 2 * M_PI * s * k, lc = log(var) + dim * log(s) + 0.5 * dim * log(M_PI);
    gsl_sf_result lk, lg, lgn;
    int st;
    if (isnan(k))
        return NAN;
    if (q == 0 && nu <= 0)
        return INFINITY;
    nl_gsl_enter();
    st = gsl_sf_lngamma_e(g, &lg);
    if (q == 0)
        st = st || gsl_sf_lngamma_e(nu, &lgn);
    else if (nu == 0) {
        st = st || gsl_sf_bessel_K0_scaled_e(q, &lk);
        lk.val = log(lk.val) - q;
    } else
        st = st || gsl_sf_bessel_lnKnu_e(fabs(nu), q, &lk);
    nl_gsl_leave();
    if (st)
        return q > 0 ? 0.0 : NAN;
    if (q == 0)
        return exp(lc + lgn.val - lg.val);
    return exp(lc + M_LN2 - lg.val + nu * log(q / 2) + lk.val);
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    return nl_spectrum_cauchy(m->var, m->scale, m->p[GAMMA], dim, nl_family_fnorm(m, dim, f));
}

const nl_family nl_family_cauchy = {
    .name = "cauchy",
    .aliases = "RMcauchy",
    .formula = "R = var (1 + a^2)^-gamma, a = |t|/scale; S = var 2 (pi^(1/2) scale)^d / Gamma(gamma) (q/2)^nu "
               "K_nu(q), q = 2 pi scale |f|, nu = gamma - d/2",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for gamma > 0 (a normal scale mixture; Gneiting and "
                "Schlather 2004)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
};
