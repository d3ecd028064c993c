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
 * so a 3D grid costs a few thousand evaluations, and R_T being even, the
 * transform is a type-I cosine transform of one orthant. */
#include "taper_internal.h"
#include "fftw_plan.h"
#include "mem.h"
#include "nl_error.h"

#include <fftw3.h>

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
    return 0;
}

void nl_taper_grid(int dim, double L0, int coarse, size_t *n, double *h, double *T)
{
    *n = dim == 1 ? 65536 : dim == 2 ? 1024 : 128;
    if (coarse)
        *n /= dim == 1 ? 16 : 4;
    *h = L0 / (dim == 1 ? 16 : dim == 2 ? 8 : 4);
    *T = (double)*n * *h / 12;
}

/* The squared integer distance of index i of the N^dim quarter grid
 * (indices 0..N-1 per axis, axis 0 fastest). */
static size_t q_of(size_t i, size_t N, int dim)
{
    size_t q = 0;
    for (int a = 0; a < dim; a++, i /= N)
        q += (i % N) * (i % N);
    return q;
}

/* R_T at every distinct q = |lag|^2 / h^2 of the quarter grid: tab[q]
 * (tab[j] = R_T(j h) in 1D, where squares would be sparse). */
static double *taper_table(const nl_model *m, int dim, size_t N, double h, double T, size_t count)
{
    size_t qmax = dim == 1 ? N - 1 : (size_t)dim * (N - 1) * (N - 1);
    double *tab = nl_alloc((qmax + 1) * sizeof *tab);
    unsigned char *need = calloc(qmax + 1, 1);
    if (!tab || !need) {
        nl_free(tab), free(need);
        return NULL;
    }
    for (size_t i = 0; i < count; i++)
        need[dim == 1 ? i : q_of(i, N, dim)] = 1;
    for (size_t q = 0; q <= qmax; q++) {
        double r = (dim == 1 ? (double)q : sqrt((double)q)) * h, lag[3] = {r, 0, 0}, e = (r / T) * (r / T);
        tab[q] = need[q] && e < 40 ? nl_model_acf(m, dim, lag) * exp(-e) : 0;
    }
    free(need);
    return tab;
}

/* The transform: R_T is even, so its DFT over the n^dim periodic grid is
 * the type-I DCT (FFTW_REDFT00) of the N = n/2 + 1 samples per axis from
 * lag 0 to the Nyquist lag n h / 2, in place. */
static int dct(double *x, int dim, size_t N)
{
    int dims[3] = {(int)N, (int)N, (int)N};
    fftw_r2r_kind kinds[3] = {FFTW_REDFT00, FFTW_REDFT00, FFTW_REDFT00};
    size_t count = dim == 1 ? N : dim == 2 ? N * N : N * N * N;
    fftw_plan p = fftw_plan_r2r(dim, dims, x, x, kinds, nl_fftw_flags(count) | FFTW_DESTROY_INPUT);
    if (!p)
        return NL_ERROR(NL_EFAIL, "FFTW could not plan a %d-D type-I cosine transform of %zu points", dim, count);
    fftw_execute(p);
    fftw_destroy_plan(p);
    return NL_OK;
}

int nl_taper_spectrum(const nl_model *m, int dim, double L0, int coarse, nl_taper_result *out)
{
    size_t n, N, count;
    double h, T, *x, *tab, abs_sum = 0, cell, df;
    int st;
    memset(out, 0, sizeof *out);
    nl_taper_grid(dim, L0, coarse, &n, &h, &T);
    N = n / 2 + 1;
    count = dim == 1 ? N : dim == 2 ? N * N : N * N * N;
    x = nl_alloc(count * sizeof *x);
    tab = x ? taper_table(m, dim, N, h, T, count) : NULL;
    if (!x || !tab) {
        nl_free(x), nl_free(tab);
        return NL_ERROR(NL_ENOMEM, "out of memory for the tapered %dD spectrum", dim);
    }
    cell = pow(h, dim);
    for (size_t i = 0; i < count; i++) {
        /* each sample stands for its 2^(axes off 0 and off Nyquist) mirror images */
        double w = 1;
        for (size_t j = i, a = 0; a < (size_t)dim; a++, j /= N)
            w *= j % N == 0 || j % N == N - 1 ? 1 : 2;
        x[i] = tab[dim == 1 ? i : q_of(i, N, dim)];
        abs_sum += w * fabs(x[i]) * cell;
    }
    nl_free(tab);
    if (!isfinite(abs_sum)) {
        /* R not finite at some lag: no spectrum to judge (the caller's
         * own checks name the lag) */
        nl_free(x);
        out->min = out->max = NAN;
        return NL_OK;
    }
    if ((st = dct(x, dim, N))) {
        nl_free(x);
        return st;
    }
    df = 1 / ((double)n * h);
    out->min = INFINITY;
    for (size_t i = 0; i < count; i++) {
        double v = x[i] * cell;
        out->max = fmax(out->max, v);
        if (v < out->min)
            out->min = v, out->min_k = sqrt((double)q_of(i, N, dim)) * df;
    }
    nl_free(x);
    out->kmax = 0.5 / h;
    out->taper = T;
    /* rounding: each sample carries a few ulps from R and the taper, the
     * FFT adds O(eps log2 N) of the sum of magnitudes; 1e-11 of that sum
     * is well above both (1e-13 for 2^21 points) */
    out->rounding = 1e-11 * abs_sum;
    return NL_OK;
}

/* The registry's test (taper_internal.h): subdivision's local matrices
 * and its coarse level are positive definite for models that are not
 * (Bohman's in 2D: its spectrum dips below 0 only near 1.6 cycles per
 * unit of its range, beyond the coarse grid's band), a periodic FFT grid
 * sums a negative integral's tail away, and no grid reaches the lobes of
 * an edge singularity.  The tapered spectrum on the coarse lattice (4096
 * points in 1D, 256^2 in 2D, 32^3 in 3D), then 8 and 64 times coarser for
 * a taper wide enough to see R's tail, and the edge asymptotics; a few
 * milliseconds in 1D and 2D. */
int nl_model_sign_check(const nl_model *m, int dim)
{
    nl_taper_result t;
    double L0;
    int st;
    /* exemplars interpolate a table between lags: not exact in sign */
    if (!nl_model_has_acf(m) || nl_model_is_spectral(m) || nl_model_is_intrinsic(m) ||
        nl_model_family(m) == &nl_family_image || (dim > 1 && !nl_model_is_isotropic(m)))
        return NL_OK;
    if (!((L0 = nl_taper_scale(m, dim)) > 0))
        return NL_OK; /* flat over 2^20 lags: a constant, valid */
    for (int j = 0; j < 3; j++) {
        if ((st = nl_taper_spectrum(m, dim, L0 * pow(8, j), 1, &t)))
            return st;
        if (t.min < -t.rounding)
            return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: the %dD spectrum of R times a Gaussian "
                            "taper of width %.3g (positive for every valid R) is %.3g times its largest value at "
                            "|k| = %.3g cycles per unit (noiselab check says why; --clamp to synthesise anyway)",
                            nl_model_spec(m), dim, dim, t.taper, t.min / t.max, t.min_k);
    }
    if (nl_model_negative_tail(m, dim, L0))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: R ~ -c r^-b with b <= %d far out, so the "
                        "integral of R over the %dD space is -infinity (noiselab check says why; --clamp to "
                        "synthesise anyway)", nl_model_spec(m), dim, dim, dim);
    if (nl_model_edge_invalid(m, dim, 64 * L0))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: R vanishes beyond a lag with an edge "
                        "singularity that its behaviour at lag 0 does not outweigh, so its %dD spectrum is negative "
                        "at high |k| (noiselab check says why; --clamp to synthesise anyway)",
                        nl_model_spec(m), dim, dim);
    return NL_OK;
}

