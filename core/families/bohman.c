/* bohman: the Bohman correlation of support `scale`, with a = |t|/scale,
 * R = var ((1 - a) cos(pi a) + sin(pi a) / pi) for a < 1, 0 beyond
 * (Bohman 1960; RandomFields' RMbohman): the autocorrelation of the half
 * cosine cos(pi x) on |x| < 1/2, so positive definite in 1D.  Not in 2D
 * nor 3D: its 1D spectrum below is 0 at f scale = 3/2, 5/2, ... and
 * positive between, so not monotone, and the 3D spectrum -S1'(f) / (2 pi f)
 * of a radial R is negative where S1 rises (at f scale = 1.75 it is -2.3e-3
 * of its peak); the 2D Hankel transform is negative too (-1.9e-3 of its
 * peak at f scale = 1.5; tests/test_families_lit.c measures both). */
#include "families_internal.h"
#include "../nl_error.h"

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

static int check_dim(const nl_model *m, int dim)
{
    if (dim > 1)
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: the Bohman model is valid in 1D only (its "
                        "%dD spectrum is negative at some frequencies)", m->spec, dim, dim);
    return NL_OK;
}

const nl_family nl_family_bohman = {
    .name = "bohman",
    .aliases = "RMbohman",
    .formula = "R = var ((1-a) cos(pi a) + sin(pi a)/pi) for a = |t|/scale < 1, else 0; 1D S = var 8 scale "
               "cos^2(pi f scale) / (pi^2 (1 - 4 f^2 scale^2)^2)",
    .flags = NL_FAMILY_FIT,
    .max_dim = 1,
    .validity = "positive definite in 1D only (the autocorrelation of a half cosine; its 2D and 3D spectra are "
                "negative at some frequencies)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
    .check_dim = check_dim,
};
