/* Experiment: the subdivision estimator as an all-pole filter (Lewis 1987,
 * eq. (8)) and the claim that oscillation needs a neighbourhood of four.
 * Period 6: not a power of two times the spacing (period 8 would put the
 * peak at the Nyquist frequency of the level of spacing 8, where a
 * negative two-point coefficient alone makes the oscillation).
 *
 * usage: lewis87_allpole RESP.tsv POLES.tsv ACF.tsv SUMMARY.tsv
 * Model R = cos(2 pi t / 6) exp(-|t| / 8) (period 6, spectral peak near
 * f0 = 1/6), a periodic 1D field of 1024 samples at spacing 1 in 7 levels
 * (coarse spacing 128, where R is e^-16: the coarse grid is white, so every
 * oscillation must come from the refinement).  For N = 1..6:
 *   - eq. (8), H(z) = 1 / (1 - sum_k a_k (z^(2k+1) + z^-(2k+1))), k = 0..N-1
 *     (a_k the coefficient of the observations at +-(2k+1) half-spacings),
 *     on the unit circle z = e^(i theta), theta in the level's fine grid:
 *     RESP.tsv "N level theta/pi |H|^2" at the level of spacing 4, where
 *     f0 falls at theta = 2 pi f0 * 2 = 2 pi / 3, and, for every level, the interior maxima
 *     (0 < theta < pi) of |H|^2;
 *   - the poles: the 4N - 2 roots of z^(2N-1) D(z) (POLES.tsv "N re im"),
 *     at the same level, by gsl_poly_complex_solve;
 *   - the exact ACF of the synthesised field (analysis/subdiv_exact.h) at
 *     lags 0..40 against R (ACF.tsv "N lag exact target"), its sign
 *     changes and its largest error.
 * SUMMARY.tsv: N, interior peaks of |H|^2 at any level, damped complex
 * poles (off the real axis and the unit circle) at the s = 4 level, that
 * level's highest interior peak theta/pi, sign changes of the field's ACF
 * over lags 0..40 (the target's: 13), max |exact - R| / R(0), damped
 * complex poles over all levels, complex poles on the unit circle over all
 * levels. */
#include "../analysis/subdiv_exact.h"
#include "../core/model.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { LEVELS = 7, NTH = 1024, NLAG = 41 };

/* D(theta) = 1 - 2 sum_k a_k cos((2k+1) theta); a_k = a[N + k] (the
 * coefficient of the observation at k + 1 in neighbourhood order). */
static double denom(const double *a, int N, double th)
{
    double d = 1;
    for (int k = 0; k < N; k++)
        d -= 2 * a[N + k] * cos((2 * k + 1) * th);
    return d;
}

/* Interior maxima of |H|^2 = 1 / D^2 on theta in (0, pi); *where the
 * largest one's theta / pi (NAN when none). */
static int peaks(const double *a, int N, FILE *resp, int level, double *where)
{
    double h[NTH + 1], best = 0;
    int n = 0;
    *where = NAN;
    for (int i = 0; i <= NTH; i++) {
        double d = denom(a, N, M_PI * i / NTH);
        h[i] = 1 / (d * d);
        if (resp)
            fprintf(resp, "%d\t%d\t%.6f\t%.8g\n", N, level, (double)i / NTH, h[i]);
    }
    if (resp)
        fprintf(resp, "\n\n");
    /* a maximum counts when it stands 1% above the lowest value on each
     * side of it (not the rounding ripples of a flat response) */
    for (int i = 1; i < NTH; i++) {
        double lo = h[i], hi = h[i];
        if (!(h[i] > h[i - 1] && h[i] >= h[i + 1]))
            continue;
        for (int j = 0; j < i; j++)
            lo = fmin(lo, h[j]);
        for (int j = i + 1; j <= NTH; j++)
            hi = fmin(hi, h[j]);
        if (h[i] > 1.01 * lo && h[i] > 1.01 * hi) {
            n++;
            if (h[i] > best)
                best = h[i], *where = (double)i / NTH;
        }
    }
    return n;
}

/* The 4N - 2 roots of z^(2N-1) D(z) (to out unless NULL); the number off
 * the real axis and off the unit circle (a damped oscillatory pair with
 * its reciprocal) and, in *oncircle, those on it (|z| = 1 to 1e-6: an
 * undamped one). */
static int poles(const double *a, int N, FILE *out, int *oncircle)
{
    int deg = 4 * N - 2, ncx = 0;
    double c[4 * 16], z[2 * 4 * 16];
    for (int i = 0; i <= deg; i++)
        c[i] = 0;
    c[2 * N - 1] = 1;
    for (int k = 0; k < N; k++) {
        c[2 * N - 1 + 2 * k + 1] -= a[N + k];
        c[2 * N - 1 - 2 * k - 1] -= a[N + k];
    }
    gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc((size_t)deg + 1);
    if (!w || gsl_poly_complex_solve(c, (size_t)deg + 1, w, z)) {
        gsl_poly_complex_workspace_free(w);
        return -1;
    }
    for (int i = 0; i < deg; i++) {
        if (out)
            fprintf(out, "%d\t%.10g\t%.10g\n", N, z[2 * i], z[2 * i + 1]);
        if (fabs(z[2 * i + 1]) > 1e-9) {
            int on = fabs(hypot(z[2 * i], z[2 * i + 1]) - 1) < 1e-6;
            ncx += !on, *oncircle += on;
        }
    }
    if (out)
        fprintf(out, "\n\n");
    gsl_poly_complex_workspace_free(w);
    return ncx;
}

/* The exact ACF of the field made with N; its sign changes over the lags
 * and the largest error. */
static void field_acf(const nl_model *m, const nl_subdiv_coeffs *c, int N, FILE *acf, int *changes, double *err)
{
    long lags[2 * NLAG];
    double ex[NLAG];
    for (int i = 0; i < NLAG; i++)
        lags[2 * i] = i, lags[2 * i + 1] = 0;
    nl_subdiv_exact_acf(c, m, 1024, 1, NLAG, lags, ex);
    *changes = 0, *err = 0;
    for (int i = 0; i < NLAG; i++) {
        double lag = i, r = nl_model_acf(m, 1, &lag);
        *err = fmax(*err, fabs(ex[i] - r) / c->r0);
        if (i > 0 && (ex[i] < 0) != (ex[i - 1] < 0))
            ++*changes;
        fprintf(acf, "%d\t%d\t%.8g\t%.8g\n", N, i, ex[i] / c->r0, r / c->r0);
    }
    fprintf(acf, "\n\n");
}

int main(int argc, char **argv)
{
    FILE *resp, *pol, *acf, *sum;
    nl_model *m;
    if (argc != 5) {
        fprintf(stderr, "usage: lewis87_allpole RESP.tsv POLES.tsv ACF.tsv SUMMARY.tsv\n");
        return 2;
    }
    gsl_set_error_handler_off();
    resp = fopen(argv[1], "w"), pol = fopen(argv[2], "w"), acf = fopen(argv[3], "w"), sum = fopen(argv[4], "w");
    if (!resp || !pol || !acf || !sum || nl_model_parse("oscillatory:omega=1.0471975512,scale=8", &m))
        return 1;
    for (int N = 1; N <= 6; N++) {
        nl_subdiv_coeffs *c;
        int anyp = 0, ncx = 0, damped = 0, undamped = 0, changes;
        double at = NAN, err;
        if (nl_subdiv_coeffs_alloc(m, 1, LEVELS, ldexp(1.0, LEVELS), N, 1e-4, 16, &c))
            return 1;
        for (int k = 0; k < LEVELS; k++) {
            const nl_subdiv_level *l = &c->level[k];
            double w;
            int s4 = l->spacing == 4.0;
            int np = peaks(l->cls[0].a, N, s4 ? resp : NULL, k, &w);
            int d = poles(l->cls[0].a, N, s4 ? pol : NULL, &undamped);
            anyp += np;
            damped += d;
            if (s4)
                at = w, ncx = d;
        }
        field_acf(m, c, N, acf, &changes, &err);
        fprintf(sum, "%d\t%d\t%d\t%.4f\t%d\t%.4f\t%d\t%d\n", N, anyp, ncx, at, changes, err, damped, undamped);
        nl_subdiv_coeffs_free(c);
    }
    nl_model_free(m);
    fclose(resp), fclose(pol), fclose(acf), fclose(sum);
    return 0;
}
