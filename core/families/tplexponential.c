/* tplexponential: the truncated power law of Exponential modes  (Hesse et al. 2014;
 * GSTools' TPLExponential): tplstable with alpha = 1. */
#include "families_internal.h"

enum { HURST, SCALE, LOWER };

static const nl_family_param params[] = {
    {.name = "hurst", .def = NAN, .placeholder = "H", .example = "0.5", .range = NL_RANGE_POSITIVE},
    NL_PARAM_SCALE,
    {.name = "lower", .def = 0, .range = NL_RANGE_NONNEG},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static int check(const nl_model *m) { return nl_tpl_check(m, SCALE, LOWER); }

static double profile(const nl_model *m, double t)
{
    return m->var * nl_tpl_cor(m->p[HURST], 1, m->p[LOWER], m->scale, fabs(t));
}

/* GSTools' TPLExponential(var, len_scale, nugget, hurst, len_low) with its
 * defaults; its upper cut-off len_up = len_low + len_scale is our scale. */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "hurst", .def = 0.25, .range = NL_RANGE_POSITIVE},
    {.name = "len_low", .def = 0, .range = NL_RANGE_NONNEG},
};

static const nl_family_alias peers[] = {
    {.name = "TPLExponential", .peer = "GSTools",
     .formula = "var b E_(1+b)(h/len_up), b = 2 hurst, len_up = len_low + len_scale (len_low = 0)",
     .nparams = 5, .params = gstools_params, .convert = nl_tpl_from_gstools},
};

const nl_family nl_family_tplexponential = {
    .name = "tplexponential",
    .aliases = "",
    .formula = "R = var 2 hurst E_(1+2 hurst)(|t|/scale), E_s(x) = x^(s-1) Gamma(1-s, x) (lower = 0; scale the "
               "upper cut-off)",
    .validity = "positive definite in every dimension for hurst > 0 (a positive mixture of exponential correlations; "
                "Hesse et al. 2014)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .check = check,
    .profile = profile,
};
