/* ML and REML with a drift: the likelihood against its direct evaluation
 * in R on Meuse with a linear drift, and a design matrix of covariates
 * against the same column space given as a polynomial drift. */
#include "../analysis/fit.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* R, in one call: the Meuse data (x, y, log(zinc): 155 lines of 3), then
 * for ML and REML with a linear drift, -2 l of a spherical + nugget model
 * with range and nugget held at the values below (the optima noiselab's
 * search reports, 8 digits) and var optimised (optimize, to 1e-12
 * relative), by the formulas of analysis/fit.h written here independently
 * with base R's chol: ML n ln 2 pi + ln|C| + r' C^-1 r, REML (n - q) ln 2 pi
 * + ln|C| + ln|X' C^-1 X| + r' C^-1 r, r = z - X beta, beta the GLS
 * estimate, X = 1, u, v (x and y centred on and divided by the half-widths
 * of their bounding box, fit.h's Drift).  Prints var, -2 l and beta (5
 * numbers) for ML then REML. */
static const double held[2][2] = {{1194.9033, 0.040139461}, {1773.0162, 0.037493886}};
static const char script[] =
    "suppressMessages(library(sp)); data(meuse)\n"
    "x <- meuse$x; y <- meuse$y; z <- log(meuse$zinc); n <- length(z)\n"
    "cat(sprintf('%%.17g %%.17g %%.17g', x, y, z), sep = '\\n')\n"
    "u <- (x - (min(x) + max(x)) / 2) / ((max(x) - min(x)) / 2)\n"
    "v <- (y - (min(y) + max(y)) / 2) / ((max(y) - min(y)) / 2)\n"
    "X <- cbind(1, u, v); D <- as.matrix(dist(cbind(x, y)))\n"
    "m2l <- function(p, reml, out = FALSE) {\n"
    "  h <- pmin(D / p[2], 1); C <- p[1] * (1 - 1.5 * h + 0.5 * h^3) + diag(p[3], n)\n"
    "  L <- chol(C); Ci <- chol2inv(L); M <- t(X) %%*%% Ci %%*%% X\n"
    "  b <- solve(M, t(X) %%*%% Ci %%*%% z); r <- z - X %%*%% b\n"
    "  f <- as.numeric(t(r) %%*%% Ci %%*%% r) + 2 * sum(log(diag(L)))\n"
    "  f <- if (reml) f + (n - 3) * log(2 * pi) + as.numeric(determinant(M)$modulus) else f + n * log(2 * pi)\n"
    "  if (out) cat(sprintf('%%.17g', c(p[1], f, b)), '\\n')\n"
    "  f\n"
    "}\n"
    "H <- list(c(%.17g, %.17g), c(%.17g, %.17g))\n"
    "for (k in 1:2) {\n"
    "  o <- optimize(function(lv) m2l(c(exp(lv), H[[k]]), k == 2), c(-3, 3), tol = 1e-12)\n"
    "  m2l(c(exp(o$minimum), H[[k]]), k == 2, TRUE)\n"
    "}\n";

/* Against R's numbers: with range and nugget held, var (the one free
 * parameter, a 1-D simplex to 1e-5 in log var, R's optimize to 1e-12)
 * must agree to 2e-5 relative; -2 l to 1e-9 relative (the same formula by
 * Cholesky factors, rounding ~1e-13 times C's condition; at the optimum in
 * var, an error of 1e-5 in log var moves -2 l by ~(n/2) 1e-10); beta to
 * 1e-6 relative (it moves with var only through rounding: C's scale
 * cancels in the GLS estimate, here through the nugget's share).  And the
 * full REML fit must reach the global minimum: R's profile over the range
 * (var and nugget optimised at 400, 600, ..., 6000 and 1773) is lowest at
 * 1773 (186.2731, a valley 10% wide: 187.59 at 1600, 188.34 at 2000;
 * 187.09 in the next valley, 1200), the range held above. */
Test(fit_ml_drift, meuse_linear_drift_equals_r_formula)
{
    double r[3 * 155 + 10], xy[2 * 155], z[155];
    char buf[4096];
    nl_fit_result res;
    if (system("command -v Rscript >/dev/null 2>&1") != 0) {
        fprintf(stderr, "skip: Meuse likelihood with a linear drift vs R's formula: Rscript is not installed\n");
        return;
    }
    snprintf(buf, sizeof buf, script, held[0][0], held[0][1], held[1][0], held[1][1]);
    cr_assert_eq(gstat_run(buf, r, 3 * 155 + 10), 3 * 155 + 10, "R's meuse data and likelihoods");
    for (int i = 0; i < 155; i++)
        xy[2 * i] = r[3 * i], xy[2 * i + 1] = r[3 * i + 1], z[i] = r[3 * i + 2];
    for (int reml = 0; reml < 2; reml++) {
        const double *rr = r + 3 * 155 + 5 * reml;
        nl_fit_options o = {.family = "spherical", .nugget = 1, .drift = NL_DRIFT_LINEAR, .nfix = 2,
                            .fix_name = {"scale", "nugget"}, .fix_value = {held[reml][0], held[reml][1]},
                            .likelihood = reml ? NL_FIT_REML : NL_FIT_ML};
        cr_assert_eq(nl_fit_ml(xy, z, 155, 2, &o, &res), NL_OK, "%s", nl_errmsg());
        cr_assert_eq(res.ndrift, 3);
        fprintf(stderr, "meuse %s linear drift, range %g: -2 l %.10f (R %.10f), var %.8g (R %.8g), beta %g %g %g\n",
                reml ? "REML" : "ML", held[reml][0], res.objective, rr[1], res.param[0].value, rr[0], res.drift[0],
                res.drift[1], res.drift[2]);
        cr_expect(fabs(res.param[0].value / rr[0] - 1) < 2e-5, "reml %d: var %.10g, R %.10g", reml,
                  res.param[0].value, rr[0]);
        cr_expect(fabs(res.objective - rr[1]) <= 1e-9 * fabs(rr[1]), "reml %d: -2 l %.12g, R %.12g", reml,
                  res.objective, rr[1]);
        for (int k = 0; k < 3; k++)
            cr_expect(fabs(res.drift[k] - rr[2 + k]) <= 1e-6 * fabs(rr[2 + k]), "reml %d: beta %d %.12g, R %.12g",
                      reml, k, res.drift[k], rr[2 + k]);
        nl_fit_result_free(&res);
    }
    nl_fit_options o = {.family = "spherical", .nugget = 1, .drift = NL_DRIFT_LINEAR, .likelihood = NL_FIT_REML};
    cr_assert_eq(nl_fit_ml(xy, z, 155, 2, &o, &res), NL_OK, "%s", nl_errmsg());
    fprintf(stderr, "meuse REML linear drift: -2 l %.6f, range %.6g, converged %d\n", res.objective,
            res.param[1].value, res.converged);
    cr_expect(res.objective <= 186.28, "-2 l %.5f above the global minimum 186.2731 (range %g)", res.objective,
              res.param[1].value);
    cr_expect(fabs(res.param[1].value / held[1][0] - 1) < 1e-4, "range %.8g, expected %.8g", res.param[1].value,
              held[1][0]);
    cr_expect(res.converged, "not converged");
    nl_fit_result_free(&res);
}

enum { N = 60 };

/* 60 points in [0, 10]^2 with a tilted plane, a smooth pattern and noise. */
static void make_data(double *x, double *z)
{
    for (int i = 0; i < N; i++) {
        x[2 * i] = 10 * nl_rng_uniform(5, 1, (uint64_t)i);
        x[2 * i + 1] = 10 * nl_rng_uniform(5, 2, (uint64_t)i);
        z[i] = 0.3 * x[2 * i] - 0.2 * x[2 * i + 1] + sin(0.9 * x[2 * i]) * cos(0.6 * x[2 * i + 1]) +
               0.8 * nl_rng_uniform(5, 3, (uint64_t)i);
    }
}

/* The drift's centred, scaled coordinates u, v (fit.h's Drift). */
static void uv(const double *x, double *u, double *v)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < N; i++)
        for (int a = 0; a < 2; a++)
            lo[a] = fmin(lo[a], x[2 * i + a]), hi[a] = fmax(hi[a], x[2 * i + a]);
    for (int i = 0; i < N; i++)
        u[i] = (x[2 * i] - (lo[0] + hi[0]) / 2) / ((hi[0] - lo[0]) / 2),
        v[i] = (x[2 * i + 1] - (lo[1] + hi[1]) / 2) / ((hi[1] - lo[1]) / 2);
}

/* Covariates in the design span the linear drift's columns: X2 = [1, 3u -
 * 1, u + v/2] = [1, u, v] T with det T = 1.5.  ML depends on X's column
 * space only: the same -2 l and parameters; REML's ln|X' C^-1 X| moves by
 * the constant 2 ln 1.5 (its -ln|X'X| left out, fit.h): the same
 * parameters, -2 l up by 0.81093; the coefficients are T^-1 beta.
 * Tolerances: the two fits evaluate the same function (up to a constant
 * and rounding) along the same simplex path: 1e-9 relative on -2 l, 1e-6
 * on the parameters (the simplex's 1e-5 in log units, should rounding
 * send the paths apart). */
Test(fit_ml_drift, design_spanning_linear_drift_equals_it)
{
    double x[2 * N], z[N], u[N], v[N], design[2 * N];
    make_data(x, z);
    uv(x, u, v);
    for (int i = 0; i < N; i++)
        design[2 * i] = 3 * u[i] - 1, design[2 * i + 1] = u[i] + v[i] / 2;
    for (int reml = 0; reml < 2; reml++) {
        nl_fit_options lin = {.family = "markov", .nugget = 1, .drift = NL_DRIFT_LINEAR,
                              .likelihood = reml ? NL_FIT_REML : NL_FIT_ML};
        nl_fit_options cov = lin;
        nl_fit_result a, b;
        cov.drift = NL_DRIFT_CONSTANT;
        cr_assert_eq(nl_fit_ml(x, z, N, 2, &lin, &a), NL_OK, "%s", nl_errmsg());
        cr_assert_eq(nl_fit_ml_design(x, z, N, 2, design, 2, &cov, &b), NL_OK, "%s", nl_errmsg());
        double shift = reml ? 2 * log(1.5) : 0;
        cr_expect(fabs(b.objective - a.objective - shift) <= 1e-9 * fabs(a.objective), "reml %d: -2 l %.12g vs %.12g + %g",
                  reml, b.objective, a.objective, shift);
        for (size_t k = 0; k < a.np; k++)
            cr_expect(fabs(b.param[k].value / a.param[k].value - 1) < 1e-6, "reml %d: %s %.10g vs %.10g", reml,
                      a.param[k].name, b.param[k].value, a.param[k].value);
        /* beta_lin = T beta_cov: b0 = c0 - c1, b1 = 3 c1 + c2, b2 = c2 / 2 */
        cr_assert_eq(b.ndrift, 3);
        double t[3] = {b.drift[0] - b.drift[1], 3 * b.drift[1] + b.drift[2], b.drift[2] / 2};
        for (int k = 0; k < 3; k++)
            cr_expect(fabs(t[k] - a.drift[k]) < 1e-6 * (fabs(a.drift[k]) + 1), "reml %d: beta %d %.10g vs %.10g", reml,
                      k, t[k], a.drift[k]);
        cr_expect(a.drift_se[1] > 0 && isfinite(a.drift_se[1]), "no standard error");
        nl_fit_result_free(&a);
        nl_fit_result_free(&b);
    }
}

/* A covariate that repeats a drift column, and a non-finite covariate, are
 * refused with their reasons; so is an unknown drift. */
Test(fit_ml_drift, refuses_dependent_and_bad_covariates)
{
    double x[2 * N], z[N], u[N], v[N];
    nl_fit_result r;
    make_data(x, z);
    uv(x, u, v);
    nl_fit_options o = {.family = "markov", .nugget = 1, .drift = NL_DRIFT_LINEAR};
    cr_expect_eq(nl_fit_ml_design(x, z, N, 2, u, 1, &o, &r), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "linearly dependent"), "%s", nl_errmsg());
    u[7] = NAN;
    o.drift = NL_DRIFT_CONSTANT;
    cr_expect_eq(nl_fit_ml_design(x, z, N, 2, u, 1, &o, &r), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "covariate 1 of point 8"), "%s", nl_errmsg());
    o.drift = 7;
    cr_expect_eq(nl_fit_ml(x, z, N, 2, &o, &r), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "drift"), "%s", nl_errmsg());
}

/* The command: --drift linear gives JSON's drift (1, u, v with standard
 * errors) equal to the library's; --drift with wls is accepted. */
Test(fit_ml_drift, cli_reports_drift)
{
    double x[2 * N], z[N];
    char path[512], err[512];
    nl_fit_result r;
    make_data(x, z);
    snprintf(path, sizeof path, "%s/drift.tsv", scratch_dir());
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(f, "x\ty\tvalue\n");
    for (int i = 0; i < N; i++)
        fprintf(f, "%.17g\t%.17g\t%.17g\n", x[2 * i], x[2 * i + 1], z[i]);
    fclose(f);
    json_t *j = run_noiselab_json("fit drift.tsv --model markov --nugget --method ml --drift linear --json");
    json_t *d = json_object_get(j, "drift");
    cr_assert(json_array_size(d) == 3, "drift: %zu terms", json_array_size(d));
    static const char *terms[] = {"1", "u", "v"};
    nl_fit_options o = {.family = "markov", .nugget = 1, .drift = NL_DRIFT_LINEAR};
    cr_assert_eq(nl_fit_ml(x, z, N, 2, &o, &r), NL_OK, "%s", nl_errmsg());
    for (int k = 0; k < 3; k++) {
        json_t *t = json_array_get(d, (size_t)k);
        double v = json_real_value(json_object_get(t, "value"));
        cr_expect_str_eq(json_string_value(json_object_get(t, "term")), terms[k]);
        /* the command starts from the wls fit, the library from its own
         * start: the same optimum to the simplex's 1e-5 in log units */
        cr_expect(fabs(v - r.drift[k]) < 1e-4 * (fabs(r.drift[k]) + 0.1), "term %s: %g, library %g", terms[k], v,
                  r.drift[k]);
        cr_expect(json_real_value(json_object_get(t, "se")) > 0, "term %s: no standard error", terms[k]);
    }
    cr_expect(json_object_get(j, "starts") && json_object_get(j, "gradient"), "no starts or gradient");
    nl_fit_result_free(&r);
    json_decref(j);
    /* wls with a drift fits the residual variogram (tests/test_fit_cov.c) */
    cr_expect_eq(run_noiselab("fit drift.tsv --model markov --drift linear", NULL, 0, err, sizeof err), 0, "%s", err);
}
