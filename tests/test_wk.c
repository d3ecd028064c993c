/* Wiener-Khinchine conversion on sampled grids: exactness of the round trip,
 * agreement with closed forms (conventions: two-sided density, cycles per
 * unit length, lags in length units). */
#include "../core/field.h"
#include "../core/model.h"
#include "../core/mem.h"
#include "../core/wk.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

static nl_field *grid(int dim, size_t n, double h)
{
    size_t nn[3] = {n, n, n};
    double hh[3] = {h, h, h};
    nl_field *f = nl_field_alloc(dim, nn, hh, NULL);
    cr_assert_not_null(f);
    return f;
}

/* Forward then inverse is the identity up to rounding (~1e-15 relative). */
Test(wk, round_trip_2d)
{
    nl_field *R = grid(2, 48, 0.7), *S = grid(2, 48, 0.7), *R2 = grid(2, 48, 0.7);
    nl_model *m = test_model("markov:scale=3.1,angle=20,ratio=0.6");
    cr_assert_eq(nl_wk_sample_acf(m, R), 0);
    cr_assert_eq(nl_wk_acf_to_spectrum(R, S), 0);
    cr_assert_eq(nl_wk_spectrum_to_acf(S, R2), 0);
    for (size_t i = 0; i < R->count; i++)
        cr_assert_float_eq(R2->data[i], R->data[i], 1e-13);
    nl_field_free(R), nl_field_free(S), nl_field_free(R2), nl_model_free(m);
}

/* The DFT of a sampled exponential is known exactly:
 * h sum_j q^|j| e^{-i theta j} = h (1 - q^2) / (1 - 2 q cos theta + q^2),
 * q = exp(-h / scale); truncation at n/2 = 2048 lags adds q^2048 ~ 1e-56. */
Test(wk, sampled_markov_closed_form)
{
    double h = 0.5, s = 8, q = exp(-h / s);
    nl_field *S = grid(1, 4096, h);
    nl_model *m = test_model("markov:scale=8");
    cr_assert_eq(nl_wk_sample_spectrum(m, S), 0);
    for (size_t k = 0; k < 4096; k += 37) {
        double th = 2 * M_PI * (double)k / 4096;
        double want = h * (1 - q * q) / (1 - 2 * q * cos(th) + q * q);
        cr_assert_float_eq(S->data[k], want, 1e-10 * want, "k=%zu", k);
    }
    nl_field_free(S), nl_model_free(m);
}

/* With a fine spacing the grid spectrum of a Gaussian ACF equals its
 * continuous two-sided spectrum s sqrt(pi) exp(-(pi f s)^2): the aliased
 * copies at f + m/h are below exp(-(pi 4 * 4)^2) ~ 1e-1000. */
Test(wk, gauss_matches_continuous_spectrum)
{
    double h = 0.25;
    nl_field *S = grid(1, 1024, h);
    nl_model *m = test_model("gauss:scale=4,var=2");
    cr_assert_eq(nl_wk_sample_spectrum(m, S), 0);
    for (size_t k = 0; k < 60; k++) {
        double f = (double)k / (1024 * h);
        double want = nl_model_spectrum(m, 1, &f);
        cr_assert_float_eq(want, 2 * 4 * sqrt(M_PI) * exp(-pow(M_PI * f * 4, 2)), 1e-15);
        cr_assert_float_eq(S->data[k], want, 1e-9 * S->data[0], "k=%zu", k);
    }
    nl_field_free(S), nl_model_free(m);
}

/* A spectrum model in 2D: S(k) = pi s^2 exp(-(pi k s)^2) is the spectrum of
 * the isotropic Gaussian exp(-(r/s)^2); its sampled inverse must return it
 * (frequency grid resolution 1/(n h) = 1/32 resolves the spectrum, whose
 * width is 1/(pi s) = 0.106, and the lag-domain period 32 >> s = 3). */
Test(wk, spectrum_model_to_acf_2d)
{
    nl_field *R = grid(2, 64, 0.5);
    nl_model *m = test_model("spectrum:3.14159265358979*9*exp(-(3.14159265358979*k*3)^2)");
    cr_assert_eq(nl_wk_sample_acf(m, R), 0);
    for (size_t j = 0; j < 20; j++)
        for (size_t i = 0; i < 20; i++) {
            double x = i * 0.5, y = j * 0.5;
            cr_assert_float_eq(R->data[j * 64 + i], exp(-(x * x + y * y) / 9), 1e-9, "(%g, %g)", x, y);
        }
    nl_field_free(R), nl_model_free(m);
}

/* The half-grid sampler (r2c, in place, threaded) gives the full sampler's
 * values on the half grid, for even and odd axes, 1-3D, models defined by R
 * (transformed) and by S (sampled): both are the same DFT of the same
 * samples, so they agree to rounding (1e-12 of the largest value). */
Test(wk, half_grid_matches_full)
{
    static const struct {
        const char *spec;
        int dim;
        size_t n[3];
    } cases[] = {
        {"markov:scale=3", 1, {64}},
        {"gauss-osc:scale=4,omega=1", 1, {45}},
        {"markov:scale=3.1,angle=20,ratio=0.6", 2, {48, 30}},
        {"matern:nu=1.5,scale=2", 2, {33, 17}},
        {"power:d=2.6", 2, {40, 36}},
        {"expr:exp(-r*r/9)", 2, {20, 22}},
        {"markov:scale=2,zratio=0.5", 3, {12, 10, 9}},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        double h[3] = {0.7, 0.9, 1.1}, *half, top = 0;
        nl_model *m = test_model(cases[c].spec);
        nl_field *S = nl_field_alloc(cases[c].dim, cases[c].n, h, NULL);
        size_t h0 = cases[c].n[0] / 2 + 1, rows = S->count / S->n[0];
        cr_assert_eq(nl_wk_sample_spectrum(m, S), 0, "%s", cases[c].spec);
        cr_assert_eq(nl_wk_sample_spectrum_half(m, cases[c].dim, cases[c].n, h, &half), 0, "%s", cases[c].spec);
        for (size_t i = 0; i < S->count; i++)
            top = fmax(top, fabs(S->data[i]));
        for (size_t r = 0; r < rows; r++)
            for (size_t i = 0; i < h0; i++)
                cr_assert_float_eq(half[r * h0 + i], S->data[r * S->n[0] + i], 1e-12 * top, "%s at (%zu, %zu)",
                                   cases[c].spec, i, r);
        nl_free(half);
        nl_field_free(S), nl_model_free(m);
    }
}

/* Sampled lags are the model at the wrapped lag, bit for bit, on every row:
 * the mirrored half of the grid (copied, not evaluated) included.  Nyquist
 * rows and columns (averaged over both signs) are skipped on even axes. */
Test(wk, sampled_acf_is_the_model_at_every_wrapped_lag)
{
    static const struct {
        const char *spec;
        int dim;
        size_t n[3];
    } cases[] = {
        {"markov:scale=3.1,angle=20,ratio=0.6", 2, {48, 31}},
        {"oscillatory:scale=5,omega=0.7,angle=-35,ratio=0.4", 2, {27, 40}},
        {"gauss:scale=2,angle=10,ratio=0.7,zratio=0.5", 3, {12, 11, 9}},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        double h[3] = {0.7, 0.9, 1.1};
        nl_model *m = test_model(cases[c].spec);
        nl_field *R = nl_field_alloc(cases[c].dim, cases[c].n, h, NULL);
        size_t checked = 0;
        cr_assert_eq(nl_wk_sample_acf(m, R), 0, "%s", cases[c].spec);
        for (size_t k = 0; k < R->n[2]; k++)
            for (size_t j = 0; j < R->n[1]; j++)
                for (size_t i = 0; i < R->n[0]; i++) {
                    size_t idx[3] = {i, j, k};
                    double lag[3];
                    int nyq = 0;
                    for (int a = 0; a < cases[c].dim; a++) {
                        nyq |= R->n[a] % 2 == 0 && 2 * idx[a] == R->n[a];
                        lag[a] = (double)nl_wrap(idx[a], R->n[a]) * h[a];
                    }
                    if (nyq)
                        continue;
                    cr_assert_eq(R->data[(k * R->n[1] + j) * R->n[0] + i], nl_model_acf(m, cases[c].dim, lag),
                                 "%s at (%zu, %zu, %zu)", cases[c].spec, i, j, k);
                    checked++;
                }
        cr_assert_gt(checked, R->count / 2);
        nl_field_free(R), nl_model_free(m);
    }
}
