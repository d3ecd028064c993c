/* Poisson faulting: its spectrum is f^-2 (1D) and k^-3 radially (2D),
 * checked by the fitted slope of the ensemble-mean periodogram containing
 * the theoretical value in its 95% confidence interval.  Bands: the
 * discrete random walk's spectrum is 1/(4 sin^2(pi f)), within 1% of a
 * power law only below f = 0.05, and the lowest frequencies (< 16 / n in
 * 1D, < 8 / n in 2D) see the finite domain; the fit uses what lies between. */
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../analysis/slope.h"
#include "../core/nl_error.h"
#include "../synth/faulting.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

Test(faulting, spectrum_is_f_minus_2_in_1d)
{
    size_t n[1] = {8192}, K;
    nl_field *f = nl_field_alloc(1, n, NULL, NULL), *P;
    double *acc = calloc(4097, sizeof *acc), *fr = malloc(4097 * sizeof *fr);
    nl_slope sl;
    for (uint64_t s = 1; s <= 32; s++) {
        cr_assert_eq(nl_synth_faulting(s, 1.0, f, &K), 0);
        cr_assert_eq(nl_psd_periodogram(f, NAN, &P), 0);
        for (int i = 0; i <= 4096; i++)
            acc[i] += P->data[i] / 32;
        nl_field_free(P);
    }
    for (int i = 0; i <= 4096; i++)
        fr[i] = i / 8192.0;
    cr_assert_eq(nl_psd_slope(fr, acc, 4097, 16 / 8192.0, 0.05, 1, &sl), 0);
    cr_log_info("faulting 1D: slope %.3f +- %.3f", sl.slope, sl.ci95);
    cr_expect_leq(fabs(sl.slope + 2), sl.ci95, "slope %.4f +- %.4f excludes -2", sl.slope, sl.ci95);
    cr_expect_float_eq(sl.fractal_dim, 1 + (3 + sl.slope) / 2, 1e-12);
    free(acc), free(fr), nl_field_free(f);
}

Test(faulting, spectrum_is_k_minus_3_in_2d)
{
    size_t n[2] = {256, 256}, K, c[129];
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *P;
    double acc[129] = {0}, r[129], v[129];
    nl_slope sl;
    for (uint64_t s = 1; s <= 16; s++) {
        cr_assert_eq(nl_synth_faulting(s, 4.0, f, &K), 0);
        cr_assert_eq(nl_psd_periodogram(f, NAN, &P), 0);
        cr_assert_eq(nl_radial(P, NL_GRID_FREQ, 1 / 256.0, 129, r, v, c), 0);
        for (int i = 0; i < 129; i++)
            acc[i] += v[i] / 16;
        nl_field_free(P);
    }
    cr_assert_eq(nl_psd_slope(r, acc, 129, 8 / 256.0, 0.1, 2, &sl), 0);
    cr_log_info("faulting 2D: radial slope %.3f +- %.3f", sl.slope, sl.ci95);
    cr_expect_leq(fabs(sl.slope + 3), sl.ci95, "slope %.4f +- %.4f excludes -3", sl.slope, sl.ci95);
    /* a Brownian surface: D = 3 - H = 2.5; D moves by half the slope, so its
     * interval is half the slope's */
    cr_expect_leq(fabs(sl.fractal_dim - 2.5), sl.ci95 / 2, "D %.4f", sl.fractal_dim);
    nl_field_free(f);
}

Test(faulting, deterministic_and_validated)
{
    size_t n[2] = {64, 48}, K1, K2;
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_synth_faulting(9, 2.0, a, &K1), 0);
    cr_assert_eq(nl_synth_faulting(9, 2.0, b, &K2), 0);
    cr_assert_eq(K1, K2);
    cr_assert_eq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    cr_expect_eq(nl_synth_faulting(9, -1.0, a, &K1), NL_EINVAL);
    cr_expect_eq(nl_synth_faulting(9, 1e12, a, &K1), NL_ETOOBIG);
    nl_field_free(a), nl_field_free(b);
}

/* The slope fit on exact power-law data: slope exact, interval ~0. */
Test(slope, exact_power_law)
{
    double f[100], p[100];
    nl_slope sl;
    for (int i = 0; i < 100; i++)
        f[i] = 0.001 * (i + 1), p[i] = 3.7 * pow(f[i], -2.385);
    cr_assert_eq(nl_psd_slope(f, p, 100, 0.005, 0.08, 2, &sl), 0);
    cr_expect_float_eq(sl.slope, -2.385, 1e-10);
    cr_expect_lt(sl.ci95, 1e-8);
    cr_expect_eq(sl.points, 76);
    /* radial slope of a 2D spectrum: the profile exponent is 2.385 - 1 */
    cr_expect_float_eq(sl.fractal_dim, 2 + (3 - 1.385) / 2, 1e-10);
    cr_expect_eq(nl_psd_slope(f, p, 100, 0.5, 0.6, 2, &sl), NL_EINVAL);
}
