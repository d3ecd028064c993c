/* Periodic FFT synthesis: filter white noise by the square root of the
 * spectrum (Lewis 1987, "Fourier synthesis"; Wiener-Khinchine, eq. (2)). */
#include "fft_internal.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../core/wk.h"

#include <complex.h>
#include <float.h>
#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct nl_synth_fft_plan {
    int dim;            /* 1..3 */
    size_t n[3];        /* grid size */
    double h[3];        /* grid spacing */
    size_t count;       /* samples */
    size_t half;        /* r2c coefficients: count / n0 * (n0/2 + 1) */
    double *amp;        /* sqrt(lambda_k / (2 count)) on the half grid (nl_alloc) */
    fftw_plan inv;      /* odd n0: the c2r from a half-grid buffer */
    /* even n0, the transform in the field (execute_in_field): the c2c along
     * the outer axes of columns 0..n0/2-1 in place and of column n0/2 in a
     * side buffer, then the c2r of ROW_BLOCK rows (and of the rest) */
    fftw_plan cols, nyq, rows, rest;
    nl_synth_fft_info info;
};

/* Rows per c2r of the second stage: 8 rows of doubles start on the field's
 * 64-byte alignment, as FFTW's new-array execute requires. */
enum { ROW_BLOCK = 8 };

void nl_synth_fft_plan_free(nl_synth_fft_plan *p)
{
    if (!p)
        return;
    fftw_plan q[5] = {p->inv, p->cols, p->nyq, p->rows, p->rest};
    for (int k = 0; k < 5; k++)
        if (q[k])
            fftw_destroy_plan(q[k]);
    nl_free(p->amp);
    free(p);
}

/* The outer axes (1..dim-1, slowest first) as FFTW guru dimensions, with
 * stride `unit` complex numbers along axis 0's neighbour. */
static int outer_dims(const nl_synth_fft_plan *p, int unit, fftw_iodim *d)
{
    int r = p->dim - 1, stride = unit;
    for (int a = 1; a < p->dim; a++) {
        d[r - a].n = (int)p->n[a], d[r - a].is = d[r - a].os = stride;
        stride *= (int)p->n[a];
    }
    return r;
}

/* The plans of execute_in_field, made on scratch arrays. */
static int plan_in_field(nl_synth_fft_plan *p, fftw_complex *x, fftw_complex *z, fftw_complex *t, double *y)
{
    const int m = (int)(p->n[0] / 2), h0 = m + 1, n0 = (int)p->n[0], nrows = (int)(p->count / p->n[0]);
    fftw_iodim d[2], many = {m, 1, 1};
    int r = outer_dims(p, m, d);
    if (r > 0) {
        p->cols = fftw_plan_guru_dft(r, d, 1, &many, x, x, FFTW_BACKWARD, nl_fftw_flags(p->count));
        outer_dims(p, 1, d);
        p->nyq = fftw_plan_guru_dft(r, d, 0, NULL, z, z, FFTW_BACKWARD, nl_fftw_flags((size_t)nrows));
        if (!p->cols || !p->nyq)
            return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", p->dim);
    }
    /* one thread each: the blocks run on the OpenMP threads */
    p->rows = fftw_plan_many_dft_c2r(1, &n0, ROW_BLOCK, t, NULL, 1, h0, y, NULL, 1, n0, nl_fftw_flags(1));
    if (nrows % ROW_BLOCK)
        p->rest = fftw_plan_many_dft_c2r(1, &n0, nrows % ROW_BLOCK, t, NULL, 1, h0, y, NULL, 1, n0, nl_fftw_flags(1));
    if (!p->rows || (nrows % ROW_BLOCK && !p->rest))
        return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", p->dim);
    return NL_OK;
}

static int make_fftw_plans(nl_synth_fft_plan *p)
{
    int dims[3];
    const size_t nrows = p->count / p->n[0], h0 = p->n[0] / 2 + 1;
    double *x = nl_alloc(p->count * sizeof *x), *y = nl_alloc(ROW_BLOCK * p->n[0] * sizeof *y);
    fftw_complex *c = nl_alloc((p->n[0] % 2 ? p->half : nrows) * sizeof *c), *t = nl_alloc(ROW_BLOCK * h0 * sizeof *t);
    int st = NL_OK;
    for (int a = 0; a < p->dim; a++)
        dims[a] = (int)p->n[p->dim - 1 - a];
    if (!x || !c || !y || !t)
        st = NL_ERROR(NL_ENOMEM, "out of memory for the FFT plan");
    if (!st && p->n[0] % 2) {
        p->inv = fftw_plan_dft_c2r(p->dim, dims, c, x, nl_fftw_flags(p->count));
        if (!p->inv)
            st = NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", p->dim);
    } else if (!st) {
        st = plan_in_field(p, (fftw_complex *)x, c, t, y);
    }
    nl_free(x), nl_free(y), nl_free(c), nl_free(t);
    return st;
}

/* Plan from the spectrum on the r2c half grid (core/wk.h), which the plan
 * takes over as its amplitude array.  Statistics are over the full grid:
 * columns 0 < i < n0/2 stand for i and n0 - i (evenness), so count twice. */
static int plan_from_half(const char *name, int dim, const size_t *n, const double *h, double *S, unsigned flags,
                          nl_synth_fft_plan **out)
{
    nl_synth_fft_plan *p;
    double cell = 1, neg = 0, lmin = INFINITY, lmax = -INFINITY, sum = 0;
    size_t h0, rows;
    int st = NL_OK;
    p = calloc(1, sizeof *p);
    if (!p) {
        nl_free(S);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    p->dim = dim;
    p->count = 1;
    for (int a = 0; a < 3; a++) {
        p->n[a] = a < dim ? n[a] : 1;
        p->h[a] = a < dim && h ? h[a] : 1;
        p->count *= p->n[a];
        cell *= p->h[a];
    }
    h0 = p->n[0] / 2 + 1;
    rows = p->count / p->n[0];
    p->half = rows * h0;
    p->amp = S;
    for (size_t k = 0; k < p->half; k++)
        if (!isfinite(S[k] / cell)) {
            st = NL_ERROR(NL_EINVAL, "%s: the sampled spectrum is not finite (%g) at frequency index (%zu, %zu, %zu): "
                          "the model's values are too large for this grid", name, S[k] / cell, k % h0,
                          k / h0 % p->n[1], k / h0 / p->n[1]);
            nl_synth_fft_plan_free(p);
            return st;
        }
    for (size_t r = 0; r < rows; r++)
        for (size_t i = 0; i < h0; i++) {
            double l = S[r * h0 + i] / cell, w = i == 0 || 2 * i == p->n[0] ? 1 : 2;
            if (l < lmin) lmin = l;
            if (l > lmax) lmax = l;
            if (l < 0) {
                neg -= w * l;
                p->info.negatives += (size_t)w;
            } else {
                sum += w * l;
            }
        }
    p->info.min_lambda = lmin * cell;
    p->info.max_lambda = lmax * cell;
    st = nl_synth_fft_verdict(name, p->count, sum, neg, flags, &p->info);
    if (!st) {
        for (size_t k = 0; k < p->half; k++) {
            double l = S[k] / cell;
            S[k] = l > 0 ? sqrt(l / (2 * (double)p->count)) : 0.0;
        }
        st = make_fftw_plans(p);
    }
    if (st) {
        nl_synth_fft_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

int nl_synth_fft_verdict(const char *name, size_t count, double sum, double neg, unsigned flags,
                         nl_synth_fft_info *info)
{
    info->variance = sum / (double)count;
    info->clamp_error = info->variance > 0 ? neg / (double)count / info->variance : INFINITY;
    if (!(info->variance > 0))
        return NL_ERROR(NL_ENOTPD, "%s: the sampled spectrum has no positive part on this grid", name);
    if (info->clamp_error > NL_SYNTH_FFT_CLAMP_TOL && !(flags & NL_SYNTH_FFT_CLAMP))
        return NL_ERROR(NL_ENOTPD,
                        "%s: not positive definite on this grid: min spectrum %.3g (max %.3g); zeroing the %zu "
                        "negative values would change the covariance by up to %.2g of R(0), above %.0e "
                        "(use --clamp to accept, or a larger grid if the model is truncated)",
                        name, info->min_lambda, info->max_lambda, info->negatives, info->clamp_error,
                        NL_SYNTH_FFT_CLAMP_TOL);
    return NL_OK;
}

/* v in the fewest significant digits (at least 2) that read back as v:
 * the value as a user most likely wrote it (4.9e-324, not 4.94066e-324). */
static const char *short_g(double v, char *buf, size_t len)
{
    for (int p = 2; p <= 17; p++) {
        snprintf(buf, len, "%.*g", p, v);
        if (strtod(buf, NULL) == v)
            break;
    }
    return buf;
}

int nl_synth_check_cell(int dim, const double *h)
{
    double cell = 1;
    char b0[32], b1[32];
    for (int a = 0; h && a < dim; a++) {
        if (!(h[a] > 0) || !isfinite(h[a]))
            return NL_ERROR(NL_EINVAL, "spacing: expected a positive finite number, got %s",
                            short_g(h[a], b0, sizeof b0));
        /* the frequencies are multiples of 1 / (n h): a denormal h makes
         * them overflow (4.9e-324: 1/h is inf) */
        if (!(h[a] >= DBL_MIN))
            return NL_ERROR(NL_EINVAL, "spacing: %s is below the smallest normal double %.17g (its frequencies "
                            "1/spacing overflow); expected spacings nearer 1", short_g(h[a], b0, sizeof b0), DBL_MIN);
        cell *= h[a];
    }
    if (!(cell >= DBL_MIN) || !isfinite(cell))
        return NL_ERROR(NL_EINVAL, "spacing: the %dD cell volume (product of the spacings %s ...) is %s, out of the "
                        "range of a double; expected spacings nearer 1", dim, short_g(h[0], b0, sizeof b0),
                        short_g(cell, b1, sizeof b1));
    return NL_OK;
}

int nl_synth_fft_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                         nl_synth_fft_plan **out)
{
    double *S;
    int st;
    *out = NULL;
    if ((st = nl_model_check_stationary(m, "FFT synthesis")))
        return st;
    /* the half spectrum, the field, and a half complex buffer */
    if ((st = nl_size_check(dim, n, sizeof(double), 3, NULL)))
        return st;
    for (int a = 0; a < dim; a++)
        if (n[a] > INT32_MAX)
            return NL_ERROR(NL_ETOOBIG, "size: %zu samples along an axis is beyond FFTW's int sizes", n[a]);
    if ((st = nl_synth_check_cell(dim, h)))
        return st;
    if ((st = nl_wk_sample_spectrum_half(m, dim, n, h, &S)))
        return st;
    return plan_from_half(nl_model_spec(m), dim, n, h, S, flags, out);
}

int nl_synth_fft_plan_spectrum(const nl_field *S, unsigned flags, nl_synth_fft_plan **out)
{
    size_t h0 = S->n[0] / 2 + 1, rows = S->count / S->n[0];
    double *half = nl_alloc(rows * h0 * sizeof *half);
    *out = NULL;
    if (!half)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t r = 0; r < rows; r++)
        memcpy(half + r * h0, S->data + r * S->n[0], h0 * sizeof *half);
    return plan_from_half("spectrum", S->dim, S->n, S->h, half, flags, out);
}

void nl_synth_fft_plan_info(const nl_synth_fft_plan *p, nl_synth_fft_info *info) { *info = p->info; }

/* Hermitian symmetry of the white spectrum G in a column holding both k
 * and -k (k0 = 0, and k0 = n0/2 for even n0): G(-k) = conj G(k) for the
 * later of the two in row order; a self-conjugate k (every component 0 or
 * n_a/2) is real with twice the variance, G = sqrt(2) Re G.  The column's
 * entry of row r is c[r * stride]. */
static void hermitian_column(const nl_synth_fft_plan *p, fftw_complex *c, size_t stride)
{
    const size_t n1 = p->n[1], n2 = p->n[2];
    for (size_t k2 = 0; k2 < n2; k2++)
        for (size_t k1 = 0; k1 < n1; k1++) {
            size_t r = k2 * n1 + k1, m = (n2 - k2) % n2 * n1 + (n1 - k1) % n1;
            if (m < r)
                c[r * stride] = conj(c[m * stride]);
            else if (m == r)
                c[r * stride] = M_SQRT2 * creal(c[r * stride]);
        }
}

/* Odd n0: G in a half-grid buffer, then FFTW's c2r into the field. */
static int execute_buffer(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out)
{
    const size_t h0 = p->n[0] / 2 + 1;
    fftw_complex *c = nl_alloc(p->half * sizeof *c);
    if (!c)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu complex samples", p->half);
    nl_rng_gauss_fill(seed, NL_STREAM_WHITE, 0, 2 * p->half, (double *)c);
    hermitian_column(p, c, h0);
#pragma omp parallel for schedule(static) if (p->count > 65536)
    for (size_t k = 0; k < p->half; k++)
        c[k] *= p->amp[k];
    fftw_execute_dft_c2r(p->inv, c, out->data);
    nl_free(c);
    return NL_OK;
}

/* Even n0: the half grid in the field itself, columns 0..m-1 (m = n0/2) of
 * row r at F + r m, column m in a side buffer Z; the c2r done as its two
 * stages (c2c along the outer axes in place; then per row, through a block
 * buffer, c2r along x into the row's own place): peak memory the field and
 * the amplitudes. */
static int execute_in_field(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out)
{
    const size_t n0 = p->n[0], m = n0 / 2, h0 = m + 1, nrows = p->count / n0;
    fftw_complex *F = (fftw_complex *)out->data, *Z = nl_alloc(nrows * sizeof *Z);
    int fail = 0;
    if (!Z)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu complex samples", nrows);
#pragma omp parallel for schedule(static) if (p->count > 65536)
    for (size_t r = 0; r < nrows; r++) {
        double g[2];
        nl_rng_gauss_fill(seed, NL_STREAM_WHITE, r * h0, 2 * m, (double *)(F + r * m));
        nl_rng_gauss_pair(seed, NL_STREAM_WHITE, r * h0 + m, g);
        Z[r] = g[0] + I * g[1];
        for (size_t k = 1; k < m; k++)
            F[r * m + k] *= p->amp[r * h0 + k];
    }
    hermitian_column(p, F, m);
    hermitian_column(p, Z, 1);
    for (size_t r = 0; r < nrows; r++)
        F[r * m] *= p->amp[r * h0], Z[r] *= p->amp[r * h0 + m];
    if (p->cols) {
        fftw_execute_dft(p->cols, F, F);
        fftw_execute_dft(p->nyq, Z, Z);
    }
#pragma omp parallel if (p->count > 65536)
    {
        fftw_complex *t = nl_alloc(ROW_BLOCK * h0 * sizeof *t);
        if (!t) {
#pragma omp atomic write
            fail = 1;
        }
#pragma omp for schedule(static)
        for (size_t r0 = 0; r0 < nrows; r0 += ROW_BLOCK) {
            size_t nb = nrows - r0 < ROW_BLOCK ? nrows - r0 : ROW_BLOCK;
            if (!t)
                continue;
            for (size_t b = 0; b < nb; b++) {
                memcpy(t + b * h0, F + (r0 + b) * m, m * sizeof *t);
                t[b * h0 + m] = Z[r0 + b];
            }
            fftw_execute_dft_c2r(nb == ROW_BLOCK ? p->rows : p->rest, t, out->data + r0 * n0);
        }
        nl_free(t);
    }
    nl_free(Z);
    return fail ? NL_ERROR(NL_ENOMEM, "out of memory for the transform's row buffers") : NL_OK;
}

int nl_synth_fft_execute(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out)
{
    if (out->dim != p->dim || out->count != p->count || out->n[0] != p->n[0] || out->n[1] != p->n[1])
        return NL_ERROR(NL_EINVAL, "FFT synthesis: the output field does not match the plan's grid");
    return p->n[0] % 2 ? execute_buffer(p, seed, out) : execute_in_field(p, seed, out);
}
