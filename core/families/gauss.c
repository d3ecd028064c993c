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

const nl_family nl_family_gauss = {
    .name = "gauss",
    .aliases = "",
    .formula = "R = var exp(-(t/scale)^2); 1D S = var scale sqrt(pi) exp(-(pi f scale)^2)",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
};
