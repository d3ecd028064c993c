/* Circulant embedding and Cholesky: exact, non-periodic methods.
 * 1. Ensemble ACF against the target R (not wrapped), bands from Isserlis'
 *    theorem (tests/stat.h), for markov, gauss-osc and matern nu = 1.5 in 1D
 *    and 2D (gauss-osc separable in 2D: the isotropic cos(10 r) exp(-r^2)
 *    is not positive definite in 2D, which the refusal test shows).
 * 2. In distribution: circulant and cholesky ensembles on a small grid have
 *    the covariance matrix of the model.  With known mean 0 the sample
 *    covariance C^_ij of M realizations has variance (C_ii C_jj + C_ij^2)/M
 *    (Wishart); z_ij = (C^_ij - C_ij) / that sd is close to N(0, 1) for
 *    M = 4000, and the n(n+1)/2 entries are tested at a family-wise rate of
 *    1e-3 (Bonferroni). */
#include "stat.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/cholesky.h"
#include "../synth/circulant.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double r_markov(double x, double y) { return exp(-hypot(x, y) / 6); }
static double r_gosc1(double x, double y) { (void)y; return cos(0.4 * x) * exp(-x * x / 36); }
static double r_gosc2(double x, double y) { return r_gosc1(x, 0) * r_gosc1(y, 0); }
static double r_matern(double x, double y)
{
    double u = sqrt(3.0) * hypot(x, y) / 5;
    return (1 + u) * exp(-u);
}

static int run_circ(void *ctx, uint64_t seed, nl_field *out) { return nl_synth_circulant_execute(ctx, seed, out); }
static int run_chol(void *ctx, uint64_t seed, nl_field *out) { return nl_synth_cholesky_execute(ctx, seed, out); }

static void check_circulant(const char *spec, stat_profile R, int dim)
{
    size_t n[2] = {dim == 1 ? 1000 : 64, dim == 1 ? 1 : 48};
    long lags[64][2];
    size_t L = dim == 1 ? stat_lags_1d(lags) : stat_lags_2d(lags);
    nl_model *m;
    nl_synth_circulant_plan *p;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, dim, n, NULL, 0, 16, &p), 0, "%s: %s", spec, nl_errmsg());
    stat_check_acf(spec, run_circ, p, n, R, 0, dim == 1 ? 200 : 64, (const long(*)[2])lags, L);
    nl_synth_circulant_plan_free(p);
    nl_model_free(m);
}

Test(circulant, markov_1d) { check_circulant("markov:scale=6", r_markov, 1); }
Test(circulant, gauss_osc_1d) { check_circulant("gauss-osc:omega=0.4,scale=6", r_gosc1, 1); }
Test(circulant, matern_1d) { check_circulant("matern:nu=1.5,scale=5", r_matern, 1); }
Test(circulant, markov_2d) { check_circulant("markov:scale=6", r_markov, 2); }
Test(circulant, gauss_osc_2d_separable) { check_circulant("gauss-osc:omega=0.4,scale=6,sep", r_gosc2, 2); }
Test(circulant, matern_2d) { check_circulant("matern:nu=1.5,scale=5", r_matern, 2); }

Test(cholesky, matern_2d_acf)
{
    size_t n[2] = {24, 20};
    long lags[64][2];
    size_t L = stat_lags_2d(lags);
    nl_model *m;
    nl_synth_cholesky_plan *p;
    cr_assert_eq(nl_model_parse("matern:nu=1.5,scale=5", &m), 0);
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 2, n, NULL, &p), 0, "%s", nl_errmsg());
    stat_check_acf("cholesky matern", run_chol, p, n, r_matern, 0, 400, (const long(*)[2])lags, L);
    nl_synth_cholesky_plan_free(p);
    nl_model_free(m);
}

static void covariance_matches(const char *name, stat_synth fn, void *ctx, size_t n, stat_profile R)
{
    const size_t M = 4000;
    size_t nn[1] = {n};
    nl_field *x = nl_field_alloc(1, nn, NULL, NULL);
    double *C = calloc(n * n, sizeof *C), zmax = 0, zcrit = gsl_cdf_ugaussian_Qinv(1e-3 / (double)(n * (n + 1)));
    for (size_t s = 1; s <= M; s++) {
        cr_assert_eq(fn(ctx, s, x), 0);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j <= i; j++)
                C[i * n + j] += x->data[i] * x->data[j] / (double)M;
    }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j <= i; j++) {
            double c = R((double)i - (double)j, 0), sd = sqrt((R(0, 0) * R(0, 0) + c * c) / (double)M);
            zmax = fmax(zmax, fabs(C[i * n + j] - c) / sd);
        }
    cr_log_info("%s: covariance matrix max |z| = %.2f (threshold %.2f)", name, zmax, zcrit);
    cr_expect_leq(zmax, zcrit, "%s: an ensemble covariance entry is %.2f sd from the model", name, zmax);
    free(C);
    nl_field_free(x);
}

Test(exact_methods, circulant_and_cholesky_have_the_model_covariance)
{
    size_t n[1] = {12};
    nl_model *m;
    nl_synth_circulant_plan *pc;
    nl_synth_cholesky_plan *ph;
    cr_assert_eq(nl_model_parse("gauss-osc:omega=0.4,scale=6", &m), 0);
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 1, n, NULL, 0, 16, &pc), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 1, n, NULL, &ph), 0, "%s", nl_errmsg());
    covariance_matches("circulant", run_circ, pc, 12, r_gosc1);
    covariance_matches("cholesky", run_chol, ph, 12, r_gosc1);
    nl_synth_circulant_plan_free(pc);
    nl_synth_cholesky_plan_free(ph);
    nl_model_free(m);
}

/* Refusals, each with a must-not counterpart above: a model that is not
 * positive definite, and a Cholesky matrix too large. */
Test(exact_methods, refusals)
{
    size_t n2[2] = {64, 64}, big[2] = {100, 100}, n1[1] = {200};
    nl_model *m;
    nl_synth_circulant_plan *pc;
    nl_synth_cholesky_plan *ph;
    cr_assert_eq(nl_model_parse("gauss-osc:omega=2,scale=3", &m), 0);
    cr_expect_eq(nl_synth_circulant_plan_alloc(m, 2, n2, NULL, 0, 16, &pc), NL_ENOTPD);
    cr_expect(strstr(nl_errmsg(), "cannot be embedded") != NULL, "%s", nl_errmsg());
    cr_expect_eq(nl_synth_circulant_plan_alloc(m, 2, n2, NULL, NL_SYNTH_FFT_CLAMP, 2, &pc), NL_OK);
    nl_synth_circulant_plan_free(pc);
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("expr:exp(-abs(t/4)^3)", &m), 0);
    cr_expect_eq(nl_synth_cholesky_plan_alloc(m, 1, n1, NULL, &ph), NL_ENOTPD);
    cr_expect_eq(nl_synth_cholesky_plan_alloc(m, 2, big, NULL, &ph), NL_ETOOBIG);
    cr_expect(strstr(nl_errmsg(), "10000") != NULL, "%s", nl_errmsg());
    nl_model_free(m);
}
