/* superspherical: the spherical models of real order, R = var
 * I_{1-a^2}(kappa+1, 1/2), a = |t|/scale < 1, 0 beyond (GSTools'
 * SuperSpherical with nu = kappa and len_scale = scale; Matern 1960):
 * hyperspherical with dim = 2 kappa + 1, R proportional to the integral
 * of (1 - u^2)^kappa from a to 1.  Positive definite in d dimensions for
 * kappa >= (d-1)/2 (for whole 2 kappa + 1 the D-ball's model; GSTools'
 * bound). */
#include "families_internal.h"
#include "../nl_error.h"

enum { KAPPA };

static const nl_family_param params[] = {
    /* fits: kappa from 0.05 to GSTools' 50 */
    {.name = "kappa", .def = NAN, .placeholder = "K", .example = "1", .range = NL_RANGE_NONNEG, .start = 1,
     .fit_lo = 0.05, .fit_hi = 50},
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    return m->var * nl_euclid_hat(m->p[KAPPA] + 1, nl_family_a(m, t));
}

/* Where 2 kappa + 1 is the dimension, hyperspherical's. */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    return 2 * m->p[KAPPA] + 1 == dim ? nl_spectrum_euclid_hat(m->var, m->scale, dim, nl_family_fnorm(m, dim, f))
                                      : NAN;
}

static int check_dim(const nl_model *m, int dim)
{
    double lo = 0.5 * (dim - 1);
    if (m->p[KAPPA] < lo)
        return NL_ERROR(NL_ENOTPD, "%s: not known to be positive definite in %dD: expected kappa >= (d-1)/2 = %g, "
                        "got kappa=%g", m->spec, dim, lo, m->p[KAPPA]);
    return NL_OK;
}

/* GSTools' SuperSpherical(var, len_scale, nugget, nu), nu our kappa, its
 * default that of a 3D model ((d-1)/2). */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "nu", .def = 1, .range = NL_RANGE_NONNEG},
};

static const nl_family_alias peers[] = {
    {.name = "SuperSpherical", .peer = "GSTools",
     .formula = "var (1 - x 2F1(1/2, -nu; 3/2; x^2) / 2F1(1/2, -nu; 3/2; 1)), x = h/len_scale < 1", .nparams = 4,
     .params = gstools_params, .convert = nl_peer_shape_first},
};

const nl_family nl_family_superspherical = {
    .name = "superspherical",
    .aliases = "",
    .formula = "R = var I_{1-a^2}(kappa+1, 1/2), a = |t|/scale < 1, else 0 (hyperspherical with dim = 2 kappa + 1)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in d dimensions for kappa >= (d-1)/2 (Matern 1960; GSTools' bound); "
                "below it for whole 2 kappa + 1 not (Gneiting 1999)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .profile = profile,
    .spectrum = spectrum,
    .check_dim = check_dim,
};
