/* Centred layouts, spectral profiles and sectors, the model's R at the lags
 * of an estimate, Bartlett's band and the per-bin density: each against its
 * definition (index arithmetic exactly; arithmetic to rounding). */
#include "../analysis/acf.h"
#include "../analysis/fftshift.h"
#include "../analysis/gof.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/spectral.h"
#include "../core/dist.h"
#include "../core/rng.h"
#include "../core/wk.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

static nl_field *ramp(int dim, const size_t *n)
{
    nl_field *f = nl_field_alloc(dim, n, NULL, NULL);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = (double)i;
    return f;
}

/* Zero frequency (index 0) lands at floor(n/2) on every axis, odd or even. */
Test(spectral, fftshift_moves_zero_to_the_centre)
{
    size_t n[3] = {5, 4, 3};
    nl_field *P = ramp(3, n), *C;
    cr_assert_eq(nl_fftshift_alloc(P, &C), 0);
    for (size_t k = 0; k < 3; k++)
        for (size_t j = 0; j < 4; j++)
            for (size_t i = 0; i < 5; i++)
                cr_assert_eq(C->data[(((k + 1) % 3) * 4 + (j + 2) % 4) * 5 + (i + 2) % 5], P->data[(k * 4 + j) * 5 + i]);
    nl_field_free(P), nl_field_free(C);
}

/* Lag l sits at index n - 1 + l, for l = -(n-1) .. n-1, in every axis. */
Test(spectral, acf_centred_layout)
{
    size_t n[2] = {6, 3};
    nl_field *x = ramp(2, n), *full, *C;
    cr_assert_eq(nl_acf_full(x, NAN, 0, &full), 0);
    cr_assert_eq(nl_acf_centred_alloc(full, &C), 0);
    cr_assert_eq(C->n[0], 11); cr_assert_eq(C->n[1], 5);
    for (long ly = -2; ly <= 2; ly++)
        for (long lx = -5; lx <= 5; lx++) {
            size_t sx = (size_t)(lx < 0 ? lx + 12 : lx), sy = (size_t)(ly < 0 ? ly + 6 : ly);
            cr_assert_eq(C->data[(size_t)(ly + 2) * 11 + (size_t)(lx + 5)], full->data[sy * 12 + sx]);
        }
    nl_field_free(x), nl_field_free(full), nl_field_free(C);
}

Test(spectral, log10_floor)
{
    nl_field *f = nl_field_alloc(1, (size_t[]){3}, NULL, NULL);
    f->data[0] = 0, f->data[1] = 1, f->data[2] = 100;
    cr_assert_eq(nl_fftshift_log10_floor(f, 1e-4), 100);
    cr_assert_float_eq(f->data[0], -2, 1e-15);
    cr_assert_eq(f->data[1], 0); cr_assert_eq(f->data[2], 2);
    nl_field_free(f);
}

/* 1D: the half spectrum at i / (n h); nD: a radial average whose counts add
 * up to the ordinates inside the smallest Nyquist radius (plus rounding of
 * the bin edge), and whose size is what nl_psd_profile_size says. */
Test(spectral, profiles)
{
    double h[2] = {0.5, 0.25}, freq[64], val[64];
    size_t cnt[64], nf, total = 0;
    nl_field *P = ramp(1, (size_t[]){10});
    P->h[0] = 0.5;
    cr_assert_eq(nl_psd_profile(P, freq, val, cnt, &nf), 0);
    cr_assert_eq(nf, 6);
    for (size_t i = 0; i < nf; i++) {
        cr_assert_eq(freq[i], (double)i / 5.0);
        cr_assert_eq(val[i], (double)i);
    }
    nl_field_free(P);
    P = nl_field_alloc(2, (size_t[]){16, 12}, h, NULL);
    for (size_t i = 0; i < P->count; i++)
        P->data[i] = 2.385;
    cr_assert_eq(nl_psd_profile(P, freq, val, cnt, &nf), 0);
    cr_assert_eq(nf, nl_psd_profile_size(P));
    cr_assert_eq(nf, (size_t)floor(1.0 / (1.0 / 8.0)) + 1);
    for (size_t b = 0; b < nf; b++) {
        total += cnt[b];
        if (cnt[b])
            cr_assert_float_eq(val[b], 2.385, 1e-14);
    }
    cr_assert(total > 0 && total <= P->count);
    nl_field_free(P);
}

/* The model's profile is the profile of the sampled spectrum. */
Test(spectral, model_profile)
{
    size_t n[2] = {16, 16}, nf, nt, cnt[40];
    double h[2] = {1, 1}, f[40], v[40], t[40];
    nl_model *m;
    nl_field *S = nl_field_alloc(2, n, h, NULL);
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    cr_assert_eq(nl_wk_sample_spectrum(m, S), 0);
    cr_assert_eq(nl_psd_profile(S, f, v, cnt, &nf), 0);
    cr_assert_eq(nl_psd_model_profile(m, 2, n, h, t, &nt), 0);
    cr_assert_eq(nt, nf);
    for (size_t b = 0; b < nf; b++)
        cr_assert(t[b] == v[b] || (isnan(t[b]) && isnan(v[b])));
    nl_model_free(m), nl_field_free(S);
}

/* A flat spectrum has equal sectors (anisotropy 1); power added along the
 * x axis (fy = 0) raises sector 0 only. */
Test(spectral, sectors)
{
    double s[18], a;
    nl_field *P = nl_field_alloc(2, (size_t[]){64, 64}, NULL, NULL);
    for (size_t i = 0; i < P->count; i++)
        P->data[i] = 1;
    cr_assert_eq(nl_psd_sectors(P, 18, 0.05, 0.45, s, &a), 0);
    cr_assert_eq(a, 1);
    for (size_t i = 0; i < 64; i++)
        P->data[i] = 50;
    cr_assert_eq(nl_psd_sectors(P, 18, 0.05, 0.45, s, &a), 0);
    cr_assert_gt(s[0], 1.5);
    for (int b = 1; b < 18; b++)
        cr_assert_eq(s[b], 1);
    cr_assert_eq(a, s[0]);
    nl_field_free(P);
}

/* R models: R at the lag; spectral models: the doubled grid's R at the
 * nearest lag, NAN from lag n on. */
Test(spectral, acf_model_values)
{
    size_t n[1] = {16};
    double h[1] = {0.5}, lag[3] = {0, 1.5, 8.0}, out[3], v[3] = {1.5, 0, 0};
    nl_model *m;
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    cr_assert_eq(nl_acf_model_values(m, 1, n, h, 0, lag, 3, out), 0);
    cr_assert_eq(out[1], nl_model_acf(m, 1, v));
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("spectrum:exp(-f*f*20)", &m), 0);
    nl_field *R = nl_field_alloc(1, (size_t[]){32}, h, NULL);
    cr_assert_eq(nl_wk_sample_acf(m, R), 0);
    cr_assert_eq(nl_acf_model_values(m, 1, n, h, 0, lag, 3, out), 0);
    cr_assert_eq(out[0], R->data[0]); cr_assert_eq(out[1], R->data[3]);
    cr_assert(isnan(out[2]));
    nl_field_free(R), nl_model_free(m);
}

/* The band is val -+ 1.959964 sqrt(Bartlett's variance) from the estimate
 * up to lag 4 maxlag. */
Test(spectral, bartlett_band)
{
    size_t n[1] = {200};
    double lag[6], val[6], lo[6], hi[6], var[6];
    nl_field *x = nl_field_alloc(1, n, NULL, NULL), *full;
    for (size_t i = 0; i < 200; i++)
        x->data[i] = nl_rng_gauss(3, 1, i);
    cr_assert_eq(nl_acf_full(x, NAN, 0, &full), 0);
    cr_assert_eq(nl_acf_axis(full, 0, 5, lag, val), 0);
    cr_assert_eq(nl_acf_bartlett_band(full, 200, 5, val, lo, hi), 0);
    cr_assert_eq(nl_acf_bartlett(full->data, 21, 200, 5, var), 0);
    for (int k = 0; k <= 5; k++) {
        cr_assert_float_eq(hi[k] - val[k], 1.959964 * sqrt(var[k]), 1e-15);
        cr_assert_float_eq(val[k] - lo[k], 1.959964 * sqrt(var[k]), 1e-15);
    }
    nl_field_free(x), nl_field_free(full);
}

/* Uniform on [0, 1]: density 1 in every bin inside, 0 outside. */
Test(spectral, gof_bin_density)
{
    double edges[5] = {-0.5, 0, 0.25, 1, 1.5}, pdf[4];
    nl_dist *d;
    cr_assert_eq(nl_dist_parse("uniform", &d), 0);
    cr_assert_eq(nl_gof_bin_density(d, edges, 4, pdf), 0);
    cr_assert_float_eq(pdf[0], 0, 1e-15); cr_assert_float_eq(pdf[1], 1, 1e-15);
    cr_assert_float_eq(pdf[2], 1, 1e-15); cr_assert_float_eq(pdf[3], 0, 1e-15);
    nl_dist_free(d);
}

/* The density integrates to 1 over the bins (widths times densities), and
 * the Gaussian column is the normal density at each midpoint. */
Test(spectral, hist_density)
{
    nl_field *x = nl_field_alloc(1, (size_t[]){500}, NULL, NULL);
    double mid[20], dens[20], g[20], total = 0, w;
    nl_moments mo;
    for (size_t i = 0; i < 500; i++)
        x->data[i] = nl_rng_gauss(8, 2, i);
    cr_assert_eq(nl_moments_compute(x, &mo), 0);
    cr_assert_eq(nl_hist_density(x, &mo, 20, mid, dens, g), 0);
    w = mid[1] - mid[0];
    for (int b = 0; b < 20; b++) {
        total += dens[b] * w;
        cr_assert_float_eq(g[b], exp(-0.5 * pow(mid[b] - mo.mean, 2) / mo.variance) / sqrt(2 * M_PI * mo.variance),
                           1e-14);
    }
    cr_assert_float_eq(total, 1, 1e-9);
    nl_field_free(x);
}

/* Bin 0 of the radial ACF holds lag 0 alone; bins are one spacing wide. */
Test(spectral, acf_radial)
{
    double h[2] = {0.5, 0.75}, lag[4], val[4];
    size_t cnt[4];
    nl_field *x = nl_field_alloc(2, (size_t[]){12, 10}, h, NULL), *full;
    for (size_t i = 0; i < x->count; i++)
        x->data[i] = nl_rng_gauss(9, 1, i);
    cr_assert_eq(nl_acf_full(x, NAN, 0, &full), 0);
    cr_assert_eq(nl_acf_radial(full, 4, lag, val, cnt), 0);
    cr_assert_eq(cnt[0], 1);
    cr_assert_eq(lag[0], 0);
    cr_assert_eq(val[0], full->data[0]);
    cr_assert_eq(cnt[1], 2); /* (+-0.5, 0) */
    nl_field_free(x), nl_field_free(full);
}
