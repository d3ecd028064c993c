/* The continuous spectral density of any model with a known or
 * transformable R: the family's closed form where it has one, else the
 * Hankel transform of the radial profile (Lewis 1987, eq. (13)), carried
 * through Stam and Fiume's ellipsoidal stretch or the separable product. */
#include "model_internal.h"

#include <math.h>

/* m without its anisotropy and nugget: the radial profile's model. */
static nl_model isotropic_copy(const nl_model *m)
{
    nl_model c = *m;
    c.sep = 0, c.angle = 0, c.cosa = 1, c.sina = 0, c.ratio = 1, c.zratio = 1, c.aniso_given = 0, c.nugget = 0;
    return c;
}

/* The profile's spectrum in dim dimensions at radial frequency k. */
static double profile_density(const nl_model *c, int dim, double k)
{
    double f[3] = {k, 0, 0}, s = nl_model_spectrum(c, dim, f);
    return isfinite(s) ? s : nl_model_spectrum_iso(c, dim, k);
}

/* One structure (no sum).  A linear map A of the lag, R(lag) = R0(|A lag|),
 * has the density S(f) = S0(|A^-T f|) / |det A|; here A = D Q with Q the
 * rotation by -angle and D = diag(1, 1/ratio, 1/zratio), so A^-T f =
 * D^-1 Q f and 1/|det A| = ratio zratio.  Separable: the product of the
 * axes' 1D spectra over R(0)^(dim-1), each axis stretched the same way. */
static double structure_density(const nl_model *m, int dim, const double *f)
{
    double s = nl_model_spectrum(m, dim, f), u, v, w;
    nl_model c;
    if (isfinite(s) || m->nterms || !m->fam->profile || m->fam->acf || (m->fam->flags & NL_FAMILY_INTRINSIC))
        return s;
    c = isotropic_copy(m);
    if (m->fam->isotropic && !m->fam->isotropic(&c))
        return NAN; /* an expression of x, y, z: no radial profile */
    if (dim == 1)
        return profile_density(&c, 1, fabs(f[0]));
    u = m->cosa * f[0] + m->sina * f[1];
    v = (-m->sina * f[0] + m->cosa * f[1]) * m->ratio;
    w = dim == 3 ? f[2] * m->zratio : 0;
    double jac = m->ratio * (dim == 3 ? m->zratio : 1);
    if (m->sep) {
        double r0 = m->fam->profile(&c, 0);
        double p = profile_density(&c, 1, fabs(u)) * profile_density(&c, 1, fabs(v));
        if (dim == 3)
            p *= profile_density(&c, 1, fabs(w)) / r0;
        return jac * p / r0;
    }
    return jac * profile_density(&c, dim, sqrt(u * u + v * v + w * w));
}

double nl_model_spectral_density(const nl_model *m, int dim, const double *f)
{
    double v = 0;
    if (dim < 1 || dim > 3)
        return NAN;
    for (int a = 0; a < dim; a++)
        if (!isfinite(f[a]))
            return NAN;
    if (!m->nterms)
        return structure_density(m, dim, f);
    if (m->fam != &nl_family_sum)
        return NAN; /* a product's density is a convolution */
    for (size_t i = 0; i < m->nterms; i++)
        v += nl_model_spectral_density(m->terms[i], dim, f);
    return v;
}
