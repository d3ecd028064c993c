/* krige --at (prediction at the points of a table), external drift and
 * k-fold cross-validation against gstat (R) on the Meuse data:
 * log(zinc) at the 155 points of sp's meuse, predicted at the 3103 points
 * of meuse.grid with vgm(0.59, "Sph", 897, 0.05) (noiselab: nugget:var=0.05
 * + spherical:var=0.59,scale=897).  Each test is one Rscript call (about
 * 1.3 s, most of it loading sp and gstat) and prints a skip line when R
 * with gstat is not installed. */
#include "gstat.h"
#include "util.h"
#include "../core/field.h"
#include "../core/io.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MODEL "'nugget:var=0.05 + spherical:var=0.59,scale=897'"
enum { NDATA = 155, NGRID = 3103 };

/* R: meuse.tsv (x, y, value = log(zinc), sdist = sqrt(dist), fold) and
 * grid.tsv (x, y, sdist) with 17 significant digits; fold is gstat.cv's
 * draw of krige.cv(nfold = 5) after set.seed(1): sample(5, 155, replace =
 * TRUE).  out() prints predictions and variances, NA as nan. */
static const char preamble[] =
    "if (!requireNamespace('gstat', quietly = TRUE)) { cat('skip\\n'); quit() }\n"
    "suppressMessages({library(sp); library(gstat)})\ndata(meuse); data(meuse.grid)\n"
    "w <- function(d, f) write.table(as.data.frame(lapply(d, function(c) sprintf('%.17g', c))), f, sep = '\\t',\n"
    "    quote = FALSE, row.names = FALSE)\n"
    "d <- data.frame(x = meuse$x, y = meuse$y, value = log(meuse$zinc), sdist = sqrt(meuse$dist))\n"
    "set.seed(1); d$fold <- sample(5, nrow(d), replace = TRUE)\n"
    "g <- data.frame(x = meuse.grid$x, y = meuse.grid$y, sdist = sqrt(meuse.grid$dist))\n"
    "w(d, 'meuse.tsv'); w(g, 'grid.tsv')\n"
    "coordinates(d) <- ~x + y; coordinates(g) <- ~x + y\n"
    "m <- vgm(0.59, 'Sph', 897, 0.05)\n"
    "f <- function(v) ifelse(is.na(v), 'nan', sprintf('%.17g', v))\n"
    "out <- function(k) cat(paste(f(k$var1.pred), f(k$var1.var)), sep = '\\n')\n";

/* Run an R script that starts with the preamble into v (max numbers);
 * 0 when R or gstat is not installed (a skip line printed).  Checking in the
 * script itself spares gstat_available's second R start (about 1 s of
 * loading gstat). */
static long r_gstat(const char *script, double *v, size_t max, const char *what)
{
    if (system("command -v Rscript >/dev/null 2>&1") != 0) {
        fprintf(stderr, "skip: %s: Rscript is not installed\n", what);
        return 0;
    }
    long n = gstat_run(script, v, max);
    if (n == 0)
        fprintf(stderr, "skip: %s: R's gstat is not installed (Debian: r-cran-gstat)\n", what);
    return n;
}

/* The last two columns (estimate, variance; "NA": NaN) of the n rows of a
 * TSV written by krige --at or --cross-validate (cols: which two). */
static void read_pairs(const char *name, size_t n, int c0, double *a, double *b)
{
    char path[600], line[4096];
    snprintf(path, sizeof path, "%s/%s", scratch_dir(), name);
    FILE *fp = fopen(path, "r");
    cr_assert(fp, "no %s", path);
    do /* the header, after any comment lines */
        cr_assert(fgets(line, sizeof line, fp), "%s: no header", name);
    while (line[0] == '#');
    for (size_t i = 0; i < n; i++) {
        cr_assert(fgets(line, sizeof line, fp), "%s: %zu rows, expected %zu", name, i, n);
        char *cell[16], *save = NULL;
        int nc = 0;
        for (char *t = strtok_r(line, "\t\n", &save); t && nc < 16; t = strtok_r(NULL, "\t\n", &save))
            cell[nc++] = t;
        int at = c0 < 0 ? nc + c0 : c0;
        cr_assert(at >= 0 && at + 1 < nc, "%s: row %zu has %d cells", name, i + 1, nc);
        a[i] = strcmp(cell[at], "NA") == 0 ? NAN : strtod(cell[at], NULL);
        b[i] = strcmp(cell[at + 1], "NA") == 0 ? NAN : strtod(cell[at + 1], NULL);
    }
    fclose(fp);
}

/* Locations whose nmax-th and (nmax + 1)-th nearest data are at the same
 * distance: the neighbourhood is a tie, broken by gstat in the order of its
 * quadtree's priority queue (src/nsearch.c), which analysis/krige_gstat_order.c
 * replays. */
static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int nmax_tie(const double *x, const double *pts, size_t nmax)
{
    double d2[NDATA];
    for (size_t i = 0; i < NDATA; i++) {
        double dx = x[0] - pts[2 * i], dy = x[1] - pts[2 * i + 1];
        d2[i] = dx * dx + dy * dy;
    }
    qsort(d2, NDATA, sizeof *d2, cmp_double);
    return d2[nmax - 1] == d2[nmax];
}

/* The grid's coordinates from grid.tsv (x, y first). */
static void read_coords(const char *name, size_t n, double *xy)
{
    read_pairs(name, n, 0, xy, xy + n);
}

/* Ordinary kriging at meuse.grid, global and with the 40 nearest data,
 * equals gstat's krige to 1e-9 (the same estimator in double precision: the
 * measured gap is about 1e-14; the TSV carries 17 digits), at every point.
 * With nmax 40, one location of the grid, (179540, 330460), has its 40th
 * and 41st nearest data equidistant (a tie: see nmax_tie); gstat's choice
 * there is replayed, and the test checks that the tie is still in the data
 * (so that it is exercised). */
Test(krige_at, equals_gstat_krige_meuse_grid)
{
    static double r[4 * NGRID], e[NGRID], v[NGRID], gx[2 * NGRID], dx[2 * NDATA];
    char script[4096];
    snprintf(script, sizeof script, "%sout(krige(value ~ 1, d, g, m, debug.level = 0))\n"
             "out(krige(value ~ 1, d, g, m, nmax = 40, debug.level = 0))\n", preamble);
    long got = r_gstat(script, r, 4 * NGRID, "krige --at vs gstat on meuse.grid");
    if (got == 0)
        return;
    cr_assert_eq(got, 4 * NGRID, "R failed (sp's meuse data?)");
    json_t *j = run_noiselab_json("krige --data meuse.tsv --acf " MODEL " --at grid.tsv -o at.tsv --json");
    cr_expect_eq(json_integer_value(json_object_get(j, "locations")), NGRID);
    cr_expect_eq(json_integer_value(json_object_get(j, "missing")), 0);
    json_decref(j);
    read_pairs("at.tsv", NGRID, -2, e, v);
    double de = 0, dv = 0;
    for (size_t i = 0; i < NGRID; i++)
        de = fmax(de, fabs(e[i] - r[2 * i])), dv = fmax(dv, fabs(v[i] - r[2 * i + 1]));
    cr_expect(de <= 1e-9 && dv <= 1e-9, "global: max |d estimate| %.3g, |d variance| %.3g", de, dv);
    fprintf(stderr, "krige --at vs gstat, global: max |d est| %.2g, |d var| %.2g\n", de, dv);
    j = run_noiselab_json("krige --data meuse.tsv --acf " MODEL " --at grid.tsv --nmax 40 -o at40.tsv --json");
    json_decref(j);
    read_pairs("at40.tsv", NGRID, -2, e, v);
    read_coords("grid.tsv", NGRID, gx);
    read_pairs("meuse.tsv", NDATA, 0, dx, dx + NDATA);
    double pts[2 * NDATA];
    for (size_t i = 0; i < NDATA; i++)
        pts[2 * i] = dx[i], pts[2 * i + 1] = dx[NDATA + i];
    size_t ties = 0;
    double dtie = 0;
    de = dv = 0;
    for (size_t i = 0; i < NGRID; i++) {
        double x[2] = {gx[i], gx[NGRID + i]}, d = fabs(e[i] - r[2 * NGRID + 2 * i]);
        if (nmax_tie(x, pts, 40))
            ties++, dtie = fmax(dtie, d);
        de = fmax(de, d), dv = fmax(dv, fabs(v[i] - r[2 * NGRID + 2 * i + 1]));
    }
    cr_expect(de <= 1e-9 && dv <= 1e-9, "nmax 40: max |d estimate| %.3g, |d variance| %.3g (%.3g at ties)", de, dv,
              dtie);
    cr_expect_eq(ties, 1, "%zu locations with tied neighbourhoods, expected the one of meuse.grid", ties);
    fprintf(stderr, "krige --at vs gstat, nmax 40: max |d est| %.2g, |d var| %.2g (%zu tied location: %.2g)\n", de,
            dv, ties, dtie);
}

/* Universal kriging with an external drift, gstat's krige(log(zinc) ~
 * sqrt(dist), ...), equals gstat to 1e-6 (the task's bound; measured about
 * 1e-14), globally and with the 30 nearest data within 1000 m. */
Test(krige_at_slow, external_drift_equals_gstat)
{
    static double r[4 * NGRID], e[NGRID], v[NGRID];
    char script[4096];
    snprintf(script, sizeof script, "%sout(krige(value ~ sdist, d, g, m, debug.level = 0))\n"
             "out(krige(value ~ sdist, d, g, m, nmax = 30, maxdist = 1000, debug.level = 0))\n", preamble);
    long got = r_gstat(script, r, 4 * NGRID, "krige --drift sdist vs gstat");
    if (got == 0)
        return;
    cr_assert_eq(got, 4 * NGRID, "R failed (sp's meuse data?)");
    static const char *const runs[] = {
        "krige --data meuse.tsv --acf " MODEL " --at grid.tsv --drift sdist -o ked.tsv",
        "krige --data meuse.tsv --acf " MODEL " --at grid.tsv --drift sdist --nmax 30 --radius 1000 -o ked.tsv"};
    for (int k = 0; k < 2; k++) {
        char out[256], err[1024];
        cr_assert_eq(run_noiselab(runs[k], out, sizeof out, err, sizeof err), 0, "%s: %s", runs[k], err);
        read_pairs("ked.tsv", NGRID, -2, e, v);
        double de = 0, dv = 0;
        size_t nan = 0;
        for (size_t i = 0; i < NGRID; i++) {
            double re = r[2 * NGRID * k + 2 * i], rv = r[2 * NGRID * k + 2 * i + 1];
            if (isnan(re) || isnan(e[i])) {
                nan++;
                cr_expect(isnan(re) && isnan(e[i]), "location %zu: %g, gstat %g", i + 1, e[i], re);
                continue;
            }
            de = fmax(de, fabs(e[i] - re)), dv = fmax(dv, fabs(v[i] - rv));
        }
        cr_expect(de <= 1e-6 && dv <= 1e-6, "%s: max |d estimate| %.3g, |d variance| %.3g", runs[k], de, dv);
        fprintf(stderr, "external drift vs gstat (%s): max |d est| %.2g, |d var| %.2g, %zu NA\n",
                k ? "nmax 30, radius 1000" : "global", de, dv, nan);
    }
}

/* With a radius, locations with no datum within it are missing (NA), as
 * gstat's krige(maxdist = 150): the same NA locations, the same values
 * elsewhere (1e-9), and the count in --json. */
Test(krige_at_slow, radius_missing_as_gstat)
{
    static double r[2 * NGRID], e[NGRID], v[NGRID];
    char script[4096];
    snprintf(script, sizeof script, "%sout(krige(value ~ 1, d, g, m, maxdist = 150, debug.level = 0))\n", preamble);
    long got = r_gstat(script, r, 2 * NGRID, "krige --radius NA vs gstat");
    if (got == 0)
        return;
    cr_assert_eq(got, 2 * NGRID, "R failed (sp's meuse data?)");
    json_t *j = run_noiselab_json("krige --data meuse.tsv --acf " MODEL " --at grid.tsv --radius 150 -o r.tsv --json");
    read_pairs("r.tsv", NGRID, -2, e, v);
    size_t na = 0, same = 0;
    double de = 0;
    for (size_t i = 0; i < NGRID; i++) {
        na += isnan(r[2 * i]);
        same += isnan(r[2 * i]) == isnan(e[i]);
        if (!isnan(r[2 * i]) && !isnan(e[i]))
            de = fmax(de, fmax(fabs(e[i] - r[2 * i]), fabs(v[i] - r[2 * i + 1])));
    }
    cr_expect_eq(same, NGRID, "NA at %zu locations where gstat's is not (or the reverse)", NGRID - same);
    cr_expect_gt(na, 100, "gstat left %zu NA", na);
    cr_expect_eq((size_t)json_integer_value(json_object_get(j, "missing")), na);
    cr_expect_leq(de, 1e-9, "max |d| %.3g", de);
    fprintf(stderr, "radius 150 vs gstat maxdist: %zu NA, max |d| %.2g\n", na, de);
    json_decref(j);
}

/* k-fold cross-validation with gstat's folds (the column fold) equals
 * krige.cv(nfold = 5) after set.seed(1): ordinary, and with the external
 * drift and nmax 30.  The table is written with 10 significant digits:
 * predictions between 1 and 10 are rounded by 5e-10 at most, within the
 * 1e-9 bound (the computation itself agrees to about 1e-14). */
Test(krige_at_slow, kfold_equals_gstat_krige_cv)
{
    static double r[6 * NDATA], p[NDATA], v[NDATA], fo[NDATA], z[NDATA];
    char script[4096];
    snprintf(script, sizeof script, "%sset.seed(1); k <- krige.cv(value ~ 1, d, m, nfold = 5, verbose = FALSE)\n"
             "cat(paste(f(k$var1.pred), f(k$var1.var), k$fold), sep = '\\n')\n"
             "set.seed(1); k <- krige.cv(value ~ sdist, d, m, nmax = 30, nfold = 5, verbose = FALSE); out(k)\n",
             preamble);
    long got = r_gstat(script, r, 5 * NDATA, "krige --cross-validate 5 vs gstat");
    if (got == 0)
        return;
    cr_assert_eq(got, 5 * NDATA, "R failed (sp's meuse data?)");
    char out[512], err[1024];
    cr_assert_eq(run_noiselab("krige --data meuse.tsv --acf " MODEL " --cross-validate 5 --folds fold -o cv.tsv", out,
                              sizeof out, err, sizeof err), 0, "%s", err);
    /* x y observed predicted variance error zscore fold */
    read_pairs("cv.tsv", NDATA, 3, p, v);
    read_pairs("cv.tsv", NDATA, 6, z, fo);
    double dp = 0, dv = 0;
    for (size_t i = 0; i < NDATA; i++) {
        cr_expect_eq(fo[i], r[3 * i + 2], "datum %zu: fold %g, gstat's %g", i + 1, fo[i], r[3 * i + 2]);
        dp = fmax(dp, fabs(p[i] - r[3 * i])), dv = fmax(dv, fabs(v[i] - r[3 * i + 1]));
    }
    cr_expect(dp <= 1e-9 && dv <= 1e-9, "5-fold: max |d pred| %.3g, |d var| %.3g", dp, dv);
    fprintf(stderr, "5-fold CV vs krige.cv: max |d pred| %.2g, |d var| %.2g\n", dp, dv);
    json_t *j = run_noiselab_json("krige --data meuse.tsv --acf " MODEL " --cross-validate --folds fold --json");
    cr_expect_eq(json_integer_value(json_object_get(j, "folds")), 5);
    cr_expect_eq(json_integer_value(json_object_get(j, "points")), NDATA);
    json_decref(j);
    cr_assert_eq(run_noiselab("krige --data meuse.tsv --acf " MODEL " --cross-validate 5 --folds fold --drift sdist "
                              "--nmax 30 -o cv2.tsv", out, sizeof out, err, sizeof err), 0, "%s", err);
    read_pairs("cv2.tsv", NDATA, 3, p, v);
    dp = dv = 0;
    for (size_t i = 0; i < NDATA; i++)
        dp = fmax(dp, fabs(p[i] - r[3 * NDATA + 2 * i])), dv = fmax(dv, fabs(v[i] - r[3 * NDATA + 2 * i + 1]));
    cr_expect(dp <= 1e-9 && dv <= 1e-9, "5-fold, sdist, nmax 30: max |d pred| %.3g, |d var| %.3g", dp, dv);
    fprintf(stderr, "5-fold CV, external drift, nmax 30 vs krige.cv: max |d pred| %.2g, |d var| %.2g\n", dp, dv);
}

/* A kriged map records its extent: noiselab sample reads it at the cell
 * centres a + (i + 0.5) h, h the extent's width over the cells (here 2,
 * whatever spacing the file records), so sampling the map at some centres
 * gives the estimates of --at there (float32 in EXR: 1e-6 relative). */
Test(krige_at, sample_reads_map_at_its_extent)
{
    static const char data[] = "x\ty\tvalue\n10.4\t20.2\t1\n17.4\t28.4\t2\n12.2\t35.8\t0.5\n26\t22.8\t1.5\n";
    /* centres of cells (1, 2), (6, 0), (3, 7) of an 8 x 8 grid on 10:26, 20:36 */
    static const char at[] = "x\ty\n13\t25\n23\t21\n17\t35\n";
    char out[4096], err[1024];
    double e[3], v[3], s[3], t[3];
    scratch_file("d.tsv", data);
    scratch_file("c.tsv", at);
    cr_assert_eq(run_noiselab("krige --data d.tsv --acf markov:scale=3 --grid 8x8 --extent 10:26,20:36 -o map.exr "
                              "--nmax 4", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("sample map.exr --points c.tsv --interpolation nearest -o s.tsv", out, sizeof out, err,
                              sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("krige --data d.tsv --acf markov:scale=3 --at c.tsv --nmax 4 -o a.tsv", out,
                              sizeof out, err, sizeof err), 0, "%s", err);
    read_pairs("a.tsv", 3, -2, e, v);
    read_pairs("s.tsv", 3, 1, t, s); /* y value */
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(s[i] - e[i]) <= 1e-6 * fabs(e[i]), "point %d: sampled %.9g, kriged there %.9g", i + 1, s[i],
                  e[i]);
}

/* A grid cell without data within the radius is NaN in EXR (not an abort)
 * and the count is in --json; a 1D TSV writes it NA. */
Test(krige_at, missing_cells_in_grids)
{
    static const char data[] = "x\tvalue\n0.1\t1\n0.2\t2\n";
    char out[4096], err[1024];
    scratch_file("d1.tsv", data);
    json_t *j = run_noiselab_json("krige --data d1.tsv --acf markov:scale=0.3 --grid 10 --extent 0:1 --radius 0.2 "
                                  "-o m.tsv --json");
    /* centres 0.05 .. 0.95: within 0.2 of 0.1 or 0.2 are 0.05 .. 0.35 (4 cells) */
    cr_expect_eq(json_integer_value(json_object_get(j, "missing")), 6);
    json_decref(j);
    char path[600];
    snprintf(path, sizeof path, "%s/m.tsv", scratch_dir());
    FILE *fp = fopen(path, "r");
    cr_assert(fp);
    size_t na = 0;
    while (fgets(out, sizeof out, fp))
        na += strstr(out, "\tNA") != NULL;
    fclose(fp);
    cr_expect_eq(na, 6, "%zu NA rows", na);
    scratch_file("d2.tsv", "x\ty\tvalue\n0.1\t0.5\t1\n0.2\t0.5\t2\n");
    cr_assert_eq(run_noiselab("krige --data d2.tsv --acf markov:scale=0.3 --grid 10x1 --extent 0:1,0:1 --radius 0.2 "
                              "-o m.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_expect(strstr(err, "6 of 10 cells"), "stderr: %s", err);
    /* cross-validation: the datum at 0.9 has no other within 0.2 */
    scratch_file("d3.tsv", "x\tvalue\n0.1\t1\n0.2\t2\n0.25\t1.5\n0.9\t3\n");
    j = run_noiselab_json("krige --data d3.tsv --acf markov:scale=0.3 --cross-validate --radius 0.2 -o cv.tsv --json");
    cr_expect_eq(json_integer_value(json_object_get(j, "missing")), 1);
    json_decref(j);
    double p[4], v[4];
    read_pairs("cv.tsv", 4, 2, p, v);
    cr_expect(isnan(p[3]) && isnan(v[3]) && !isnan(p[0]), "predictions %g %g %g %g", p[0], p[1], p[2], p[3]);
    snprintf(path, sizeof path, "%s/cv.tsv", scratch_dir());
    fp = fopen(path, "r");
    cr_assert(fp);
    na = 0;
    while (fgets(out, sizeof out, fp))
        na += strstr(out, "\tNA\tNA\t") != NULL; /* as R writes a missing value, not nan */
    fclose(fp);
    cr_expect_eq(na, 1, "%zu rows with NA", na);
}

/* A covariate on a grid (--covariate NAME=FIELD.exr, sample i at cell i)
 * gives the estimates of --at at the cell centres with the same covariate
 * values (the field's float32 values, printed exactly): the same
 * estimator, so equal to the map's float32 rounding (6e-8 relative; 1e-6
 * allowed). */
Test(krige_at, covariate_field_aligned_with_grid)
{
    enum { N = 8, ND = 30 };
    char path[600], out[4096], err[1024], *tab = malloc(64 * 1024);
    size_t g[2] = {N, N};
    double h[2] = {1.0 / N, 1.0 / N}, e[N * N], v[N * N];
    nl_field *m = NULL;
    int st;
    nl_field *f = nl_field_alloc(2, g, h, &st);
    cr_assert(f, "%s", nl_errmsg());
    for (size_t j = 0; j < N; j++)
        for (size_t i = 0; i < N; i++)
            f->data[j * N + i] = (float)(sin(3.0 * (double)i / N) + 0.7 * (double)j / N);
    snprintf(path, sizeof path, "%s/cov.exr", scratch_dir());
    cr_assert_eq(nl_exr_write(path, f, NULL), NL_OK);
    size_t at = (size_t)snprintf(tab, 64 * 1024, "x\ty\tvalue\tc\n");
    for (int k = 0; k < ND; k++) { /* data: the covariate known at the data points */
        double x = fmod(0.37 * k + 0.05, 1.0), y = fmod(0.61 * k + 0.11, 1.0), c = sin(3.0 * x) + 0.7 * y;
        at += (size_t)snprintf(tab + at, 64 * 1024 - at, "%.17g\t%.17g\t%.17g\t%.17g\n", x, y, 2 * c + sin(7 * y), c);
    }
    scratch_file("dc.tsv", tab);
    at = (size_t)snprintf(tab, 64 * 1024, "x\ty\tc\n");
    for (size_t t = 0; t < N * N; t++)
        at += (size_t)snprintf(tab + at, 64 * 1024 - at, "%.17g\t%.17g\t%.17g\n", ((double)(t % N) + 0.5) / N,
                               ((double)(t / N) + 0.5) / N, f->data[t]);
    scratch_file("cells.tsv", tab);
    cr_assert_eq(run_noiselab("krige --data dc.tsv --acf markov:scale=0.4 --grid 8x8 --extent 0:1,0:1 --drift c "
                              "--covariate c=cov.exr --nmax 10 -o map.exr", out, sizeof out, err, sizeof err), 0, "%s",
                 err);
    cr_assert_eq(run_noiselab("krige --data dc.tsv --acf markov:scale=0.4 --at cells.tsv --drift c --nmax 10 "
                              "-o cells_out.tsv", out, sizeof out, err, sizeof err), 0, "%s", err);
    read_pairs("cells_out.tsv", N * N, -2, e, v);
    snprintf(path, sizeof path, "%s/map.exr", scratch_dir());
    cr_assert_eq(nl_field_read(path, &m, NULL), NL_OK, "%s", nl_errmsg());
    for (size_t t = 0; t < N * N; t++)
        cr_expect(fabs(m->data[t] - e[t]) <= 1e-6 * fmax(1, fabs(e[t])), "cell %zu: map %.9g, --at %.9g", t,
                  m->data[t], e[t]);
    nl_field_free(f), nl_field_free(m), free(tab);
}
