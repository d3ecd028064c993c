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

/* R: the Meuse data, the drift's design 1, u, v (x and y centred on and
 * divided by the half-widths of their bounding box, as analysis/fit.h's
 * Drift), and -2 l of a spherical + nugget model by the formulas of
 * fit.h (ML: n ln 2 pi + ln|C| + r' C^-1 r; REML: (n - q) ln 2 pi + ln|C|
 * + ln|X' C^-1 X| + r' C^-1 r, r = z - X beta, beta the GLS estimate),
 * written here independently with base R's chol.  Prints -2 l and beta at
 * the given parameters for ML then REML, then the minimum R's optim
 * (Nelder-Mead on the log parameters) finds from there for each. */
static const char script[] =
    "suppressMessages(library(sp)); data(meuse)\n"
    "x <- meuse$x; y <- meuse$y; z <- log(meuse$zinc); n <- length(z)\n"
    "u <- (x - (min(x) + max(x)) / 2) / ((max(x) - min(x)) / 2)\n"
    "v <- (y - (min(y) + max(y)) / 2) / ((max(y) - min(y)) / 2)\n"
    "X <- cbind(1, u, v); D <- as.matrix(dist(cbind(x, y)))\n"
    "m2l <- function(p, reml, out = FALSE) {\n"
    "  h <- pmin(D / p[2], 1); C <- p[1] * (1 - 1.5 * h + 0.5 * h^3) + diag(p[3], n)\n"
    "  L <- chol(C); Ci <- chol2inv(L); M <- t(X) %%*%% Ci %%*%% X\n"
    "  b <- solve(M, t(X) %%*%% Ci %%*%% z); r <- z - X %%*%% b\n"
    "  f <- as.numeric(t(r) %%*%% Ci %%*%% r) + 2 * sum(log(diag(L)))\n"
    "  f <- if (reml) f + (n - 3) * log(2 * pi) + as.numeric(determinant(M)$modulus) else f + n * log(2 * pi)\n"
    "  if (out) cat(sprintf('%%.17g', c(f, b)), '\\n')\n"
    "  f\n"
    "}\n"
    "P <- list(c(%.17g, %.17g, %.17g), c(%.17g, %.17g, %.17g))\n"
    "for (k in 1:2) m2l(P[[k]], k == 2, TRUE)\n"
    "for (k in 1:2) {\n"
    "  g <- function(w) tryCatch(m2l(exp(w), k == 2), error = function(e) 1e10)\n"
    "  o <- optim(log(P[[k]]), g, control = list(reltol = 1e-10, maxit = 400))\n"
    "  cat(sprintf('%%.17g', o$value), '\\n')\n"
    "}\n";

/* The same data, fit, and R's numbers: noiselab's -2 l at its optimum must
 * be R's at those parameters to 1e-9 relative (the same formula, both by
 * Cholesky factors: rounding of ~1e-13 times C's condition), the
 * coefficients to 1e-7 relative (a solve with X' C^-1 X, condition ~1e3);
 * R's optim from there must find nothing more than 1e-4 lower (the simplex
 * ends within 1e-5 in log units, where -2 l is within ~1e-8 of its
 * minimum; a missed optimum is off by 0.1 or more). */
Test(fit_ml_drift, meuse_linear_drift_equals_r_formula)
{
    double r[3 * 155], xy[2 * 155], z[155], q[16];
    char buf[4096];
    if (system("command -v Rscript >/dev/null 2>&1") != 0) {
        fprintf(stderr, "skip: Meuse likelihood with a linear drift vs R's formula: Rscript is not installed\n");
        return;
    }
    cr_assert_eq(gstat_run("suppressMessages(library(sp)); data(meuse)\n"
                           "cat(sprintf('%.17g %.17g %.17g', meuse$x, meuse$y, log(meuse$zinc)), sep = '\\n')\n",
                           r, 3 * 155),
                 3 * 155, "R's meuse data");
    for (int i = 0; i < 155; i++)
        xy[2 * i] = r[3 * i], xy[2 * i + 1] = r[3 * i + 1], z[i] = r[3 * i + 2];
    nl_fit_result res[2];
    for (int reml = 0; reml < 2; reml++) {
        nl_fit_options o = {.family = "spherical", .nugget = 1, .drift = NL_DRIFT_LINEAR,
                            .likelihood = reml ? NL_FIT_REML : NL_FIT_ML};
        cr_assert_eq(nl_fit_ml(xy, z, 155, 2, &o, &res[reml]), NL_OK, "%s", nl_errmsg());
        cr_assert_eq(res[reml].ndrift, 3);
    }
    snprintf(buf, sizeof buf, script, res[0].param[0].value, res[0].param[1].value, res[0].param[2].value,
             res[1].param[0].value, res[1].param[1].value, res[1].param[2].value);
    cr_assert_eq(gstat_run(buf, q, 16), 10, "R's likelihood");
    for (int reml = 0; reml < 2; reml++) {
        const nl_fit_result *f = &res[reml];
        double *rr = q + 4 * reml;
        fprintf(stderr, "meuse %s linear drift: -2 l %.10f (R %.10f, R's optim %.10f), beta %g %g %g, range %g\n",
                reml ? "REML" : "ML", f->objective, rr[0], q[8 + reml], f->drift[0], f->drift[1], f->drift[2],
                f->param[1].value);
        cr_expect(fabs(f->objective - rr[0]) <= 1e-9 * fabs(rr[0]), "reml %d: -2 l %.12g, R %.12g", reml,
                  f->objective, rr[0]);
        for (int k = 0; k < 3; k++)
            cr_expect(fabs(f->drift[k] - rr[1 + k]) <= 1e-7 * fabs(rr[1 + k]) + 1e-12, "reml %d: beta %d %.12g, R %.12g",
                      reml, k, f->drift[k], rr[1 + k]);
        cr_expect(q[8 + reml] >= f->objective - 1e-4, "reml %d: R's optim found %.10f below %.10f", reml, q[8 + reml],
                  f->objective);
        cr_expect(f->converged, "reml %d not converged", reml);
        /* the global minima: R's profile over the range (optim in var and
         * nugget at each of 400, 600, ..., 6000 and 1773) is lowest at 1200
         * for ML (186.618; the optimum 186.608 at 1195) and at 1773 for REML
         * (186.2731, a valley 10% wide: 187.59 at 1600, 188.34 at 2000;
         * 187.09 at the next valley, 1200) */
        cr_expect(f->objective <= (reml ? 186.28 : 186.61), "reml %d: -2 l %.5f above the global minimum (range %g)",
                  reml, f->objective, f->param[1].value);
    }
    nl_fit_result_free(&res[0]);
    nl_fit_result_free(&res[1]);
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
 * errors) equal to the library's; --drift with wls is refused, exit 2,
 * naming the option. */
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
    cr_expect_eq(run_noiselab("fit drift.tsv --model markov --drift linear", NULL, 0, err, sizeof err), 2);
    cr_expect(strstr(err, "--drift") && strstr(err, "ml or reml"), "%s", err);
}
