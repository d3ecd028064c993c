/* Midpoint displacement (Fournier, Fussell and Carpenter 1982) expressed as
 * a subdivision plan with nearest-neighbour coefficients. */
#include "subdiv.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

/* Semivariogram of fBm: gamma(h) = sigma2 |h|^(2H) / 2. */
static double gam(double sigma2, double H, double dx, double dy)
{
    return 0.5 * sigma2 * pow(hypot(dx, dy), 2 * H);
}

int nl_subdiv_coeffs_midpoint(int dim, int levels, double spacing0, double H, double sigma2, double vscale,
                           nl_subdiv_coeffs **out)
{
    static const int classes2[] = {NL_SUBDIV_FACE, NL_SUBDIV_EDGE_X, NL_SUBDIV_EDGE_Y};
    nl_subdiv_coeffs *c;
    *out = NULL;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "midpoint: expected dimension 1 or 2, got %d", dim);
    if (!(H > 0 && H < 1))
        return NL_ERROR(NL_EINVAL, "midpoint: expected a Hurst exponent 0 < H < 1, got %g", H);
    if (levels < 1 || levels > 40)
        return NL_ERROR(NL_EINVAL, "midpoint: levels: expected 1 to 40, got %d", levels);
    if (!(spacing0 > 0) || !isfinite(spacing0) || !(sigma2 > 0) || !isfinite(sigma2) || !(vscale > 0) ||
        !isfinite(vscale))
        return NL_ERROR(NL_EINVAL, "midpoint: expected a positive finite spacing, variance and variance-scale, got "
                        "%g, %g and %g", spacing0, sigma2, vscale);
    c = calloc(1, sizeof *c);
    if (!c || !(c->level = calloc((size_t)levels, sizeof *c->level))) {
        free(c);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    c->dim = dim;
    c->levels = levels;
    c->spacing0 = spacing0;
    c->r0 = 0.5 * sigma2 * pow(spacing0, 2 * H);
    for (int k = 0; k < levels; k++) {
        nl_subdiv_level *l = &c->level[k];
        double s = ldexp(spacing0, -k);
        l->level = k;
        l->spacing = s;
        l->N = 1;
        l->reach = 1;
        l->nclass = dim == 1 ? 1 : 3;
        for (int j = 0; j < l->nclass; j++) {
            nl_subdiv_class *cl = &l->cls[j];
            /* 2x2 block (r, c) in {0, 1}^2, or the pair k in {0, 1} */
            double px[4], py[4], tx, ty, v = 0;
            int cls = dim == 1 ? NL_SUBDIV_MID : classes2[j];
            cl->cls = cls;
            cl->n = dim == 1 ? 2 : 4;
            cl->a = calloc(cl->n, sizeof *cl->a);
            if (!cl->a) {
                nl_subdiv_coeffs_free(c);
                return NL_ERROR(NL_ENOMEM, "out of memory");
            }
            for (size_t i = 0; i < cl->n; i++) {
                px[i] = dim == 1 ? (double)i * s : (double)(i % 2) * s;
                py[i] = dim == 1 ? 0 : (double)(i / 2) * s;
            }
            tx = cls == NL_SUBDIV_EDGE_Y ? 0 : 0.5 * s;
            ty = dim == 1 || cls == NL_SUBDIV_EDGE_X ? 0 : 0.5 * s;
            if (cls == NL_SUBDIV_MID)
                cl->a[0] = cl->a[1] = 0.5;
            else if (cls == NL_SUBDIV_FACE)
                cl->a[0] = cl->a[1] = cl->a[2] = cl->a[3] = 0.25;
            else if (cls == NL_SUBDIV_EDGE_X)
                cl->a[0] = cl->a[1] = 0.5;
            else
                cl->a[0] = cl->a[2] = 0.5;
            for (size_t i = 0; i < cl->n; i++) {
                v += 2 * cl->a[i] * gam(sigma2, H, tx - px[i], ty - py[i]);
                for (size_t q = 0; q < cl->n; q++)
                    v -= cl->a[i] * cl->a[q] * gam(sigma2, H, px[i] - px[q], py[i] - py[q]);
            }
            v *= pow(vscale, k);
            if (!isfinite(v) || !isfinite(c->r0)) {
                nl_subdiv_coeffs_free(c);
                return NL_ERROR(NL_EINVAL, "midpoint: the variance of level %d is %g (variance-scale %g per level, "
                                "coarse spacing %g, H %g); expected a finite number: lower the variance-scale, the "
                                "levels or the spacing", k, isfinite(v) ? 0.5 * sigma2 * pow(spacing0, 2 * H) : v,
                                vscale, spacing0, H);
            }
            cl->variance = cl->raw_variance = v;
            cl->condition = 1;
            cl->min_eigenvalue = NAN;
        }
    }
    *out = c;
    return NL_OK;
}
