/* rational: the rational quadratic R = var (1 + a^2 / alpha)^-alpha, a =
 * |t|/scale (GSTools' Rational with len_scale = scale; Rasmussen and
 * Williams 2006, eq. 4.19): the cauchy model of gamma = alpha and scale
 * sqrt(alpha) scale, tending to exp(-a^2) as alpha grows; positive definite
 * in every dimension. */
#include "families_internal.h"

enum { ALPHA };

static const nl_family_param params[] = {
    /* fits: GSTools' bounds for Rational */
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "3", .range = NL_RANGE_POSITIVE, .start = 1,
     .fit_lo = 0.5, .fit_hi = 50},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t), al = m->p[ALPHA];
    return m->var * pow(1 + a * a / al, -al);
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    double al = m->p[ALPHA];
    return nl_spectrum_cauchy(m->var, m->scale * sqrt(al), al, dim, nl_family_fnorm(m, dim, f));
}

/* GSTools' Rational(var, len_scale, nugget, alpha), alpha's default 1. */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "alpha", .def = 1, .range = NL_RANGE_POSITIVE},
};

static const nl_family_alias peers[] = {
    {.name = "Rational", .peer = "GSTools", .formula = "var (1 + (h/len_scale)^2 / alpha)^-alpha", .nparams = 4,
     .params = gstools_params, .convert = nl_peer_shape_first},
};

const nl_family nl_family_rational = {
    .name = "rational",
    .aliases = "",
    .formula = "R = var (1 + a^2/alpha)^-alpha, a = |t|/scale; S = cauchy's with gamma = alpha and scale sqrt(alpha) "
               "scale",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for alpha > 0 (a normal scale mixture)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .profile = profile,
    .spectrum = spectrum,
};
