/* Welch averaging of windowed periodograms, planned once per segment size. */
#include "welch.h"
#include "acf.h"
#include "../core/fftw_plan.h"
#include "../core/autocorr.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <complex.h>
#include <limits.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nl_welch_plan {
    int dim;          /* 1 or 2 */
    size_t S;         /* segment side */
    size_t rows, H;   /* S (2D) or 1; S/2 + 1 */
    double *w;        /* Hann window, S values */
    double U;         /* mean of the window's square (its square in 2D) */
    double *seg;      /* windowed segment, S^dim, planned on */
    fftw_complex *c;  /* its half spectrum, planned on */
    fftw_plan p;      /* r2c on seg/c */
};

void nl_welch_plan_free(nl_welch_plan *p)
{
    if (!p)
        return;
    if (p->p)
        fftw_destroy_plan(p->p);
    nl_free(p->c), nl_free(p->seg), free(p->w), free(p);
}

int nl_welch_plan_alloc(int dim, size_t S, nl_welch_plan **out)
{
    int dims[2] = {(int)S, (int)S};
    nl_welch_plan *p;
    *out = NULL;
    if (dim < 1 || dim > 2)
        return NL_ERROR(NL_EINVAL, "welch: expected a 1D or 2D field, got %dD", dim);
    if (S < 4 || S > (size_t)INT_MAX)
        return NL_ERROR(NL_EINVAL, "welch: expected a segment of 4 samples up to the field's size, got %zu", S);
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->dim = dim, p->S = S, p->H = S / 2 + 1, p->rows = dim == 2 ? S : 1;
    p->w = malloc(S * sizeof *p->w);
    p->seg = nl_alloc(p->rows * S * sizeof(double));
    p->c = nl_alloc(p->rows * p->H * sizeof(fftw_complex));
    if (!p->w || !p->seg || !p->c) {
        nl_welch_plan_free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < S; i++)
        p->w[i] = 0.5 * (1 - cos(2 * M_PI * ((double)i + 0.5) / (double)S));
    for (size_t i = 0; i < S; i++)
        p->U += p->w[i] * p->w[i] / (double)S;
    if (dim == 2)
        p->U *= p->U;
    p->p = fftw_plan_dft_r2c(dim, dim == 2 ? dims : dims + 1, p->seg, p->c, nl_fftw_flags(p->rows * S));
    if (!p->p) {
        nl_welch_plan_free(p);
        return NL_ERROR(NL_EFAIL, "FFTW could not plan the Welch segment transform");
    }
    *out = p;
    return NL_OK;
}

/* Window the segment at (x0, y0), transform it, and add its periodogram,
 * expanded from the half spectrum (P(-k) = P(k)), to P. */
static void add_segment(nl_welch_plan *p, const nl_field *x, double m, size_t x0, size_t y0, double *P)
{
    size_t S = p->S, H = p->H, rows = p->rows;
    const double *w = p->w;
    for (size_t j = 0; j < rows; j++)
        for (size_t i = 0; i < S; i++)
            p->seg[j * S + i] = (x->data[(y0 + j) * x->n[0] + x0 + i] - m) * w[i] * (p->dim == 2 ? w[j] : 1);
    fftw_execute(p->p);
    for (size_t j = 0; j < rows; j++) {
        size_t jn = (rows - j) % rows;
        for (size_t i = 0; i < H; i++) {
            const fftw_complex *c = p->c;
            double v = creal(c[j * H + i]) * creal(c[j * H + i]) + cimag(c[j * H + i]) * cimag(c[j * H + i]);
            P[j * S + i] += v;
            if (i && 2 * i != S)
                P[jn * S + (S - i)] += v;
        }
    }
}

int nl_welch_plan_execute(nl_welch_plan *p, const nl_field *x, double mean, nl_field *P, size_t *segments)
{
    int dim = p->dim;
    size_t S = p->S, half = S / 2, cnt = 0, ny = dim == 2 ? x->n[1] : 1;
    double m, cell = x->h[0] * (dim == 2 ? x->h[1] : 1);
    if (x->dim != dim || P->dim != dim || P->n[0] != S || (dim == 2 && P->n[1] != S))
        return NL_ERROR(NL_EINVAL, "welch: expected a %dD field and a %dD output of %zu samples per axis", dim, dim, S);
    if (S > x->n[0] || (dim == 2 && S > ny))
        return NL_ERROR(NL_EINVAL, "welch: expected a segment of 4 samples up to the field's size, got %zu", S);
    if (nl_estimate_check_range(x, mean, 1))
        return NL_EINVAL;
    m = isnan(mean) ? nl_field_mean(x) : mean;
    memset(P->data, 0, P->count * sizeof(double));
    for (size_t y0 = 0; y0 + (dim == 2 ? S : 1) <= ny; y0 += dim == 2 ? half : 1) {
        for (size_t x0 = 0; x0 + S <= x->n[0]; x0 += half) {
            add_segment(p, x, m, x0, y0, P->data);
            cnt++;
        }
        if (dim == 1)
            break;
    }
    double norm = cell / (pow((double)S, dim) * p->U * (double)cnt);
    for (size_t i = 0; i < P->count; i++)
        P->data[i] *= norm;
    if (segments)
        *segments = cnt;
    return NL_OK;
}

int nl_psd_welch(const nl_field *x, size_t S, double mean, nl_field **out, size_t *segments)
{
    size_t n2[2] = {S, S};
    int st;
    nl_welch_plan *p;
    nl_field *P;
    *out = NULL;
    if (x->dim > 2)
        return NL_ERROR(NL_EINVAL, "welch: expected a 1D or 2D field, got %dD", x->dim);
    if (S < 4 || S > x->n[0] || (x->dim == 2 && S > x->n[1]))
        return NL_ERROR(NL_EINVAL, "welch: expected a segment of 4 samples up to the field's size, got %zu", S);
    if ((st = nl_welch_plan_alloc(x->dim, S, &p)))
        return st;
    P = nl_field_alloc(x->dim, n2, x->h, &st);
    if (P && (st = nl_welch_plan_execute(p, x, mean, P, segments))) {
        nl_field_free(P);
        P = NULL;
    }
    nl_welch_plan_free(p);
    *out = P;
    return P ? NL_OK : st;
}
