/* cubic: the cubic model of range `scale` (Chiles and Delfiner 2012,
 * sec. 2.5; GSTools Cubic, RandomFields RMcubic), twice differentiable at
 * the origin and compactly supported; positive definite in 1D to 3D. */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

/* 1 - 7 a^2 + 35/4 a^3 - 7/2 a^5 + 3/4 a^7 for a < 1 */
static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t), a2 = a * a;
    return a < 1 ? m->var * (1 + a2 * (-7 + a * (35.0 / 4 + a2 * (-7.0 / 2 + a2 * 3.0 / 4)))) : 0.0;
}

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Cubic", .peer = "GSTools",
     .formula = "var (1 - 7 a^2 + 35/4 a^3 - 7/2 a^5 + 3/4 a^7), a = h/len_scale < 1", .nparams = 3,
     .params = nl_peer_gstools_params, .convert = same_length},
};

const nl_family nl_family_cubic = {
    .name = "cubic",
    .aliases = "RMcubic",
    .formula = "R = var (1 - 7 a^2 + 35/4 a^3 - 7/2 a^5 + 3/4 a^7) for a = |t|/scale < 1, else 0 (scale = range)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D, 2D and 3D (Chiles and Delfiner 2012)",
    .max_dim = 3,
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
