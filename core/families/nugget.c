/* nugget: white noise alone, R = var at lag 0 exactly and 0 elsewhere (gstat
 * "Nug", RandomFields RMnugget); the structure a nested model begins
 * with, as nugget:var=0.05.  Its variance is the model's nugget (the
 * nugget= key of every family defined by R), so that every method and
 * fit treats it as one. */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "var", .role = NL_ROLE_NUGGET, .def = 1, .range = NL_RANGE_NONNEG},
};

static double profile(const nl_model *m, double t)
{
    (void)m;
    (void)t;
    return 0.0;
}

/* The continuous part is 0: its spectrum is 0 (the nugget's density
 * depends on the grid, core/model.h). */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    (void)m;
    (void)dim;
    (void)f;
    return 0.0;
}

static void from_psill(const double *q, double *p) { p[0] = q[0]; }

static const nl_family_param gstat_params[] = {
    {.name = "psill", .role = NL_ROLE_NUGGET, .def = 1, .range = NL_RANGE_NONNEG},
};

static const nl_family_alias peers[] = {
    {.name = "Nug", .peer = "gstat", .formula = "psill at h = 0, else 0", .nparams = 1, .params = gstat_params,
     .convert = from_psill},
};

const nl_family nl_family_nugget = {
    .name = "nugget",
    .aliases = "white RMnugget",
    .formula = "R = var at t = 0 exactly, else 0 (white noise; its var is the model's nugget)",
    .flags = 0,
    .validity = "positive definite in every dimension",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
};
