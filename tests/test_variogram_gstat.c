/* gstat's bin boundaries and residual variograms: noiselab variogram
 * against gstat's variogram() on the Meuse data (sp's meuse, log(zinc)),
 * where pair distances fall on bin boundaries, and the boundary rule on
 * points whose distances are known exactly. */
#include "../analysis/variogram.h"
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
Test(variogram_gstat, meuse_bins)
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
Test(variogram_gstat, meuse_drift)
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
