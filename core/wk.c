/* Sampling models on wrapped grids; Wiener-Khinchine by FFT. */
#include "wk.h"
#include "fftw_plan.h"
#include "nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>

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
    buf = fftw_alloc_complex(x->count);
    if (!buf)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu complex samples", x->count);
    for (int a = 0; a < x->dim; a++)
        dims[a] = (int)x->n[x->dim - 1 - a];
    p = fftw_plan_dft(x->dim, dims, buf, buf, sign, nl_fftw_flags(x->count));
    if (!p) {
        fftw_free(buf);
        return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", x->dim);
    }
    for (size_t i = 0; i < x->count; i++)
        buf[i] = x->data[i];
    fftw_execute(p);
    for (size_t i = 0; i < x->count; i++)
        y->data[i] = scale * creal(buf[i]);
    fftw_destroy_plan(p);
    fftw_free(buf);
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

/* Fill f with model values at the wrapped lags (freq = 0) or frequencies. */
static int fill(const nl_model *m, nl_field *f, int freq)
{
    int st = nl_model_check_dim(m, f->dim);
    if (st)
        return st;
    for (size_t k = 0; k < f->n[2]; k++)
        for (size_t j = 0; j < f->n[1]; j++)
            for (size_t i = 0; i < f->n[0]; i++) {
                size_t idx[3] = {i, j, k};
                double y = value_at(m, f, idx, freq);
                if (!isfinite(y))
                    return NL_ERROR(NL_EINVAL, "%s: the model is not finite (%g) at %s index (%zu, %zu, %zu)",
                                    nl_model_spec(m), y, freq ? "frequency" : "lag", i, j, k);
                f->data[(k * f->n[1] + j) * f->n[0] + i] = y;
            }
    return NL_OK;
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
