/* The band of frequencies where a model's spectrum may be positive, from
 * its families' NL_ROLE_BAND parameters (core/family.h). */
#include "model.h"
#include "model_internal.h"
#include "nl_error.h"

#include <math.h>

/* One structure: its family's band parameters (the lower edge first), or
 * the whole axis for a family without. */
static void structure_band(const nl_model *m, double *lo, double *hi)
{
    int first = nl_family_role_index(m->fam, NL_ROLE_BAND);
    *lo = 0, *hi = INFINITY;
    if (first < 0)
        return;
    *lo = m->p[first];
    for (size_t k = (size_t)first + 1; k < m->fam->nparams; k++)
        if (m->fam->params[k].role == NL_ROLE_BAND) {
            *hi = m->p[k];
            break;
        }
}

static void band(const nl_model *m, double *lo, double *hi)
{
    if (!m->nterms) {
        structure_band(m, lo, hi);
        return;
    }
    if (m->fam == &nl_family_product) {
        /* S of a product is the convolution of its factors' spectra: it may
         * reach 0 (two symmetric bands overlap there after a shift) and
         * up to the sum of their upper edges */
        *lo = 0, *hi = 0;
        for (size_t i = 0; i < m->nterms; i++) {
            double a, b;
            band(m->terms[i], &a, &b);
            *hi += b;
        }
        return;
    }
    /* a sum: S is positive where any term's is */
    *lo = INFINITY, *hi = 0;
    for (size_t i = 0; i < m->nterms; i++) {
        double a, b;
        band(m->terms[i], &a, &b);
        *lo = fmin(*lo, a), *hi = fmax(*hi, b);
    }
}

int nl_model_band(const nl_model *m, int dim, double *fmin, double *fmax)
{
    double lo, hi;
    if (!m || !fmin || !fmax)
        return NL_ERROR(NL_EINVAL, "model band: expected a model and two results, got NULL");
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "model band: expected dim 1, 2 or 3, got %d", dim);
    band(m, &lo, &hi);
    *fmin = lo, *fmax = hi;
    return NL_OK;
}
