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

enum { P_SCALE = 1, P_VAR, P_NUGGET };

/* gstat's Mat, Ste and Bes: vgm(psill, model, range, nugget, kappa), kappa
 * 0.5 by default (gstat/src/vario_fn.c: Mat is ours with u = h / range,
 * Ste ours with u = 2 sqrt(kappa) h / range, Bes Mat with kappa = 1);
 * GSTools' Matern(var, len_scale, nugget, nu), nu 1 by default, is ours
 * with u = sqrt(nu) h / len_scale (gstools/covmodel/models.py);
 * RandomFields' RMwhittle(nu, var, scale) ours with u = h / scale. */
static const nl_family_param gstat_params[] = {
    NL_PEER_PSILL, NL_PEER_RANGE, NL_PARAM_NUGGET,
    {.name = "kappa", .def = 0.5, .range = NL_RANGE_POSITIVE},
};
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "nu", .def = 1, .range = NL_RANGE_POSITIVE},
};
static const nl_family_param whittle_params[] = {
    NL_PARAM_VAR, NL_PARAM_SCALE, NL_PARAM_NUGGET,
    {.name = "nu", .def = NAN, .placeholder = "V", .example = "1.5", .range = NL_RANGE_POSITIVE},
};

/* q: variance, length, nugget, smoothness; the length is our scale over
 * `factor`. */
static void set_matern(const double *q, double *p, double factor)
{
    p[NU] = q[3];
    p[P_SCALE] = q[1] * factor;
    p[P_VAR] = q[0];
    p[P_NUGGET] = q[2];
}

static void from_mat(const double *q, double *p) { set_matern(q, p, sqrt(2 * q[3])); }
static void from_ste(const double *q, double *p) { set_matern(q, p, M_SQRT1_2); }
static void from_gstools(const double *q, double *p) { set_matern(q, p, M_SQRT2); }

static void from_bes(const double *q, double *p)
{
    double r[4] = {q[0], q[1], q[2], 1};
    set_matern(r, p, M_SQRT2);
}

static const nl_family_alias peers[] = {
    {.name = "Mat", .peer = "gstat", .formula = "psill 2^(1-kappa)/Gamma(kappa) u^kappa K_kappa(u), u = h/range",
     .nparams = 4, .params = gstat_params, .convert = from_mat},
    {.name = "Ste", .peer = "gstat",
     .formula = "psill 2^(1-kappa)/Gamma(kappa) u^kappa K_kappa(u), u = 2 sqrt(kappa) h/range", .nparams = 4,
     .params = gstat_params, .convert = from_ste},
    {.name = "Bes", .peer = "gstat", .formula = "psill (h/range) K_1(h/range)", .nparams = 3,
     .params = gstat_params, .convert = from_bes},
    {.name = "Matern", .peer = "GSTools",
     .formula = "var 2^(1-nu)/Gamma(nu) u^nu K_nu(u), u = sqrt(nu) h/len_scale", .nparams = 4,
     .params = gstools_params, .convert = from_gstools},
    {.name = "RMwhittle", .peer = "RandomFields", .formula = "var 2^(1-nu)/Gamma(nu) u^nu K_nu(u), u = h/scale",
     .nparams = 4, .params = whittle_params, .convert = from_mat},
};

const nl_family nl_family_matern = {
    .name = "matern",
    .aliases = "RMmatern",
    .formula = "R = var 2^(1-nu)/Gamma(nu) u^nu K_nu(u), u = sqrt(2 nu) |t| / scale",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for nu > 0",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
