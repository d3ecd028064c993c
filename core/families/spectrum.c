/* spectrum: a spectral density given as an expression of the frequency
 * (a density: its white-noise part is a constant in S, not a key); a
 * removable singularity is evaluated as its limit. */
#include "families_internal.h"

static const char *const names[] = {"f", "fx", "fy", "fz", "k"};

static int parse_argument(nl_model *m, const char *arg) { return nl_expr_model_compile(m, arg, names, 5); }

/* f: signed in 1D, |frequency| in 2D and 3D (p[0..2], zeros past dim) */
static void vars_1d(const double *p, double *v)
{
    v[0] = v[1] = p[0], v[2] = v[3] = 0, v[4] = fabs(p[0]);
}

static void vars_nd(const double *p, double *v)
{
    v[0] = v[4] = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    v[1] = p[0], v[2] = p[1], v[3] = p[2];
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    double p[3] = {f[0], dim > 1 ? f[1] : 0, dim > 2 ? f[2] : 0};
    return nl_expr_model_eval(m, dim == 1 ? vars_1d : vars_nd, p, dim);
}

const nl_family nl_family_spectrum = {
    .name = "spectrum",
    .aliases = "",
    .argument = "EXPR",
    .usage = "variables f, fx, fy, fz, k",
    .formula = "S = EXPR, a non-negative two-sided density",
    .flags = NL_FAMILY_EXPRESSION | NL_FAMILY_ARGUMENT | NL_FAMILY_SPECTRAL,
    .validity = "valid where the expression is non-negative: noiselab check measures it",
    .parse_argument = parse_argument,
    .spectrum = spectrum,
    .isotropic = nl_expr_isotropic,
};
