/* spherical: the spherical model of range `scale` (Matheron 1971; gstat
 * "Sph", GSTools Spherical with len_scale = a), positive definite in 1, 2
 * and 3 dimensions only (its 4D Hankel transform is negative somewhere). */
#include "families_internal.h"

static const nl_family_param params[] = {
    /* the range: the fit starts at twice the e-folding lag */
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return a < 1 ? m->var * (1 - a * (1.5 - 0.5 * a * a)) : 0.0;
}

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Sph", .peer = "gstat", .formula = "psill (1 - 1.5 h/range + 0.5 (h/range)^3) for h < range",
     .nparams = 3, .params = nl_peer_gstat_params, .convert = same_length},
    {.name = "Spherical", .peer = "GSTools", .formula = "var (1 - 1.5 h/len_scale + 0.5 (h/len_scale)^3)",
     .nparams = 3, .params = nl_peer_gstools_params, .convert = same_length},
};

const nl_family nl_family_spherical = {
    .name = "spherical",
    .aliases = "RMspheric",
    .formula = "R = var (1 - 1.5 a + 0.5 a^3) for a = |t|/scale < 1, else 0 (scale = range); valid in 1D to 3D",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D, 2D and 3D only",
    .max_dim = 3,
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
