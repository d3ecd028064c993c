/* pentaspherical: the pentaspherical model of range `scale`, the
 * autoconvolution of a 5D ball's indicator restricted to 3D (Wackernagel
 * 2003, Table; gstat "Pen"); positive definite in 1D to 3D. */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

/* 1 - 15/8 a + 5/4 a^3 - 3/8 a^5 for a < 1 (gstat/src/vario_fn.c) */
static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t), a2 = a * a;
    return a < 1 ? m->var * (1 - a * (15.0 / 8 + a2 * (-5.0 / 4 + a2 * 3.0 / 8))) : 0.0;
}

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Pen", .peer = "gstat", .formula = "psill (1 - 15/8 a + 5/4 a^3 - 3/8 a^5), a = h/range < 1",
     .nparams = 3, .params = nl_peer_gstat_params, .convert = same_length},
};

const nl_family nl_family_pentaspherical = {
    .name = "pentaspherical",
    .aliases = "",
    .formula = "R = var (1 - 15/8 a + 5/4 a^3 - 3/8 a^5) for a = |t|/scale < 1, else 0 (scale = range)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D, 2D and 3D (the 5D ball's autoconvolution: valid up to 5D; checked here "
                "to 3D)",
    .max_dim = 3,
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
