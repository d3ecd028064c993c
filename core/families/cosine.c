/* cosine: the periodic model, a cosine of period `scale` (gstat "Per");
 * positive definite in 1D only (as a function of |lag| in 2D and 3D it is
 * not: its spectrum there is a ring's, J0 and sinc, which are). */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 4},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t) { return m->var * cos(2 * M_PI * t / m->scale); }

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Per", .peer = "gstat", .formula = "psill cos(2 pi h/range)", .nparams = 3,
     .params = nl_peer_gstat_params, .convert = same_length},
};

const nl_family nl_family_cosine = {
    .name = "cosine",
    .aliases = "periodic",
    .formula = "R = var cos(2 pi t/scale) (scale = the period; the spectrum is two lines at f = +-1/scale)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D only (Bochner: two spectral lines); as a function of |lag| not in 2D or 3D",
    .max_dim = 1,
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
