/* Model spectra at integer wave vectors (Keller 2001, eq. 13). */
#include "rank1_model.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

double nl_rank1_model_spectrum(const long *k, int s, void *ctx)
{
    const nl_rank1_model_ctx *c = ctx;
    double f[3] = {0, 0, 0}, f2 = 0;
    for (int a = 0; a < s; a++)
        f2 += ((double)k[a] / c->extent) * ((double)k[a] / c->extent);
    for (int a = 0; a < s && a < 3; a++)
        f[a] = (double)k[a] / c->extent;
    double v = nl_model_is_spectral(c->m) ? nl_model_spectrum(c->m, s, f) : nl_model_spectrum_iso(c->m, s, sqrt(f2));
    /* quadrature leaves rounding-level negatives where the spectrum is ~0 */
    if (v < 0 && v > -1e-12 * fabs(nl_model_is_spectral(c->m) ? v : nl_model_spectrum_iso(c->m, s, 0)))
        v = 0;
    return v / pow(c->extent, s);
}

int nl_rank1_model_check(const nl_model *m, int s)
{
    if (nl_model_is_spectral(m)) {
        if (s > 3)
            return NL_ERROR(NL_EINVAL, "%s: spectrum models reach 3 dimensions; in 4 give an isotropic --acf",
                            nl_model_spec(m));
        return NL_OK;
    }
    if (!nl_model_is_isotropic(m))
        return NL_ERROR(NL_EINVAL, "%s: rank-1 lattice synthesis needs a spectrum or an isotropic R (its Hankel "
                        "transform, eq. 13)", nl_model_spec(m));
    return NL_OK;
}

int nl_rank1_model_synthesize(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed, double *f,
                              double *grad, double *imag)
{
    nl_rank1_model_ctx ctx = {m, L->s, extent};
    double *coef;
    int st;
    if ((st = nl_rank1_model_check(m, L->s)))
        return st;
    if (!(extent > 0) || !isfinite(extent))
        return NL_ERROR(NL_EINVAL, "extent: expected a positive finite length, got %g", extent);
    if (!(coef = malloc(2 * L->N * sizeof *coef)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu coefficients", L->N);
    if (!(st = nl_rank1_coefficients(L, nl_rank1_model_spectrum, &ctx, seed, coef)))
        st = nl_rank1_synthesize(L, coef, extent, f, grad, imag);
    free(coef);
    return st;
}
