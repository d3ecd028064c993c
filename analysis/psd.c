/* The periodogram, by one r2c FFT, planned once per grid size. */
#include "psd.h"
#include "acf.h"
#include "../core/fftw_plan.h"
#include "../core/autocorr.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

struct nl_psd_plan {
    int dim;           /* axes */
    size_t n[3];       /* samples per axis (1 beyond dim) */
    size_t count;      /* n[0] n[1] n[2] */
    size_t h0, rows;   /* n[0]/2 + 1 and count / n[0]: the half spectrum */
    double *buf;       /* real input scratch, planned on */
    fftw_complex *c;   /* half spectrum, planned on */
    fftw_plan p;       /* r2c on buf/c */
};

void nl_psd_plan_free(nl_psd_plan *p)
{
    if (!p)
        return;
    if (p->p)
        fftw_destroy_plan(p->p);
    nl_free(p->c);
    nl_free(p->buf);
    free(p);
}

int nl_psd_plan_alloc(int dim, const size_t *n, nl_psd_plan **out)
{
    int dims[3], st;
    nl_psd_plan *p;
    *out = NULL;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "periodogram: expected 1 to 3 dimensions, got %d", dim);
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the periodogram plan");
    p->dim = dim;
    for (int a = 0; a < 3; a++)
        p->n[a] = a < dim ? n[a] : 1;
    if ((st = nl_size_check(dim, p->n, sizeof(double), 2, &p->count))) {
        free(p);
        return st;
    }
    p->h0 = p->n[0] / 2 + 1, p->rows = p->count / p->n[0];
    p->buf = nl_alloc(p->count * sizeof(double));
    p->c = nl_alloc(p->rows * p->h0 * sizeof(fftw_complex));
    for (int a = 0; a < dim; a++)
        dims[a] = (int)p->n[dim - 1 - a];
    if (p->buf && p->c)
        p->p = fftw_plan_dft_r2c(dim, dims, p->buf, p->c, nl_fftw_flags(p->count));
    if (!p->p) {
        nl_psd_plan_free(p);
        return NL_ERROR(NL_ENOMEM, "cannot plan the periodogram FFT");
    }
    *out = p;
    return NL_OK;
}

int nl_psd_plan_execute(nl_psd_plan *p, const nl_field *x, double mean, nl_field *P)
{
    double cell = x->h[0] * x->h[1] * x->h[2], m;
    const size_t *n = p->n;
    if (x->dim != p->dim || P->dim != p->dim || x->count != p->count || P->count != p->count)
        return NL_ERROR(NL_EINVAL, "periodogram: expected %d-D fields of %zu samples, got %d-D of %zu and %d-D of %zu",
                        p->dim, p->count, x->dim, x->count, P->dim, P->count);
    for (int a = 0; a < p->dim; a++)
        if (x->n[a] != n[a] || P->n[a] != n[a])
            return NL_ERROR(NL_EINVAL, "periodogram: axis %d: expected %zu samples, got %zu and %zu", a, n[a],
                            x->n[a], P->n[a]);
    if (nl_estimate_check_range(x, mean, 1))
        return NL_EINVAL;
    m = isnan(mean) ? nl_field_mean(x) : mean;
    for (size_t i = 0; i < x->count; i++)
        p->buf[i] = x->data[i] - m;
    fftw_execute(p->p);
    /* Expand the half spectrum: P(-k) = P(k) for real input. */
    for (size_t r = 0; r < p->rows; r++) {
        size_t j = r % n[1], k = r / n[1], h0 = p->h0;
        size_t rneg = ((n[2] - k) % n[2]) * n[1] + (n[1] - j) % n[1];
        const fftw_complex *c = p->c + r * h0;
        for (size_t i = 0; i < h0; i++) {
            double v = cell / (double)x->count * (creal(c[i]) * creal(c[i]) + cimag(c[i]) * cimag(c[i]));
            P->data[r * n[0] + i] = v;
            P->data[rneg * n[0] + (n[0] - i) % n[0]] = v;
        }
    }
    return NL_OK;
}

int nl_psd_periodogram(const nl_field *x, double mean, nl_field **out)
{
    int st;
    nl_psd_plan *p;
    nl_field *P;
    *out = NULL;
    if ((st = nl_psd_plan_alloc(x->dim, x->n, &p)))
        return st;
    P = nl_field_alloc(x->dim, x->n, x->h, &st);
    if (P && (st = nl_psd_plan_execute(p, x, mean, P))) {
        nl_field_free(P);
        P = NULL;
    }
    nl_psd_plan_free(p);
    *out = P;
    return P ? NL_OK : st;
}
