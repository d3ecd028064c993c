/* Statistical tests of subdivision synthesis.
 *
 * Lewis's construction estimates each new point from the points of earlier
 * levels only, so new points of one level get independent displacements
 * although their estimation errors are correlated: the field's covariance
 * differs from the target R except for Markovian models in 1D.  Its exact
 * expected ACF follows by propagating the covariance through the levels
 * (analysis/subdiv_exact.h).  Two properties are tested:
 *
 * 1. The implementation: ensembles of M realizations (seeds 1..M) match the
 *    exact expected ACF.  The unbiased ACF estimate with known mean 0 is
 *    averaged over the ensemble; its standard error is the ensemble's own
 *    spread sd / sqrt(M), and z = (mean - exact) / se follows Student's t
 *    with M - 1 degrees of freedom.  L lags are tested with a family-wise
 *    false-alarm rate of 1e-3: threshold t_{M-1}^{-1}(1 - 1e-3 / (2 L))
 *    (Bonferroni; conservative for correlated lags).
 * 2. The method: for exp(-|t|) in 1D the exact ACF equals the target to
 *    rounding; for the other models the largest deviation from the target
 *    is logged (it is the method's own error, not sampling error). */
#include "../analysis/acf.h"
#include "../analysis/subdiv_exact.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

static void check(const char *spec, int dim, size_t nx, size_t ny, int L, double h, int N, int taps, size_t M,
                  const long *lags, size_t nl, double *method_error)
{
    nl_model *m;
    nl_subdiv_coeffs *c;
    size_t n[2] = {nx, ny};
    nl_field *f, *full;
    double *s1 = calloc(nl, sizeof *s1), *s2 = calloc(nl, sizeof *s2), *ex = calloc(nl, sizeof *ex);
    double zmax = 0, zcrit, err = 0;
    size_t worst = 0;
    cr_assert_eq(nl_model_parse(spec, &m), 0);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, dim, L, ldexp(h, L), N, 1e-4, 16, &c), 0, "%s", nl_errmsg());
    if (taps)
        cr_assert_eq(nl_subdiv_coeffs_correlate(c, m, taps, NL_SUBDIV_DISP_ERROR), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_exact_acf(c, m, nx, ny, nl, lags, ex), 0, "%s", nl_errmsg());
    f = nl_field_alloc(dim, n, NULL, NULL);
    for (size_t s = 1; s <= M; s++) {
        cr_assert_eq(nl_subdiv_synth_periodic(c, m, s, 0, f), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_acf_full(f, 0.0, NL_ACF_UNBIASED, &full), 0);
        for (size_t i = 0; i < nl; i++) {
            long lx = lags[2 * i], ly = dim == 2 ? lags[2 * i + 1] : 0;
            double v = full->data[(size_t)ly * full->n[0] + (size_t)lx];
            s1[i] += v, s2[i] += v * v;
        }
        nl_field_free(full);
    }
    zcrit = gsl_cdf_tdist_Qinv(1e-3 / (2.0 * (double)nl), (double)M - 1);
    for (size_t i = 0; i < nl; i++) {
        double mean = s1[i] / (double)M, var = (s2[i] - (double)M * mean * mean) / ((double)M - 1);
        double z = (mean - ex[i]) / sqrt(var / (double)M);
        double lag[2] = {(double)lags[2 * i] * h, dim == 2 ? (double)lags[2 * i + 1] * h : 0};
        err = fmax(err, fabs(ex[i] - nl_model_acf(m, dim, lag)));
        if (fabs(z) > zmax)
            zmax = fabs(z), worst = i;
    }
    cr_log_info("subdiv %s (%dD, N=%d, taps %d, %d levels): ensemble vs exact max |z| = %.2f (threshold %.2f); "
                "method error max |exact - R| = %.4f of R(0) = %.4g",
                spec, dim, N, taps, L, zmax, zcrit, err / c->r0, c->r0);
    cr_expect_leq(zmax, zcrit, "%s: ensemble ACF at lag (%ld, %ld) is %.2f standard errors from the exact "
                  "expectation (threshold %.2f)", spec, lags[2 * worst], lags[2 * worst + 1], zmax, zcrit);
    if (method_error)
        *method_error = err / c->r0;
    nl_field_free(f), nl_model_free(m), nl_subdiv_coeffs_free(c);
    free(s1), free(s2), free(ex);
}

static void check_1d_n(const char *spec, double h, int N, int taps, double *err)
{
    long lags[2 * 33];
    for (int i = 0; i < 33; i++)
        lags[2 * i] = i, lags[2 * i + 1] = 0;
    check(spec, 1, 1024, 1, 6, h, N, taps, 200, lags, 33, err);
}

static void check_1d(const char *spec, double h, double *err) { check_1d_n(spec, h, 2, 0, err); }

static void check_2d_n(const char *spec, int N, int taps, double *err)
{
    long lags[2 * 27];
    int k = 0;
    for (int i = 0; i <= 8; i++)
        lags[2 * k] = i, lags[2 * k++ + 1] = 0;
    for (int i = 1; i <= 9; i++)
        lags[2 * k] = 0, lags[2 * k++ + 1] = i;
    for (int i = 1; i <= 9; i++)
        lags[2 * k] = i, lags[2 * k++ + 1] = i;
    check(spec, 2, 64, 64, 4, 1.0, N, taps, 64, lags, 27, err);
}

static void check_2d(const char *spec, int N, double *err) { check_2d_n(spec, N, 0, err); }

Test(nl_subdiv_stat, markov_1d_is_exact)
{
    double err;
    check_1d("markov:scale=8", 1.0, &err);
    /* Markovian: the residuals of sibling midpoints are independent, so the
     * construction is exact up to rounding of the covariance propagation */
    cr_expect_lt(err, 1e-10, "markov method error %g", err);
}

Test(nl_subdiv_stat, markaussian_1d) { check_1d("markaussian:alpha=1.4,scale=8", 1.0, NULL); }
Test(nl_subdiv_stat, lewis_table1_model_1d) { check_1d("expr:100*cos(10*t)*exp(-abs(t))", 15.0 / 1024, NULL); }
Test(nl_subdiv_stat, gauss_osc_1d) { check_1d("gauss-osc:omega=10", 0.01171875, NULL); }
Test(nl_subdiv_stat_slow, isotropic_markaussian_2d) { check_2d("markaussian:alpha=1.4,scale=6", 2, NULL); }
Test(nl_subdiv_stat_slow, separable_markov_2d) { check_2d("markov:scale=6,sep", 2, NULL); }

/* Correlated displacements (synth/subdiv_disp.c): the ensembles must match
 * the exact propagation with the filter's covariance (the same t-test), and
 * the exact method error must shrink by the factors the construction is
 * for: these errors are computed, not sampled, so the factors are
 * deterministic (1D N = 4 with 4 taps: at least 10x for markaussian 1.4 and
 * the Table 1 model, 5x for gauss-osc; 2D N = 2: 5x for isotropic
 * markaussian with 2 taps and separable markov with 4). */
static void improves(const char *spec, int dim, double h, int N, int taps, double factor)
{
    double e0, e1;
    if (dim == 1)
        check_1d_n(spec, h, N, 0, &e0), check_1d_n(spec, h, N, taps, &e1);
    else
        check_2d_n(spec, N, 0, &e0), check_2d_n(spec, N, taps, &e1);
    cr_log_info("%s %dD N=%d: method error %.2e independent, %.2e correlated (%d taps): %.1fx", spec, dim, N, e0,
                e1, taps, e0 / e1);
    cr_expect_leq(e1 * factor, e0, "%s: correlated error %.3g is not %gx below independent %.3g", spec, e1, factor,
                  e0);
}

Test(nl_subdiv_corr, markaussian_1d) { improves("markaussian:alpha=1.4,scale=8", 1, 1.0, 4, 4, 10); }
Test(nl_subdiv_corr, lewis_table1_model_1d)
{
    improves("expr:100*cos(10*t)*exp(-abs(t))", 1, 15.0 / 1024, 4, 4, 10);
}
Test(nl_subdiv_corr, gauss_osc_1d) { improves("gauss-osc:omega=10", 1, 0.01171875, 4, 4, 5); }
Test(nl_subdiv_corr_slow, isotropic_markaussian_2d) { improves("markaussian:alpha=1.4,scale=6", 2, 1.0, 2, 2, 5); }
Test(nl_subdiv_corr_slow, separable_markov_2d) { improves("markov:scale=6,sep", 2, 1.0, 2, 4, 5); }
