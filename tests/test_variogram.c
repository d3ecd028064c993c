/* The spatial index against brute force, and the empirical variogram
 * against gstat's variogram() on the same points, width and cutoff. */
#include "../analysis/variogram.h"
#include "../core/nl_error.h"
#include "../core/spindex.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Deterministic uniform numbers in [0, 1) (a 64-bit LCG's top bits). */
static double unif(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* n points of dim coordinates in [0, 10.37) x [0, 7.9) x [0, 3.1), with a
 * trend plus noise as values; every seventh point repeats an earlier one
 * when dups (ties for the index). */
static void make_points(int dim, size_t n, int dups, double *pts, double *val)
{
    static const double ext[3] = {10.37, 7.9, 3.1};
    unsigned long long s = 2385;
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < dim; k++)
            pts[i * dim + k] = dups && i % 7 == 6 ? pts[(i / 2) * dim + k] : ext[k] * unif(&s);
        val[i] = 0.3 * pts[i * dim] + 2 * sin(pts[i * dim + (dim - 1)]) + unif(&s) - 0.5;
    }
}

static double dist2(int dim, const double *a, const double *b)
{
    double s = 0;
    for (int k = 0; k < dim; k++)
        s += (a[k] - b[k]) * (a[k] - b[k]);
    return s;
}

static int cmp_pair(const void *a, const void *b)
{
    const double *x = a, *y = b;
    return x[0] < y[0] ? -1 : x[0] > y[0] ? 1 : x[1] < y[1] ? -1 : x[1] > y[1];
}

/* Property: the k nearest and the points within r are exactly brute
 * force's (sorted by distance, ties by index; exact comparison: both
 * compute the same sums of squares). */
Test(spindex, knn_and_radius_equal_brute_force)
{
    for (int dim = 1; dim <= 3; dim++) {
        size_t n = 1000, k = 33, idx[1000];
        double pts[3000], val[1000], d2[1000], (*bf)[2] = malloc(n * sizeof *bf);
        make_points(dim, n, 1, pts, val);
        nl_spindex *s;
        cr_assert_eq(nl_spindex_alloc(dim, n, pts, &s), 0, "%s", nl_errmsg());
        for (int q = 0; q < 50; q++) {
            const double *x = pts + (size_t)(q * 17) * dim; /* data points: ties at distance 0 */
            double xq[3] = {x[0] + 0.01 * q, dim > 1 ? x[1] : 0, dim > 2 ? x[2] : 0};
            const double *xs = q % 2 ? xq : x;
            for (size_t i = 0; i < n; i++)
                bf[i][0] = dist2(dim, xs, pts + i * dim), bf[i][1] = (double)i;
            qsort(bf, n, sizeof *bf, cmp_pair);
            cr_assert_eq(nl_spindex_knn(s, xs, k, idx, d2), k);
            for (size_t j = 0; j < k; j++)
                cr_assert(idx[j] == (size_t)bf[j][1] && d2[j] == bf[j][0], "dim %d query %d rank %zu", dim, q, j);
            double r = 0.9;
            size_t within = 0;
            while (within < n && bf[within][0] <= r * r)
                within++;
            cr_assert_eq(nl_spindex_within(s, xs, r, 20, idx, d2), within);
            for (size_t j = 0; j < 20 && j < within; j++)
                cr_assert_eq(idx[j], (size_t)bf[j][1]);
        }
        nl_spindex_free(s);
        free(bf);
    }
}

typedef struct {
    size_t count;
    double sum;
} pcount;

static int count_pair(void *ctx, size_t i, size_t j, double d2)
{
    pcount *c = ctx;
    c->count++, c->sum += (double)(i * 1000 + j) + d2;
    return i < j ? 0 : 1;
}

/* Property: the pairs within the cutoff are every pair i < j at d < c once. */
Test(spindex, pairs_equal_brute_force)
{
    size_t n = 700;
    double pts[2100], val[700];
    make_points(3, n, 1, pts, val);
    nl_spindex *s;
    cr_assert_eq(nl_spindex_alloc(3, n, pts, &s), 0);
    pcount c = {0, 0}, b = {0, 0};
    cr_assert_eq(nl_spindex_pairs(s, 1.7, count_pair, &c), 0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            double d = dist2(3, pts + 3 * i, pts + 3 * j);
            if (d < 1.7 * 1.7)
                count_pair(&b, i, j, d);
        }
    cr_expect_eq(c.count, b.count);
    cr_expect(fabs(c.sum - b.sum) <= 1e-12 * b.sum, "%.17g %.17g", c.sum, b.sum);
    nl_spindex_free(s);
}

/* Compare our JSON (17 digits) with gstat's numbers, printed as
 * np dist gamma per bin by the R program.  Tolerance 1e-9 relative: both
 * sum the same terms in double precision in different orders (rounding
 * ~ pairs x 1e-16 relative, under 1e-11 here). */
static void compare(const char *args, const char *rexpr, const char *what)
{
    char script[2048];
    double r[3 * 64];
    snprintf(script, sizeof script,
             "suppressMessages(library(gstat))\nd <- read.delim('pts.tsv')\nv <- %s\n"
             "cat(sprintf('%%d %%.17g %%.17g', v$np, v$dist, v$gamma), sep = '\\n')\n", rexpr);
    long m = gstat_run(script, r, 3 * 64);
    cr_assert(m > 0 && m % 3 == 0, "%s: R failed (%ld numbers)", what, m);
    json_t *j = run_noiselab_json(args);
    json_t *jd = json_object_get(j, "distance"), *jg = json_object_get(j, "gamma"), *jp = json_object_get(j, "pairs");
    cr_assert_eq(json_array_size(jd), (size_t)m / 3, "%s: %zu bins, gstat %ld", what, json_array_size(jd), m / 3);
    for (size_t k = 0; k < (size_t)m / 3; k++) {
        double np = json_real_value(json_array_get(jp, k)), d = json_real_value(json_array_get(jd, k));
        double g = json_real_value(json_array_get(jg, k));
        cr_expect_eq(np, r[3 * k], "%s bin %zu: pairs %g, gstat %g", what, k, np, r[3 * k]);
        cr_expect(fabs(d - r[3 * k + 1]) <= 1e-9 * r[3 * k + 1], "%s bin %zu: distance %.17g, gstat %.17g", what, k, d,
                  r[3 * k + 1]);
        cr_expect(fabs(g - r[3 * k + 2]) <= 1e-9 * r[3 * k + 2], "%s bin %zu: gamma %.17g, gstat %.17g", what, k, g,
                  r[3 * k + 2]);
    }
    json_decref(j);
}

Test(variogram_slow, equals_gstat_2d)
{
    if (!gstat_available("variogram vs gstat"))
        return;
    size_t n = 400;
    double pts[800], val[400];
    char path[512];
    make_points(2, n, 0, pts, val);
    snprintf(path, sizeof path, "%s/pts.tsv", scratch_dir());
    gstat_write_points(path, 2, n, pts, val);
    compare("variogram pts.tsv --json", "variogram(value ~ 1, locations = ~x + y, data = d)", "default");
    compare("variogram pts.tsv --json --width 0.37 --cutoff 5.3",
            "variogram(value ~ 1, locations = ~x + y, data = d, width = 0.37, cutoff = 5.3)", "width, cutoff");
    compare("variogram pts.tsv --json --estimator cressie",
            "variogram(value ~ 1, locations = ~x + y, data = d, cressie = TRUE)", "cressie");
    static const double dirs[][2] = {{0, 22.5}, {30, 20}, {90, 10}, {135, 45}, {-40, 15}};
    for (size_t i = 0; i < sizeof dirs / sizeof *dirs; i++) {
        char a[256], r[256], w[64];
        snprintf(a, sizeof a, "variogram pts.tsv --json --direction %g --angle-tolerance %g", dirs[i][0], dirs[i][1]);
        snprintf(r, sizeof r, "variogram(value ~ 1, locations = ~x + y, data = d, alpha = %g, tol.hor = %g)",
                 dirs[i][0], dirs[i][1]);
        snprintf(w, sizeof w, "alpha %g tol.hor %g", dirs[i][0], dirs[i][1]);
        compare(a, r, w);
    }
}

Test(variogram, equals_gstat_3d)
{
    if (!gstat_available("variogram 3D vs gstat"))
        return;
    size_t n = 300;
    double pts[900], val[300];
    char path[512];
    make_points(3, n, 0, pts, val);
    snprintf(path, sizeof path, "%s/pts.tsv", scratch_dir());
    gstat_write_points(path, 3, n, pts, val);
    /* explicit width and cutoff (the default's 3D rule: tests/test_fit_gstat.c) */
    compare("variogram pts.tsv --json --cutoff 4.1 --width 0.29",
            "variogram(value ~ 1, locations = ~x + y + z, data = d, cutoff = 4.1, width = 0.29)", "3D");
}

/* Property: a field's variogram is the variogram of its samples as points
 * (same pairs; sums in another order, so 1e-12 relative). */
Test(variogram, field_equals_points)
{
    size_t n[2] = {23, 17};
    double h[2] = {0.5, 0.75};
    nl_field *f = nl_field_alloc(2, n, h, NULL);
    nl_points p = {.dim = 2, .n = f->count};
    p.pts = malloc(2 * f->count * sizeof(double)), p.val = malloc(f->count * sizeof(double));
    unsigned long long s = 11;
    for (size_t j = 0, i = 0; j < n[1]; j++)
        for (size_t k = 0; k < n[0]; k++, i++) {
            f->data[i] = p.val[i] = sin(0.3 * (double)k) + unif(&s);
            p.pts[2 * i] = (double)k * h[0], p.pts[2 * i + 1] = (double)j * h[1];
        }
    for (int dir = 0; dir < 2; dir++) {
        nl_variogram_options o;
        nl_variogram *a, *b;
        nl_variogram_options_default(&o);
        o.directional = dir, o.direction = 60, o.tolerance = 30, o.width = 0.61;
        cr_assert_eq(nl_variogram_field(f, &o, &a), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_variogram_points(&p, &o, &b), 0, "%s", nl_errmsg());
        cr_assert_eq(a->nbins, b->nbins);
        for (size_t k = 0; k < a->nbins; k++) {
            cr_expect_eq(a->pairs[k], b->pairs[k]);
            cr_expect(fabs(a->gamma[k] - b->gamma[k]) <= 1e-12 * b->gamma[k]);
            cr_expect(fabs(a->distance[k] - b->distance[k]) <= 1e-12 * b->distance[k]);
        }
        nl_variogram_free(a), nl_variogram_free(b);
    }
    free(p.pts), free(p.val), nl_field_free(f);
}

Test(variogram, refusals)
{
    double pts[6] = {1, 2, 1, 2, 1, 2}, val[3] = {1, 2, 3};
    nl_points p = {.dim = 2, .n = 1, .pts = pts, .val = val};
    nl_variogram_options o;
    nl_variogram *v;
    nl_variogram_options_default(&o);
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "at least 2") != NULL, "%s", nl_errmsg());
    p.n = 3;
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "one place") != NULL, "%s", nl_errmsg());
    /* distinct points 1e-300 apart: their squared distances underflow, and
     * the message says so rather than "at one place" */
    pts[2] = 0, pts[3] = 1e-300, pts[0] = 0, pts[1] = 0, pts[4] = 1e-300, pts[5] = 0;
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "span only 1e-300") != NULL && strstr(nl_errmsg(), "one place") == NULL, "%s",
              nl_errmsg());
    pts[0] = 1, pts[1] = 2, pts[2] = 1, pts[3] = 2, pts[4] = 1, pts[5] = 2;
    pts[0] = 0, val[1] = NAN;
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "finite") != NULL, "%s", nl_errmsg());
    cr_expect_null(v);
}

/* Values whose squared differences summed over the pairs overflow are
 * refused (NL_EINVAL naming the values) by the variogram of points and of a
 * field alike, where an estimate would be inf; values just inside the bound
 * sqrt(DBL_MAX / (n (n - 1))) give finite semivariances. */
Test(variogram, overflowing_values_refused)
{
    double pts[8] = {0, 0, 1, 0, 0, 1, 1, 1}, val[4] = {1e200, -1e200, 3e199, -2e199};
    nl_points p = {.dim = 2, .n = 4, .pts = pts, .val = val};
    size_t n[2] = {2, 2};
    double h[2] = {1, 1}, bound = sqrt(DBL_MAX / 12);
    nl_field *f = nl_field_alloc(2, n, h, NULL);
    nl_variogram_options o;
    nl_variogram *v;
    nl_variogram_options_default(&o);
    o.cutoff = 2;
    memcpy(f->data, val, sizeof val);
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "values run from") != NULL, "%s", nl_errmsg());
    cr_expect_null(v);
    cr_expect_eq(nl_variogram_field(f, &o, &v), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "samples run from") != NULL, "%s", nl_errmsg());
    val[0] = 0.49 * bound, val[1] = -0.49 * bound, val[2] = val[3] = 0;
    memcpy(f->data, val, sizeof val);
    cr_assert_eq(nl_variogram_points(&p, &o, &v), 0, "%s", nl_errmsg());
    for (size_t k = 0; k < v->nbins; k++)
        cr_expect(isfinite(v->gamma[k]), "bin %zu: %g", k, v->gamma[k]);
    nl_variogram_free(v);
    o.estimator = NL_VARIOGRAM_CRESSIE;
    cr_assert_eq(nl_variogram_field(f, &o, &v), 0, "%s", nl_errmsg());
    for (size_t k = 0; k < v->nbins; k++)
        cr_expect(isfinite(v->gamma[k]), "bin %zu: %g", k, v->gamma[k]);
    nl_variogram_free(v), nl_field_free(f);
}

/* The work is estimated before the pairs are walked: 100,000 points spread
 * over the unit square have about half of their 5e9 pairs within the
 * default cutoff (0.47), over the 1e9 limit: NL_ETOOBIG at once, naming the
 * estimate; a small cutoff keeps them in. */
Test(variogram, too_many_pairs_refused)
{
    size_t n = 100000;
    nl_points p = {.dim = 2, .n = n};
    unsigned long long s = 5;
    nl_variogram_options o;
    nl_variogram *v;
    p.pts = malloc(2 * n * sizeof(double)), p.val = malloc(n * sizeof(double));
    for (size_t i = 0; i < n; i++)
        p.pts[2 * i] = unif(&s), p.pts[2 * i + 1] = unif(&s), p.val[i] = unif(&s);
    nl_variogram_options_default(&o);
    cr_expect_eq(nl_variogram_points(&p, &o, &v), NL_ETOOBIG);
    cr_expect(strstr(nl_errmsg(), "pairs within the cutoff") != NULL, "%s", nl_errmsg());
    o.cutoff = 0.002;
    cr_expect_eq(nl_variogram_points(&p, &o, &v), 0, "%s", nl_errmsg());
    nl_variogram_free(v);
    free(p.pts), free(p.val);
}
