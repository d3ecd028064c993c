/* Fits of degenerate data answer honestly: a singular information matrix
 * flags the parameters it cannot resolve instead of printing rounding
 * noise, a shape parameter that runs to the end of its fit range is
 * flagged, coincident data are refused without a nugget and fitted with
 * the nugget on the diagonal only, data without variation are refused, and
 * a likelihood fit beyond its work budget is refused before it starts. */
#include "../analysis/fit.h"
#include "../analysis/fit_internal.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <string.h>

static const nl_fit_param *param(const nl_fit_result *r, const char *name)
{
    for (size_t k = 0; k < r->np; k++)
        if (strcmp(r->param[k].name, name) == 0)
            return &r->param[k];
    cr_assert_fail("no parameter %s", name);
    return NULL;
}

/* The threshold itself: an eigenvalue below sqrt(DBL_EPSILON) = 1.5e-8 of
 * the largest is a singular direction, one of 1e-6 is not; a parameter
 * with over a tenth of a singular direction's weight is flagged.  The
 * matrices are exact, so the decisions are too. */
Test(fit_hostile, information_threshold)
{
    double rank1[4] = {1, 1, 1, 1}, weak[4] = {1, 0, 0, 1e-10}, fine[4] = {1, 0, 0, 1e-6}, cov[4];
    unsigned f1[2] = {0, 0}, f2[2] = {0, 0}, f3[2] = {0, 0};
    double rc;
    cr_assert_eq(nl_fit_info_check(rank1, 2, f1, cov), 0);
    cr_assert(f1[0] == NL_FIT_PARAM_SINGULAR && f1[1] == NL_FIT_PARAM_SINGULAR);
    cr_assert(isnan(cov[0]) && isnan(cov[3]));
    rc = nl_fit_info_check(weak, 2, f2, cov);
    cr_assert_float_eq(rc, 1e-10, 1e-20);
    cr_assert(f2[0] == 0 && f2[1] == NL_FIT_PARAM_SINGULAR);
    cr_assert_float_eq(cov[0], 1, 1e-15, "the regular direction keeps its inverse");
    cr_assert(isnan(cov[3]));
    rc = nl_fit_info_check(fine, 2, f3, cov);
    cr_assert_float_eq(rc, 1e-6, 1e-16);
    cr_assert(f3[0] == 0 && f3[1] == 0);
    cr_assert_float_eq(cov[3], 1e6, 1e-4);
}

/* Data that rise linearly along x (values = x) give gauss-osc a likelihood
 * that does not curve in some directions (the reported case printed
 * standard errors of 1e-154 and intervals of width 0): those parameters
 * are flagged, with no standard error or interval; any other keeps
 * positive numbers. */
Test(fit_hostile, singular_information_flagged)
{
    enum { N = 30 };
    double x[2 * N], z[N];
    nl_fit_result r;
    nl_fit_options o = {.family = "gauss-osc", .intervals = NL_FIT_INTERVALS_ALL,
                        .start = (const double[]){0.27736274, 2.8836154, 0.00053135042}};
    for (int i = 0; i < N; i++)
        x[2 * i] = i / 29.0, x[2 * i + 1] = (i * 7 % 30) / 29.0, z[i] = i / 29.0;
    cr_assert_eq(nl_fit_ml(x, z, N, 2, &o, &r), NL_OK, "%s", nl_errmsg());
    cr_assert(r.flags & NL_FIT_PARAM_SINGULAR, "rcond %g", r.rcond);
    for (size_t k = 0; k < r.np; k++) {
        const nl_fit_param *q = &r.param[k];
        if (q->flags & NL_FIT_PARAM_SINGULAR)
            cr_assert(isnan(q->se) && isnan(q->lower) && isnan(q->upper), "%s", q->name);
        else
            cr_assert(q->se > 1e-9 * q->value && q->upper > q->lower, "%s: se %g", q->name, q->se);
    }
    nl_fit_result_free(&r);
}

/* The exact semivariogram of gauss (matern's nu -> infinity limit) drives
 * a matern fit to the end of nu's fit range (30): the fit stops there and
 * says so, with no standard error for nu. */
Test(fit_hostile, bound_flagged)
{
    enum { BINS = 15 };
    double h[BINS], g[BINS], n[BINS], zero[3] = {0, 0, 0};
    nl_model *m;
    nl_fit_result r;
    nl_fit_options o = {.family = "matern"};
    cr_assert_eq(nl_model_parse("gauss:scale=2.5,var=1.3", &m), NL_OK);
    for (int k = 0; k < BINS; k++) {
        double lag[3] = {0.4 * k + 0.3, 0, 0};
        h[k] = lag[0], g[k] = nl_model_acf(m, 2, zero) - nl_model_acf(m, 2, lag), n[k] = 100 + 37 * k;
    }
    nl_model_free(m);
    cr_assert_eq(nl_fit_variogram(h, g, n, BINS, 2, &o, &r), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(param(&r, "nu")->value, 30);
    cr_assert(param(&r, "nu")->flags & NL_FIT_PARAM_AT_BOUND);
    cr_assert(isnan(param(&r, "nu")->se));
    cr_assert(r.flags & NL_FIT_PARAM_AT_BOUND);
    cr_assert(!(param(&r, "var")->flags), "var is not at a bound");
    nl_fit_result_free(&r);
}

/* -2 l of the three data below with var free, scale = 1 and nugget = 0.5
 * fixed: C_ij = var exp(-|x_i - x_j|) off the diagonal, var + nugget on it
 * (points 1 and 2 share a place, not their white noise). */
static double minus2l(const double *x, const double *z, double var)
{
    double c[9], y[3], a[3], aa, ay, yy, logdet = 0;
    gsl_matrix_view C = gsl_matrix_view_array(c, 3, 3);
    gsl_vector_view Y = gsl_vector_view_array(y, 3), A = gsl_vector_view_array(a, 3);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            c[3 * i + j] = var * exp(-fabs(x[i] - x[j])) + (i == j ? 0.5 : 0);
        y[i] = z[i], a[i] = 1;
    }
    gsl_linalg_cholesky_decomp1(&C.matrix);
    for (int i = 0; i < 3; i++)
        logdet += 2 * log(c[4 * i]);
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, &C.matrix, &Y.vector);
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, &C.matrix, &A.vector);
    gsl_blas_ddot(&A.vector, &A.vector, &aa);
    gsl_blas_ddot(&A.vector, &Y.vector, &ay);
    gsl_blas_ddot(&Y.vector, &Y.vector, &yy);
    return 3 * log(2 * M_PI) + logdet + yy - ay * ay / aa;
}

/* Two data at one place with different values: refused without a nugget
 * (the message names both points and the nugget); with one, -2 l is the
 * independent computation above at the fitted var, to rounding (1e-9
 * relative: the same sums in another order). */
Test(fit_hostile, coincident_points)
{
    double x[3] = {0, 0, 2}, z[3] = {1, 3, 2};
    nl_fit_result r;
    nl_fit_options o = {.family = "markov", .nfix = 1, .fix_name = {"scale"}, .fix_value = {1}};
    cr_assert_eq(nl_fit_ml(x, z, 3, 1, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "points 1 and 2") && strstr(nl_errmsg(), "nugget"), "%s", nl_errmsg());
    o = (nl_fit_options){.family = "markov", .nfix = 2, .fix_name = {"scale", "nugget"}, .fix_value = {1, 0.5}};
    cr_assert_eq(nl_fit_ml(x, z, 3, 1, &o, &r), NL_OK, "%s", nl_errmsg());
    {
        double want = minus2l(x, z, param(&r, "var")->value);
        cr_assert(fabs(r.objective - want) <= 1e-9 * fabs(want), "-2 l %.17g, expected %.17g", r.objective, want);
    }
    nl_fit_result_free(&r);
}

/* Constant data are refused by both fits, not fitted. */
Test(fit_hostile, no_variation)
{
    double x[8] = {0, 0, 1, 0, 0, 1, 1, 1}, z[4] = {2.5, 2.5, 2.5, 2.5};
    double h[4] = {1, 2, 3, 4}, g[4] = {0, 0, 0, 0}, n[4] = {10, 10, 10, 10};
    nl_fit_result r;
    nl_fit_options o = {.family = "markov"};
    cr_assert_eq(nl_fit_ml(x, z, 4, 2, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "no variation"), "%s", nl_errmsg());
    cr_assert_eq(nl_fit_variogram(h, g, n, 4, 2, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "no variation"), "%s", nl_errmsg());
}

/* The work estimate grows as n^3 (within 10% of 8 per doubling at 1000
 * data, where the n^2 term is 15% of the n^3 one), and a fit above its
 * budget is refused with the cost and the alternative named. */
Test(fit_hostile, work_budget)
{
    double x[2 * 60], z[60];
    nl_fit_result r;
    nl_fit_options o = {.family = "markov", .nugget = 1, .intervals = NL_FIT_INTERVALS_ALL};
    double ratio = nl_fit_ml_work(2000, 2, &o) / nl_fit_ml_work(1000, 2, &o);
    cr_assert(ratio > 7.2 && ratio <= 8, "ratio %g", ratio);
    cr_assert(nl_fit_ml_work(4096, 2, &o) > NL_FIT_ML_WORK_MAX);
    for (int i = 0; i < 60; i++)
        x[2 * i] = i % 8 * 0.37, x[2 * i + 1] = i / 8 * 0.41, z[i] = sin(1.7 * i);
    o.max_work = 1e6;
    cr_assert_eq(nl_fit_ml(x, z, 60, 2, &o, &r), NL_ETOOBIG);
    cr_assert(strstr(nl_errmsg(), "budget") && strstr(nl_errmsg(), "variogram"), "%s", nl_errmsg());
    cr_assert_null(r.param);
}
