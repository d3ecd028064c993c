/* markov: the exponential autocorrelation (Lewis 1987's Markov model). */
#include "families_internal.h"

static const nl_family_param params[] = {NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET};

static double profile(const nl_model *m, double t) { return m->var * exp(-nl_family_a(m, t)); }

/* The Lorentzian: the Fourier transform of exp(-|t|/s). */
double nl_spectrum_markov1d(double var, double s, double f)
{
    double q = 2 * M_PI * f * s;
    return var * 2 * s / (1 + q * q);
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    return dim == 1 ? nl_spectrum_markov1d(m->var, m->scale, f[0]) : NAN;
}

NL_PEER_VLN(same_length, 1)

static const nl_family_alias peers[] = {
    {.name = "Exp", .peer = "gstat", .formula = "psill exp(-h/range)", .nparams = 3, .params = nl_peer_gstat_params,
     .convert = same_length},
    {.name = "Exponential", .peer = "GSTools", .formula = "var exp(-h/len_scale)", .nparams = 3,
     .params = nl_peer_gstools_params, .convert = same_length},
};

const nl_family nl_family_markov = {
    .name = "markov",
    .aliases = "exponential RMexp",
    .formula = "R = var exp(-|t|/scale) (+ nugget at t = 0, as every R model); 1D S = var 2 scale / (1 + (2 pi f "
               "scale)^2)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension (a completely monotone function of |t|)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
