/* Positive definiteness of an isotropic R that decays slowly or not at all,
 * judged on the spectrum of R times a Gaussian taper.
 *
 * The product of two positive definite functions is positive definite
 * (Schur), and exp(-(r/T)^2) is positive definite in every dimension
 * (Schoenberg 1938), so R valid in d makes R_T = R exp(-(r/T)^2) valid in
 * d: its spectrum S_T = S * G_T (a convolution with a positive Gaussian of
 * width 1 / (pi T)) is >= 0.  The samples of R_T on a lattice of spacing h
 * have the discrete Fourier transform sum_m S_T(k + m / h) (Poisson), a sum
 * of non-negative terms: a negative value beyond rounding is a proof that R
 * is not positive definite, with no truncation artefact (R_T is below
 * exp(-36) R(0) at the periodic grid's edge) and no singularity at the
 * origin (an integrable S ~ |k|^(b-d) of a power-law tail r^-b, b < d, is
 * smoothed to a finite peak).  Conversely a negative lobe of S wider than
 * 1 / (pi T), or a negative high-frequency tail (a power r^a, 2 < a < 4, at
 * the origin: S ~ -|k|^-(d+a)), survives the convolution and the aliasing.
 *
 * The lattice (nl_taper_grid): 65536 points of spacing L0 / 16 in 1D,
 * 1024^2 of L0 / 8 in 2D, 128^3 of L0 / 4 in 3D (L0 the lag where R first
 * falls appreciably), T = n h / 12; a coarse lattice has 16 times fewer
 * points per axis in 1D and 4 times fewer in 2D and 3D, at the same
 * spacing.  R is evaluated once per distinct |lag|^2 (a multiple of h^2),
 * so a 3D grid costs a few thousand evaluations. */
#include "taper_internal.h"
#include "mem.h"
#include "nl_error.h"
#include "wk.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double nl_taper_scale(const nl_model *m, int dim)
{
    double lag[3] = {1e-7, 0, 0}, r0 = nl_model_acf(m, dim, lag);  /* R(0+): without a nugget */
    for (double frac = 0.5; frac > 0.001; frac /= 50)
        for (double t = 1e-6; t < 1048576; t *= 1.05) {
            lag[0] = t;
            if (fabs(r0 - nl_model_acf(m, dim, lag)) >= frac * fabs(r0))
                return t;
        }
    return 1;
}

void nl_taper_grid(int dim, double L0, int coarse, size_t *n, double *h, double *T)
{
    *n = dim == 1 ? 65536 : dim == 2 ? 1024 : 128;
    if (coarse)
        *n /= dim == 1 ? 16 : 4;
    *h = L0 / (dim == 1 ? 16 : dim == 2 ? 8 : 4);
    *T = (double)*n * *h / 12;
}

/* |k| (cycles per unit) of the wrapped index i of S. */
static double grid_k(const nl_field *S, size_t i)
{
    size_t n = S->n[0];
    double k2 = 0, df = 1 / ((double)n * S->h[0]);
    for (int a = 0; a < S->dim; a++, i /= n) {
        double w = (double)nl_wrap(i % n, n) * df;
        k2 += w * w;
    }
    return sqrt(k2);
}

/* The table's index of the wrapped index i of an n^dim grid: the squared
 * integer distance (|i| itself in 1D, where squares would be sparse). */
static size_t q_of(size_t i, size_t n, int dim)
{
    if (dim == 1)
        return (size_t)labs(nl_wrap(i, n));
    size_t q = 0;
    for (int a = 0; a < dim; a++, i /= n) {
        long w = nl_wrap(i % n, n);
        q += (size_t)(w * w);
    }
    return q;
}

/* R_T at every distinct q = |lag|^2 / h^2 that the grid holds: tab[q]. */
static double *taper_table(const nl_model *m, int dim, size_t n, double h, double T, size_t count)
{
    size_t qmax = dim == 1 ? n / 2 : (size_t)dim * (n / 2) * (n / 2);
    double *tab = nl_alloc((qmax + 1) * sizeof *tab);
    unsigned char *need = calloc(qmax + 1, 1);
    if (!tab || !need) {
        nl_free(tab), free(need);
        return NULL;
    }
    for (size_t i = 0; i < count; i++)
        need[q_of(i, n, dim)] = 1;
    for (size_t q = 0; q <= qmax; q++) {
        double r = (dim == 1 ? (double)q : sqrt((double)q)) * h, lag[3] = {r, 0, 0}, e = (r / T) * (r / T);
        tab[q] = need[q] && e < 40 ? nl_model_acf(m, dim, lag) * exp(-e) : 0;
    }
    free(need);
    return tab;
}

int nl_taper_spectrum(const nl_model *m, int dim, double L0, int coarse, nl_taper_result *out)
{
    size_t n, nn[3];
    double h, T, hh[3], *tab, abs_sum = 0, cell;
    nl_field *R, *S;
    int st;
    memset(out, 0, sizeof *out);
    nl_taper_grid(dim, L0, coarse, &n, &h, &T);
    nn[0] = nn[1] = nn[2] = n;
    hh[0] = hh[1] = hh[2] = h;
    R = nl_field_alloc(dim, nn, hh, NULL);
    S = nl_field_alloc(dim, nn, hh, NULL);
    tab = R ? taper_table(m, dim, n, h, T, R->count) : NULL;
    if (!R || !S || !tab) {
        nl_field_free(R), nl_field_free(S), nl_free(tab);
        return NL_ERROR(NL_ENOMEM, "out of memory for the tapered %dD spectrum", dim);
    }
    cell = pow(h, dim);
    for (size_t i = 0; i < R->count; i++) {
        R->data[i] = tab[q_of(i, n, dim)];
        abs_sum += fabs(R->data[i]) * cell;
    }
    nl_free(tab);
    st = nl_wk_acf_to_spectrum(R, S);
    nl_field_free(R);
    if (st) {
        nl_field_free(S);
        return st;
    }
    out->min = INFINITY;
    for (size_t i = 0; i < S->count; i++) {
        out->max = fmax(out->max, S->data[i]);
        if (S->data[i] < out->min)
            out->min = S->data[i], out->min_k = grid_k(S, i);
    }
    nl_field_free(S);
    out->kmax = 0.5 / h;
    out->taper = T;
    /* rounding: each sample carries a few ulps from R and the taper, the
     * FFT adds O(eps log2 N) of the sum of magnitudes; 1e-11 of that sum
     * is well above both (1e-13 for 2^21 points) */
    out->rounding = 1e-11 * abs_sum;
    return NL_OK;
}
