/* matern: the Matern autocorrelation of smoothness nu. */
#include "families_internal.h"
#include "../gsl_guard_internal.h"

#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>

enum { NU };

static const nl_family_param params[] = {
    /* fits hold nu to GSTools' bounds for Matern (0.2 to 30): below, the
     * field is rougher than data sets resolve; above, it is the gauss model
     * within 1% (the large-nu form below: R off by 0.23 / nu), and each
     * step of a fit would evaluate K_nu at orders that cost time ~ nu */
    {.name = "nu", .def = NAN, .placeholder = "V", .example = "1.5", .range = NL_RANGE_POSITIVE, .start = 1,
     .fit_lo = 0.2, .fit_hi = 30},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

/* Above this nu, GSL's K_nu costs time proportional to nu (2 s of CPU for
 * 31 lags at nu = 1e7), and the large-nu form below omits terms of order
 * 1 / nu^2 < 1e-12. */
#define MATERN_NU_ASYMPTOTIC 1e6
/* Beyond it nu is no longer a shape parameter but an input error (gauss is
 * the model); the value is NaN, which every method refuses as "not finite",
 * as GSL's K_nu did for nu of 1e300 and more. */
#define MATERN_NU_MAX 1e15

/* The Matern correlation for large nu as a function of a = u / sqrt(2 nu):
 * from the uniform (Debye) expansion of K_nu(nu z) (Abramowitz and Stegun
 * 9.7.8) and Stirling's series of Gamma(nu),
 *     ln R = -a^2 / 2 + (a^4 - 4 a^2) / (8 nu) + O(a^6 / nu^2),
 * the Gauss limit exp(-a^2 / 2) (off by up to 0.23 / nu) with its first
 * correction.  The omitted terms are R times a polynomial in a^2 over nu^2,
 * small while a^2 << nu (R underflows before a^2 reaches 1500, where a^2 / nu
 * is still < 2e-3); at nu = 2e6 the form agrees with K_nu to the 1e-8 that
 * K_nu's own logarithms keep (tests/test_model.c). */
static double matern_large_nu(double nu, double u)
{
    double a2 = u * u / (2 * nu);
    return exp(-a2 / 2 + (a2 * a2 - 4 * a2) / (8 * nu));
}

/* The only GSL calls of the closed-form models, so the only guarded path:
 * markov, gauss and the others never touch the guard. */
static double matern(double nu, double u)
{
    gsl_sf_result lk, lg;
    int st;
    if (u == 0)
        return 1.0;
    if (nu > MATERN_NU_MAX)
        return NAN;
    if (nu > MATERN_NU_ASYMPTOTIC)
        return matern_large_nu(nu, u);
    nl_gsl_enter();
    st = gsl_sf_bessel_lnKnu_e(nu, u, &lk) || gsl_sf_lngamma_e(nu, &lg);
    nl_gsl_leave();
    if (st)
        return 0.0;
    return exp((1 - nu) * M_LN2 - lg.val + nu * log(u) + lk.val);
}

static double profile(const nl_model *m, double t)
{
    double nu = m->p[NU];
    return m->var * matern(nu, sqrt(2 * nu) * nl_family_a(m, t));
}

const nl_family nl_family_matern = {
    .name = "matern",
    .aliases = "",
    .formula = "R = var 2^(1-nu)/Gamma(nu) u^nu K_nu(u), u = sqrt(2 nu) |t| / scale",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for nu > 0",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
};
