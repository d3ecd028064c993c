/* noiselab krige --block, --transform and --indicator against the library
 * calls they make (analysis/krige_flavours.h), on 1D data written as TSV. */
#include "../analysis/krige_flavours.h"
#include "../core/io.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NP 40
#define NC 25

/* 40 positive values on [0, 10], fixed seed. */
static void data(double *pts, double *val)
{
    unsigned long long s = 2385;
    for (int i = 0; i < NP; i++) {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        double u = (double)(s >> 11) / 9007199254740992.0;
        pts[i] = 10 * u, val[i] = exp(sin(1.7 * pts[i]) + 0.3 * u);
    }
    gstat_write_points(scratch_file("p.tsv", ""), 1, NP, pts, val);
}

static void cells(double *x)
{
    for (int t = 0; t < NC; t++)
        x[t] = (t + 0.5) * 10.0 / NC;
}

/* Column col (0: x) of a TSV table without comments: NC rows. */
static void read_column(const char *name, int col, double *v)
{
    char path[512], line[4096];
    snprintf(path, sizeof path, "%s/%s", scratch_dir(), name);
    FILE *fp = fopen(path, "r");
    cr_assert(fp, "%s missing", path);
    int row = 0;
    while (fgets(line, sizeof line, fp))
        if (line[0] != '#' && !(line[0] == 'x' || line[0] == 'p')) {
            char *p = line;
            for (int c = 0; c <= col; c++)
                v[row] = strtod(p, &p);
            row++;
        }
    fclose(fp);
    cr_assert_eq(row, NC, "%s: %d rows", name, row);
}

/* The TSV prints 10 significant digits: agreement to 1e-9 relative. */
static void same(const double *a, const double *b, const char *what)
{
    for (int t = 0; t < NC; t++)
        cr_expect(fabs(a[t] - b[t]) <= 1e-9 * fmax(1, fabs(b[t])), "%s, cell %d: %.12g, library %.12g", what, t, a[t],
                  b[t]);
}

static void run(const char *args, char *err)
{
    char cmd[1024], out[4096];
    const char *d = scratch_dir();
    snprintf(cmd, sizeof cmd, "krige --data %s/p.tsv --grid %d --extent 0:10 %s", d, NC, args);
    int rc = run_noiselab(cmd, out, sizeof out, err, 4096);
    cr_assert_eq(rc, 0, "%s: exit %d: %s", cmd, rc, err);
}

Test(krige_flavours_cli, block_and_transform_equal_the_library)
{
    double pts[NP], val[NP], y[NP], x[NC], est[NC], got[NC];
    char err[4096], args[512];
    data(pts, val);
    cells(x);
    nl_model *m = test_model("markov:scale=2,nugget=0.1");
    nl_krige_local_options o = {.nmax = 10, .drift = NL_DRIFT_LINEAR};
    nl_krige_local *k;
    nl_krige_block b = {{0.8}, 5};
    cr_assert_eq(nl_krige_local_alloc(m, 1, NP, pts, val, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_block_eval(k, &b, NC, x, est, NULL), 0, "%s", nl_errmsg());
    nl_krige_local_free(k);
    snprintf(args, sizeof args, "--acf markov:scale=2,nugget=0.1 --nmax 10 --drift linear --block 0.8 --block-points 5 "
             "-o %s/b.tsv", scratch_dir());
    run(args, err);
    read_column("b.tsv", 1, got);
    same(got, est, "--block 0.8 --block-points 5");
    o.nmax = 0, o.drift = NL_DRIFT_CONSTANT;
    cr_assert_eq(nl_krige_tg_transform(0.3, NP, val, y), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_local_alloc(m, 1, NP, pts, y, &o, &k), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_tg_eval(k, NULL, 0.3, NC, x, est, NULL), 0, "%s", nl_errmsg());
    nl_krige_local_free(k);
    snprintf(args, sizeof args, "--acf markov:scale=2,nugget=0.1 --transform boxcox:0.3 -o %s/t.tsv", scratch_dir());
    run(args, err);
    read_column("t.tsv", 1, got);
    same(got, est, "--transform boxcox:0.3");
    o.drift = NL_DRIFT_NONE, o.mean = 1.5; /* simple block kriging */
    cr_assert_eq(nl_krige_local_alloc(m, 1, NP, pts, val, &o, &k), 0, "%s", nl_errmsg());
    b.points = 0;
    cr_assert_eq(nl_krige_block_eval(k, &b, NC, x, est, NULL), 0, "%s", nl_errmsg());
    nl_krige_local_free(k);
    snprintf(args, sizeof args, "--acf markov:scale=2,nugget=0.1 --mean 1.5 --block 0.8 -o %s/s.tsv", scratch_dir());
    run(args, err);
    read_column("s.tsv", 1, got);
    same(got, est, "--block 0.8 --mean 1.5");
    nl_model_free(m);
}

/* Three thresholds, each its own model, nmax 4: the corrected columns and
 * the count of corrected cells are the library's. */
Test(krige_flavours_cli, indicator_equals_the_library)
{
    double pts[NP], val[NP], x[NC], cdf[NC * 3], got[NC];
    const double thr[3] = {0.8, 1.3, 2.1};
    char err[4096], args[1024];
    size_t nc;
    data(pts, val);
    cells(x);
    nl_model *m[3] = {test_model("markov:scale=1,nugget=0.05"), test_model("markov:scale=2,nugget=0.05"),
                      test_model("spherical:scale=3,nugget=0.1")};
    nl_krige_local_options o = {.nmax = 4, .drift = NL_DRIFT_CONSTANT};
    cr_assert_eq(nl_krige_indicator((const nl_model *const *)m, 3, thr, 1, NP, pts, val, &o, NULL, NC, x, NULL, cdf, &nc),
                 0, "%s", nl_errmsg());
    snprintf(args, sizeof args, "--indicator 0.8,1.3,2.1 --indicator-acf markov:scale=1,nugget=0.05 --indicator-acf "
             "markov:scale=2,nugget=0.05 --indicator-acf spherical:scale=3,nugget=0.1 --nmax 4 -o %s/i.tsv",
             scratch_dir());
    run(args, err);
    for (int j = 0; j < 3; j++) {
        double want[NC];
        for (int t = 0; t < NC; t++)
            want[t] = cdf[t * 3 + j];
        read_column("i.tsv", j + 1, got);
        same(got, want, "--indicator");
    }
    fprintf(stderr, "indicator CLI: %zu of %d cells corrected\n", nc, NC);
    /* the EXR outputs, one per threshold (float32: 1e-7 relative) */
    snprintf(args, sizeof args, "--indicator 0.8,1.3,2.1 --indicator-acf markov:scale=1,nugget=0.05 --indicator-acf "
             "markov:scale=2,nugget=0.05 --indicator-acf spherical:scale=3,nugget=0.1 --nmax 4 -o %s/i.exr",
             scratch_dir());
    run(args, err);
    for (int j = 0; j < 3; j++) {
        char path[512];
        nl_field *f;
        snprintf(path, sizeof path, "%s/i.%d.exr", scratch_dir(), j + 1);
        cr_assert_eq(nl_exr_read(path, &f, NULL), 0, "%s", nl_errmsg());
        cr_assert_eq(f->count, NC);
        for (int t = 0; t < NC; t++)
            cr_expect(fabs(f->data[t] - cdf[t * 3 + j]) <= 1e-7, "%s, cell %d: %g, library %g", path, t, f->data[t],
                      cdf[t * 3 + j]);
        nl_field_free(f);
    }
    char note[64];
    snprintf(note, sizeof note, "corrected at %zu of %d cells", nc, NC);
    cr_expect(nc == 0 ? strstr(err, "corrected") == NULL : strstr(err, note) != NULL, "stderr: %s (want %s)", err, note);
    for (int j = 0; j < 3; j++)
        nl_model_free(m[j]);
}
