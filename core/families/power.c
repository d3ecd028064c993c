/* power: a power-law spectrum S = c |f|^-d on a band of frequencies
 * (Lewis 1987's fractal model); its R is computed by quadrature
 * (core/model_hankel.c, eq. (13)).  var is R(0) in every dimension: c is
 * var over the integral of |f|^-d over the band's shell in dim dimensions
 * (power_norm), so that the integral of S over all frequencies is var.
 * A grid holds only the frequencies |f| >= 1/(n h): at the default fmin,
 * 64^3 samples of d=3.5 hold 26% of var (the sum of S over the grid's
 * frequencies; six fields measured 0.25), 256^2 of d=2.5 hold 59%, and
 * 65536 samples of d=1 all of it. */
#include "families_internal.h"
#include "../nl_error.h"

enum { D, FMIN, FMAX };

static const nl_family_param params[] = {
    {.name = "d", .def = NAN, .placeholder = "D", .example = "2.5"},
    {.name = "fmin", .role = NL_ROLE_BAND, .def = 1.0 / 1024, .def_text = "1/1024"},
    {.name = "fmax", .role = NL_ROLE_BAND, .def = 0.5},
    NL_PARAM_VAR,
};

static int check(const nl_model *m)
{
    double fmin = m->p[FMIN], fmax = m->p[FMAX];
    if (!(fmin >= 0) || !(fmax > fmin))
        return NL_ERROR(NL_EINVAL, "%s: expected 0 <= fmin < fmax, got fmin=%g, fmax=%g", m->fam->name, fmin, fmax);
    if (fmin == 0 && m->p[D] >= 1)
        return NL_ERROR(NL_EINVAL, "%s: fmin=0 with d=%g: the variance diverges; expected fmin > 0", m->fam->name,
                        m->p[D]);
    return NL_OK;
}

static double acf(const nl_model *m, int dim, const double *lag)
{
    double r2 = 0;
    for (int a = 0; a < dim; a++)
        r2 += lag[a] * lag[a];
    return nl_model_power_acf(m, dim, sqrt(r2));
}

/* Integral of k^-d over fmin <= |k| <= fmax in `dim` dimensions. */
static double power_norm(const nl_model *m, int dim)
{
    static const double shell[] = {0, 2.0, 2 * M_PI, 4 * M_PI};
    double fmin = m->p[FMIN], fmax = m->p[FMAX];
    double e = dim - 1 - m->p[D];  /* integrand k^e dk over the radius */
    double radial;
    if (fabs(e + 1) < 1e-12)
        radial = log(fmax / fmin);
    else
        radial = (pow(fmax, e + 1) - pow(fmin, e + 1)) / (e + 1);
    return shell[dim] * radial;
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    double k2 = 0, k;
    for (int a = 0; a < dim; a++)
        k2 += f[a] * f[a];
    k = sqrt(k2);
    if (k < m->p[FMIN] || k > m->p[FMAX] || k == 0)
        return 0.0;
    return m->var / power_norm(m, dim) * pow(k, -m->p[D]);
}

const nl_family nl_family_power = {
    .name = "power",
    .aliases = "",
    .formula = "S = c |f|^-d for fmin <= |f| <= fmax (0 elsewhere), c such that the integral of S over that band in "
               "the field's dimension is var: var is R(0), the variance of the field in 1D, 2D and 3D alike (c depends "
               "on the dimension); a grid of n samples at spacing h holds no frequency 0 < |f| < 1/(n h), so where fmin "
               "is below that its variance falls short of var by the integral of S there",
    .flags = NL_FAMILY_SPECTRAL,
    .validity = "a non-negative density in every dimension: valid wherever its band is",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .check = check,
    .acf = acf,
    .spectrum = spectrum,
};
