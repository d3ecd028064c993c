/* circular: the circular model of range `scale`, the normalised area of
 * intersection of two discs of diameter `scale` (Matheron 1965; gstat
 * "Cir", GSTools Circular, RandomFields RMcircular); positive definite in
 * 1D and 2D only. */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

/* 1 - (2/pi) (a sqrt(1 - a^2) + asin a) for a < 1 (gstat/src/vario_fn.c's
 * variogram), the same as (2/pi) (acos a - a sqrt(1 - a^2)). */
static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return a < 1 ? m->var * (2 / M_PI) * (acos(a) - a * sqrt(1 - a * a)) : 0.0;
}

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Cir", .peer = "gstat", .formula = "psill (2/pi) (acos a - a sqrt(1 - a^2)), a = h/range < 1",
     .nparams = 3, .params = nl_peer_gstat_params, .convert = same_length},
    {.name = "Circular", .peer = "GSTools", .formula = "var (2/pi) (acos a - a sqrt(1 - a^2)), a = h/len_scale < 1",
     .nparams = 3, .params = nl_peer_gstools_params, .convert = same_length},
};

const nl_family nl_family_circular = {
    .name = "circular",
    .aliases = "RMcircular",
    .formula = "R = var (2/pi) (acos a - a sqrt(1 - a^2)) for a = |t|/scale < 1, else 0 (scale = range)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D and 2D only (Matheron 1965; Gneiting 1999)",
    .max_dim = 2,
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
