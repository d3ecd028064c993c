/* oscillatory: a cosine damped by an exponential. */
#include "families_internal.h"

enum { OMEGA };

static const nl_family_param params[] = {
    {.name = "omega", .def = NAN, .placeholder = "W", .example = "10", .start = 1, .start_per_scale = 1},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    return m->var * cos(m->p[OMEGA] * t) * exp(-nl_family_a(m, t));
}

/* The Lorentzian shifted to +-omega / 2 pi. */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    double f0 = m->p[OMEGA] / (2 * M_PI);
    if (dim != 1)
        return NAN;
    return 0.5 * (nl_spectrum_markov1d(m->var, m->scale, f[0] - f0) +
                  nl_spectrum_markov1d(m->var, m->scale, f[0] + f0));
}

const nl_family nl_family_oscillatory = {
    .name = "oscillatory",
    .aliases = "",
    .formula = "R = var cos(omega t) exp(-|t|/scale)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in 1D for every omega; in 2D and 3D only up to a largest omega that depends on the dimension and the scale (noiselab check finds it)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
};
