/* linear: the triangular (bounded linear) model of range `scale` (gstat
 * "Lin" with a range, GSTools Linear); positive definite in 1D only. */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return a < 1 ? m->var * (1 - a) : 0.0;
}

/* The triangle's transform: var scale sinc^2(pi f scale). */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    double q = M_PI * f[0] * m->scale, s = q == 0 ? 1 : sin(q) / q;
    return dim == 1 ? m->var * m->scale * s * s : NAN;
}

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Lin", .peer = "gstat", .formula = "psill (1 - h/range) for h < range (range > 0: gstat's bounded Lin)",
     .nparams = 3, .params = nl_peer_gstat_params, .convert = same_length},
    {.name = "Linear", .peer = "GSTools", .formula = "var (1 - h/len_scale) for h < len_scale", .nparams = 3,
     .params = nl_peer_gstools_params, .convert = same_length},
};

const nl_family nl_family_linear = {
    .name = "linear",
    .aliases = "triangular",
    .formula = "R = var (1 - |t|/scale) for |t| < scale, else 0; 1D S = var scale sinc^2(pi f scale)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D only (the 1D ball's autoconvolution)",
    .max_dim = 1,
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
