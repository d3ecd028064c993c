/* Planned FFT lag-product sums (Wiener-Khinchine on a zero-padded grid). */
#include "autocorr_plan.h"
#include "fftw_plan.h"
#include "mem.h"
#include "nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <stdlib.h>
#include <string.h>

struct nl_autocorr_plan {
    int dim;            /* axes of the input */
    size_t n[3];        /* input samples per axis (1 beyond dim) */
    size_t m[3];        /* padded grid, 2 n per axis (1 beyond dim) */
    size_t count;       /* m[0] m[1] m[2] */
    size_t half;        /* complex half-spectrum length */
    double *buf;        /* padded real scratch, planned on */
    fftw_complex *spec; /* half spectrum, planned on */
    fftw_plan fwd, inv; /* r2c and c2r on buf/spec */
};

void nl_autocorr_plan_free(nl_autocorr_plan *p)
{
    if (!p)
        return;
    if (p->fwd)
        fftw_destroy_plan(p->fwd);
    if (p->inv)
        fftw_destroy_plan(p->inv);
    nl_free(p->spec);
    nl_free(p->buf);
    free(p);
}

int nl_autocorr_plan_alloc(int dim, const size_t *n, nl_autocorr_plan **out)
{
    int dims[3], st;
    nl_autocorr_plan *p;

    *out = NULL;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "autocorrelation: expected 1 to 3 dimensions, got %d", dim);
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the autocorrelation plan");
    p->dim = dim;
    for (int a = 0; a < 3; a++) {
        p->n[a] = a < dim ? n[a] : 1;
        p->m[a] = a < dim ? 2 * n[a] : 1;
    }
    if ((st = nl_size_check(dim, p->m, sizeof(double), 2, &p->count)) ||
        (st = nl_size_check(dim, p->n, sizeof(double), 1, NULL))) {
        free(p);
        return st;
    }
    p->half = p->count / p->m[0] * (p->m[0] / 2 + 1);
    p->buf = nl_alloc(p->count * sizeof(double));
    p->spec = nl_alloc(p->half * sizeof(fftw_complex));
    if (!p->buf || !p->spec) {
        nl_autocorr_plan_free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory for the autocorrelation");
    }
    for (int a = 0; a < dim; a++) /* FFTW wants the slowest axis first */
        dims[a] = (int)p->m[dim - 1 - a];
    p->fwd = fftw_plan_dft_r2c(dim, dims, p->buf, p->spec, nl_fftw_flags(p->count));
    p->inv = fftw_plan_dft_c2r(dim, dims, p->spec, p->buf, nl_fftw_flags(p->count));
    if (!p->fwd || !p->inv) {
        nl_autocorr_plan_free(p);
        return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D transform", dim);
    }
    *out = p;
    return NL_OK;
}

void nl_autocorr_plan_grid(const nl_autocorr_plan *p, int *dim, size_t *m)
{
    *dim = p->dim;
    for (int a = 0; a < 3; a++)
        m[a] = p->m[a];
}

int nl_autocorr_plan_execute(nl_autocorr_plan *p, const nl_field *x, double mean, nl_field *c)
{
    size_t *m = p->m;
    if (x->dim != p->dim || c->dim != p->dim)
        return NL_ERROR(NL_EINVAL, "autocorrelation: expected %d-D fields, got %d-D and %d-D", p->dim, x->dim,
                        c->dim);
    for (int a = 0; a < p->dim; a++)
        if (x->n[a] != p->n[a] || c->n[a] != m[a])
            return NL_ERROR(NL_EINVAL, "autocorrelation: axis %d: expected %zu samples in and %zu out, got %zu "
                            "and %zu", a, p->n[a], m[a], x->n[a], c->n[a]);
    memset(p->buf, 0, p->count * sizeof(double));
    for (size_t k = 0; k < x->n[2]; k++)
        for (size_t j = 0; j < x->n[1]; j++)
            for (size_t i = 0; i < x->n[0]; i++)
                p->buf[(k * m[1] + j) * m[0] + i] = x->data[(k * x->n[1] + j) * x->n[0] + i] - mean;
    fftw_execute(p->fwd);
    for (size_t i = 0; i < p->half; i++)
        p->spec[i] = creal(p->spec[i]) * creal(p->spec[i]) + cimag(p->spec[i]) * cimag(p->spec[i]);
    fftw_execute(p->inv);
    /* FFTW is unnormalised: forward then inverse multiplies by the count. */
    for (size_t i = 0; i < p->count; i++)
        c->data[i] = p->buf[i] / (double)p->count;
    return NL_OK;
}
