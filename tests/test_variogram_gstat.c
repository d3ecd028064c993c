/* gstat's bin boundaries and residual variograms: noiselab variogram
 * against gstat's variogram() on the Meuse data (sp's meuse, log(zinc)),
 * where pair distances fall on bin boundaries, and the boundary rule on
 * points whose distances are known exactly. */
#include "../analysis/variogram.h"
#include "../core/io.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* R: the Meuse data to meuse.tsv (x, y, log(zinc)), then the variograms
 * VARIOS (R expressions of d), each printed as rows "set np dist gamma". */
static const char meuse_head[] =
    "suppressMessages(library(gstat))\ndata(meuse, package = 'sp')\n"
    "d <- data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc))\n"
    "write.table(format(d, digits = 17), 'meuse.tsv', sep = '\\t', quote = FALSE, row.names = FALSE)\n"
    "vs <- list(%s)\n"
    "for (i in seq_along(vs)) { v <- vs[[i]]\n"
    "  cat(sprintf('%%d %%d %%.17g %%.17g', i, v$np, v$dist, v$gamma), sep = '\\n') }\n";

#define MAXROWS 256

/* Run the R program for the variograms `varios` into r (4 numbers a row);
 * returns the rows. */
static size_t run_meuse(const char *varios, double *r)
{
    char script[2048];
    snprintf(script, sizeof script, meuse_head, varios);
    long m = gstat_run(script, r, 4 * MAXROWS);
    cr_assert(m > 0 && m % 4 == 0, "R failed (%ld numbers; sp's meuse data?)", m);
    return (size_t)m / 4;
}

/* Our variogram (noiselab ARGS --json) equals gstat's set `set` of r:
 * the same bins with the same pair counts (exact: the same pairs), mean
 * distances and gammas to 1e-9 relative (the same terms summed in another
 * order: rounding ~ pairs x 1e-16). */
static void expect_set(const char *args, const double *r, size_t rows, int set)
{
    json_t *j = run_noiselab_json(args);
    json_t *jd = json_object_get(j, "distance"), *jg = json_object_get(j, "gamma"), *jp = json_object_get(j, "pairs");
    size_t k = 0;
    for (size_t i = 0; i < rows; i++) {
        const double *g = r + 4 * i;
        if (g[0] != set)
            continue;
        cr_assert(k < json_array_size(jd), "%s: %zu bins, gstat more", args, json_array_size(jd));
        double np = json_real_value(json_array_get(jp, k)), d = json_real_value(json_array_get(jd, k));
        double gam = json_real_value(json_array_get(jg, k));
        cr_expect_eq(np, g[1], "%s bin %zu: pairs %g, gstat %g", args, k, np, g[1]);
        cr_expect(fabs(d - g[2]) <= 1e-9 * g[2], "%s bin %zu: distance %.17g, gstat %.17g", args, k, d, g[2]);
        cr_expect(fabs(gam - g[3]) <= 1e-9 * g[3], "%s bin %zu: gamma %.17g, gstat %.17g", args, k, gam, g[3]);
        k++;
    }
    cr_expect_eq(k, json_array_size(jd), "%s: %zu bins, gstat %zu", args, json_array_size(jd), k);
    json_decref(j);
}

/* The pairs of bin k of our variogram ARGS --json. */
static double pairs_in(const char *args, size_t k)
{
    json_t *j = run_noiselab_json(args);
    double v = json_real_value(json_array_get(json_object_get(j, "pairs"), k));
    json_decref(j);
    return v;
}

/* Meuse has a pair at exactly 200 m and one at 450 m: with width 50 they
 * sit on boundaries, gstat putting each in the bin below, (150, 200] and
 * (400, 450]; with cutoff 450 the 450 m pair is kept (h <= cutoff).  Every
 * bin equals gstat's, for the default bins too, and --bins floor moves
 * the boundary pairs (the test sees a boundary). */
Test(variogram_gstat_slow, meuse_bins)
{
    if (!gstat_available("variogram bins vs gstat on Meuse"))
        return;
    double r[4 * MAXROWS];
    size_t rows = run_meuse("variogram(value ~ 1, ~x + y, d), variogram(value ~ 1, ~x + y, d, width = 50, cutoff = "
                            "1000), variogram(value ~ 1, ~x + y, d, width = 50, cutoff = 450)", r);
    expect_set("variogram meuse.tsv --json", r, rows, 1);
    expect_set("variogram meuse.tsv --width 50 --cutoff 1000 --json", r, rows, 2);
    expect_set("variogram meuse.tsv --width 50 --cutoff 450 --bins gstat --json", r, rows, 3);
    /* the boundary pairs: one more in (150, 200] than in [150, 200), one
     * fewer in (200, 250]; the last bin of cutoff 450 holds the 450 m pair */
    cr_expect_eq(pairs_in("variogram meuse.tsv --width 50 --cutoff 1000 --json", 3),
                 pairs_in("variogram meuse.tsv --width 50 --cutoff 1000 --bins floor --json", 3) + 1);
    cr_expect_eq(pairs_in("variogram meuse.tsv --width 50 --cutoff 450 --json", 8),
                 pairs_in("variogram meuse.tsv --width 50 --cutoff 450 --bins floor --json", 8) + 1);
}

/* The residual variogram equals gstat's variogram(log(zinc) ~ x + y)
 * (--drift linear) and its quadratic (--drift quadratic) to 1e-9 (as
 * above: OLS residuals agree to ~1e-13 relative).  gstat's quadratic is
 * given centred coordinates in km: on raw metres (x^2 ~ 3e10) gstat's
 * least squares loses digits (its gammas differ from R's lm residuals by
 * 1.5e-5 relative; ours and R's lm agree to 1e-10), and the residuals do
 * not depend on the polynomial's basis. */
Test(variogram_gstat_slow, meuse_drift)
{
    if (!gstat_available("residual variogram vs gstat on Meuse"))
        return;
    double r[4 * MAXROWS];
    size_t rows = run_meuse("variogram(value ~ x + y, ~x + y, d), {d$u <- (d$x - 180000) / 1000; "
                            "d$w <- (d$y - 331000) / 1000; variogram(value ~ u + w + I(u^2) + I(u*w) + I(w^2), "
                            "~x + y, d)}", r);
    expect_set("variogram meuse.tsv --drift linear --json", r, rows, 1);
    expect_set("variogram meuse.tsv --drift quadratic --json", r, rows, 2);
}

/* The boundary rule on distances known exactly: points on a line at 0, 1,
 * 2, 3 and a duplicate of 0, width 1, cutoff 2.  gstat's bins: the first,
 * [0, 1] (gstat's ZERO_INCLUDE puts distance 0 there), holds the pair at 0
 * and the four at 1; (1, 2] the three at 2 (the cutoff kept); the pairs at
 * 3 are beyond.  floor: [0, 1) the pair at 0, [1, 2) the four at 1, the
 * pairs at 2 dropped (h < cutoff).  Exact counts and a distance of 2
 * exactly (a mean of equal terms). */
Test(variogram_gstat, boundary_rule)
{
    double pts[5] = {0, 1, 2, 3, 0}, val[5] = {0.3, 1.7, 0.2, 2.9, 1.1};
    nl_points p = {.dim = 1, .n = 5, .pts = pts, .val = val};
    nl_variogram_options o;
    nl_variogram *v;
    nl_variogram_options_default(&o);
    o.width = 1, o.cutoff = 2;
    cr_assert_eq(nl_variogram_points(&p, &o, &v), 0);
    cr_assert_eq(v->nbins, 2);
    cr_expect_eq(v->pairs[0], 5, "first bin %g pairs", v->pairs[0]);
    cr_expect_eq(v->pairs[1], 3, "(1, 2]: %g pairs", v->pairs[1]);
    cr_expect(fabs(v->distance[1] - 2) < 1e-15);
    nl_variogram_free(v);
    o.bins = NL_VARIOGRAM_BINS_FLOOR;
    cr_assert_eq(nl_variogram_points(&p, &o, &v), 0);
    cr_assert_eq(v->nbins, 2);
    cr_expect_eq(v->pairs[0], 1, "[0, 1): %g pairs", v->pairs[0]);
    cr_expect_eq(v->pairs[1], 4, "[1, 2): %g pairs", v->pairs[1]);
    nl_variogram_free(v);
    o.bins = 7;
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_EINVAL);
}

/* gstat's anisotropy convention through its peer names: kriging Meuse
 * on a 4 x 3 grid with Sph:...,angle=30,ratio=0.5 (gstat's anis = c(30,
 * 0.5): the major axis 30 degrees clockwise from north) equals gstat's
 * krige with vgm(0.59, "Sph", 897, 0.05, anis = c(30, 0.5)) at the cell
 * centres, and so does noiselab's own spherical:...,angle=60 (angle = 90 -
 * gstat's); the unconverted angle=30 does not (the test sees the angle).
 * Tolerance 1e-6: the EXR output holds 32-bit floats (half an ulp of
 * values below 8 is 4.8e-7); the systems themselves agree to ~1e-12. */
Test(variogram_gstat_slow, anisotropy_angle_krige)
{
    if (!gstat_available("anisotropic kriging vs gstat on Meuse"))
        return;
    static const char script[] =
        "suppressMessages(library(gstat))\ndata(meuse, package = 'sp')\n"
        "d <- data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc))\n"
        "write.table(format(d, digits = 17), 'meuse.tsv', sep = '\\t', quote = FALSE, row.names = FALSE)\n"
        "g <- expand.grid(x = 178600 + (0:3 + 0.5) * 700, y = 329700 + (0:2 + 0.5) * 1300)\n"
        "k <- krige(value ~ 1, ~x + y, d, g, model = vgm(0.59, 'Sph', 897, 0.05, anis = c(30, 0.5)),\n"
        "           debug.level = 0)\n"
        "cat(sprintf('%.17g', k$var1.pred), sep = '\\n')\n";
    static const char *const specs[] = {"Sph:psill=0.59,range=897,nugget=0.05,angle=30,ratio=0.5",
                                        "spherical:var=0.59,scale=897,nugget=0.05,angle=60,ratio=0.5",
                                        "spherical:var=0.59,scale=897,nugget=0.05,angle=30,ratio=0.5"};
    double r[12];
    cr_assert_eq(gstat_run(script, r, 12), 12, "R failed (sp's meuse data?)");
    for (int s = 0; s < 3; s++) {
        char cmd[256], path[512];
        double worst = 0;
        nl_field *f;
        snprintf(cmd, sizeof cmd, "krige --data meuse.tsv --acf '%s' --grid 4x3 --extent 178600:181400,329700:333600 "
                 "-o k.exr", specs[s]);
        cr_assert_eq(run_noiselab(cmd, NULL, 0, NULL, 0), 0, "%s", cmd);
        snprintf(path, sizeof path, "%s/k.exr", scratch_dir());
        cr_assert_eq(nl_field_read(path, &f, NULL), 0, "%s", nl_errmsg());
        cr_assert_eq(f->count, 12);
        for (int i = 0; i < 12; i++) /* x fastest, as expand.grid */
            worst = fmax(worst, fabs(f->data[i] - r[i]));
        nl_field_free(f);
        if (s < 2)
            cr_expect(worst <= 1e-6, "%s: predictions differ from gstat's by up to %g", specs[s], worst);
        else
            cr_expect(worst > 1e-3, "%s: equals gstat's anis = c(30, 0.5) (max difference %g)", specs[s], worst);
    }
}

/* The conversion on the model itself: the semivariogram of gstat's
 * Sph:range=10,angle=30,ratio=0.4 at a lag h along gstat's direction 30
 * (sin 30, cos 30) is the isotropic spherical's at h, across it (120) the
 * isotropic's at h / 0.4; ratio alone keeps gstat's major axis north.
 * Exact up to rounding in the rotation (1e-14). */
Test(variogram_gstat, anisotropy_angle_model)
{
    nl_model *g = test_model("Sph:psill=1,range=10,angle=30,ratio=0.4"), *iso = test_model("spherical:scale=10");
    nl_model *north = test_model("Sph:psill=1,range=10,ratio=0.4");
    for (double h = 0.5; h < 12; h += 1.3) {
        double a = 30 * M_PI / 180, along[2] = {h * sin(a), h * cos(a)}, across[2] = {h * cos(a), -h * sin(a)};
        double r1[1] = {h}, r2[1] = {h / 0.4}, up[2] = {0, h}, east[2] = {h, 0};
        cr_expect(fabs(nl_model_variogram(g, 2, along) - nl_model_variogram(iso, 1, r1)) < 1e-14, "along, h %g", h);
        cr_expect(fabs(nl_model_variogram(g, 2, across) - nl_model_variogram(iso, 1, r2)) < 1e-14, "across, h %g", h);
        cr_expect(fabs(nl_model_variogram(north, 2, up) - nl_model_variogram(iso, 1, r1)) < 1e-14, "north, h %g", h);
        cr_expect(fabs(nl_model_variogram(north, 2, east) - nl_model_variogram(iso, 1, r2)) < 1e-14, "east, h %g", h);
    }
    nl_model_free(g), nl_model_free(iso), nl_model_free(north);
}

/* fit --variogram on the table variogram -o writes (distance, gamma,
 * pairs) equals the fit on the data it came from: the same bins, rounded
 * to the 10 significant digits of the table, so the parameters agree to
 * about 1e-9 relative; 1e-7 allows for the solver's stopping tolerance
 * (1e-10 on the objective, section WLS of analysis/fit.h) amplified by
 * the rounding. */
Test(variogram_gstat, table_roundtrip)
{
    cr_assert_eq(run_noiselab("synth circulant --acf markov:scale=6,nugget=0.2 --size 64x64 --seed 2 -o rt.exr", NULL, 0,
                              NULL, 0), 0);
    cr_assert_eq(run_noiselab("sample rt.exr --random 300 --seed 3 --interpolation nearest -o rt.tsv", NULL, 0, NULL, 0),
                 0);
    cr_assert_eq(run_noiselab("variogram rt.tsv -o rtv.tsv", NULL, 0, NULL, 0), 0);
    json_t *a = run_noiselab_json("fit rt.tsv --model markov --nugget --json");
    json_t *b = run_noiselab_json("fit --variogram rtv.tsv --model markov --nugget --json");
    static const char *const names[] = {"var", "scale", "nugget"};
    for (int k = 0; k < 3; k++) {
        double x = json_real_value(json_object_get(json_object_get(a, "parameters"), names[k]));
        double y = json_real_value(json_object_get(json_object_get(b, "parameters"), names[k]));
        cr_expect(fabs(x - y) <= 1e-7 * fabs(x), "%s: from the data %.12g, from the table %.12g", names[k], x, y);
    }
    json_decref(a), json_decref(b);
}
