/* The Wiener-interpolated noise lattice (synth/lattice.h).
 *
 * 1. Interpolation (exact, tolerance 1e-12 = rounding of a 16-term sum):
 *    the weights of the node offset are the unit vector on that node, the
 *    field equals the lattice values there, and the weights of every
 *    offset reproduce a constant as well as R allows (they sum to <= 1).
 * 2. Implementation against its own exact ACF: for a sample at offset u of
 *    its cell, E x(t) x(t + l) = sum_a sum_b w_a(u) w_b(v) R((s + b - a) c)
 *    (v = (u + l) mod c, s = floor((u + l) / c)); averaged over u this is
 *    what the ensemble-mean ACF estimates.  The z test of the ensemble
 *    against it, max |z| over the lags below the Bonferroni threshold of
 *    Student's t(M - 1) at a family-wise rate of 1e-3, fails with
 *    probability 1e-3 for a correct implementation.
 * 3. The paper's claim ("greater spectral control"): at equal finest
 *    lattice spacing (4 samples), the Wiener lattice's ACF error against
 *    gauss:scale=8 is smaller than the Perlin octave sum's: the
 *    simultaneous 95% interval of the largest |mean ACF - R| / R(0) over
 *    the lags (analysis/validate.h, nl_validate_effect_of) for Wiener lies
 *    wholly below Perlin's. */
#include "../analysis/acf.h"
#include "../analysis/validate.h"
#include "../analysis/verdict.h"
#include "../core/mem.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/lattice.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

enum { NS = 4096, M = 64, NL = 25 };

Test(lattice_wiener, interpolates_the_lattice)
{
    nl_model *m;
    nl_synth_lattice_wiener_plan *p;
    size_t n[2] = {96, 64};
    double w[16], *L;
    cr_assert_eq(nl_model_parse("markaussian:alpha=1.5,scale=7.385", &m), 0);
    cr_assert_eq(nl_synth_lattice_wiener_plan_alloc(m, 2, n, 4, 0, &p), NL_OK);
    int u0[2] = {0, 0};
    nl_synth_lattice_wiener_weights(p, u0, w);
    for (int q = 0; q < 16; q++)
        cr_expect_float_eq(w[q], q == 5 ? 1.0 : 0.0, 1e-12, "node weight %d = %g", q, w[q]);
    for (int uy = 0; uy < 4; uy++)
        for (int ux = 0; ux < 4; ux++) {
            int u[2] = {ux, uy};
            double s = 0;
            nl_synth_lattice_wiener_weights(p, u, w);
            for (int q = 0; q < 16; q++)
                s += w[q];
            cr_expect(s <= 1 + 1e-12 && s > 0.5, "offset (%d, %d): weights sum to %g", ux, uy, s);
        }
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_synth_lattice_wiener_execute(p, 7, f, &L), NL_OK);
    for (size_t j = 0; j < 16; j++)
        for (size_t i = 0; i < 24; i++)
            cr_expect_float_eq(f->data[4 * j * 96 + 4 * i], L[j * 24 + i], 1e-12, "node (%zu, %zu)", i, j);
    nl_free(L), nl_field_free(f);
    nl_synth_lattice_wiener_plan_free(p);
    nl_model_free(m);
}

/* Ensemble mean and se of the unbiased ACF (known mean 0) at lags 0..NL-1. */
static void ensemble(nl_field *f, int (*make)(void *, uint64_t, nl_field *), void *ctx, double *mean, double *se)
{
    double s1[NL] = {0}, s2[NL] = {0}, lag[NL], v[NL];
    for (uint64_t k = 1; k <= M; k++) {
        nl_field *full;
        cr_assert_eq(make(ctx, k, f), NL_OK);
        cr_assert_eq(nl_acf_full(f, 0, 1, &full), NL_OK);
        cr_assert_eq(nl_acf_axis(full, 0, NL - 1, lag, v), NL_OK);
        for (int l = 0; l < NL; l++)
            s1[l] += v[l], s2[l] += v[l] * v[l];
        nl_field_free(full);
    }
    for (int l = 0; l < NL; l++) {
        mean[l] = s1[l] / M;
        se[l] = sqrt(fmax(s2[l] / M - mean[l] * mean[l], 0) * M / (M - 1) / M);
    }
}

static int make_wiener(void *ctx, uint64_t seed, nl_field *f)
{
    return nl_synth_lattice_wiener_execute(ctx, seed, f, NULL);
}

static int make_perlin(void *ctx, uint64_t seed, nl_field *f) { return nl_synth_lattice_execute(ctx, seed, f); }

/* The exact position-averaged ACF of the Wiener lattice (module comment, 2). */
static double wiener_expected(const nl_synth_lattice_wiener_plan *p, const nl_model *m, int c, int l)
{
    double e = 0, wu[4], wv[4];
    for (int u = 0; u < c; u++) {
        int v = (u + l) % c, s = (u + l) / c;
        nl_synth_lattice_wiener_weights(p, &u, wu);
        nl_synth_lattice_wiener_weights(p, &v, wv);
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++) {
                double lag[1] = {(double)((s + b - a) * c)};
                e += wu[a] * wv[b] * nl_model_acf(m, 1, lag);
            }
    }
    return e / c;
}

Test(lattice_wiener, acf_is_its_own_and_closer_than_perlin)
{
    nl_model *m;
    nl_synth_lattice_wiener_plan *wp;
    nl_synth_lattice_plan pp;
    size_t n[1] = {NS};
    nl_field *f = nl_field_alloc(1, n, NULL, NULL);
    double mw[NL], sw[NL], mp[NL], sp[NL], R[NL], E[NL];
    cr_assert_eq(nl_model_parse("gauss:scale=8", &m), 0);
    cr_assert_eq(nl_synth_lattice_wiener_plan_alloc(m, 1, n, 4, 0, &wp), NL_OK);
    cr_assert_eq(nl_synth_lattice_plan_init(m, 1, 64, 5, 0, &pp), NL_OK); /* cells 64 .. 4 */
    ensemble(f, make_wiener, wp, mw, sw);
    ensemble(f, make_perlin, &pp, mp, sp);
    for (int l = 0; l < NL; l++) {
        double lag[1] = {l};
        R[l] = nl_model_acf(m, 1, lag);
        E[l] = wiener_expected(wp, m, 4, l);
    }
    size_t worst;
    double z = nl_verdict_zmax(NL, mw, sw, E, &worst), thr = nl_verdict_threshold(1e-3, NL, M - 1);
    cr_log_info("wiener vs its exact ACF: max |z| %.2f at lag %zu (threshold %.2f)", z, worst, thr);
    cr_expect_leq(z, thr, "the Wiener lattice misses its own exact ACF: |z| %.2f at lag %zu", z, worst);
    nl_validate_effect ew, ep;
    double c = nl_verdict_threshold(0.05, NL, M - 1);
    nl_validate_effect_of(NL, mw, sw, R, R[0], c, c, &ew, &worst);
    nl_validate_effect_of(NL, mp, sp, R, R[0], c, c, &ep, &worst);
    cr_log_info("ACF error: wiener %.4f [%.4f, %.4f], perlin %.4f [%.4f, %.4f]", ew.effect.est, ew.effect.lo,
                ew.effect.hi, ep.effect.est, ep.effect.lo, ep.effect.hi);
    cr_expect_lt(ew.effect.hi, ep.effect.lo, "wiener %.4f [%.4f, %.4f] not below perlin %.4f [%.4f, %.4f]",
                 ew.effect.est, ew.effect.lo, ew.effect.hi, ep.effect.est, ep.effect.lo, ep.effect.hi);
    nl_field_free(f);
    nl_synth_lattice_wiener_plan_free(wp);
    nl_model_free(m);
}

Test(lattice_wiener, refusals)
{
    nl_model *m, *s;
    nl_synth_lattice_wiener_plan *p;
    size_t n[2] = {64, 64}, odd[2] = {66, 64};
    cr_assert_eq(nl_model_parse("gauss:scale=4", &m), 0);
    cr_assert_eq(nl_model_parse("spectrum:exp(-k)", &s), 0);
    cr_expect_eq(nl_synth_lattice_wiener_plan_alloc(m, 2, n, 0, 0, &p), NL_EINVAL);
    cr_expect_eq(nl_synth_lattice_wiener_plan_alloc(m, 2, n, 32, 0, &p), NL_EINVAL); /* 2 nodes < 4 */
    cr_expect_eq(nl_synth_lattice_wiener_plan_alloc(m, 2, odd, 4, 0, &p), NL_EINVAL);
    cr_expect_eq(nl_synth_lattice_wiener_plan_alloc(m, 3, n, 4, 0, &p), NL_EINVAL);
    cr_expect_eq(nl_synth_lattice_wiener_plan_alloc(s, 2, n, 4, 0, &p), NL_EINVAL);
    cr_expect_null(p);
    /* the Perlin octave sum of a Gaussian spectrum: every weight 0, refused rather than a field of zeros */
    nl_model *g;
    nl_synth_lattice_plan pp;
    cr_assert_eq(nl_model_parse("spectrum:pi*36*exp(-(6*pi*k)^2)", &g), 0);
    cr_expect_eq(nl_synth_lattice_plan_init(g, 2, 16, 4, 0, &pp), NL_EINVAL);
    nl_model_free(g);
    nl_model_free(m), nl_model_free(s);
}
