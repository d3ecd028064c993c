/* gauss: the Gaussian autocorrelation. */
#include "families_internal.h"

static const nl_family_param params[] = {NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return m->var * exp(-a * a);
}

double nl_spectrum_gauss1d(double var, double s, double f)
{
    double q = M_PI * f * s;
    return var * s * sqrt(M_PI) * exp(-q * q);
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    return dim == 1 ? nl_spectrum_gauss1d(m->var, m->scale, f[0]) : NAN;
}

NL_PEER_VLN(same_length, 1)
/* GSTools' Gaussian is exp(-(pi/4) (h/len_scale)^2): its rescale factor
 * sqrt(pi)/2 (gstools/covmodel/models.py) */
NL_PEER_VLN(gstools_length, 2 / sqrt(M_PI))

static const nl_family_alias peers[] = {
    {.name = "Gau", .peer = "gstat", .formula = "psill exp(-(h/range)^2)", .nparams = 3,
     .params = nl_peer_gstat_params, .convert = same_length},
    {.name = "Gaussian", .peer = "GSTools", .formula = "var exp(-(pi/4) (h/len_scale)^2)", .nparams = 3,
     .params = nl_peer_gstools_params, .convert = gstools_length},
};

const nl_family nl_family_gauss = {
    .name = "gauss",
    .aliases = "gaussian RMgauss",
    .formula = "R = var exp(-(t/scale)^2); 1D S = var scale sqrt(pi) exp(-(pi f scale)^2)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
