/* markaussian: the stable (powered exponential) autocorrelation,
 * exp(-|t/scale|^alpha), between Markov (alpha = 1) and Gauss (alpha = 2). */
#include "families_internal.h"

enum { ALPHA };

static const nl_family_param params[] = {
    /* exp(-|t|^alpha) is positive definite exactly for 0 < alpha <= 2 */
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "1.4", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "above 2 the ACF is not positive definite", .start = 1, .fit_lo = 0.05, .fit_hi = 2},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t) { return m->var * exp(-pow(nl_family_a(m, t), m->p[ALPHA])); }

/* gstat's Exc: vgm(psill, "Exc", range, nugget, kappa), kappa 0.5 by default */
static const nl_family_param gstat_params[] = {
    NL_PEER_PSILL, NL_PEER_RANGE, NL_PARAM_NUGGET,
    {.name = "kappa", .def = 0.5, .range = NL_RANGE_UPTO, .hi = 2, .why = "above 2 the ACF is not positive definite"},
};

/* GSTools' Stable(var, len_scale, nugget, alpha), alpha 1.5 by default */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "alpha", .def = 1.5, .range = NL_RANGE_UPTO, .hi = 2, .why = "above 2 the ACF is not positive definite"},
};

static const nl_family_alias peers[] = {
    {.name = "Exc", .peer = "gstat", .formula = "psill exp(-(h/range)^kappa)", .nparams = 4, .params = gstat_params,
     .convert = nl_peer_shape_first},
    {.name = "Stable", .peer = "GSTools", .formula = "var exp(-(h/len_scale)^alpha)", .nparams = 4,
     .params = gstools_params, .convert = nl_peer_shape_first},
};

const nl_family nl_family_markaussian = {
    .name = "markaussian",
    .aliases = "stable powexp RMstable",
    .formula = "R = var exp(-|t/scale|^alpha), 0 < alpha <= 2",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for 0 < alpha <= 2 (a completely monotone function of |t|^alpha)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
