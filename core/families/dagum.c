/* dagum: the Dagum correlation R = var (1 - (a^beta / (1 + a^beta))^(gamma/beta)),
 * a = |t|/scale (Berg, Mateu and Porcu 2008, in RandomFields' RMdagum
 * parameters): like gencauchy it sets the roughness near 0 (by beta) and
 * the power-law tail (R ~ (gamma/beta) a^-beta) apart; positive definite in
 * every dimension for 0 < beta <= 1 and 0 < gamma <= 1. */
#include "families_internal.h"

enum { BETA, GAMMA };

static const nl_family_param params[] = {
    {.name = "beta", .def = NAN, .placeholder = "B", .example = "0.5", .range = NL_RANGE_UPTO, .hi = 1,
     .why = "positive definiteness is known for beta <= 1 only", .start = 0.5, .fit_lo = 0.05, .fit_hi = 1},
    {.name = "gamma", .def = NAN, .placeholder = "G", .example = "0.5", .range = NL_RANGE_UPTO, .hi = 1,
     .why = "positive definiteness is known for gamma <= 1 only", .start = 0.5, .fit_lo = 0.05, .fit_hi = 1},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double b = m->p[BETA], ab = pow(nl_family_a(m, t), b);
    return m->var * (1 - pow(ab / (1 + ab), m->p[GAMMA] / b));
}

const nl_family nl_family_dagum = {
    .name = "dagum",
    .aliases = "RMdagum",
    .formula = "R = var (1 - (a^beta / (1 + a^beta))^(gamma/beta)), a = |t|/scale, 0 < beta <= 1, 0 < gamma <= 1",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in every dimension for 0 < beta <= 1 and 0 < gamma <= 1 (Berg, Mateu and "
                "Porcu 2008)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
};
