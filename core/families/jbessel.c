/* jbessel: the J-Bessel hole effect R = var Gamma(nu+1) (2/a)^nu J_nu(a),
 * a = |t|/scale, R(0) = var (Yaglom 1987; Chiles and Delfiner 1999, p. 92;
 * RandomFields' RMbessel, GSTools' JBessel with len_scale = scale),
 * positive definite in d dimensions iff nu >= (d-2)/2: it is the
 * characteristic function of the uniform distribution on the sphere of
 * R^(2nu+2), whose projection on R^d is a density for nu > (d-2)/2. */
#include "families_internal.h"
#include "../gsl_guard_internal.h"
#include "../nl_error.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>

enum { NU };

static const nl_family_param params[] = {
    /* fits: nu from 0.05 to GSTools' 50 (nu in [-1/2, 0) is reached by
     * fixing it) */
    {.name = "nu", .def = NAN, .placeholder = "N", .example = "4.5", .range = NL_RANGE_ANY, .start = 1,
     .fit_lo = 0.05, .fit_hi = 50},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static int check(const nl_model *m)
{
    if (!(m->p[NU] >= -0.5))
        return NL_ERROR(NL_EINVAL, "%s: nu: expected nu >= -1/2 (below, R is positive definite in no "
                        "dimension), got %g", m->spec, m->p[NU]);
    return NL_OK;
}

/* GSL 2.7's J_nu is NaN at isolated arguments (J_1/2 at 3 pi/2 exactly):
 * there, the value at the next double, off by about 1e-16 of |J'|. */
int nl_family_jnu(double nu, double x, double *out)
{
    gsl_sf_result j;
    int st = gsl_sf_bessel_Jnu_e(nu, x, &j);
    if (!st && isnan(j.val))
        st = gsl_sf_bessel_Jnu_e(nu, nextafter(x, INFINITY), &j);
    *out = j.val;
    return st;
}

/* Gamma(nu+1) (2/a)^nu J_nu(a) for nu >= -1/2: below a = 1 the power series
 * sum_k (-a^2/4)^k Gamma(nu+1) / (k! Gamma(nu+k+1)) (Abramowitz and Stegun
 * 9.1.10), whose terms fall by a factor 4 (nu+1) at least, so no
 * cancellation and no underflow of (a/2)^nu at large nu; above, GSL's J_nu
 * (J_-mu = cos(mu pi) J_mu - sin(mu pi) Y_mu for nu = -mu < 0, A&S 9.1.2). */
static double jbessel(double nu, double a)
{
    gsl_sf_result y, lg;
    double j;
    int st;
    if (a < 1) {
        double sum = 1, term = 1, q = -a * a / 4;
        for (int k = 1; k < 40 && fabs(term) > 1e-17; k++) {
            term *= q / (k * (nu + k));
            sum += term;
        }
        return sum;
    }
    nl_gsl_enter();
    if (nu >= 0)
        st = nl_family_jnu(nu, a, &j);
    else {
        st = nl_family_jnu(-nu, a, &j) || gsl_sf_bessel_Ynu_e(-nu, a, &y);
        j = cos(nu * M_PI) * j + sin(nu * M_PI) * y.val;
    }
    st = st || gsl_sf_lngamma_e(nu + 1, &lg);
    nl_gsl_leave();
    if (st)
        return NAN;
    return exp(lg.val + nu * log(2 / a)) * j;
}

static double profile(const nl_model *m, double t) { return m->var * jbessel(m->p[NU], nl_family_a(m, t)); }

double nl_spectrum_jbessel(double var, double s, double nu, int dim, double k)
{
    double k0 = 1 / (2 * M_PI * s), e = nu - 0.5 * dim, c;
    gsl_sf_result g1, g2;
    int st;
    if (!(e > -1) || isnan(k))
        return NAN;
    if (k >= k0)
        return 0.0;
    nl_gsl_enter();
    st = gsl_sf_lngamma_e(nu + 1, &g1) || gsl_sf_lngamma_e(e + 1, &g2);
    nl_gsl_leave();
    if (st)
        return NAN;
    c = exp(g1.val - g2.val - 0.5 * dim * log(M_PI) - dim * log(k0));
    return var * c * pow(1 - (k / k0) * (k / k0), e);
}

/* The projection on R^d of the uniform distribution on the sphere of
 * radius k0 = 1/(2 pi scale) in R^(2nu+2) (Yaglom 1987, Section 22):
 * S = var Gamma(nu+1) / (pi^(d/2) Gamma(nu+1-d/2) k0^d) (1 - |f|^2/k0^2)^(nu-d/2)
 * for |f| < k0, 0 beyond; a density for nu > (d-2)/2 only (at nu = (d-2)/2
 * the spectrum is the sphere itself: NAN). */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    return nl_spectrum_jbessel(m->var, m->scale, m->p[NU], dim, nl_family_fnorm(m, dim, f));
}

static int check_dim(const nl_model *m, int dim)
{
    double lo = 0.5 * (dim - 2);
    if (m->p[NU] < lo)
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: expected nu >= (d-2)/2 = %g (Yaglom 1987), "
                        "got nu=%g", m->spec, dim, lo, m->p[NU]);
    return NL_OK;
}

/* GSTools' JBessel(var, len_scale, nugget, nu), nu's default that of a 3D
 * model (d/2). */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "nu", .def = 1.5, .range = NL_RANGE_ANY},
};

static const nl_family_alias peers[] = {
    {.name = "JBessel", .peer = "GSTools", .formula = "var Gamma(nu+1) J_nu(x) / (x/2)^nu, x = h/len_scale",
     .nparams = 4, .params = gstools_params, .convert = nl_peer_shape_first},
};

const nl_family nl_family_jbessel = {
    .name = "jbessel",
    .aliases = "RMbessel",
    .formula = "R = var Gamma(nu+1) (2/a)^nu J_nu(a), a = |t|/scale; S = var Gamma(nu+1) / (pi^(d/2) "
               "Gamma(nu+1-d/2) k0^d) (1 - |f|^2/k0^2)^(nu-d/2) for |f| < k0 = 1/(2 pi scale), else 0",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in d dimensions iff nu >= (d-2)/2: every nu >= -1/2 in 1D (nu = -1/2: cos), "
                "nu >= 0 in 2D, nu >= 1/2 in 3D (Yaglom 1987; Chiles and Delfiner 1999)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .check = check,
    .profile = profile,
    .spectrum = spectrum,
    .check_dim = check_dim,
};
