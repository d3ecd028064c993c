/* powvar: the power variogram gamma(h) = c |h|^alpha, 0 < alpha <= 2
 * (Matheron 1973; gstat's vgm(c, "Pow", alpha), whose "range" is the
 * exponent; RandomFields' RMfbm(alpha, var, scale): peer aliases below).  An intrinsic model:
 * the field has stationary increments, E (Z(x+h) - Z(x))^2 = 2 gamma(h),
 * and no covariance (the fractional Brownian field of Hurst index
 * H = alpha/2, scaled).  Its "R" (core/model.h, Intrinsic models) is the
 * generalized covariance K(h) = -c |h|^alpha, which is conditionally
 * positive definite of order 0 for 0 < alpha <= 2 in every dimension
 * (Matheron 1973, "The intrinsic random functions and their applications";
 * Schoenberg 1938: |h|^alpha is conditionally negative definite iff
 * exp(-s |h|^alpha) is positive definite for all s > 0, which holds in every
 * dimension exactly for alpha <= 2; a variogram grows slower than |h|^2). */
#include "families_internal.h"
#include "../nl_error.h"

enum { ALPHA, C };

static const nl_family_param params[] = {
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "1.5", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "a variogram grows slower than |h|^2: c |h|^alpha is conditionally negative definite only for "
            "0 < alpha <= 2"},
    {.name = "c", .role = NL_ROLE_VARIANCE, .def = 1, .range = NL_RANGE_POSITIVE},
    NL_PARAM_NUGGET,
};

static int check(const nl_model *m)
{
    if (m->sep)
        return NL_ERROR(NL_EINVAL, "%s: sep: a separable product applies to covariances, not to the intrinsic "
                        "powvar; expected angle and ratio only", m->spec);
    return NL_OK;
}

/* The generalized covariance K = -gamma (the nugget adds at lag 0 as for
 * every model, so K(0) - K(h) = nugget + c |h|^alpha). */
static double profile(const nl_model *m, double t)
{
    return t == 0 ? 0.0 : -m->var * pow(fabs(t), m->p[ALPHA]);
}

/* The generalized spectrum: gamma(h) = integral of (1 - cos(2 pi f.h)) S(f) df
 * over R^d with the (not integrable) density
 *     S(f) = c (alpha/2) Gamma((d + alpha)/2) / (pi^(alpha + d/2) Gamma(1 - alpha/2)) |f|^-(d + alpha),
 * f in cycles per unit (from the integral of (1 - cos k.h) |k|^-(d + alpha)
 * dk = |h|^alpha pi^(d/2) Gamma(1 - alpha/2) / (2^alpha (alpha/2) Gamma((d + alpha)/2)),
 * the spectral representation of an intrinsic random function, Matheron
 * 1973; verified against gamma by quadrature in tests/test_intrinsic_model.c).
 * Positive for 0 < alpha < 2 (check reads it); at alpha = 2 all of it sits
 * at f = 0: NAN. */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    double a = m->p[ALPHA], k2 = 0;
    if (!(a < 2))
        return NAN;
    for (int i = 0; i < dim; i++)
        k2 += f[i] * f[i];
    return m->var * (a / 2) * tgamma((dim + a) / 2) / (pow(M_PI, a + dim / 2.0) * tgamma(1 - a / 2)) *
           pow(k2, -(dim + a) / 2);
}

/* gstat's vgm(psill, "Pow", range, nugget): the "range" is the exponent
 * (gstat refuses it above 2); RandomFields' RMfbm(alpha, var, scale):
 * gamma = var (|h|/scale)^alpha (its RFvariogram), so c = var scale^-alpha. */
static const nl_family_param gstat_params[] = {
    NL_PEER_PSILL,
    {.name = "range", .def = NAN, .placeholder = "A", .example = "1.5", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "gstat's Pow: the range is the exponent, a variogram only up to 2"},
    NL_PARAM_NUGGET,
};
static const nl_family_param rf_params[] = {
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "1.5", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "RMfbm: a variogram only for 0 < alpha <= 2"},
    {.name = "var", .role = NL_ROLE_VARIANCE, .def = 1, .range = NL_RANGE_POSITIVE},
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE},
};

static void from_gstat(const double *q, double *p) { p[C] = q[0], p[ALPHA] = q[1], p[2] = q[2]; }
static void from_rf(const double *q, double *p) { p[ALPHA] = q[0], p[C] = q[1] * pow(q[2], -q[0]); }

static const nl_family_alias peers[] = {
    {.name = "Pow", .peer = "gstat", .formula = "psill h^range, 0 < range <= 2", .nparams = 3,
     .params = gstat_params, .convert = from_gstat},
    {.name = "RMfbm", .peer = "RandomFields", .formula = "var (h/scale)^alpha, 0 < alpha <= 2", .nparams = 3,
     .params = rf_params, .convert = from_rf},
};

const nl_family nl_family_powvar = {
    .name = "powvar",
    .aliases = "",
    .formula = "gamma = c |t|^alpha, 0 < alpha <= 2 (intrinsic: no covariance; R is the generalized covariance "
               "-gamma)",
    .flags = NL_FAMILY_INTRINSIC,
    .validity = "conditionally negative definite (a variogram) in every dimension for 0 < alpha <= 2 "
                "(fractional Brownian field, H = alpha/2); not for alpha > 2",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .check = check,
    .profile = profile,
    .spectrum = spectrum,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
