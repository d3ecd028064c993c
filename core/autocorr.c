/* FFT-based lag-product sums (Wiener-Khinchine on a zero-padded grid). */
#include "autocorr.h"
#include "fftw_plan.h"
#include "mem.h"
#include "nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <string.h>

double nl_field_mean(const nl_field *x)
{
    double s = 0;
    for (size_t i = 0; i < x->count; i++)
        s += x->data[i];
    return s / (double)x->count;
}

int nl_autocorr_sums(const nl_field *x, double mean, nl_field **out)
{
    size_t m[3] = {1, 1, 1}, half;
    int dims[3], st;
    nl_field *c;
    fftw_complex *spec;
    fftw_plan fwd, inv;

    *out = NULL;
    for (int a = 0; a < x->dim; a++)
        m[a] = 2 * x->n[a];
    if ((st = nl_size_check(x->dim, m, sizeof(double), 2, NULL)))
        return st;
    c = nl_field_alloc(x->dim, m, x->h, &st);
    if (!c)
        return st;
    half = c->count / m[0] * (m[0] / 2 + 1);
    spec = nl_alloc(half * sizeof(fftw_complex));
    if (!spec) {
        nl_field_free(c);
        return NL_ERROR(NL_ENOMEM, "out of memory for the autocorrelation");
    }
    for (int a = 0; a < x->dim; a++)  /* FFTW wants the slowest axis first */
        dims[a] = (int)m[x->dim - 1 - a];
    fwd = fftw_plan_dft_r2c(x->dim, dims, c->data, spec, nl_fftw_flags(c->count));
    inv = fftw_plan_dft_c2r(x->dim, dims, spec, c->data, nl_fftw_flags(c->count));
    if (!fwd || !inv) {
        fftw_destroy_plan(fwd);
        fftw_destroy_plan(inv);
        nl_free(spec);
        nl_field_free(c);
        return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", x->dim);
    }
    for (size_t k = 0; k < x->n[2]; k++)
        for (size_t j = 0; j < x->n[1]; j++)
            for (size_t i = 0; i < x->n[0]; i++)
                c->data[(k * m[1] + j) * m[0] + i] = x->data[(k * x->n[1] + j) * x->n[0] + i] - mean;
    fftw_execute(fwd);
    for (size_t i = 0; i < half; i++)
        spec[i] = creal(spec[i]) * creal(spec[i]) + cimag(spec[i]) * cimag(spec[i]);
    fftw_execute(inv);
    /* FFTW is unnormalised: forward then inverse multiplies by the count. */
    for (size_t i = 0; i < c->count; i++)
        c->data[i] /= (double)c->count;
    fftw_destroy_plan(fwd);
    fftw_destroy_plan(inv);
    nl_free(spec);
    *out = c;
    return NL_OK;
}
