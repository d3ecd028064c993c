/* The periodogram, by one r2c FFT. */
#include "psd.h"
#include "../core/fftw_plan.h"
#include "../core/autocorr.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>

int nl_psd_periodogram(const nl_field *x, double mean, nl_field **out)
{
    size_t h0 = x->n[0] / 2 + 1, rows = x->count / x->n[0];
    double cell = x->h[0] * x->h[1] * x->h[2], m = isnan(mean) ? nl_field_mean(x) : mean;
    int dims[3], st;
    fftw_complex *c;
    fftw_plan p;
    nl_field *P = nl_field_alloc(x->dim, x->n, x->h, &st);

    *out = NULL;
    if (!P)
        return st;
    c = nl_alloc(rows * h0 * sizeof(fftw_complex));
    for (int a = 0; a < x->dim; a++)
        dims[a] = (int)x->n[x->dim - 1 - a];
    p = c ? fftw_plan_dft_r2c(x->dim, dims, P->data, c, nl_fftw_flags(x->count)) : NULL;
    if (!p) {
        nl_free(c);
        nl_field_free(P);
        return NL_ERROR(NL_ENOMEM, "cannot plan the periodogram FFT");
    }
    for (size_t i = 0; i < x->count; i++)
        P->data[i] = x->data[i] - m;
    fftw_execute(p);
    /* Expand the half spectrum: P(-k) = P(k) for real input. */
    for (size_t r = 0; r < rows; r++) {
        size_t j = r % x->n[1], k = r / x->n[1];
        size_t rneg = ((x->n[2] - k) % x->n[2]) * x->n[1] + (x->n[1] - j) % x->n[1];
        for (size_t i = 0; i < h0; i++) {
            double v = cell / (double)x->count * (creal(c[r * h0 + i]) * creal(c[r * h0 + i]) +
                                                  cimag(c[r * h0 + i]) * cimag(c[r * h0 + i]));
            P->data[r * x->n[0] + i] = v;
            P->data[rneg * x->n[0] + (x->n[0] - i) % x->n[0]] = v;
        }
    }
    fftw_destroy_plan(p);
    nl_free(c);
    *out = P;
    return NL_OK;
}
