/* bohman: the Bohman correlation of support `scale`, with a = |t|/scale,
 * R = var ((1 - a) cos(pi a) + sin(pi a) / pi) for a < 1, 0 beyond
 * (Bohman 1960; Gneiting 2002, eq. 3.12; RandomFields' RMbohman): the
 * autocorrelation of cos(pi x) on |x| < 1/2, positive definite in 1D to 3D
 * only (Gneiting 2002). */
#include "families_internal.h"

static const nl_family_param params[] = {
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 3},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return a < 1 ? m->var * ((1 - a) * cos(M_PI * a) + sin(M_PI * a) / M_PI) : 0.0;
}

/* 1D: the squared Fourier transform of the half cosine cos(pi x / s) on
 * |x| < s/2, 2 s cos(pi f s) / (pi (1 - 4 f^2 s^2)), over its energy s/2:
 * S = 8 s cos^2(pi f s) / (pi^2 (1 - 4 f^2 s^2)^2), whose limit at
 * f s = 1/2 is s / 2. */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    double s = m->scale, q = fabs(f[0]) * s, d;
    if (dim != 1)
        return NAN;
    d = 1 - 4 * q * q;
    if (fabs(d) < 1e-6)
        return m->var * s / 2;
    return m->var * 8 * s * cos(M_PI * q) * cos(M_PI * q) / (M_PI * M_PI * d * d);
}

const nl_family nl_family_bohman = {
    .name = "bohman",
    .aliases = "",
    .formula = "R = var ((1-a) cos(pi a) + sin(pi a)/pi) for a = |t|/scale < 1, else 0; 1D S = var 8 scale "
               "cos^2(pi f scale) / (pi^2 (1 - 4 f^2 scale^2)^2)",
    .flags = NL_FAMILY_FIT,
    .max_dim = 3,
    .validity = "positive definite in 1D, 2D and 3D only (Gneiting 2002, Section 3.1)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
};
