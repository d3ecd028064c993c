/* Model spectra at integer wave vectors. */
#include "rank1_spec.h"
#include "../core/nl_error.h"

#include <math.h>

double cli_rank1_model_spectrum(const long *k, int s, void *ctx)
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

int cli_rank1_model_check(const nl_model *m, int s)
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
