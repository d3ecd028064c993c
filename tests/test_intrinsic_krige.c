/* Kriging with the intrinsic power variogram (core/model.h, Intrinsic
 * models) against gstat, and its refusals. */
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#define NMEUSE 155
#define NG 80

/* R prints the Meuse data (x, y, log(zinc)), then per point of a 10 x 8
 * grid over the data's extent (metres) x, y, gstat's ordinary kriging
 * prediction and variance with vgm(0.012, "Pow", 0.58) (gstat's fit to
 * the sample variogram, rounded; Pow's "range" is the exponent), global
 * or with nmax = nmax. */
static long meuse_gstat(int nmax, double *r, size_t max)
{
    char script[2048];
    snprintf(script, sizeof script,
             "suppressMessages({library(sp); library(gstat)})\ndata(meuse)\n"
             "cat(sprintf('%%.17g %%.17g %%.17g', meuse$x, meuse$y, log(meuse$zinc)), sep = '\\n')\n"
             "g <- expand.grid(x = 178600 + (0:9 + 0.5) * 280, y = 329700 + (0:7 + 0.5) * 487.5)\n"
             "k <- krige(log(zinc) ~ 1, ~x + y, meuse, g, model = vgm(0.012, 'Pow', 0.58), %s debug.level = 0)\n"
             "cat(sprintf('%%.17g %%.17g %%.17g %%.17g', g$x, g$y, k$var1.pred, k$var1.var), sep = '\\n')\n",
             nmax ? "nmax = 32," : "");
    return gstat_run(script, r, max);
}

/* Predictions and variances to 1e-10 relative: both solve the same
 * ordinary kriging system in double precision (our constant shift of K
 * changes neither, analysis/krige.c; its cancellation costs a factor
 * shift / variance ~ 20 on 1e-16), so they agree to ~1e-13. */
static void compare(const double *r, const double *est, const double *var, const char *what)
{
    double worst = 0;
    for (size_t i = 0; i < NG; i++) {
        const double *g = r + 3 * NMEUSE + 4 * i;
        double de = fabs(est[i] - g[2]) / fabs(g[2]), dv = fabs(var[i] - g[3]) / g[3];
        cr_expect_leq(de, 1e-10, "%s at (%g, %g): estimate %.17g, gstat %.17g", what, g[0], g[1], est[i], g[2]);
        cr_expect_leq(dv, 1e-10, "%s at (%g, %g): variance %.17g, gstat %.17g", what, g[0], g[1], var[i], g[3]);
        worst = fmax(worst, fmax(de, dv));
    }
    fprintf(stderr, "%s: largest relative difference from gstat %.3g\n", what, worst);
}

static void split(const double *r, double *pts, double *val, double *x)
{
    for (size_t i = 0; i < NMEUSE; i++)
        pts[2 * i] = r[3 * i], pts[2 * i + 1] = r[3 * i + 1], val[i] = r[3 * i + 2];
    for (size_t i = 0; i < NG; i++)
        x[2 * i] = r[3 * NMEUSE + 4 * i], x[2 * i + 1] = r[3 * NMEUSE + 4 * i + 1];
}

Test(intrinsic_krige, ordinary_equals_gstat_on_meuse)
{
    if (!gstat_available("Meuse power-variogram kriging vs gstat"))
        return;
    double r[3 * NMEUSE + 4 * NG], pts[2 * NMEUSE], val[NMEUSE], x[2 * NG], est[NG], var[NG];
    cr_assert_eq(meuse_gstat(0, r, 3 * NMEUSE + 4 * NG), 3 * NMEUSE + 4 * NG, "R's output");
    split(r, pts, val, x);
    nl_model *m = test_model("powvar:alpha=0.58,c=0.012");
    nl_krige_plan *p;
    nl_krige_info info;
    cr_assert_eq(nl_krige_plan_alloc(m, 2, NMEUSE, pts, val, 0, 0, 1, &p), NL_OK, "%s", nl_errmsg());
    nl_krige_plan_info(p, &info);
    cr_expect(!info.pseudo_inverse, "the shifted matrix is positive definite (Cholesky)");
    cr_assert_eq(nl_krige_eval_block(p, NG, x, est, var), NL_OK);
    compare(r, est, var, "global ordinary kriging");
    nl_krige_plan_free(p), nl_model_free(m);
}

Test(intrinsic_krige_slow, local_equals_gstat_on_meuse)
{
    if (!gstat_available("Meuse power-variogram kriging, nmax 32, vs gstat"))
        return;
    double r[3 * NMEUSE + 4 * NG], pts[2 * NMEUSE], val[NMEUSE], x[2 * NG], est[NG], var[NG];
    cr_assert_eq(meuse_gstat(32, r, 3 * NMEUSE + 4 * NG), 3 * NMEUSE + 4 * NG, "R's output");
    split(r, pts, val, x);
    nl_model *m = test_model("powvar:alpha=0.58,c=0.012");
    nl_krige_local_options o = {.nmax = 32, .drift = NL_DRIFT_CONSTANT};
    nl_krige_local *k;
    cr_assert_eq(nl_krige_local_alloc(m, 2, NMEUSE, pts, val, &o, &k), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_eval(k, NG, x, est, var), NL_OK, "%s", nl_errmsg());
    compare(r, est, var, "ordinary kriging, nmax 32");
    nl_krige_local_free(k), nl_model_free(m);
}

/* An intrinsic model has no mean: simple kriging is refused, globally and
 * locally, naming the model. */
Test(intrinsic_krige, simple_kriging_is_refused)
{
    double pts[] = {0, 0, 1, 0, 0, 1}, val[] = {1, 2, 3};
    nl_model *m = test_model("powvar:alpha=1.2");
    nl_krige_plan *p;
    nl_krige_local *k;
    nl_krige_local_options o = {.drift = NL_DRIFT_NONE, .mean = 0};
    cr_expect_eq(nl_krige_plan_alloc(m, 2, 3, pts, val, 1, 0.5, 0, &p), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "intrinsic"), "%s", nl_errmsg());
    cr_expect_eq(nl_krige_local_alloc(m, 2, 3, pts, val, &o, &k), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "intrinsic"), "%s", nl_errmsg());
    nl_model_free(m);
}

/* The variogram: R(0) - R(lag) for a stationary model, c |lag|^alpha plus
 * the nugget off the origin for powvar (exact arithmetic but pow). */
Test(intrinsic_krige, variogram_of_models)
{
    nl_model *m = test_model("powvar:alpha=1.37,c=2.385,nugget=0.25"), *s = test_model("markov:scale=3,var=2");
    double lag[2] = {3, 4}, zero[2] = {0, 0};
    cr_expect_float_eq(nl_model_variogram(m, 2, lag), 0.25 + 2.385 * pow(5, 1.37), 1e-13);
    cr_expect_eq(nl_model_variogram(m, 2, zero), 0.0);
    cr_expect_float_eq(nl_model_variogram(s, 2, lag), 2 * (1 - exp(-5.0 / 3)), 1e-14);
    cr_expect(nl_model_is_intrinsic(m) && !nl_model_is_intrinsic(s));
    cr_expect_eq(nl_model_check_stationary(s, "x"), NL_OK);
    cr_expect_eq(nl_model_check_stationary(m, "synth fft"), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "powvar is intrinsic (no covariance): use synth intrinsic"), "%s", nl_errmsg());
    nl_model_free(m), nl_model_free(s);
}

/* Leave-one-out cross-validation with the power variogram, global
 * neighbourhood, against gstat's krige.cv: each left-out prediction and
 * variance to 1e-10 relative (as above). */
Test(intrinsic_krige_slow, cross_validation_equals_gstat_on_meuse)
{
    if (!gstat_available("Meuse power-variogram krige.cv vs gstat"))
        return;
    double r[3 * NMEUSE + 2 * NMEUSE], pts[2 * NMEUSE], val[NMEUSE], pred[NMEUSE], var[NMEUSE], worst = 0;
    long got = gstat_run("suppressMessages({library(sp); library(gstat)})\ndata(meuse)\n"
                         "cat(sprintf('%.17g %.17g %.17g', meuse$x, meuse$y, log(meuse$zinc)), sep = '\\n')\n"
                         "cv <- krige.cv(log(zinc) ~ 1, ~x + y, meuse, model = vgm(0.012, 'Pow', 0.58), "
                         "verbose = FALSE)\ncat(sprintf('%.17g %.17g', cv$var1.pred, cv$var1.var), sep = '\\n')\n",
                         r, 5 * NMEUSE);
    cr_assert_eq(got, 5 * NMEUSE, "R's output");
    for (size_t i = 0; i < NMEUSE; i++)
        pts[2 * i] = r[3 * i], pts[2 * i + 1] = r[3 * i + 1], val[i] = r[3 * i + 2];
    nl_model *m = test_model("powvar:alpha=0.58,c=0.012");
    nl_krige_local_options o = {.nmax = 0, .drift = NL_DRIFT_CONSTANT};
    nl_krige_local *k;
    nl_krige_cv_summary s;
    cr_assert_eq(nl_krige_local_alloc(m, 2, NMEUSE, pts, val, &o, &k), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_cv(k, pred, var, &s), NL_OK, "%s", nl_errmsg());
    for (size_t i = 0; i < NMEUSE; i++) {
        const double *g = r + 3 * NMEUSE + 2 * i;
        double de = fabs(pred[i] - g[0]) / fabs(g[0]), dv = fabs(var[i] - g[1]) / g[1];
        cr_expect_leq(de, 1e-10, "datum %zu: prediction %.17g, gstat %.17g", i, pred[i], g[0]);
        cr_expect_leq(dv, 1e-10, "datum %zu: variance %.17g, gstat %.17g", i, var[i], g[1]);
        worst = fmax(worst, fmax(de, dv));
    }
    fprintf(stderr, "cross-validation: largest relative difference from gstat %.3g\n", worst);
    nl_krige_local_free(k), nl_model_free(m);
}
