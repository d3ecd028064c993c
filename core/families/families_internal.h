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

/* A peer alias with keys (variance, length, nugget, shape) of a family
 * whose params[] begin shape, scale, var, nugget, the length its scale. */
void nl_peer_shape_first(const double *q, double *p);

/* A gstat name's angle= and ratio= are gstat's anis = c(angle, ratio):
 * turn its angle into noiselab's (core/families/peers.c). */
void nl_peer_gstat_anis(nl_model *m);

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
 * variables names[0..n-1] (the order nl_expr_model_eval takes their
 * values in); NL_OK or NL_EINVAL. */
int nl_expr_model_compile(nl_model *m, const char *arg, const char *const *names, size_t n);

/* The model's expression at p[0..dim-1] (a lag or a frequency), through
 * `vars`, which makes the variables' values from p.  Where the expression
 * is not finite, its limit at p (core/expr_limit.c) when the limit exists,
 * else the value itself. */
typedef void (*nl_expr_vars_fn)(const double *p, double *values);
double nl_expr_model_eval(const nl_model *m, nl_expr_vars_fn vars, const double *p, int dim);

/* |f| for a family's closed-form isotropic spectrum in dim dimensions, or
 * NAN where the model is stretched, rotated or separable in 2D and 3D (its
 * spectrum is then not a function of |f| alone). */
static inline double nl_family_fnorm(const nl_model *m, int dim, const double *f)
{
    double k2 = 0;
    if (dim > 1 && m->aniso_given)
        return NAN;
    for (int a = 0; a < dim; a++)
        k2 += f[a] * f[a];
    return sqrt(k2);
}

/* The d-dimensional spectrum (cycles per unit, two-sided) at |f| = k of
 * var (1 + (r/s)^2)^-gamma (cauchy.c; INFINITY at k = 0 where gamma <= d/2). */
double nl_spectrum_cauchy(double var, double s, double gamma, int dim, double k);

/* J_nu(x) for nu >= 0, x > 0 into *out by GSL (call inside the GSL guard);
 * GSL's status (jbessel.c). */
int nl_family_jnu(double nu, double x, double *out);

/* The d-dimensional spectrum at |f| = k of var Gamma(nu+1) (2s/r)^nu
 * J_nu(r/s) (jbessel.c; NAN where nu <= (d-2)/2: no density). */
double nl_spectrum_jbessel(double var, double s, double nu, int dim, double k);

/* The normalised intersection of two balls of unit diameter whose centres
 * are a apart, generalised to real b = (D+1)/2: I_{1-a^2}(b, 1/2)
 * (hyperspherical.c; 0 for a >= 1, NAN where GSL fails). */
double nl_euclid_hat(double b, double a);

/* The D-dimensional spectrum at |f| = k of var nl_euclid_hat((D+1)/2,
 * |t|/s): the squared transform of the ball of diameter s over its volume
 * (hyperspherical.c). */
double nl_spectrum_euclid_hat(double var, double s, int D, double k);

/* The truncated power law of stable modes exp(-(r/l)^alpha) with Hurst
 * coefficient h over lengths lo < l < hi, normalised to 1 at r = 0
 * (tplstable.c, Hesse et al. 2014). */
double nl_tpl_cor(double h, double alpha, double lo, double hi, double r);

/* NL_OK when the model's parameter of index `lower` is below that of
 * index `scale`, NL_EINVAL with a message otherwise (tplstable.c; a
 * family's check runs before m->scale is set). */
int nl_tpl_check(const nl_model *m, int scale, int lower);

/* GSTools' TPLGaussian and TPLExponential (var, len_scale, nugget, hurst,
 * len_low) into params[] hurst, scale, lower, var, nugget: our scale is
 * its upper cut-off len_low + len_scale. */
void nl_tpl_from_gstools(const double *q, double *p);

#endif
