/* Welch averaging of windowed periodograms. */
#include "welch.h"
#include "../core/fftw_plan.h"
#include "../core/autocorr.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

int nl_psd_welch(const nl_field *x, size_t S, double mean, nl_field **out, size_t *segments)
{
    int dim = x->dim, dims[2] = {(int)S, (int)S}, st;
    size_t ny = dim == 2 ? x->n[1] : 1, n2[2] = {S, S}, half = S / 2, cnt = 0, H = S / 2 + 1, rows = dim == 2 ? S : 1;
    double m = isnan(mean) ? nl_field_mean(x) : mean, U = 0, *w, cell = x->h[0] * (dim == 2 ? x->h[1] : 1);
    *out = NULL;
    if (dim > 2)
        return NL_ERROR(NL_EINVAL, "welch: expected a 1D or 2D field, got %dD", dim);
    if (S < 4 || S > x->n[0] || (dim == 2 && S > ny))
        return NL_ERROR(NL_EINVAL, "welch: expected a segment of 4 samples up to the field's size, got %zu", S);
    nl_field *P = nl_field_alloc(dim, n2, x->h, &st), *seg = nl_field_alloc(dim, n2, x->h, &st);
    fftw_complex *c = nl_alloc(rows * H * sizeof(fftw_complex));
    w = malloc(S * sizeof *w);
    if (!P || !seg || !c || !w) {
        nl_field_free(P), nl_field_free(seg), nl_free(c), free(w);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < S; i++)
        w[i] = 0.5 * (1 - cos(2 * M_PI * ((double)i + 0.5) / (double)S));
    for (size_t i = 0; i < S; i++)
        U += w[i] * w[i] / (double)S;
    if (dim == 2)
        U *= U;
    fftw_plan p = fftw_plan_dft_r2c(dim, dim == 2 ? dims : dims + 1, seg->data, c, nl_fftw_flags(seg->count));
    for (size_t y0 = 0; y0 + (dim == 2 ? S : 1) <= ny; y0 += dim == 2 ? half : 1) {
        for (size_t x0 = 0; x0 + S <= x->n[0]; x0 += half) {
            for (size_t j = 0; j < rows; j++)
                for (size_t i = 0; i < S; i++)
                    seg->data[j * S + i] =
                        (x->data[(y0 + j) * x->n[0] + x0 + i] - m) * w[i] * (dim == 2 ? w[j] : 1);
            fftw_execute(p);
            /* expand the half spectrum (P(-k) = P(k)) while accumulating */
            for (size_t j = 0; j < rows; j++) {
                size_t jn = (rows - j) % rows;
                for (size_t i = 0; i < H; i++) {
                    double v = creal(c[j * H + i]) * creal(c[j * H + i]) + cimag(c[j * H + i]) * cimag(c[j * H + i]);
                    P->data[j * S + i] += v;
                    if (i && 2 * i != S)
                        P->data[jn * S + (S - i)] += v;
                }
            }
            cnt++;
        }
        if (dim == 1)
            break;
    }
    double norm = cell / (pow((double)S, dim) * U * (double)cnt);
    for (size_t i = 0; i < P->count; i++)
        P->data[i] *= norm;
    fftw_destroy_plan(p), nl_free(c), free(w), nl_field_free(seg);
    *out = P;
    if (segments)
        *segments = cnt;
    return NL_OK;
}
