/* What the family descriptors share: the common parameters and the 1D
 * spectra that several families are built from. */
#ifndef NL_FAMILIES_INTERNAL_H
#define NL_FAMILIES_INTERNAL_H

#include "../family.h"
#include "../model_internal.h"

#include <math.h>

/* scale's fit start is the lag where the variogram first reaches 1 - 1/e
 * of the sill (WLS) or a tenth of the data's extent (ML), times .start */
#define NL_PARAM_SCALE {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 1}
#define NL_PARAM_VAR {.name = "var", .role = NL_ROLE_VARIANCE, .def = 1, .range = NL_RANGE_POSITIVE}
#define NL_PARAM_NUGGET {.name = "nugget", .role = NL_ROLE_NUGGET, .def = 0, .range = NL_RANGE_NONNEG}

/* The peers' keys (core/family.h, nl_family_alias): gstat's vgm(psill,
 * model, range, nugget, kappa), GSTools' CovModel(var, len_scale, nugget),
 * with their defaults (gstat's range has none). */
#define NL_PEER_PSILL {.name = "psill", .role = NL_ROLE_VARIANCE, .def = 1, .range = NL_RANGE_POSITIVE}
#define NL_PEER_RANGE                                                                                               \
    {.name = "range", .role = NL_ROLE_SCALE, .def = NAN, .placeholder = "A", .example = "900",                   \
     .range = NL_RANGE_POSITIVE}
#define NL_PEER_LEN_SCALE {.name = "len_scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE}

/* A peer alias whose keys are (variance, length, nugget) and whose length
 * is the family's scale times `factor`: NL_PEER_VLN(id, factor) defines
 * the converter id(q, p) for a family whose params[] begin scale, var,
 * nugget. */
#define NL_PEER_VLN(id, factor)                                                                                     \
    static void id(const double *q, double *p)                                                                      \
    {                                                                                                                \
        p[0] = q[1] * (factor);                                                                                     \
        p[1] = q[0];                                                                                                 \
        p[2] = q[2];                                                                                                 \
    }

/* gstat's and GSTools' keys for a family of one length: psill range
 * nugget, var len_scale nugget. */
extern const nl_family_param nl_peer_gstat_params[3];
extern const nl_family_param nl_peer_gstools_params[3];

/* |t| / scale, the lag in units of the correlation length. */
static inline double nl_family_a(const nl_model *m, double t) { return fabs(t) / m->scale; }

/* Two-sided 1D spectra of var exp(-|t|/s) and var exp(-(t/s)^2) at f. */
double nl_spectrum_markov1d(double var, double s, double f);
double nl_spectrum_gauss1d(double var, double s, double f);

/* Are the expression's variables free of single lag or frequency
 * components (x, y, z, fx, fy, fz)?  (expr:, spectrum:) */
int nl_expr_isotropic(const nl_model *m);

/* Compile an expression into m->eval, checking that it names only the
 * variables in `allowed` (space separated); NL_OK or NL_EINVAL. */
int nl_expr_compile(nl_model *m, const char *arg, const char *allowed);

/* Evaluate the model's expression at the named variables. */
double nl_expr_eval(const nl_model *m, const char *const *names, double *values, int n);

#endif
