/* Energy folded by decimation without low-pass filtering. */
#include "aliasing.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

/* Is wrapped frequency index k (of n) above half the Nyquist rate? */
static int high(size_t k, size_t n) { return 4 * (size_t)labs(nl_wrap(k, n)) > n; }

int nl_aliasing_measure(const nl_field *f, double *A)
{
    size_t nx = f->n[0], ny = f->dim == 2 ? f->n[1] : 1, h0 = nx / 2 + 1;
    int dims[2] = {(int)ny, (int)nx}, st;
    double mean = 0, num = 0, den = 0;
    fftw_complex *c;
    fftw_plan fwd, inv;
    nl_field *lp;
    if (f->dim > 2 || nx % 2 || (f->dim == 2 && ny % 2))
        return NL_ERROR(NL_EINVAL, "aliasing: expected a 1D or 2D field of even sizes");
    lp = nl_field_alloc(f->dim, f->n, f->h, &st);
    if (!lp)
        return st;
    c = nl_alloc(ny * h0 * sizeof(fftw_complex));
    fwd = c ? fftw_plan_dft_r2c(f->dim, f->dim == 2 ? dims : dims + 1, lp->data, c, nl_fftw_flags(f->count)) : NULL;
    inv = c ? fftw_plan_dft_c2r(f->dim, f->dim == 2 ? dims : dims + 1, c, lp->data, nl_fftw_flags(f->count)) : NULL;
    if (!fwd || !inv) {
        fftw_destroy_plan(fwd), fftw_destroy_plan(inv), nl_free(c), nl_field_free(lp);
        return NL_ERROR(NL_ENOMEM, "aliasing: cannot plan the FFT");
    }
    for (size_t i = 0; i < f->count; i++)
        lp->data[i] = f->data[i], mean += f->data[i] / (double)f->count;
    fftw_execute(fwd);
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < h0; i++)
            if (high(i, nx) || (f->dim == 2 && high(j, ny)))
                c[j * h0 + i] = 0;
    fftw_execute(inv);
    for (size_t j = 0; j < ny; j += (f->dim == 2 ? 2 : 1))
        for (size_t i = 0; i < nx; i += 2) {
            double x = f->data[j * nx + i], e = x - lp->data[j * nx + i] / (double)f->count;
            num += e * e;
            den += (x - mean) * (x - mean);
        }
    fftw_destroy_plan(fwd), fftw_destroy_plan(inv), nl_free(c), nl_field_free(lp);
    *A = den > 0 ? num / den : 0;
    return NL_OK;
}

int nl_aliasing_predict(const nl_model *m, const nl_field *f, double *A)
{
    nl_field *S;
    double hi = 0, all = 0;
    int st;
    S = nl_field_alloc(f->dim, f->n, f->h, &st);
    if (!S)
        return st;
    if ((st = nl_wk_sample_spectrum(m, S))) {
        nl_field_free(S);
        return st;
    }
    for (size_t k = 0; k < S->n[2]; k++)
        for (size_t j = 0; j < S->n[1]; j++)
            for (size_t i = 0; i < S->n[0]; i++) {
                double s = fmax(S->data[(k * S->n[1] + j) * S->n[0] + i], 0);
                all += s;
                if (high(i, S->n[0]) || (S->dim >= 2 && high(j, S->n[1])) || (S->dim == 3 && high(k, S->n[2])))
                    hi += s;
            }
    nl_field_free(S);
    *A = all > 0 ? hi / all : 0;
    return NL_OK;
}
