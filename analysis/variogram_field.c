/* Empirical variogram of a field: every pair of samples, grouped by their
 * integer offset (each offset once, in the half-space o > 0). */
#include "variogram.h"
#include "variogram_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

/* Sum over the sample pairs at offset o of (z - z')^2 (Matheron) or
 * |z - z'|^(1/2) (Cressie); *count receives their number. */
static double offset_sum(const nl_field *f, const long *o, int cressie, double *count)
{
    size_t n0 = f->n[0], n1 = f->n[1], n2 = f->n[2];
    size_t a0 = o[0] < 0 ? (size_t)-o[0] : 0, b0 = o[0] > 0 ? n0 - (size_t)o[0] : n0;
    size_t a1 = o[1] < 0 ? (size_t)-o[1] : 0, b1 = o[1] > 0 ? n1 - (size_t)o[1] : n1;
    size_t b2 = n2 - (size_t)o[2];
    long shift = o[0] + o[1] * (long)n0 + o[2] * (long)(n0 * n1);
    double s = 0;
    for (size_t k = 0; k < b2; k++)
        for (size_t j = a1; j < b1; j++) {
            const double *z = f->data + (k * n1 + j) * n0;
            for (size_t i = a0; i < b0; i++) {
                double d = z[i + shift] - z[i];
                s += cressie ? sqrt(fabs(d)) : d * d;
            }
        }
    *count = (double)(b2 * (b1 - a1) * (b0 - a0));
    return s;
}

/* Offset number t of the box [-m0, m0] x [-m1, m1] x [0, m2] into o. */
static void offset_of(size_t t, const long *m, long *o)
{
    size_t w0 = (size_t)(2 * m[0] + 1), w1 = (size_t)(2 * m[1] + 1);
    o[0] = (long)(t % w0) - m[0], o[1] = (long)(t / w0 % w1) - m[1], o[2] = (long)(t / w0 / w1);
}

static int positive(const long *o) { return o[2] > 0 || (o[2] == 0 && (o[1] > 0 || (o[1] == 0 && o[0] > 0))); }

int nl_variogram_field(const nl_field *f, const nl_variogram_options *o, nl_variogram **out)
{
    nl_vg_acc a;
    double diag = 0, *sums, *per;
    long m[3];
    size_t bad, nt;
    int st;
    *out = NULL;
    if (!f || f->count < 2)
        return NL_ERROR(NL_EINVAL, "variogram: expected a field of 2 samples at least, got %zu", f ? f->count : 0);
    if (nl_field_check_finite(f, INFINITY, &bad))
        return NL_ERROR(NL_EINVAL, "variogram: sample %zu of the field is %g; expected finite samples", bad, f->data[bad]);
    if ((st = nl_vg_check_values(f->data, f->count, "the field's samples")))
        return st;
    for (int k = 0; k < f->dim; k++)
        diag += ((double)f->n[k] - 1) * f->h[k] * ((double)f->n[k] - 1) * f->h[k];
    if ((st = nl_vg_check_options(o)) || (st = nl_vg_bins(o, sqrt(diag), &a)))
        return st;
    if (o->drift != NL_VARIOGRAM_DRIFT_CONSTANT)
        return NL_ERROR(NL_EINVAL, "variogram: drift: a field's residual variogram is not supported; expected points "
                        "(sample the field first), or no drift");
    for (int k = 0; k < 3; k++)
        m[k] = k < f->dim ? (long)fmin((double)f->n[k] - 1, ceil(a.cutoff / f->h[k])) : 0;
    nt = (size_t)(2 * m[0] + 1) * (size_t)(2 * m[1] + 1) * (size_t)(m[2] + 1);
    if ((st = nl_vg_sums_alloc(a.nb, &sums)))
        return st;
    if (!(per = calloc(2 * nt, sizeof *per))) {
        free(sums);
        return NL_ERROR(NL_ENOMEM, "variogram: out of memory for %zu offsets", nt);
    }
#pragma omp parallel for schedule(dynamic, 16) if (f->count * nt > 1000000)
    for (size_t t = 0; t < nt; t++) {
        long ot[3];
        offset_of(t, m, ot);
        if (positive(ot))
            per[2 * t] = offset_sum(f, ot, a.cressie, &per[2 * t + 1]);
    }
    for (size_t t = 0; t < nt; t++) { /* in offset order: independent of the threads */
        long ot[3];
        offset_of(t, m, ot);
        double dx[3] = {(double)ot[0] * f->h[0], (double)ot[1] * f->h[1], (double)ot[2] * f->h[2]};
        double d = sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
        if (!positive(ot) || !(per[2 * t + 1] > 0))
            continue;
        long k = nl_vg_bin(&a, d, dx);
        if (k >= 0) {
            double *s = sums + 3 * (size_t)k;
            s[0] += d * per[2 * t + 1], s[1] += per[2 * t], s[2] += per[2 * t + 1];
        }
    }
    free(per);
    st = nl_vg_finish(&a, sums, out);
    free(sums);
    return st;
}
