/* Sparse convolution (shaped Poisson impulses).
 * The field is not Gaussian (its fourth cumulant is lambda E[a^4] sum h^4),
 * so the ACF bands come from the ensemble's own spread: z = (mean - R) /
 * (sd / sqrt(M)) is Student's t with M - 1 degrees of freedom, L lags at a
 * family-wise rate of 1e-3 (Bonferroni).  The kernel is truncated at the
 * radius that keeps all but 1e-4 of its energy, a change in R far below the
 * bands. */
#include "../analysis/acf.h"
#include "../analysis/hist.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/sparse.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <omp.h>
#include <string.h>

static double r_matern(double x, double y)
{
    double u = sqrt(3.0) * hypot(x, y) / 5;
    return (1 + u) * exp(-u);
}
static double r_gosc(double x, double y) { return cos(0.4 * x) * exp(-x * x / 36) * cos(0.4 * y) * exp(-y * y / 36); }
static double r_markov(double x, double y) { return exp(-hypot(x, y) / 6); }

static void check(const char *spec, double (*R)(double, double), int dim)
{
    size_t n[2] = {dim == 1 ? 4096 : 128, dim == 1 ? 1 : 128}, M = dim == 1 ? 100 : 48, L = dim == 1 ? 33 : 21;
    long lags[33][2];
    double s1[33] = {0}, s2[33] = {0}, zmax = 0, zcrit;
    nl_model *m;
    nl_synth_sparse_plan *p;
    nl_field *f = nl_field_alloc(dim, n, NULL, NULL), *full;
    for (size_t i = 0; i < L; i++)
        lags[i][0] = dim == 1 ? (long)i : (long)(i <= 10 ? i : 0), lags[i][1] = dim == 1 ? 0 : (long)(i <= 10 ? 0 : i - 10);
    cr_assert_eq(nl_model_parse(spec, &m), 0);
    cr_assert_eq(nl_synth_sparse_plan_model(m, dim, NULL, SPARSE_OPTS(0, 0, 32), &p), 0, "%s", nl_errmsg());
    for (size_t s = 1; s <= M; s++) {
        cr_assert_eq(nl_synth_sparse_execute(p, s, NL_SYNTH_SPARSE_WRAP, NULL, f), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_acf_full(f, 0.0, NL_ACF_UNBIASED, &full), 0);
        for (size_t i = 0; i < L; i++) {
            double v = full->data[(size_t)lags[i][1] * full->n[0] + (size_t)lags[i][0]];
            s1[i] += v, s2[i] += v * v;
        }
        nl_field_free(full);
    }
    zcrit = gsl_cdf_tdist_Qinv(1e-3 / (2.0 * (double)L), (double)M - 1);
    for (size_t i = 0; i < L; i++) {
        double mean = s1[i] / (double)M, sd = sqrt((s2[i] - (double)M * mean * mean) / ((double)M - 1));
        zmax = fmax(zmax, fabs(mean - R((double)lags[i][0], (double)lags[i][1])) / (sd / sqrt((double)M)));
    }
    cr_log_info("sparse %s %dD: max |z| = %.2f (threshold %.2f)", spec, dim, zmax, zcrit);
    cr_expect_leq(zmax, zcrit, "%s: ensemble ACF %.2f standard errors from the target", spec, zmax);
    nl_field_free(f), nl_synth_sparse_plan_free(p), nl_model_free(m);
}

Test(sparse, markov_1d) { check("markov:scale=6", r_markov, 1); }
Test(sparse, matern_1d) { check("matern:nu=1.5,scale=5", r_matern, 1); }
Test(sparse, gauss_osc_1d) { check("gauss-osc:omega=0.4,scale=6", r_gosc, 1); }
Test(sparse_slow, markov_2d) { check("markov:scale=6", r_markov, 2); }
Test(sparse_slow, matern_2d) { check("matern:nu=1.5,scale=5", r_matern, 2); }
Test(sparse_slow, gauss_osc_2d_separable) { check("gauss-osc:omega=0.4,scale=6,sep", r_gosc, 2); }

/* Excess kurtosis against density: the measured value (mean over 16
 * periodic 128x128 realizations, its standard error from their spread)
 * agrees with the compound-Poisson prediction 3 sum h^4 / (lambda (sum
 * h^2)^2) within the t(15) Bonferroni bound over the 4 densities, and the
 * measured values fall toward 0 (Gaussian) as the density grows. */
Test(sparse_slow, kurtosis_against_density)
{
    const double dens[4] = {0.5, 4, 32, 256};
    size_t n[2] = {128, 128};
    double zcrit = gsl_cdf_tdist_Qinv(1e-3 / 8, 15), last = INFINITY;
    nl_model *m;
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_model_parse("matern:nu=1.5,scale=4", &m), 0);
    for (int d = 0; d < 4; d++) {
        nl_synth_sparse_plan *p;
        nl_synth_sparse_info info;
        double s1 = 0, s2 = 0;
        cr_assert_eq(nl_synth_sparse_plan_model(m, 2, NULL, SPARSE_OPTS(0, 16, dens[d]), &p), 0, "%s", nl_errmsg());
        nl_synth_sparse_plan_info(p, &info);
        for (uint64_t s = 1; s <= 16; s++) {
            nl_moments mo;
            cr_assert_eq(nl_synth_sparse_execute(p, s, NL_SYNTH_SPARSE_WRAP, NULL, f), 0);
            nl_moments_compute(f, &mo);
            s1 += mo.kurtosis, s2 += mo.kurtosis * mo.kurtosis;
        }
        double mean = s1 / 16, se = sqrt((s2 - 16 * mean * mean) / 15 / 16);
        cr_log_info("sparse density %g: excess kurtosis %.4f +- %.4f, predicted %.4f", dens[d], mean, se,
                    info.kurtosis);
        cr_expect_leq(fabs(mean - info.kurtosis), zcrit * se + 1e-12, "density %g: kurtosis %.4f, predicted %.4f",
                      dens[d], mean, info.kurtosis);
        cr_expect_lt(mean, last, "measured kurtosis does not fall with density");
        last = mean;
        nl_synth_sparse_plan_free(p);
    }
    nl_field_free(f), nl_model_free(m);
}

/* Any sample is a function of the seed and its position only. */
Test(sparse, windows_agree)
{
    nl_synth_sparse_plan *p;
    size_t n[2] = {50, 40};
    long o1[2] = {-13, 7}, o2[2] = {0, 0};
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_synth_sparse_plan_expr("cos(0.5*x+0.3*y)*exp(-r/4)", 2, SPARSE_OPTS(12, 8, 3), &p), 0);
    cr_assert_eq(nl_synth_sparse_set_angle(p, "0.01*x"), 0);
    cr_assert_eq(nl_synth_sparse_execute(p, 4, 0, o1, a), 0);
    cr_assert_eq(nl_synth_sparse_execute(p, 4, 0, o2, b), 0);
    for (long y = 7; y < 40; y++)
        for (long x = 0; x < 37; x++)
            cr_assert_eq(a->data[(y - 7) * 50 + (x + 13)], b->data[y * 50 + x], "(%ld, %ld)", x, y);
    nl_field_free(a), nl_field_free(b), nl_synth_sparse_plan_free(p);
}

Test(sparse, refusals)
{
    nl_synth_sparse_plan *p;
    size_t n[2] = {40, 40};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_expect_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(8, 8, -1), &p), NL_EINVAL);
    cr_expect_eq(nl_synth_sparse_plan_expr("exp(-q)", 2, SPARSE_OPTS(8, 8, 1), &p), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(30, 8, 1), &p), 0);
    cr_expect_eq(nl_synth_sparse_execute(p, 1, NL_SYNTH_SPARSE_WRAP, NULL, f), NL_EINVAL,
                 "kernel larger than the tile");
    cr_expect(strstr(nl_errmsg(), "larger than the tile") != NULL, "%s", nl_errmsg());
    nl_synth_sparse_plan_free(p);
    nl_field_free(f);
}

/* The same seed gives the same bits with 1 and 2 OpenMP threads (impulses
 * come from the counter-based RNG by cell, whatever thread visits it). */
Test(sparse, bit_reproducible_across_threads)
{
    size_t n[2] = {192, 160};
    nl_model *m;
    nl_synth_sparse_plan *p;
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_model_parse("matern:nu=1.5,scale=5", &m), 0);
    cr_assert_eq(nl_synth_sparse_plan_model(m, 2, NULL, SPARSE_OPTS(0, 0, 8), &p), 0, "%s", nl_errmsg());
    omp_set_num_threads(1);
    cr_assert_eq(nl_synth_sparse_execute(p, 9, NL_SYNTH_SPARSE_WRAP, NULL, a), 0);
    omp_set_num_threads(2);
    cr_assert_eq(nl_synth_sparse_execute(p, 9, NL_SYNTH_SPARSE_WRAP, NULL, b), 0);
    cr_expect_eq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    cr_assert_eq(nl_synth_sparse_execute(p, 10, NL_SYNTH_SPARSE_WRAP, NULL, b), 0);
    cr_expect_neq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    nl_synth_sparse_plan_free(p), nl_model_free(m), nl_field_free(a), nl_field_free(b);
}
