/* Circulant embedding: periodic FFT synthesis on an embedding grid, cropped. */
#include "circulant_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nl_synth_circulant_plan {
    int dim;                 /* 1..3 */
    size_t n[3];             /* output grid */
    double h[3];             /* spacing */
    nl_synth_fft_plan *fft;     /* periodic synthesis on the embedding */
    size_t m[3];             /* embedding size */
    const nl_model *model;   /* while planning only (not kept) */
    nl_synth_circulant_info info;
};

/* Smallest even 2,3,5-smooth number >= x. */
static size_t smooth_even(size_t x)
{
    for (size_t m = x + (x % 2);; m += 2) {
        size_t r = m;
        while (r % 2 == 0) r /= 2;
        while (r % 3 == 0) r /= 3;
        while (r % 5 == 0) r /= 5;
        if (r == 1)
            return m;
    }
}

size_t nl_synth_circulant_size(size_t n) { return smooth_even(2 * (n > 1 ? n - 1 : 1)); }

double nl_synth_circulant_loss(const nl_model *m, int dim, double variance)
{
    double zero[3] = {0, 0, 0}, r0;
    if (!nl_model_is_spectral(m))
        return 0;
    r0 = nl_model_acf(m, dim, zero);
    return isfinite(r0) && r0 > 0 ? 1 - variance / r0 : NAN;
}

int nl_synth_circulant_refuse(const nl_model *m, const nl_synth_circulant_info *info, const size_t *mm)
{
    return NL_ERROR(NL_ENOTPD,
                    "%s: cannot be embedded: the smallest eigenvalue is %.3g (largest %.3g) at embedding "
                    "%zux%zux%zu after %d doublings; zeroing the negatives would change the covariance "
                    "by %.2g of R(0) (use --clamp to accept)",
                    nl_model_spec(m), info->min_eigenvalue, info->max_eigenvalue, mm[0], mm[1], mm[2],
                    info->doublings, info->clamp_error);
}

void nl_synth_circulant_plan_free(nl_synth_circulant_plan *p)
{
    if (!p)
        return;
    nl_synth_fft_plan_free(p->fft);
    free(p);
}

int nl_synth_circulant_embed(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                             int max_factor, nl_synth_circulant_try_fn *try_plan, void *ctx,
                             nl_synth_circulant_info *info)
{
    size_t mm[3] = {1, 1, 1};
    double cell = 1;
    int st;
    memset(info, 0, sizeof *info);
    for (int a = 0; a < dim; a++) {
        cell *= h ? h[a] : 1;
        mm[a] = nl_synth_circulant_size(n[a]);
    }
    for (;;) {
        nl_synth_fft_info fi;
        if ((st = try_plan(ctx, mm, &fi)))
            return st;
        info->min_eigenvalue = fi.min_lambda / cell;
        info->max_eigenvalue = fi.max_lambda / cell;
        info->clamp_error = fi.clamp_error;
        memcpy(info->m, mm, sizeof mm);
        info->variance_loss = nl_synth_circulant_loss(m, dim, fi.variance);
        if (fi.clamp_error <= NL_SYNTH_FFT_CLAMP_TOL)
            return NL_OK;
        int grow = 1;
        for (int a = 0; a < dim; a++)
            if (2 * mm[a] > (size_t)max_factor * n[a])
                grow = 0;
        if (!grow)
            return flags & NL_SYNTH_FFT_CLAMP ? NL_OK : nl_synth_circulant_refuse(m, info, mm);
        for (int a = 0; a < dim; a++)
            mm[a] *= 2;
        info->doublings++;
    }
}

/* The one-process plan of an embedding (nl_synth_circulant_try_fn), the
 * previous one freed. */
static int try_serial(void *ctx, const size_t *mm, nl_synth_fft_info *fi)
{
    nl_synth_circulant_plan *p = ctx;
    int st;
    nl_synth_fft_plan_free(p->fft);
    p->fft = NULL;
    if ((st = nl_synth_fft_plan_alloc(p->model, p->dim, mm, p->h, NL_SYNTH_FFT_CLAMP, &p->fft)))
        return st;
    nl_synth_fft_plan_info(p->fft, fi);
    memcpy(p->m, mm, sizeof p->m);
    return NL_OK;
}

int nl_synth_circulant_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                               int max_factor, nl_synth_circulant_plan **out)
{
    nl_synth_circulant_plan *p;
    int st;
    *out = NULL;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    if ((st = nl_model_check_stationary(m, "circulant embedding")))
        return st;
    p = calloc(1, sizeof *p);
    if (!p)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->dim = dim;
    p->model = m;
    for (int a = 0; a < 3; a++) {
        p->n[a] = a < dim ? n[a] : 1;
        p->h[a] = a < dim && h ? h[a] : 1;
        p->m[a] = 1;
    }
    st = nl_synth_circulant_embed(m, dim, p->n, p->h, flags, max_factor, try_serial, p, &p->info);
    p->model = NULL;
    if (st) {
        nl_synth_circulant_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

void nl_synth_circulant_plan_info(const nl_synth_circulant_plan *p, nl_synth_circulant_info *info) { *info = p->info; }

int nl_synth_circulant_execute(const nl_synth_circulant_plan *p, uint64_t seed, nl_field *out)
{
    nl_field *w;
    int st;
    if (out->dim != p->dim || out->n[0] != p->n[0] || out->n[1] != p->n[1] || out->n[2] != p->n[2])
        return NL_ERROR(NL_EINVAL, "circulant: the output field does not match the plan's grid");
    /* this call's own embedding-size workspace: the plan is only read */
    if (!(w = nl_field_alloc(p->dim, p->m, p->h, &st)))
        return st;
    if ((st = nl_synth_fft_execute(p->fft, seed, w))) {
        nl_field_free(w);
        return st;
    }
    for (size_t k = 0; k < p->n[2]; k++)
        for (size_t j = 0; j < p->n[1]; j++)
            memcpy(out->data + (k * p->n[1] + j) * p->n[0], w->data + (k * w->n[1] + j) * w->n[0],
                   p->n[0] * sizeof *out->data);
    nl_field_free(w);
    return NL_OK;
}
