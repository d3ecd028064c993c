/* Evaluation of R(lag) and S(f) through the family descriptors, and Stam
 * and Fiume's ellipsoidal anisotropy. */
#include "model_internal.h"
#include "nl_error.h"

#include <math.h>

static double acf_continuous(const nl_model *m, int dim, const double *lag);

/* The nugget is white noise: it adds to R at lag 0 exactly and nowhere else. */
double nl_model_acf(const nl_model *m, int dim, const double *lag)
{
    double v;
    if (m->nterms)
        return nl_model_composite_acf(m, dim, lag);
    v = acf_continuous(m, dim, lag);
    if (m->nugget != 0) {
        int zero = 1;
        for (int a = 0; a < dim; a++)
            zero &= lag[a] == 0;
        if (zero)
            v += m->nugget;
    }
    return v;
}

static double acf_continuous(const nl_model *m, int dim, const double *lag)
{
    const nl_family *f = m->fam;
    double u, v, w, r;
    if (f->acf)
        return f->acf(m, dim, lag);
    if (!f->profile)
        return NAN;
    if (dim == 1)
        return f->profile(m, lag[0]);
    /* Stam and Fiume's ellipsoid: rotate by -angle, then shrink the y and z
     * axes by their length ratios. */
    u = m->cosa * lag[0] + m->sina * lag[1];
    v = (-m->sina * lag[0] + m->cosa * lag[1]) / m->ratio;
    w = dim == 3 ? lag[2] / m->zratio : 0;
    if (m->sep) {
        double r0 = f->profile(m, 0), p = f->profile(m, u) * f->profile(m, v);
        if (dim == 3)
            p *= f->profile(m, w) / r0;
        return p / r0;
    }
    r = sqrt(u * u + v * v + w * w);
    if (f->acf_stretched)
        return f->acf_stretched(m, u, v, w, r);
    return f->profile(m, r);
}

double nl_model_spectrum(const nl_model *m, int dim, const double *f)
{
    return m->fam->spectrum ? m->fam->spectrum(m, dim, f) : NAN;
}

double nl_model_acf_d2(const nl_model *m, double t)
{
    return m->fam->acf_d2 ? m->fam->acf_d2(m, t) : NAN;
}

int nl_model_is_isotropic(const nl_model *m)
{
    if (m->sep || m->angle != 0 || m->ratio != 1 || m->zratio != 1)
        return 0;
    return m->fam->isotropic ? m->fam->isotropic(m) : 1;
}

double nl_model_variogram(const nl_model *m, int dim, const double *lag)
{
    const double zero[3] = {0, 0, 0};
    return nl_model_acf(m, dim, zero) - nl_model_acf(m, dim, lag);
}

/* A sum with an intrinsic term is intrinsic (products refuse them). */
int nl_model_is_intrinsic(const nl_model *m)
{
    for (size_t i = 0; i < m->nterms; i++)
        if (nl_model_is_intrinsic(m->terms[i]))
            return 1;
    return (m->fam->flags & NL_FAMILY_INTRINSIC) != 0;
}

int nl_model_check_stationary(const nl_model *m, const char *what)
{
    const nl_model *s = m;
    if (!nl_model_is_intrinsic(m))
        return NL_OK;
    for (size_t i = 0; i < nl_model_structures(m); i++)
        if (nl_model_is_intrinsic(nl_model_structure(m, i)))
            s = nl_model_structure(m, i);
    return NL_ERROR(NL_EINVAL, "%s: %s needs a covariance; %s is intrinsic (no covariance): use synth intrinsic "
                    "or ordinary kriging (krige)", m->spec, what, s->fam->name);
}
