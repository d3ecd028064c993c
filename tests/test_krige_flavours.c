/* Block, trans-Gaussian and indicator kriging (analysis/krige_flavours.h)
 * against gstat's krige(..., block = ), krigeTg and the ordinary kriging of
 * indicators on the Meuse data, and the order-relation correction against
 * GSLIB's ordrel. */
#include "../analysis/krige_flavours.h"
#include "../core/io_points.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 101 cells of meuse.grid (every 31st) */
#define NG 101

/* R: the Meuse data (x, y, zinc) to meuse.tsv and the NG locations
 * printed as "x y" lines, then the program's own lines. */
#define MEUSE_R                                                                                                   \
    "suppressMessages(library(gstat))\ndata(meuse, package = 'sp'); data(meuse.grid, package = 'sp')\n"          \
    "write.table(format(data.frame(x = meuse$x, y = meuse$y, value = meuse$zinc), digits = 17), 'meuse.tsv',"   \
    " sep = '\\t', quote = FALSE, row.names = FALSE)\n"                                                          \
    "g <- meuse.grid[seq(1, 3103, by = 31), c('x', 'y')]\n"                                                      \
    "cat(sprintf('%.17g %.17g', g$x, g$y), sep = '\\n')\n"                                                       \
    "out <- function(a, b) cat(sprintf('%.17g %.17g', a, b), sep = '\\n')\n"

/* The Meuse data read back from the scratch directory. */
static nl_points *meuse(void)
{
    char path[512];
    nl_points *p;
    snprintf(path, sizeof path, "%s/meuse.tsv", scratch_dir());
    cr_assert_eq(nl_points_read(path, &p), 0, "%s", nl_errmsg());
    cr_assert_eq(p->n, 155);
    return p;
}

/* Largest absolute difference of est/var from the pairs r[2t], r[2t+1]. */
static double differ(const double *est, const double *var, const double *r, size_t n)
{
    double d = 0;
    for (size_t t = 0; t < n; t++)
        d = fmax(d, fmax(fabs(est[t] - r[2 * t]), var ? fabs(var[t] - r[2 * t + 1]) : 0));
    return d;
}

/* Both sides solve the same systems of 155 or fewer points in double
 * precision, with gstat's 10-digit Gauss-Legendre constants on both sides.  Point kriging agrees to
 * ~1e-12; block kriging to ~1e-8, because gstat's block results differ by
 * about that from the exact averages (the kriging system written out in R
 * with the same discretisation gives ours to 1e-15 and differs from
 * gstat's by about 4e-9 at (181170, 333250)).  1e-6 is the agreement asked for;
 * a wrong discretisation (regular 4 x 4 for the default) differs by 1e-3. */
Test(krige_flavours, block_equals_gstat_meuse)
{
    if (!gstat_available("block kriging vs gstat"))
        return;
    static double r[2 * NG * 5];
    long got = gstat_run(MEUSE_R "m <- vgm(0.59, 'Sph', 897, 0.05)\n"
                         "k <- krige(log(zinc) ~ 1, ~x + y, meuse, g, m, block = c(40, 40), debug.level = 0); out(k$var1.pred, k$var1.var)\n"
                         "k <- krige(log(zinc) ~ x + y, ~x + y, meuse, g, m, block = c(40, 60), nmax = 20, set = list(nblockdiscr = 3), debug.level = 0); out(k$var1.pred, k$var1.var)\n"
                         "k <- krige(log(zinc) ~ 1, ~x + y, meuse, g, m, beta = 5.9, block = c(40, 40), nmax = 20, debug.level = 0); out(k$var1.pred, k$var1.var)\n"
                         "k <- krige(log(zinc) ~ 1, ~x + y, meuse, g, vgm(1e-5, 'Pow', 1.5, 0.05), block = c(50, 30), nmax = 20, debug.level = 0); out(k$var1.pred, k$var1.var)\n",
                         r, 2 * NG * 5);
    cr_assert_eq(got, 2 * NG * 5, "R printed %ld numbers", got);
    nl_points *p = meuse();
    nl_model *m = test_model("spherical:var=0.59,scale=897,nugget=0.05");
    nl_model *pw = test_model("nugget:var=0.05 + powvar:alpha=1.5,c=1e-5"); /* gstat's vgm(c, 'Pow', alpha, nugget) */
    cr_assert_eq(nl_krige_tg_transform(0, p->n, p->val, p->val), 0);
    struct {
        size_t nmax;
        int drift;
        nl_krige_block b;
        const nl_model *m;
        const char *what;
    } c[4] = {{0, NL_DRIFT_CONSTANT, {{40, 40}, 0}, m, "ordinary, global, 40 x 40, Gauss 4x4 (gstat's default)"},
              {20, NL_DRIFT_LINEAR, {{40, 60}, 3}, m, "universal x + y, nmax 20, 40 x 60, regular 3x3"},
              {20, NL_DRIFT_NONE, {{40, 40}, 0}, m, "simple (mean 5.9), nmax 20, 40 x 40"},
              {20, NL_DRIFT_CONSTANT, {{50, 30}, 0}, pw, "ordinary, nmax 20, 50 x 30, intrinsic Nug + Pow"}};
    double est[NG], var[NG];
    for (int i = 0; i < 4; i++) {
        nl_krige_local_options o = {.nmax = c[i].nmax, .drift = c[i].drift, .mean = 5.9};
        nl_krige_local *k;
        cr_assert_eq(nl_krige_local_alloc(c[i].m, 2, p->n, p->pts, p->val, &o, &k), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_krige_block_eval(k, &c[i].b, NG, r, est, var), 0, "%s", nl_errmsg());
        double d = differ(est, var, r + 2 * NG * (i + 1), NG);
        fprintf(stderr, "block kriging, %s: largest difference from gstat %.3g\n", c[i].what, d);
        cr_expect(d <= 1e-6, "%s: differs from gstat by %g", c[i].what, d);
        nl_krige_local_free(k);
    }
    nl_model_free(m), nl_model_free(pw), nl_points_free(p);
}

/* krigeTg's var1TG.pred and var1TG.var; tolerance as above, relative to
 * values of order 1e3 (estimates) and 1e5 (variances).  (Blocks are not
 * compared here: krigeTg finds the Lagrange multiplier as (OK var - SK var)
 * / (1 - sum of SK weights), a quotient of two differences that, near
 * sum = 1, amplifies the ~1e-9 by which gstat's block covariances differ
 * from the exact averages.) */
Test(krige_flavours, trans_gaussian_equals_krigeTg_meuse)
{
    if (!gstat_available("trans-Gaussian kriging vs krigeTg"))
        return;
    static double r[2 * NG * 3];
    long got = gstat_run(MEUSE_R "suppressMessages(library(sp)); coordinates(meuse) <- ~x + y; coordinates(g) <- ~x + y\n"
                         "m0 <- vgm(0.59, 'Sph', 897, 0.05); m1 <- vgm(8, 'Sph', 897, 1)\n"
                         "k <- krigeTg(zinc ~ 1, meuse, g, m0, lambda = 0, debug.level = 0); out(k$var1TG.pred, k$var1TG.var)\n"
                         "k <- krigeTg(zinc ~ 1, meuse, g, m1, lambda = 0.25, nmax = 30, debug.level = 0); out(k$var1TG.pred, k$var1TG.var)\n"
                         , r, 2 * NG * 3);
    cr_assert_eq(got, 2 * NG * 3, "R printed %ld numbers", got);
    nl_points *p = meuse();
    struct {
        const char *spec;
        double lambda;
        size_t nmax;
        int block;
        const char *what;
    } c[2] = {{"spherical:var=0.59,scale=897,nugget=0.05", 0, 0, 0, "log, global"},
              {"spherical:var=8,scale=897,nugget=1", 0.25, 30, 0, "lambda 0.25, nmax 30"}};
    double est[NG], var[NG], *y = malloc(p->n * sizeof *y);
    nl_krige_block b = {{40, 40}, 0};
    for (int i = 0; i < 2; i++) {
        nl_model *m = test_model(c[i].spec);
        nl_krige_local_options o = {.nmax = c[i].nmax, .drift = NL_DRIFT_CONSTANT};
        nl_krige_local *k;
        cr_assert_eq(nl_krige_tg_transform(c[i].lambda, p->n, p->val, y), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_krige_local_alloc(m, 2, p->n, p->pts, y, &o, &k), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_krige_tg_eval(k, c[i].block ? &b : NULL, c[i].lambda, NG, r, est, var), 0, "%s", nl_errmsg());
        const double *q = r + 2 * NG * (i + 1);
        double de = 0, dv = 0;
        for (size_t t = 0; t < NG; t++)
            de = fmax(de, fabs(est[t] - q[2 * t]) / q[2 * t]), dv = fmax(dv, fabs(var[t] - q[2 * t + 1]) / q[2 * t + 1]);
        fprintf(stderr, "trans-Gaussian, %s: largest relative difference from krigeTg: estimate %.3g, variance %.3g\n",
                c[i].what, de, dv);
        cr_expect(de <= 1e-6 && dv <= 1e-6, "%s: estimate differs by %g, variance by %g (relative)", c[i].what, de, dv);
        nl_krige_local_free(k), nl_model_free(m);
    }
    free(y), nl_points_free(p);
}

/* Ordinary kriging of I(zinc < t) for four thresholds, each with its own
 * model, with nmax = 12 (small neighbourhoods make order-relation
 * violations); R also applies GSLIB's ordrel (clip, cummax, reversed
 * cummin, average) as the reference of the correction.  Tolerance as in
 * the block test, on probabilities. */
Test(krige_flavours_slow, indicator_equals_gstat_meuse)
{
    if (!gstat_available("indicator kriging vs gstat"))
        return;
    enum { NK = 4 };
    static double r[2 * NG + 2 * NG * NK + 1];
    long got = gstat_run(MEUSE_R "th <- c(200.5, 400.5, 800.5, 1200.5)\n"
                         "ms <- list(vgm(0.05, 'Sph', 600, 0.02), vgm(0.15, 'Sph', 900, 0.05), vgm(0.12, 'Sph', 1200, 0.06), vgm(0.06, 'Sph', 500, 0.03))\n"
                         "P <- sapply(1:4, function(j) { meuse$ind <- as.numeric(meuse$zinc < th[j])\n"
                         "  krige(ind ~ 1, ~x + y, meuse, g, ms[[j]], nmax = 12, debug.level = 0)$var1.pred })\n"
                         "C <- t(apply(pmin(pmax(P, 0), 1), 1, function(p) (cummax(p) + rev(cummin(rev(p)))) / 2))\n"
                         "cat(sprintf('%.17g', t(P)), sep = '\\n'); cat(sprintf('%.17g', t(C)), sep = '\\n')\n"
                         "cat(sum(apply(abs(C - P) > 1e-12, 1, any)), '\\n')\n",
                         r, 2 * NG + 2 * NG * NK + 1);
    cr_assert_eq(got, 2 * NG + 2 * NG * NK + 1, "R printed %ld numbers", got);
    nl_points *p = meuse();
    const double thr[NK] = {200.5, 400.5, 800.5, 1200.5};
    const char *spec[NK] = {"spherical:var=0.05,scale=600,nugget=0.02", "spherical:var=0.15,scale=900,nugget=0.05",
                            "spherical:var=0.12,scale=1200,nugget=0.06", "spherical:var=0.06,scale=500,nugget=0.03"};
    nl_model *m[NK];
    for (int j = 0; j < NK; j++)
        m[j] = test_model(spec[j]);
    nl_krige_local_options o = {.nmax = 12, .drift = NL_DRIFT_CONSTANT};
    double raw[NG * NK], cdf[NG * NK], draw = 0, dcdf = 0;
    size_t nc = 0;
    cr_assert_eq(nl_krige_indicator((const nl_model *const *)m, NK, thr, 2, p->n, p->pts, p->val, &o, NULL, NG, r, raw,
                                    cdf, &nc), 0, "%s", nl_errmsg());
    const double *P = r + 2 * NG, *C = P + NG * NK;
    for (size_t t = 0; t < NG * NK; t++)
        draw = fmax(draw, fabs(raw[t] - P[t])), dcdf = fmax(dcdf, fabs(cdf[t] - C[t]));
    fprintf(stderr, "indicator kriging: largest difference from gstat %.3g, of the corrected CDF from ordrel in R "
            "%.3g; %zu of %d locations corrected (R: %g)\n", draw, dcdf, nc, NG, C[NG * NK]);
    cr_expect(draw <= 1e-6, "kriged indicators differ from gstat's by %g", draw);
    cr_expect(dcdf <= 1e-6, "corrected probabilities differ from ordrel's by %g", dcdf);
    cr_expect(nc > 0 && (double)nc == C[NG * NK], "%zu locations corrected, R %g (the data must need a correction)",
              nc, C[NG * NK]);
    for (size_t t = 0; t < NG; t++)
        for (int j = 0; j < NK; j++)
            cr_expect(cdf[t * NK + j] >= 0 && cdf[t * NK + j] <= 1 && (j == 0 || cdf[t * NK + j] >= cdf[t * NK + j - 1]),
                      "location %zu: the corrected CDF is not monotone in [0, 1]", t);
    for (int j = 0; j < NK; j++)
        nl_model_free(m[j]);
    nl_points_free(p);
}

/* GSLIB's ordrel by hand: clip [-0.1, 0.5, 0.4, 1.2] to [0, 0.5, 0.4, 1];
 * upward [0, 0.5, 0.5, 1], downward [0, 0.4, 0.4, 1]; average
 * [0, 0.45, 0.45, 1].  A monotone row in [0, 1] is left alone. */
Test(krige_flavours, order_relations_by_hand)
{
    double p[8] = {-0.1, 0.5, 0.4, 1.2, 0.1, 0.2, 0.2, 0.9}, want[8] = {0, 0.45, 0.45, 1, 0.1, 0.2, 0.2, 0.9};
    cr_expect_eq(nl_krige_order_relations(2, 4, p), 1);
    for (int i = 0; i < 8; i++)
        cr_expect(fabs(p[i] - want[i]) < 1e-15, "p[%d] = %.17g, expected %g", i, p[i], want[i]);
}

/* The discretisations: gstat's Gauss-Legendre nodes and weights (sum 1 to
 * their 10 digits), regular midpoints, and the refusals. */
Test(krige_flavours, discretisation)
{
    static double d[3 * NL_KRIGE_BLOCK_POINTS_MAX], w[NL_KRIGE_BLOCK_POINTS_MAX];
    size_t nd;
    nl_krige_block b = {{40, 60}, 0};
    cr_assert_eq(nl_krige_block_discretise(&b, 2, &nd, d, w), 0, "%s", nl_errmsg());
    cr_expect_eq(nd, 16);
    double s = 0;
    for (size_t j = 0; j < nd; j++)
        s += w[j];
    cr_expect(fabs(s - 1) < 1e-9, "weights sum to %.17g", s);
    cr_expect(fabs(d[0] + 40 * 0.4305681558) < 1e-12 && fabs(d[1] + 60 * 0.4305681558) < 1e-12, "%g %g", d[0], d[1]);
    b.points = 3;
    cr_assert_eq(nl_krige_block_discretise(&b, 2, &nd, d, w), 0, "%s", nl_errmsg());
    cr_expect_eq(nd, 9);
    cr_expect(fabs(d[0] + 40.0 / 3) < 1e-12 && fabs(d[2 * 4]) < 1e-12 && fabs(w[0] - 1.0 / 9) < 1e-15);
    b.points = 1;
    cr_expect_eq(nl_krige_block_discretise(&b, 2, &nd, d, w), NL_EINVAL);
    b.points = 17, b.size[2] = 20;
    cr_expect_eq(nl_krige_block_discretise(&b, 3, &nd, d, w), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "4913") != NULL, "%s", nl_errmsg());
    b.points = 0, b.size[1] = 0, b.size[2] = 1;
    cr_expect_eq(nl_krige_block_discretise(&b, 2, &nd, d, w), NL_EINVAL);
}

/* 60 positive values at scattered points of the unit square, fixed seed. */
static void scattered(double *pts, double *val, size_t n)
{
    unsigned long long s = 2385;
    for (size_t i = 0; i < n; i++) {
        double u[3];
        for (int j = 0; j < 3; j++) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            u[j] = (double)(s >> 11) / 9007199254740992.0;
        }
        pts[2 * i] = u[0], pts[2 * i + 1] = u[1], val[i] = exp(sin(4 * u[0]) + u[1] + 0.4 * u[2]);
    }
}

/* Leave-one-out is kriging from the others: trans-Gaussian and indicator
 * cross-validation at datum i equal the estimate at t_i of a plan without
 * datum i (the same arithmetic on the same neighbourhood: to rounding,
 * 1e-10 relative). */
Test(krige_flavours, cross_validation_is_kriging_without_the_datum)
{
    enum { N = 60 };
    double pts[2 * N], val[N], y[N], pred[N], var[N], p2[2 * N], v2[N], y2[N], e, v;
    const double thr[2] = {1.5, 3.1};
    double cdf[N * 2], c1[2];
    nl_krige_cv_summary s;
    scattered(pts, val, N);
    nl_model *m = test_model("markov:scale=0.3,nugget=0.02");
    const nl_model *mm[2] = {m, m};
    nl_krige_local_options o = {.nmax = 12, .drift = NL_DRIFT_CONSTANT};
    nl_krige_local *k;
    cr_assert_eq(nl_krige_tg_transform(0.5, N, val, y), 0);
    cr_assert_eq(nl_krige_local_alloc(m, 2, N, pts, y, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_tg_cv(k, 0.5, val, pred, var, &s), 0, "%s", nl_errmsg());
    nl_krige_local_free(k);
    cr_assert_eq(nl_krige_indicator(mm, 2, thr, 2, N, pts, val, &o, NULL, N, NULL, NULL, cdf, NULL), 0, "%s",
                 nl_errmsg());
    for (size_t i = 0; i < N; i += 17) {
        size_t q = 0;
        for (size_t j = 0; j < N; j++)
            if (j != i)
                p2[2 * q] = pts[2 * j], p2[2 * q + 1] = pts[2 * j + 1], v2[q] = val[j], y2[q++] = y[j];
        cr_assert_eq(nl_krige_local_alloc(m, 2, N - 1, p2, y2, &o, &k), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_krige_tg_eval(k, NULL, 0.5, 1, pts + 2 * i, &e, &v), 0, "%s", nl_errmsg());
        nl_krige_local_free(k);
        cr_expect(fabs(e - pred[i]) <= 1e-10 * fabs(e) && fabs(v - var[i]) <= 1e-10 * v, "datum %zu: %g %g, cv %g %g",
                  i, e, v, pred[i], var[i]);
        cr_assert_eq(nl_krige_indicator(mm, 2, thr, 2, N - 1, p2, v2, &o, NULL, 1, pts + 2 * i, NULL, c1, NULL), 0, "%s",
                     nl_errmsg());
        cr_expect(fabs(c1[0] - cdf[2 * i]) <= 1e-10 && fabs(c1[1] - cdf[2 * i + 1]) <= 1e-10, "datum %zu: %g %g, cv %g %g",
                  i, c1[0], c1[1], cdf[2 * i], cdf[2 * i + 1]);
    }
    nl_model_free(m);
}

/* What the flavours refuse, each naming the value. */
Test(krige_flavours, refusals)
{
    enum { N = 20 };
    double pts[2 * N], val[N], y[N], x[2] = {0.5, 0.5}, e, cdf[2];
    const double up[2] = {1.5, 3.1}, down[2] = {3.1, 1.5};
    scattered(pts, val, N);
    nl_model *m = test_model("markov:scale=0.3");
    const nl_model *mm[2] = {m, m};
    nl_krige_local *k;
    nl_krige_local_options lin = {.drift = NL_DRIFT_LINEAR}, sk = {.drift = NL_DRIFT_NONE, .mean = 2};
    cr_assert_eq(nl_krige_local_alloc(m, 2, N, pts, val, &lin, &k), 0, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_tg_eval(k, NULL, 0, 1, x, &e, NULL), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "polynomial drift") != NULL, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_tg_eval(k, NULL, 7, 1, x, &e, NULL), NL_EINVAL);
    nl_krige_local_free(k);
    val[3] = -1;
    cr_expect_eq(nl_krige_tg_transform(0.5, N, val, y), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "point 4 is -1") != NULL, "%s", nl_errmsg());
    val[3] = 1;
    cr_expect_eq(nl_krige_indicator(mm, 2, down, 2, N, pts, val, &lin, NULL, 1, x, NULL, cdf, NULL), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "threshold 2 is 1.5") != NULL, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_indicator(mm, 2, up, 2, N, pts, val, &sk, NULL, 1, x, NULL, cdf, NULL), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "own mean") != NULL, "%s", nl_errmsg());
    cr_expect_eq(nl_krige_indicator(mm, 2, up, 2, N, pts, val, &lin, NULL, 5, NULL, NULL, cdf, NULL), NL_EINVAL);
    nl_model_free(m);
}

/* gstat's block discretisation in 3D (4 x 4 x 4 Gauss-Legendre points) and
 * 1D (gstat: points on the line y = 0, a block c(W, 0) discretised along x
 * alone), on scattered data of the unit cube and interval, with an
 * exponential model and a nugget (which the block's own variance must
 * leave out); tolerance as block_equals_gstat_meuse. */
Test(krige_flavours_slow, block_3d_and_1d_equal_gstat)
{
    if (!gstat_available("3D and 1D block kriging vs gstat"))
        return;
    enum { N3 = 80, N1 = 30, M = 20 };
    double p3[3 * N3], v3[N3], p1[N1], v1[N1], x3[3 * M], x1[M], est[M], var[M], r[4 * M];
    unsigned long long s = 2385;
    for (int i = 0; i < 3 * N3 + N3 + 2 * N1 + 4 * M; i++) { /* one stream of uniforms */
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        double u = (double)(s >> 11) / 9007199254740992.0;
        int j = i;
        if (j < 3 * N3)
            p3[j] = u;
        else if ((j -= 3 * N3) < N3)
            v3[j] = sin(5 * p3[3 * j]) + p3[3 * j + 2] + 0.3 * u;
        else if ((j -= N3) < 2 * N1)
            j % 2 ? (v1[j / 2] = cos(4 * p1[j / 2]) + 0.2 * u) : (p1[j / 2] = u);
        else if ((j -= 2 * N1) < 3 * M)
            x3[j] = u;
        else
            x1[j - 3 * M] = u;
    }
    char path[512];
    snprintf(path, sizeof path, "%s/p3.tsv", scratch_dir());
    gstat_write_points(path, 3, N3, p3, v3);
    snprintf(path, sizeof path, "%s/p1.tsv", scratch_dir());
    gstat_write_points(path, 1, N1, p1, v1);
    snprintf(path, sizeof path, "%s/x3.tsv", scratch_dir());
    gstat_write_points(path, 3, M, x3, x1);
    long got = gstat_run("suppressMessages(library(gstat))\nd3 <- read.delim('p3.tsv'); d1 <- read.delim('p1.tsv'); "
                         "x <- read.delim('x3.tsv')\nm <- vgm(1, 'Exp', 0.3, 0.1)\n"
                         "k <- krige(value ~ 1, ~x + y + z, d3, x, m, block = c(0.1, 0.2, 0.15), nmax = 30, debug.level = 0)\n"
                         "cat(sprintf('%.17g %.17g', k$var1.pred, k$var1.var), sep = '\\n')\n"
                         "d1$y <- 0; k <- krige(value ~ 1, ~x + y, d1, data.frame(x = x$value, y = 0), m, block = c(0.12, 0), debug.level = 0)\n"
                         "cat(sprintf('%.17g %.17g', k$var1.pred, k$var1.var), sep = '\\n')\n",
                         r, 4 * M);
    cr_assert_eq(got, 4 * M, "R printed %ld numbers", got);
    nl_model *m = test_model("markov:scale=0.3,nugget=0.1");
    nl_krige_local_options o = {.nmax = 30, .drift = NL_DRIFT_CONSTANT}, g = {.drift = NL_DRIFT_CONSTANT};
    nl_krige_block b3 = {{0.1, 0.2, 0.15}, 0}, b1 = {{0.12}, 0};
    nl_krige_local *k;
    cr_assert_eq(nl_krige_local_alloc(m, 3, N3, p3, v3, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_block_eval(k, &b3, M, x3, est, var), 0, "%s", nl_errmsg());
    nl_krige_local_free(k);
    double d = differ(est, var, r, M);
    cr_assert_eq(nl_krige_local_alloc(m, 1, N1, p1, v1, &g, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_block_eval(k, &b1, M, x1, est, var), 0, "%s", nl_errmsg());
    nl_krige_local_free(k);
    double d1 = differ(est, var, r + 2 * M, M);
    fprintf(stderr, "block kriging: largest difference from gstat, 3D %.3g, 1D %.3g\n", d, d1);
    cr_expect(d <= 1e-6 && d1 <= 1e-6, "differs from gstat by %g (3D), %g (1D)", d, d1);
    nl_model_free(m);
}
