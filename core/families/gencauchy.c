/* gencauchy: the generalized Cauchy autocorrelation of Gneiting and
 * Schlather (2004), R = var (1 + (|t|/scale)^alpha)^(-beta/alpha): alpha
 * sets the roughness near 0 (fractal dimension d + 1 - alpha/2 in d
 * dimensions), beta the decay at large lags (R ~ |t|^-beta, long memory
 * for beta < d), independently (RandomFields' RMgencauchy). */
#include "families_internal.h"

enum { ALPHA, BETA };

static const nl_family_param params[] = {
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "1", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "above 2 the ACF is not positive definite", .start = 1, .fit_lo = 0.05, .fit_hi = 2},
    /* fits: beta from 0.05 (R ~ |t|^-0.05, no decay a data set sees) to 50
     * (a decay the scale absorbs) */
    {.name = "beta", .def = NAN, .placeholder = "B", .example = "1.5", .range = NL_RANGE_POSITIVE, .start = 1,
     .fit_lo = 0.05, .fit_hi = 50},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double alpha = m->p[ALPHA];
    return m->var * pow(1 + pow(nl_family_a(m, t), alpha), -m->p[BETA] / alpha);
}

const nl_family nl_family_gencauchy = {
    .name = "gencauchy",
    .aliases = "generalized-cauchy RMgencauchy",
    .formula = "R = var (1 + (|t|/scale)^alpha)^(-beta/alpha), 0 < alpha <= 2, beta > 0",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for 0 < alpha <= 2 and beta > 0 (Gneiting and Schlather "
                "2004: a completely monotone function of |t|^alpha)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
};
