/* Indicator kriging (Journel 1983) of P(Z <= t_k) with GSLIB's order-
 * relation correction (Deutsch and Journel 1998, section IV.1.9, ik3d's
 * ordrel). */
#include "krige_flavours.h"
#include "krige_flavours_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NK_MAX 256

size_t nl_krige_order_relations(size_t count, size_t nk, double *p)
{
    size_t changed = 0;
    double up[NK_MAX], down[NK_MAX];
    if (nk == 0 || nk > NK_MAX)
        return 0;
    for (size_t t = 0; t < count; t++) {
        double *q = p + t * nk;
        int moved = 0;
        for (size_t j = 0; j < nk; j++) { /* clip, then the upward pass */
            double c = fmin(fmax(q[j], 0), 1);
            up[j] = j ? fmax(up[j - 1], c) : c;
            down[j] = c;
        }
        for (size_t j = nk - 1; j-- > 0;) /* the downward pass */
            down[j] = fmin(down[j + 1], down[j]);
        for (size_t j = 0; j < nk; j++) {
            double c = 0.5 * (up[j] + down[j]);
            moved |= fabs(c - q[j]) > 1e-12;
            q[j] = c;
        }
        changed += (size_t)moved;
    }
    return changed;
}

static int check(size_t nk, const double *thr, size_t n, const double *x, size_t count,
                 const nl_krige_local_options *o)
{
    if (o->drift == NL_DRIFT_NONE)
        return NL_ERROR(NL_EINVAL, "indicator kriging: expected an unknown mean (ordinary or universal), got simple "
                        "kriging: each indicator has its own mean");
    if (nk == 0 || nk > NK_MAX)
        return NL_ERROR(NL_EINVAL, "indicator kriging: %zu thresholds; expected 1 to %d", nk, NK_MAX);
    for (size_t j = 0; j < nk; j++)
        if (!isfinite(thr[j]) || (j && !(thr[j] > thr[j - 1])))
            return NL_ERROR(NL_EINVAL, "indicator kriging: threshold %zu is %g; expected finite thresholds in "
                            "increasing order", j + 1, thr[j]);
    if (!x && count != n)
        return NL_ERROR(NL_EINVAL, "indicator kriging: cross-validation at %zu locations; expected the %zu data",
                        count, n);
    return NL_OK;
}

/* Threshold j: its indicator plan, then the estimates into column j of raw. */
static int one_threshold(const nl_model *m, double t, int dim, size_t n, const double *pts, const double *val,
                         const nl_krige_local_options *o, const nl_kf_support *s0, const nl_krige_block *b,
                         size_t count, const double *x, nl_kf_out *out, double *ind)
{
    nl_krige_local *k;
    nl_kf_support s = *s0;
    int st;
    for (size_t i = 0; i < n; i++)
        ind[i] = val[i] <= t ? 1.0 : 0.0;
    if ((st = nl_krige_local_alloc(m, dim, n, pts, ind, o, &k)))
        return st;
    if (b) /* the block-to-block covariance of this threshold's model */
        st = nl_kf_support_init(k, b, &s);
    else
        s.cbb = k->r0;
    if (!st) {
        st = nl_kf_run(k, &s, count, x, x == NULL, out);
        if (b)
            nl_kf_support_free(&s);
    }
    nl_krige_local_free(k);
    return st;
}

int nl_krige_indicator(const nl_model *const *m, size_t nk, const double *thr, int dim, size_t n, const double *pts,
                       const double *val, const nl_krige_local_options *o, const nl_krige_block *b, size_t count,
                       const double *x, double *raw, double *cdf, size_t *ncorrected)
{
    int st = check(nk, thr, n, x, count, o);
    if (st)
        return st;
    double one = 1, zero[3] = {0, 0, 0};
    nl_kf_support pt = {.nd = 1, .d = zero, .w = &one};
    nl_kf_out *out = malloc((count ? count : 1) * sizeof *out);
    double *ind = malloc((n ? n : 1) * sizeof *ind);
    if (!out || !ind) {
        free(out), free(ind);
        return NL_ERROR(NL_ENOMEM, "indicator kriging: out of memory for %zu locations", count);
    }
    for (size_t j = 0; j < nk && !st; j++) {
        st = one_threshold(m[j], thr[j], dim, n, pts, val, o, &pt, b, count, x, out, ind);
        for (size_t t = 0; t < count && !st; t++) {
            cdf[t * nk + j] = out[t].est;
            if (raw)
                raw[t * nk + j] = out[t].est;
        }
    }
    free(out), free(ind);
    if (st)
        return st;
    size_t c = nl_krige_order_relations(count, nk, cdf);
    if (ncorrected)
        *ncorrected = c;
    return NL_OK;
}
