/* Fitting: WLS recovers the parameters of an exact model semivariogram,
 * ML and REML match their closed forms where one exists, and the refusals
 * name what is wrong. */
#include "../analysis/fit.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <string.h>

enum { BINS = 15 };

/* gamma(h) = R(0) - R(h) of spec at BINS distances 0.7 k + 0.3 (k = 0..14),
 * pairs 100 + 37 k. */
static void exact_variogram(const char *spec, double *h, double *g, double *n)
{
    nl_model *m;
    double zero[3] = {0, 0, 0};
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s", nl_errmsg());
    for (int k = 0; k < BINS; k++) {
        double lag[3] = {0.7 * k + 0.3, 0, 0};
        h[k] = lag[0];
        g[k] = nl_model_acf(m, 2, zero) - nl_model_acf(m, 2, lag);
        n[k] = 100 + 37 * k;
    }
    nl_model_free(m);
}

static double value_of(const nl_fit_result *r, const char *name)
{
    for (size_t k = 0; k < r->np; k++)
        if (strcmp(r->param[k].name, name) == 0)
            return r->param[k].value;
    cr_assert_fail("no parameter %s", name);
    return NAN;
}

/* An exact semivariogram is fitted exactly: the objective's minimum is 0 at
 * the true parameters, so the fit must reach them to the solver's tolerance
 * (xtol 1e-10 on the log-parameters; 1e-6 relative leaves room for the
 * finite-difference Jacobian's last steps). */
Test(fit, wls_recovers_exact_variograms)
{
    struct {
        const char *spec, *family;
        int nugget;
        const char *names[4];
        double truth[4];
    } cases[] = {
        {"markov:scale=2.385,var=1.7,nugget=0.31", "markov", 1, {"var", "scale", "nugget"}, {1.7, 2.385, 0.31}},
        {"spherical:scale=6.2,var=0.8,nugget=0.05", "spherical", 1, {"var", "scale", "nugget"}, {0.8, 6.2, 0.05}},
        {"gauss:scale=3.1,var=2.2", "gauss", 0, {"var", "scale"}, {2.2, 3.1}},
        {"matern:nu=1.3,scale=2.5,var=1.1", "matern", 0, {"var", "scale", "nu"}, {1.1, 2.5, 1.3}},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++)
        for (int w = 0; w < 2; w++) {
            double h[BINS], g[BINS], n[BINS];
            nl_fit_options o = {.family = cases[c].family, .nugget = cases[c].nugget, .weights = w};
            nl_fit_result r;
            exact_variogram(cases[c].spec, h, g, n);
            cr_assert_eq(nl_fit_variogram(h, g, n, BINS, 2, &o, &r), NL_OK, "%s: %s", cases[c].spec, nl_errmsg());
            cr_assert(r.converged, "%s", cases[c].spec);
            for (int k = 0; k < 4 && cases[c].names[k]; k++)
                cr_assert_float_eq(value_of(&r, cases[c].names[k]), cases[c].truth[k], 1e-6 * cases[c].truth[k],
                                   "%s weights %d: %s = %.10g", cases[c].spec, w, cases[c].names[k],
                                   value_of(&r, cases[c].names[k]));
            /* the spec parses back to the fitted model */
            {
                nl_model *m;
                cr_assert_eq(nl_model_parse(r.spec, &m), NL_OK, "%s", r.spec);
                nl_model_free(m);
            }
            nl_fit_result_free(&r);
        }
}

/* A fixed parameter stays at its value with no standard error, and the
 * others are fitted around it. */
Test(fit, wls_fixed_parameter)
{
    double h[BINS], g[BINS], n[BINS];
    nl_fit_options o = {.family = "markov", .nfix = 1, .fix_name = {"nugget"}, .fix_value = {0.31}};
    nl_fit_result r;
    exact_variogram("markov:scale=2.385,var=1.7,nugget=0.31", h, g, n);
    cr_assert_eq(nl_fit_variogram(h, g, n, BINS, 2, &o, &r), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(r.np, 3);
    cr_assert_eq(r.nfree, 2);
    cr_assert_eq(value_of(&r, "nugget"), 0.31);
    cr_assert(r.param[2].fixed && r.param[2].se == 0);
    cr_assert_float_eq(value_of(&r, "scale"), 2.385, 1e-6 * 2.385);
    nl_fit_result_free(&r);
}

Test(fit, refusals_name_the_problem)
{
    double h[BINS], g[BINS], n[BINS];
    nl_fit_result r;
    nl_fit_options o = {.family = "sphere"};
    exact_variogram("markov:scale=2", h, g, n);
    cr_assert_eq(nl_fit_variogram(h, g, n, BINS, 2, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "sphere"));
    o = (nl_fit_options){.family = "markov", .nfix = 1, .fix_name = {"nu"}, .fix_value = {1}};
    cr_assert_eq(nl_fit_variogram(h, g, n, BINS, 2, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "\"nu\""));
    o = (nl_fit_options){.family = "spherical", .nfix = 1, .fix_name = {"scale"}, .fix_value = {0}};
    cr_assert_eq(nl_fit_variogram(h, g, n, BINS, 2, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "scale=0"));
    o = (nl_fit_options){.family = "markov", .nugget = 1};
    cr_assert_eq(nl_fit_variogram(h, g, n, 3, 2, &o, &r), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "expected at least 4"), "%s", nl_errmsg());
    {
        double x[8] = {1, 1, 1, 1, 1, 1, 1, 1}, z[4] = {1, 2, 3, 4};
        o = (nl_fit_options){.family = "markov"};
        cr_assert_eq(nl_fit_ml(x, z, 4, 2, &o, &r), NL_EINVAL);
        cr_assert(strstr(nl_errmsg(), "identical"), "%s", nl_errmsg());
        cr_assert_eq(nl_fit_ml(x, z, 3, 2, &o, &r), NL_EINVAL);
        cr_assert(strstr(nl_errmsg(), "expected at least 4"), "%s", nl_errmsg());
    }
}

/* With the correlation fixed, ML and REML for var alone have closed forms:
 * C = var P, so -2 l is minimised at var = r' P^-1 r / n (REML: / (n - 1)),
 * r the GLS residual, and the observed information of log var is n / 2
 * ((n - 1) / 2), so se(var) = var sqrt(2 / n) (sqrt(2 / (n - 1))).  The
 * simplex stops at a size of 1e-5 in log var (1e-5 relative); the Hessian's
 * central difference is exact up to h^2 / 12 of the fourth derivative
 * (2e-3^2 / 12 = 3e-7 relative).  Data: 60 points, uniform in [0, 10]^2,
 * values uniform: the closed forms hold for any data. */
Test(fit, ml_and_reml_closed_forms)
{
    enum { N = 60 };
    double x[2 * N], z[N], q, a1 = 0, az = 0, zz = 0;
    nl_model *m;
    gsl_matrix *P = gsl_matrix_alloc(N, N);
    gsl_vector *y = gsl_vector_alloc(N), *a = gsl_vector_alloc(N);
    for (int i = 0; i < N; i++) {
        x[2 * i] = 10 * nl_rng_uniform(5, 1, (uint64_t)i);
        x[2 * i + 1] = 10 * nl_rng_uniform(5, 2, (uint64_t)i);
        z[i] = nl_rng_uniform(5, 3, (uint64_t)i);
    }
    cr_assert_eq(nl_model_parse("markov:scale=2.5,var=1", &m), NL_OK);
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            double lag[3] = {x[2 * i] - x[2 * j], x[2 * i + 1] - x[2 * j + 1], 0};
            gsl_matrix_set(P, i, j, nl_model_acf(m, 2, lag));
        }
    nl_model_free(m);
    cr_assert_eq(gsl_linalg_cholesky_decomp1(P), 0);
    for (int i = 0; i < N; i++)
        gsl_vector_set(y, i, z[i]), gsl_vector_set(a, i, 1);
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, P, y);
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, P, a);
    gsl_blas_ddot(a, a, &a1);
    gsl_blas_ddot(a, y, &az);
    gsl_blas_ddot(y, y, &zz);
    q = zz - az * az / a1;
    for (int reml = 0; reml < 2; reml++) {
        nl_fit_options o = {.family = "markov", .nfix = 1, .fix_name = {"scale"}, .fix_value = {2.5},
                            .likelihood = reml ? NL_FIT_REML : NL_FIT_ML};
        nl_fit_result r;
        double dof = reml ? N - 1 : N, v = q / dof;
        cr_assert_eq(nl_fit_ml(x, z, N, 2, &o, &r), NL_OK, "%s", nl_errmsg());
        cr_assert_float_eq(r.param[0].value, v, 2e-5 * v, "reml %d: var %.10g, closed form %.10g", reml,
                           r.param[0].value, v);
        cr_assert_float_eq(r.param[0].se, v * sqrt(2 / dof), 1e-4 * v, "reml %d: se %.10g", reml, r.param[0].se);
        cr_assert_float_eq(r.mean, az / a1, 1e-12, "GLS mean");
        cr_assert_float_eq(r.aic, r.objective + 2 * 2, 1e-9);
        nl_fit_result_free(&r);
    }
    gsl_vector_free(a);
    gsl_vector_free(y);
    gsl_matrix_free(P);
}
