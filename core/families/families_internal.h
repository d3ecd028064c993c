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

#endif
