/* dampedcos: the damped cosine R = var exp(-lambda a) cos(a), a = |t|/scale
 * (Yaglom 1987; RandomFields' RMdampedcos), positive definite in d
 * dimensions iff lambda >= 1 / tan(pi / (2d)) (Zastavnyi 1993): every
 * lambda >= 0 in 1D, lambda >= 1 in 2D, lambda >= sqrt(3) in 3D. */
#include "families_internal.h"
#include "../nl_error.h"

enum { LAMBDA };

static const nl_family_param params[] = {
    /* fits: lambda from 0.01 (a cosine) to 100 (an exponential) */
    {.name = "lambda", .def = NAN, .placeholder = "L", .example = "2", .range = NL_RANGE_NONNEG, .start = 2,
     .fit_lo = 0.01, .fit_hi = 100},
    NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return m->var * exp(-m->p[LAMBDA] * a) * cos(a);
}

/* 1D: the Lorentzian of decay length scale/lambda shifted to +-1/(2 pi
 * scale); 3D: from the 3D Fourier transform of a radial function,
 * S(k) = 1 / (2 pi^2 k) int_0^inf r sin(kr) R(r) dr (angular k, unit
 * scale), and int_0^inf r e^(-l r) sin(w r) dr = 2 l w / (l^2 + w^2)^2:
 *     S(k) = l / (2 pi^2 k) [(k+1) / (l^2 + (k+1)^2)^2 + (k-1) / (l^2 + (k-1)^2)^2],
 * in cycles per unit (2 pi s)^3 S(2 pi s |f|).  2D: none in closed form. */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    double l = m->p[LAMBDA], s = m->scale, k = nl_family_fnorm(m, dim, f);
    if (!(l > 0) || (dim != 1 && dim != 3) || isnan(k))
        return NAN;
    if (dim == 1) {
        double f0 = 1 / (2 * M_PI * s);
        return 0.5 * (nl_spectrum_markov1d(m->var, s / l, k - f0) + nl_spectrum_markov1d(m->var, s / l, k + f0));
    }
    k *= 2 * M_PI * s;
    {
        double p = k + 1, q = k - 1, d1 = l * l + p * p, d2 = l * l + q * q, c = 2 * M_PI * s;
        double sk = k > 1e-6 ? l / (2 * M_PI * M_PI * k) * (p / (d1 * d1) + q / (d2 * d2))
                             /* the limit k -> 0: l / pi^2 d/dk[(k+1)/(l^2+(k+1)^2)^2] at k = 0 */
                             : l / (M_PI * M_PI) * (l * l - 3) / pow(l * l + 1, 3);
        return m->var * c * c * c * sk;
    }
}

static int check_dim(const nl_model *m, int dim)
{
    double lo = dim == 1 ? 0 : 1 / tan(M_PI / (2 * dim));
    /* 1 / tan(pi/6) is sqrt(3) to the last bit or so: allow 4 ulps */
    if (m->p[LAMBDA] < lo * (1 - 1e-15))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: expected lambda >= 1/tan(pi/(2d)) = %.6g "
                        "(Zastavnyi 1993), got lambda=%g", m->spec, dim, lo, m->p[LAMBDA]);
    return NL_OK;
}

const nl_family nl_family_dampedcos = {
    .name = "dampedcos",
    .aliases = "RMdampedcos",
    .formula = "R = var exp(-lambda a) cos(a), a = |t|/scale; 1D S = the Lorentzian of scale/lambda at +-1/(2 pi "
               "scale); 3D S in closed form",
    .flags = NL_FAMILY_FIT,
    .validity = "positive definite in d dimensions iff lambda >= 1/tan(pi/(2d)): lambda >= 0 in 1D, 1 in 2D, "
                "sqrt(3) in 3D (Zastavnyi 1993; Yaglom 1987)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .profile = profile,
    .spectrum = spectrum,
    .check_dim = check_dim,
};
