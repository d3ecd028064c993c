/* Sampling models on wrapped grids; Wiener-Khinchine by FFT. */
#include "wk.h"
#include "gsl_guard_internal.h"
#include "fftw_plan.h"
#include "mem.h"
#include "nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

static int same_grid(const nl_field *a, const nl_field *b)
{
    if (a->dim != b->dim)
        return 0;
    for (int i = 0; i < 3; i++)
        if (a->n[i] != b->n[i] || a->h[i] != b->h[i])
            return 0;
    return 1;
}

/* y = scale * Re(DFT_sign(x)) over the n-D grid of x. */
static int dft_real(const nl_field *x, nl_field *y, int sign, double scale)
{
    int dims[3];
    fftw_complex *buf;
    fftw_plan p;
    if (!same_grid(x, y))
        return NL_ERROR(NL_EINVAL, "Wiener-Khinchine: input and output grids differ");
    buf = nl_alloc(x->count * sizeof *buf);
    if (!buf)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu complex samples", x->count);
    for (int a = 0; a < x->dim; a++)
        dims[a] = (int)x->n[x->dim - 1 - a];
    p = fftw_plan_dft(x->dim, dims, buf, buf, sign, nl_fftw_flags(x->count));
    if (!p) {
        nl_free(buf);
        return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", x->dim);
    }
    for (size_t i = 0; i < x->count; i++)
        buf[i] = x->data[i];
    fftw_execute(p);
    for (size_t i = 0; i < x->count; i++)
        y->data[i] = scale * creal(buf[i]);
    fftw_destroy_plan(p);
    nl_free(buf);
    return NL_OK;
}

int nl_wk_acf_to_spectrum(const nl_field *R, nl_field *S)
{
    double cell = R->h[0] * R->h[1] * R->h[2];
    return dft_real(R, S, FFTW_FORWARD, cell);
}

int nl_wk_spectrum_to_acf(const nl_field *S, nl_field *R)
{
    double df = 1.0;
    for (int a = 0; a < S->dim; a++)
        df /= (double)S->n[a] * S->h[a];
    return dft_real(S, R, FFTW_BACKWARD, df);
}

/* Model value at wrapped index idx.  On an even axis the Nyquist index
 * n/2 stands for both +n/2 and -n/2; averaging the two keeps the sampled
 * field even (R_j = R_-j), so that its transform is exactly real. */
static double value_at(const nl_model *m, const nl_field *f, const size_t *idx, int freq)
{
    double v[3] = {0, 0, 0}, unit[3], sum = 0;
    int nyq[3] = {0, 0, 0}, combos = 1;
    for (int a = 0; a < f->dim; a++) {
        unit[a] = freq ? 1.0 / ((double)f->n[a] * f->h[a]) : f->h[a];
        nyq[a] = f->n[a] % 2 == 0 && idx[a] == f->n[a] / 2;
        combos <<= nyq[a];
    }
    for (int c = 0; c < combos; c++) {
        int bit = 0;
        for (int a = 0; a < f->dim; a++) {
            double s = 1;
            if (nyq[a])
                s = (c >> bit++) & 1 ? -1 : 1;
            v[a] = s * (double)nl_wrap(idx[a], f->n[a]) * unit[a];
        }
        sum += freq ? nl_model_spectrum(m, f->dim, v) : nl_model_acf(m, f->dim, v);
    }
    return sum / combos;
}

/* The row holding the negated (j, k) of row r. */
static size_t mirror_row(const nl_field *g, size_t r)
{
    size_t j = r % g->n[1], k = r / g->n[1];
    return (g->n[2] - k) % g->n[2] * g->n[1] + (g->n[1] - j) % g->n[1];
}

/* A covariance, and the spectrum of a real field, are even: R(-t) = R(t),
 * S(-f) = S(f).  Sampling only half the spectrum (the r2c half grid) or
 * taking the real part of the DFT of an odd part would silently keep the
 * even part of an expression that is not (named models are even exactly,
 * see fill_rows), so check about EVEN_SAMPLES points
 * spread over the grid against their mirrors: NL_EINVAL when some pair
 * differs by more than EVEN_TOL of the largest magnitude sampled (rounding
 * in a tabulated or transformed model stays far below). */
enum { EVEN_SAMPLES = 2048 };
#define EVEN_TOL 1e-6

static int check_even(const nl_model *m, const nl_field *g, int freq)
{
    size_t step = g->count > EVEN_SAMPLES ? g->count / EVEN_SAMPLES : 1, worst = 0;
    double big = 0, diff = 0, wa = 0, wb = 0;
    nl_gsl_enter();
    for (size_t k = 0; k < g->count; k += step) {
        size_t idx[3] = {k % g->n[0], k / g->n[0] % g->n[1], k / (g->n[0] * g->n[1])}, mir[3];
        for (int a = 0; a < 3; a++)
            mir[a] = (g->n[a] - idx[a]) % g->n[a];
        double va = value_at(m, g, idx, freq), vb = value_at(m, g, mir, freq);
        if (!isfinite(va) || !isfinite(vb))
            continue; /* fill_rows names it */
        big = fmax(big, fmax(fabs(va), fabs(vb)));
        if (fabs(va - vb) > diff)
            diff = fabs(va - vb), worst = k, wa = va, wb = vb;
    }
    nl_gsl_leave();
    if (diff > EVEN_TOL * big) {
        size_t i = worst % g->n[0], j = worst / g->n[0] % g->n[1], l = worst / (g->n[0] * g->n[1]);
        return NL_ERROR(NL_EINVAL, "%s: not even: the %s at index (%zu, %zu, %zu) is %g but %g at its mirror "
                        "image; %s", nl_model_spec(m), freq ? "spectrum" : "covariance", i, j, l, wa, wb,
                        freq ? "the spectrum of a real field must satisfy S(-f) = S(f)"
                             : "a covariance must satisfy R(-t) = R(t)");
    }
    return NL_OK;
}

/* Model values at the wrapped lags (freq = 0) or frequencies (i < ni, rows
 * r0 <= r < r1, row r = j + n1 k) of the grid g, row r into dst + (r - r0)
 * stride.  Reentrant models are sampled on all threads, and, when the whole
 * grid's rows are asked for, only on half of them: R(-x) = R(x) and
 * S(-f) = S(f) hold exactly in floating point for them (negation is exact,
 * and cos, |.| and the rotation commute with it), so the other half is
 * copied reversed.  Expressions are evaluated everywhere: an odd expression
 * must show up as such. */
static int fill_rows(const nl_model *m, const nl_field *g, size_t ni, size_t r0, size_t r1, double *dst,
                     size_t stride, int freq)
{
    size_t rows = g->n[1] * g->n[2], bad = r1, n0 = g->n[0];
    int st = nl_model_check_dim(m, g->dim), reentrant = nl_model_is_reentrant(m);
    int sym = reentrant && ni == n0 && rows > 1 && r0 == 0 && r1 == rows;
    if (st || (!reentrant && (st = check_even(m, g, freq))))
        return st;
    /* each worker brackets its share once, so that the models' own GSL
     * guards (Matern, power) cost it a thread-local counter per value;
     * nowait: the region's end is the only barrier, as before */
#pragma omp parallel if (reentrant && (r1 - r0) * ni > 65536)
    {
        nl_gsl_enter();
#pragma omp for schedule(dynamic, 16) nowait
        for (size_t r = r0; r < r1; r++) {
            size_t idx[3] = {0, r % g->n[1], r / g->n[1]};
            if (sym && mirror_row(g, r) < r)
                continue;
            for (size_t i = 0; i < ni; i++) {
                double y;
                idx[0] = i;
                y = value_at(m, g, idx, freq);
                if (!isfinite(y)) {
#pragma omp critical
                    if (r < bad)
                        bad = r;
                    break;
                }
                dst[(r - r0) * stride + i] = y;
            }
        }
        nl_gsl_leave();
    }
    if (bad < r1) {
        size_t idx[3] = {0, bad % g->n[1], bad / g->n[1]};
        for (size_t i = 0; i < ni; i++) {
            double y;
            idx[0] = i;
            if (!isfinite(y = value_at(m, g, idx, freq)))
                return NL_ERROR(NL_EINVAL, "%s: the model is not finite (%g) at %s index (%zu, %zu, %zu)",
                                nl_model_spec(m), y, freq ? "frequency" : "lag", i, idx[1], idx[2]);
        }
    }
#pragma omp parallel for schedule(static) if (sym && rows * ni > 65536)
    for (size_t r = 0; r < rows; r++) {
        size_t mr = sym ? mirror_row(g, r) : r;
        if (mr < r) {
            const double *from = dst + mr * stride;
            double *to = dst + r * stride;
            to[0] = from[0];
            for (size_t i = 1; i < n0; i++)
                to[i] = from[n0 - i];
        }
    }
    return NL_OK;
}

/* A grid of n[0..dim-1] samples at spacing h (NULL: unit), without data. */
static nl_field grid_of(int dim, const size_t *n, const double *h)
{
    nl_field g = {.dim = dim, .n = {1, 1, 1}, .h = {1, 1, 1}, .count = 1, .data = NULL};
    for (int a = 0; a < dim && a < 3; a++) {
        g.n[a] = n[a];
        g.h[a] = h ? h[a] : 1;
        g.count *= n[a];
    }
    return g;
}

int nl_wk_check_even(const nl_model *m, int dim, const size_t *n, const double *h, int freq)
{
    nl_field g;
    int st;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    g = grid_of(dim, n, h);
    if ((st = nl_model_check_dim(m, dim)))
        return st;
    return nl_model_is_reentrant(m) ? NL_OK : check_even(m, &g, freq);
}

int nl_wk_sample_rows(const nl_model *m, int dim, const size_t *n, const double *h, size_t r0, size_t r1, int freq,
                      double *dst, size_t stride)
{
    nl_field g;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    g = grid_of(dim, n, h);
    return fill_rows(m, &g, g.n[0], r0, r1, dst, stride, freq);
}

double nl_wk_value(const nl_model *m, int dim, const size_t *n, const double *h, const size_t *idx, int freq)
{
    nl_field g = grid_of(dim, n, h);
    double v;
    nl_gsl_enter();
    v = value_at(m, &g, idx, freq);
    nl_gsl_leave();
    return v;
}

/* Fill f with model values at the wrapped lags (freq = 0) or frequencies. */
static int fill(const nl_model *m, nl_field *f, int freq)
{
    return fill_rows(m, f, f->n[0], 0, f->n[1] * f->n[2], f->data, f->n[0], freq);
}

int nl_wk_sample_acf(const nl_model *m, nl_field *R)
{
    nl_field *S;
    int st;
    if (!nl_model_is_spectral(m))
        return fill(m, R, 0);
    S = nl_field_alloc(R->dim, R->n, R->h, &st);
    if (!S)
        return st;
    st = fill(m, S, 1);
    if (!st)
        st = nl_wk_spectrum_to_acf(S, R);
    nl_field_free(S);
    return st;
}

int nl_wk_sample_spectrum(const nl_model *m, nl_field *S)
{
    nl_field *R;
    int st;
    if (nl_model_is_spectral(m))
        return fill(m, S, 1);
    R = nl_field_alloc(S->dim, S->n, S->h, &st);
    if (!R)
        return st;
    st = fill(m, R, 0);
    if (!st)
        st = nl_wk_acf_to_spectrum(R, S);
    nl_field_free(R);
    return st;
}

int nl_wk_sample_spectrum_half(const nl_model *m, int dim, const size_t *n, const double *h, double **out)
{
    nl_field g;
    size_t h0, rows, half;
    double *S, *buf, cell = 1;
    fftw_plan p;
    int dims[3], st;
    *out = NULL;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    g = grid_of(dim, n, h);
    for (int a = 0; a < dim; a++) {
        cell *= g.h[a];
        dims[a] = (int)n[dim - 1 - a];
    }
    h0 = g.n[0] / 2 + 1;
    rows = g.n[1] * g.n[2];
    half = rows * h0;
    S = nl_alloc(half * sizeof *S);
    if (!S)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu spectrum samples", half);
    if (nl_model_is_spectral(m)) {
        if ((st = fill_rows(m, &g, h0, 0, rows, S, h0, 1))) {
            nl_free(S);
            return st;
        }
        *out = S;
        return NL_OK;
    }
    /* In-place r2c: rows padded to 2 h0 doubles; planned before filling,
     * since a measured plan overwrites its arrays.  S is the real parts,
     * compacted in place (S[k] from c[k], k ascending, never ahead of its
     * source) and the block shrunk: the transform's buffer is the only one. */
    nl_free(S);
    buf = nl_alloc(2 * half * sizeof *buf);
    p = buf ? fftw_plan_dft_r2c(dim, dims, buf, (fftw_complex *)buf, nl_fftw_flags(g.count)) : NULL;
    if (!p) {
        nl_free(buf);
        return buf ? NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", dim)
                   : NL_ERROR(NL_ENOMEM, "out of memory for %zu samples", 2 * half);
    }
    if (!(st = fill_rows(m, &g, g.n[0], 0, rows, buf, 2 * h0, 0))) {
        fftw_execute(p);
        for (size_t k = 0; k < half; k++)
            buf[k] = cell * buf[2 * k];
        S = realloc(buf, half * sizeof *S);
        *out = S ? S : buf;
        buf = NULL;
    }
    fftw_destroy_plan(p);
    nl_free(buf);
    return st;
}
