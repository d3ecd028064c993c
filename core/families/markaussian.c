/* markaussian: the stable (powered exponential) autocorrelation,
 * exp(-|t/scale|^alpha), between Markov (alpha = 1) and Gauss (alpha = 2). */
#include "families_internal.h"

enum { ALPHA };

static const nl_family_param params[] = {
    /* exp(-|t|^alpha) is positive definite exactly for 0 < alpha <= 2 */
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "1.4", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "above 2 the ACF is not positive definite", .start = 1, .fit_lo = 0.05, .fit_hi = 2},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t) { return m->var * exp(-pow(nl_family_a(m, t), m->p[ALPHA])); }

const nl_family nl_family_markaussian = {
    .name = "markaussian",
    .aliases = "",
    .formula = "R = var exp(-|t/scale|^alpha), 0 < alpha <= 2",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for 0 < alpha <= 2 (a completely monotone function of |t|^alpha)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
};
