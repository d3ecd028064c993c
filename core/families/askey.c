/* askey: the truncated power R = var (1 - |t|/scale)_+^nu of Askey (1973),
 * compactly supported on |t| < scale; positive definite in d dimensions
 * iff nu >= (d+1)/2 (Askey 1973 for sufficiency, Zastavnyi 2006 for
 * necessity; Gneiting 1999, 2002).  RandomFields' RMaskey(alpha = nu) and
 * GSTools' TPLSimple(nu, len_scale) are this function. */
#include "families_internal.h"
#include "../nl_error.h"

enum { NU };

static const nl_family_param params[] = {
    /* fits: nu from 1 (the 1D bound) to 30 (a shape the scale absorbs) */
    {.name = "nu", .def = NAN, .placeholder = "N", .example = "2", .range = NL_RANGE_POSITIVE, .start = 2,
     .fit_lo = 1, .fit_hi = 30},
    /* the support: the fit starts at three times the e-folding lag */
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 3},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return a < 1 ? m->var * pow(1 - a, m->p[NU]) : 0.0;
}

static int check_dim(const nl_model *m, int dim)
{
    double lo = 0.5 * (dim + 1);
    if (m->p[NU] < lo)
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: expected nu >= (d+1)/2 = %g (Askey 1973, "
                        "Zastavnyi 2006), got nu=%g", m->spec, dim, lo, m->p[NU]);
    return NL_OK;
}

/* The peers' keys: RandomFields' RMaskey(alpha, var, scale), GSTools'
 * TPLSimple(var, len_scale, nugget, nu) (nu's default that of a 3D model,
 * (d+1)/2). */
static const nl_family_param rf_params[] = {
    NL_PARAM_VAR, NL_PARAM_SCALE, NL_PARAM_NUGGET,
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "2", .range = NL_RANGE_POSITIVE},
};
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "nu", .def = 2, .range = NL_RANGE_POSITIVE},
};

static const nl_family_alias peers[] = {
    {.name = "RMaskey", .peer = "RandomFields", .formula = "var (1 - h/scale)^alpha for h < scale", .nparams = 4,
     .params = rf_params, .convert = nl_peer_shape_first},
    {.name = "TPLSimple", .peer = "GSTools", .formula = "var (1 - h/len_scale)^nu for h < len_scale", .nparams = 4,
     .params = gstools_params, .convert = nl_peer_shape_first},
};

const nl_family nl_family_askey = {
    .name = "askey",
    .aliases = "tplsimple",
    .formula = "R = var (1 - |t|/scale)^nu for |t| < scale, else 0",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in d dimensions iff nu >= (d+1)/2 (Askey 1973; Zastavnyi 2006; Gneiting 2002)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .profile = profile,
    .check_dim = check_dim,
};
