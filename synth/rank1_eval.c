/* Rank-1 lattice fields between the lattice points: the trigonometric
 * polynomial of Keller 2001, section 3.2, by direct sums or by a 2D FFT
 * through the lattice's wave vectors. */
#include "rank1.h"
#include "../core/fftw_plan.h"
#include "../core/field.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <string.h>

/* c_m as a complex number; the N/2 term is split in two halves at k and -k
 * (its real part: cos), so *pair says whether to add the mirror term. */
static double complex coef(const nl_rank1_lattice *L, const double *c, size_t m, int *pair)
{
    *pair = 2 * m == L->N;
    return (c[2 * m] + I * c[2 * m + 1]) * (*pair ? 0.5 : 1);
}

int nl_rank1_eval(const nl_rank1_lattice *L, const double *c, double extent, size_t count, const double *x, double *f,
                  double *grad, double *imag)
{
    int s = L->s;
    double im = 0;
    if (!(extent > 0) || !isfinite(extent))
        return NL_ERROR(NL_EINVAL, "rank-1 field: extent: expected a positive finite size, got %g", extent);
    for (size_t q = 0; q < count * (size_t)s; q++)
        if (!(fabs(x[q]) <= 1e9))
            return NL_ERROR(NL_EINVAL, "rank-1 field: point %zu: expected coordinates within 1e9, got %g", q / (size_t)s,
                            x[q]);
    for (size_t q = 0; q < count; q++) {
        const double *p = x + q * (size_t)s;
        double complex v = 0, g[NL_RANK1_MAX_DIM] = {0};
        for (size_t m = 0; m < L->N; m++) {
            int pair;
            double complex cm = coef(L, c, m, &pair);
            for (int side = 0; side <= pair; side++) {
                double ph = 0, sg = side ? -1 : 1;
                for (int a = 0; a < s; a++)
                    ph += sg * (double)L->k[m * (size_t)s + (size_t)a] * p[a];
                /* reduce the phase mod 1 before the exponential: exact for integer k */
                double complex e = cm * cexp(2 * M_PI * I * (ph - floor(ph)));
                v += e;
                for (int a = 0; grad && a < s; a++)
                    g[a] += I * 2 * M_PI * sg * (double)L->k[m * (size_t)s + (size_t)a] / extent * e;
            }
        }
        f[q] = creal(v), im = fmax(im, fabs(cimag(v)));
        for (int a = 0; grad && a < s; a++)
            grad[q * (size_t)s + (size_t)a] = creal(g[a]);
    }
    if (imag)
        *imag = im;
    return NL_OK;
}

/* Bin the coefficients (times the factor of component comp: -1 the field,
 * 0 or 1 the gradient) into b (W x W). */
static void bin(const nl_rank1_lattice *L, const double *c, double extent, size_t W, const double *at, int comp,
                fftw_complex *b)
{
    int s = L->s;
    memset(b, 0, W * W * sizeof *b);
    for (size_t m = 0; m < L->N; m++) {
        int pair;
        double complex cm = coef(L, c, m, &pair);
        for (int side = 0; side <= pair; side++) {
            const long *k = L->k + m * (size_t)s;
            double sg = side ? -1 : 1, ph = sg * (double)(k[0] + k[1]) / (2 * (double)W);
            for (int a = 2; a < s; a++)
                ph += sg * (double)k[a] * at[a - 2];
            double complex e = cm * cexp(2 * M_PI * I * (ph - floor(ph)));
            if (comp >= 0)
                e *= I * 2 * M_PI * sg * (double)k[comp] / extent;
            long W_ = (long)W, i = (((long)sg * k[0]) % W_ + W_) % W_, j = (((long)sg * k[1]) % W_ + W_) % W_;
            b[(size_t)j * W + (size_t)i] += e;
        }
    }
}

int nl_rank1_grid(const nl_rank1_lattice *L, const double *c, double extent, size_t W, const double *at, double *img,
                  double *gx, double *gy, double *imag)
{
    size_t n2[2] = {W, W};
    int st;
    if (L->s < 2 || W < 2 || W > 65536)
        return NL_ERROR(NL_EINVAL, "rank-1 grid: expected a lattice of 2 to 4 dimensions and 2 to 65536 pixels a side, "
                        "got %dD and %zu", L->s, W);
    if (!(extent > 0) || !isfinite(extent))
        return NL_ERROR(NL_EINVAL, "rank-1 grid: extent: expected a positive finite size, got %g", extent);
    for (int a = 2; a < L->s; a++)
        if (!(fabs(at[a - 2]) <= 1e9))
            return NL_ERROR(NL_EINVAL, "rank-1 grid: coordinate %d: expected a value within 1e9, got %g", a + 1,
                            at[a - 2]);
    if ((st = nl_size_check(2, n2, sizeof(fftw_complex), 1, NULL)))
        return st;
    fftw_complex *b = nl_alloc(W * W * sizeof *b);
    fftw_plan p = b ? fftw_plan_dft_2d((int)W, (int)W, b, b, FFTW_BACKWARD, nl_fftw_flags(W * W)) : NULL;
    double im = 0, *out[3] = {img, gx, gy};
    if (!p) {
        nl_free(b);
        return NL_ERROR(NL_ENOMEM, "cannot plan a %zu x %zu FFT", W, W);
    }
    for (int comp = -1; comp < (gx && gy ? 2 : 0); comp++) {
        bin(L, c, extent, W, at, comp, b);
        fftw_execute(p);
        for (size_t q = 0; q < W * W; q++)
            out[comp + 1][q] = creal(b[q]), im = fmax(im, fabs(cimag(b[q])));
    }
    if (imag)
        *imag = im;
    fftw_destroy_plan(p);
    nl_free(b);
    return NL_OK;
}
