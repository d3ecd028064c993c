/* lgd: the local-global distinguisher of Gneiting (2000) and Gneiting and
 * Schlather (2004, eq. 16; RandomFields' RMlgd), a = |t|/scale:
 *     R = var (1 - beta/(alpha+beta) a^alpha)  for a <= 1,
 *     R = var alpha/(alpha+beta) a^-beta       for a > 1,
 * fractal dimension d + 1 - alpha/2 and Hurst coefficient 1 - beta/2 set
 * apart; positive definite in d dimensions for 0 < alpha <= (3-d)/2 and
 * beta > 0, so in 1D and 2D only. */
#include "families_internal.h"
#include "../nl_error.h"

enum { ALPHA, BETA };

static const nl_family_param params[] = {
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "0.5", .range = NL_RANGE_UPTO, .hi = 1,
     .why = "above 1 the ACF is positive definite in no dimension", .start = 0.5, .fit_lo = 0.05, .fit_hi = 1},
    {.name = "beta", .def = NAN, .placeholder = "B", .example = "1", .range = NL_RANGE_POSITIVE, .start = 1,
     .fit_lo = 0.05, .fit_hi = 50},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t), al = m->p[ALPHA], be = m->p[BETA];
    return m->var * (a <= 1 ? 1 - be / (al + be) * pow(a, al) : al / (al + be) * pow(a, -be));
}

static int check_dim(const nl_model *m, int dim)
{
    double hi = 0.5 * (3 - dim);
    if (!(m->p[ALPHA] <= hi))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: expected 0 < alpha <= (3-d)/2 = %g (Gneiting "
                        "and Schlather 2004), got alpha=%g", m->spec, dim, hi, m->p[ALPHA]);
    return NL_OK;
}

const nl_family nl_family_lgd = {
    .name = "lgd",
    .aliases = "RMlgd",
    .formula = "R = var (1 - beta/(alpha+beta) a^alpha) for a = |t|/scale <= 1, var alpha/(alpha+beta) a^-beta "
               "beyond",
    .flags = NL_FAMILY_FIT,
    .max_dim = 2,
    .validity = "positive definite in d = 1, 2 for 0 < alpha <= (3-d)/2 and beta > 0 (Gneiting 2000; Gneiting and "
                "Schlather 2004), in no dimension above 2",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .check_dim = check_dim,
};
