/* spectrum: a spectral density given as a libmatheval expression of the
 * frequency (a density: its white-noise part is a constant in S, not a
 * key). */
#include "families_internal.h"

static int parse_argument(nl_model *m, const char *arg) { return nl_expr_compile(m, arg, "f fx fy fz k"); }

static double spectrum(const nl_model *m, int dim, const double *f)
{
    static const char *const names[] = {"f", "fx", "fy", "fz", "k"};
    double k2 = 0, k;
    for (int a = 0; a < dim; a++)
        k2 += f[a] * f[a];
    k = sqrt(k2);
    {
        double v[] = {dim == 1 ? f[0] : k, f[0], dim > 1 ? f[1] : 0, dim > 2 ? f[2] : 0, k};
        return nl_expr_eval(m, names, v, 5);
    }
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
