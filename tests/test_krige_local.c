/* Local (nmax) and universal kriging and leave-one-out cross-validation
 * against gstat's krige() and krige.cv(), and their properties without R. */
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NPTS 200
#define NG 15

static double unif(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* 200 points in the unit square with a smooth trend plus noise. */
static void make_data(double *pts, double *val)
{
    unsigned long long s = 2385;
    for (size_t i = 0; i < NPTS; i++) {
        double x = unif(&s), y = unif(&s);
        pts[2 * i] = x, pts[2 * i + 1] = y;
        val[i] = sin(3 * x) + 2.3 * y * y + 0.3 * unif(&s);
    }
}

/* NG x NG cell centres of the unit square, x fastest. */
static void make_grid(double *g)
{
    for (size_t j = 0, t = 0; j < NG; j++)
        for (size_t i = 0; i < NG; i++, t++)
            g[2 * t] = ((double)i + 0.5) / NG, g[2 * t + 1] = ((double)j + 0.5) / NG;
}

/* Our estimates and variances at the grid against gstat's, to 1e-6
 * (absolute, on values of order 1): both solve the same well-conditioned
 * systems in double precision (condition numbers below 1e4 here), so they
 * agree to ~1e-12; 1e-6 is the acceptance the comparison asks for. */
static void against_gstat(const char *spec, const char *formula, const char *vgm, const nl_krige_local_options *o,
                          const char *what)
{
    double pts[2 * NPTS], val[NPTS], g[2 * NG * NG], est[NG * NG], var[NG * NG], r[2 * NG * NG + 1];
    char path[512], script[2048];
    make_data(pts, val);
    make_grid(g);
    snprintf(path, sizeof path, "%s/pts.tsv", scratch_dir());
    gstat_write_points(path, 2, NPTS, pts, val);
    snprintf(script, sizeof script,
             "suppressMessages(library(gstat))\nd <- read.delim('pts.tsv')\n"
             "g <- expand.grid(x = (0:%d + 0.5) / %d, y = (0:%d + 0.5) / %d)\n"
             "k <- krige(%s, ~x + y, d, g, model = %s, %s debug.level = 0)\n"
             "cat(sprintf('%%.17g %%.17g', k$var1.pred, k$var1.var), sep = '\\n')\n",
             NG - 1, NG, NG - 1, NG, formula, vgm, o->nmax ? "nmax = 32," : "");
    long m = gstat_run(script, r, 2 * NG * NG + 1);
    cr_assert_eq(m, 2 * NG * NG, "%s: R printed %ld numbers", what, m);
    nl_model *mod = test_model(spec);
    nl_krige_local *k;
    cr_assert_eq(nl_krige_local_alloc(mod, 2, NPTS, pts, val, o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_eval(k, NG * NG, g, est, var), 0, "%s", nl_errmsg());
    double de = 0, dv = 0;
    for (size_t t = 0; t < NG * NG; t++)
        de = fmax(de, fabs(est[t] - r[2 * t])), dv = fmax(dv, fabs(var[t] - r[2 * t + 1]));
    fprintf(stderr, "%s: largest difference from gstat: estimate %.3g, variance %.3g\n", what, de, dv);
    cr_expect(de <= 1e-6 && dv <= 1e-6, "%s: estimate differs by %g, variance by %g", what, de, dv);
    nl_krige_local_free(k), nl_model_free(mod);
}

/* markov:scale=a is gstat's vgm(1, "Exp", a) (exp(-h/a)); gauss:scale=a
 * is vgm(1, "Gau", a) (exp(-(h/a)^2)). */
Test(krige_local_slow, nmax32_equals_gstat)
{
    if (!gstat_available("krige nmax = 32 vs gstat"))
        return;
    nl_krige_local_options o = {.nmax = 32, .drift = NL_DRIFT_CONSTANT};
    against_gstat("markov:scale=0.2", "value ~ 1", "vgm(1, 'Exp', 0.2)", &o, "ordinary, nmax 32, Exp");
    against_gstat("gauss:scale=0.15,var=1.7", "value ~ 1", "vgm(1.7, 'Gau', 0.15)", &o, "ordinary, nmax 32, Gau");
    o.drift = NL_DRIFT_LINEAR;
    against_gstat("markov:scale=0.2", "value ~ x + y", "vgm(1, 'Exp', 0.2)", &o, "universal linear, nmax 32");
}

Test(krige_local_slow, universal_equals_gstat)
{
    if (!gstat_available("krige value ~ x + y vs gstat"))
        return;
    nl_krige_local_options o = {.nmax = 0, .drift = NL_DRIFT_LINEAR};
    against_gstat("markov:scale=0.2", "value ~ x + y", "vgm(1, 'Exp', 0.2)", &o, "universal linear, global");
    o.drift = NL_DRIFT_QUADRATIC;
    against_gstat("markov:scale=0.3", "value ~ x + y + I(x^2) + I(x*y) + I(y^2)", "vgm(1, 'Exp', 0.3)", &o,
                  "universal quadratic, global");
}

Test(krige_local_slow, cv_equals_gstat)
{
    if (!gstat_available("krige.cv vs gstat"))
        return;
    double pts[2 * NPTS], val[NPTS], pred[NPTS], var[NPTS], r[2 * NPTS + 4];
    char path[512];
    make_data(pts, val);
    snprintf(path, sizeof path, "%s/pts.tsv", scratch_dir());
    gstat_write_points(path, 2, NPTS, pts, val);
    long m = gstat_run("suppressMessages(library(gstat))\nd <- read.delim('pts.tsv')\n"
                       "cv <- krige.cv(value ~ x + y, ~x + y, d, model = vgm(1, 'Exp', 0.2), nmax = 32, debug.level = 0)\n"
                       "cat(sprintf('%.17g %.17g', cv$var1.pred, cv$var1.var), sep = '\\n')\n"
                       "cat(sprintf('%.17g', c(mean(cv$residual), var(cv$residual), mean(cv$zscore), var(cv$zscore))), sep = '\\n')\n",
                       r, 2 * NPTS + 4);
    cr_assert_eq(m, 2 * NPTS + 4, "R printed %ld numbers", m);
    nl_model *mod = test_model("markov:scale=0.2");
    nl_krige_local_options o = {.nmax = 32, .drift = NL_DRIFT_LINEAR};
    nl_krige_local *k;
    nl_krige_cv_summary s;
    cr_assert_eq(nl_krige_local_alloc(mod, 2, NPTS, pts, val, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_cv(k, pred, var, &s), 0, "%s", nl_errmsg());
    double d = 0;
    for (size_t i = 0; i < NPTS; i++)
        d = fmax(d, fmax(fabs(pred[i] - r[2 * i]), fabs(var[i] - r[2 * i + 1])));
    const double *q = r + 2 * NPTS, ours[4] = {s.mean_error, s.var_error, s.mean_z, s.var_z};
    for (int j = 0; j < 4; j++)
        d = fmax(d, fabs(ours[j] - q[j]));
    fprintf(stderr, "krige.cv: largest difference from gstat %.3g\n", d);
    cr_expect(d <= 1e-6, "cross-validation differs from gstat's by %g", d);
    nl_krige_local_free(k), nl_model_free(mod);
}

/* Property (no R): with every datum in the neighbourhood, local ordinary
 * kriging is the global kriging of analysis/krige.h (same estimator, other
 * algebra: agreement to rounding, 1e-9 on values of order 1). */
Test(krige_local, global_neighbourhood_equals_global_plan)
{
    double pts[2 * NPTS], val[NPTS], g[2 * NG * NG], est[NG * NG], var[NG * NG];
    make_data(pts, val);
    make_grid(g);
    nl_model *mod = test_model("markov:scale=0.2");
    nl_krige_local_options o = {.nmax = NPTS, .drift = NL_DRIFT_CONSTANT};
    nl_krige_local *k;
    nl_krige_plan *p;
    cr_assert_eq(nl_krige_local_alloc(mod, 2, NPTS, pts, val, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_plan_alloc(mod, 2, NPTS, pts, val, 0, 0, 1, &p), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_eval(k, NG * NG, g, est, var), 0);
    for (size_t t = 0; t < NG * NG; t++) {
        double e, v;
        cr_assert_eq(nl_krige_eval(p, g + 2 * t, &e, &v, NULL), 0);
        cr_expect(fabs(e - est[t]) <= 1e-9 && fabs(v - var[t]) <= 1e-9, "cell %zu: %.17g %.17g vs %.17g %.17g", t,
                  est[t], var[t], e, v);
    }
    nl_krige_plan_free(p), nl_krige_local_free(k), nl_model_free(mod);
}

/* Property: kriging interpolates; at a datum the estimate is the datum
 * and the variance 0 (to rounding of the solve, 1e-9). */
Test(krige_local, exact_at_data)
{
    double pts[2 * NPTS], val[NPTS], est[NPTS], var[NPTS];
    make_data(pts, val);
    nl_model *mod = test_model("markov:scale=0.2");
    nl_krige_local_options o = {.nmax = 16, .radius = 0.4, .drift = NL_DRIFT_LINEAR};
    nl_krige_local *k;
    cr_assert_eq(nl_krige_local_alloc(mod, 2, NPTS, pts, val, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_eval(k, NPTS, pts, est, var), 0, "%s", nl_errmsg());
    for (size_t i = 0; i < NPTS; i++)
        cr_expect(fabs(est[i] - val[i]) <= 1e-9 && var[i] <= 1e-9, "datum %zu: %g vs %g, variance %g", i, est[i],
                  val[i], var[i]);
    nl_krige_local_free(k), nl_model_free(mod);
}

Test(krige_local, refusals)
{
    double pts[8] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.2, 0.1}, val[4] = {1, 2, 3, NAN};
    nl_model *mod = test_model("markov:scale=0.2");
    nl_krige_local_options o = {.nmax = 8, .drift = NL_DRIFT_CONSTANT};
    nl_krige_local *k;
    cr_expect_eq(nl_krige_local_alloc(mod, 2, 1, pts, val, &o, &k), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "at least 2") != NULL, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_local_alloc(mod, 2, 3, pts, val, &o, &k), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "one place") != NULL, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_local_alloc(mod, 2, 4, pts, val, &o, &k), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "finite") != NULL, "%s", nl_errmsg());
    val[3] = 4, o.drift = NL_DRIFT_QUADRATIC; /* 6 terms, 4 points */
    cr_expect_eq(nl_krige_local_alloc(mod, 2, 4, pts, val, &o, &k), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "6 terms") != NULL, "%s", nl_errmsg());
    cr_expect_null(k);
    nl_model_free(mod);
}

/* Cross-validation of values whose squared errors overflow is refused
 * (NL_EINVAL naming the values) rather than summarised as inf and nan; the
 * same data scaled into range give a finite summary. */
Test(krige_local, cv_overflowing_values_refused)
{
    double pts[2 * NPTS], val[NPTS], pred[NPTS], var[NPTS];
    nl_model *mod = test_model("markov:scale=0.2");
    nl_krige_local_options o = {.nmax = 16, .drift = NL_DRIFT_CONSTANT};
    nl_krige_local *k;
    nl_krige_cv_summary s;
    make_data(pts, val);
    for (size_t i = 0; i < NPTS; i++)
        val[i] *= 1e250;
    cr_assert_eq(nl_krige_local_alloc(mod, 2, NPTS, pts, val, &o, &k), 0, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_local_cv(k, pred, var, &s), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "values run from") != NULL, "%s", nl_errmsg());
    nl_krige_local_free(k);
    for (size_t i = 0; i < NPTS; i++)
        val[i] *= 1e-250;
    cr_assert_eq(nl_krige_local_alloc(mod, 2, NPTS, pts, val, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_cv(k, pred, var, &s), 0, "%s", nl_errmsg());
    cr_expect(isfinite(s.rmse) && isfinite(s.var_error) && isfinite(s.var_z), "%g %g %g", s.rmse, s.var_error, s.var_z);
    nl_krige_local_free(k), nl_model_free(mod);
}

/* A nested model: the sum of its structures' covariances, each with its
 * own nugget and anisotropy, as gstat's vgm(..., add.to = ) with anis =
 * c(90 - angle, ratio) (gstat's principal direction is clockwise from
 * north, ours counterclockwise from x; both ratios are minor over major
 * when below 1). */
Test(krige_local_slow, nested_equals_gstat)
{
    if (!gstat_available("krige with a nested model vs gstat"))
        return;
    nl_krige_local_options o = {.nmax = 0, .drift = NL_DRIFT_CONSTANT};
    against_gstat("spherical:var=0.7,scale=0.5,nugget=0.05 + markov:var=0.3,scale=0.1", "value ~ 1",
                  "vgm(0.7, 'Sph', 0.5, 0.05, add.to = vgm(0.3, 'Exp', 0.1))", &o, "ordinary, global, Nug+Sph+Exp");
    o.nmax = 32;
    against_gstat("spherical:var=0.7,scale=0.5,nugget=0.05,angle=30,ratio=0.4 + markov:var=0.3,scale=0.1", "value ~ 1",
                  "vgm(0.7, 'Sph', 0.5, 0.05, anis = c(60, 0.4), add.to = vgm(0.3, 'Exp', 0.1))", &o,
                  "ordinary, nmax 32, Nug+Sph(anisotropic)+Exp");
    /* an intrinsic sum: white noise plus the power variogram (gstat's
     * vgm(c, "Pow", alpha, nugget)) */
    o.nmax = 0;
    against_gstat("nugget:var=0.01 + powvar:alpha=1.5,c=0.1", "value ~ 1", "vgm(0.1, 'Pow', 1.5, 0.01)", &o,
                  "ordinary, global, Nug+Pow");
}
