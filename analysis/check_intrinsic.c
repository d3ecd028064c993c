/* The check of an intrinsic model (analysis/check_intrinsic.h). */
#include "check_intrinsic.h"
#include "../core/nl_error.h"

#include <math.h>
#include <string.h>

int nl_check_intrinsic_model(const nl_model *m, int dim, nl_check_intrinsic *out)
{
    int st;
    memset(out, 0, sizeof *out);
    const nl_model *im = nl_model_intrinsic_structure(m);
    if (!nl_model_is_intrinsic(m))
        return NL_ERROR(NL_EINVAL, "%s: not an intrinsic model; expected powvar", nl_model_spec(m));
    if (!im)
        return NL_ERROR(NL_EINVAL, "%s: a sum of an intrinsic model and other structures than nuggets; expected "
                        "powvar, or powvar plus nugget: structures (ordinary kriging takes any such sum)",
                        nl_model_spec(m));
    if ((st = nl_model_check_dim(m, dim)))
        return st;
    out->dim = dim;
    nl_model_param(im, "alpha", &out->alpha), nl_model_param(im, "c", &out->c);
    out->nugget = nl_model_nugget(m);
    out->hurst = out->alpha / 2, out->fractal_dimension = dim + 1 - out->alpha / 2;
    out->spectrum_coef = out->min_spectrum = NAN;
    if (out->alpha < 2) {
        double f[3] = {1, 0, 0}, lo = INFINITY;
        out->spectrum_coef = nl_model_spectrum(m, dim, f);
        for (int i = 0; i <= 60; i++) {
            f[0] = pow(10, -3 + 0.1 * i);
            lo = fmin(lo, nl_model_spectrum(m, dim, f));
        }
        out->min_spectrum = lo;
    }
    out->valid = out->alpha > 0 && out->alpha <= 2 && (out->alpha == 2 || out->min_spectrum > 0);
    return NL_OK;
}
