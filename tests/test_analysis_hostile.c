/* Hostile inputs to the analysis library and the readers it depends on:
 * each refusal comes back as the documented NL_E* code with a message
 * naming the value, and the valid neighbour of each input still passes.
 * These are exact properties (a status, a substring), so no tolerance is
 * involved.  Criterion runs each test in its own process, so
 * NOISELAB_MEMORY_LIMIT set here does not leak. */
#include "../analysis/acf.h"
#include "../analysis/hist.h"
#include "../analysis/krige.h"
#include "../analysis/nonlin.h"
#include "../analysis/psd.h"
#include "../analysis/welch.h"
#include "../core/dist.h"
#include "../core/io.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* status `code` and a message holding `needle` */
#define REFUSED(code, needle, expr)                                                                                    \
    do {                                                                                                               \
        int st_ = (expr);                                                                                              \
        cr_expect_eq(st_, (code), "%s: expected status %d, got %d (%s)", #expr, (code), st_, nl_errmsg());             \
        cr_expect(strstr(nl_errmsg(), (needle)) != NULL, "%s: message \"%s\" does not name \"%s\"", #expr,            \
                  nl_errmsg(), (needle));                                                                              \
    } while (0)

/* Write `text` to a fresh temporary file; returns its name (static). */
static const char *tmpfile_with(const char *text)
{
    static char path[64];
    snprintf(path, sizeof path, "/tmp/nl-hostile-%ld.tsv", (long)getpid());
    FILE *fp = fopen(path, "w");
    cr_assert_not_null(fp);
    fputs(text, fp);
    fclose(fp);
    return path;
}

static int read_series(const char *text, nl_field **f)
{
    const char *p = tmpfile_with(text);
    int st = nl_tsv_read_field(p, f);
    unlink(p);
    return st;
}

Test(hostile_tsv, series_refused_when_not_a_regular_series)
{
    nl_field *f = NULL;
    REFUSED(NL_EINPUT, "regular", read_series("t\tvalue\n0\t1\n1\t2\n3\t0.5\n4\t1\n", &f));
    REFUSED(NL_EINPUT, "increasing", read_series("t\tvalue\n0\t1\n0\t2\n0\t3\n", &f));
    REFUSED(NL_EINPUT, "increasing", read_series("x\tvalue\n0\t1\n-1\t2\n-2\t3\n", &f));
    REFUSED(NL_EINPUT, "\"value\"", read_series("x\ty\n0\t1\n1\t2\n", &f));
    REFUSED(NL_EINPUT, "3 columns", read_series("x\ty\tvalue\n0\t1\t1\n1\t2\t2\n", &f));
    REFUSED(NL_EINPUT, "finite coordinate", read_series("t\tvalue\n0\t1\nnan\t2\n", &f));
    cr_expect_null(f);
    /* the valid neighbour: spacing from the coordinate, printed to 10 digits */
    cr_assert_eq(read_series("t\tvalue\n0\t1\n0.1\t2\n0.2\t3\n0.3000000001\t4\n", &f), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(f->n[0], 4);
    cr_expect_float_eq(f->h[0], 0.1, 1e-15);
    nl_field_free(f);
}

Test(hostile_tsv, growth_checked_against_the_memory_limit)
{
    char *text = malloc(200000);
    size_t len = (size_t)sprintf(text, "t\tvalue\n");
    nl_field *f = NULL;
    for (int i = 0; i < 10000; i++)
        len += (size_t)sprintf(text + len, "%d\t1\n", i);
    setenv("NOISELAB_MEMORY_LIMIT", "40000", 1);
    REFUSED(NL_ETOOBIG, "memory", read_series(text, &f));
    free(text);
}

Test(hostile_krige, overflowing_data_and_models_refused)
{
    nl_model *m;
    nl_krige_plan *p = NULL;
    double x[3] = {0.1, 0.5, 0.7}, big[3] = {1e308, -1e308, 0.3}, ok[3] = {1, -1, 0.3};
    double far[3] = {-1e308, 1e308, 0.7};
    cr_assert_eq(nl_model_parse("gauss:scale=0.3", &m), NL_OK);
    REFUSED(NL_EINVAL, "values run from", nl_krige_plan_alloc(m, 1, 3, x, big, 0, 0, 0, &p));
    REFUSED(NL_EINVAL, "x run from", nl_krige_plan_alloc(m, 1, 3, far, ok, 0, 0, 0, &p));
    cr_expect_null(p);
    cr_assert_eq(nl_krige_plan_alloc(m, 1, 3, x, ok, 0, 0, 0, &p), NL_OK, "%s", nl_errmsg());
    nl_krige_plan_free(p);
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("expr:1/r", &m), NL_OK);
    REFUSED(NL_EINVAL, "expr:1/r", nl_krige_plan_alloc(m, 1, 3, x, ok, 0, 0, 0, &p));
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("expr:-exp(-r)", &m), NL_OK);
    REFUSED(NL_EINVAL, "R(0) = -1", nl_krige_plan_alloc(m, 1, 3, x, ok, 0, 0, 0, &p));
    nl_model_free(m);
}

Test(hostile_krige, matrix_checked_against_the_memory_limit)
{
    size_t n = 2000;
    double *x = malloc(n * sizeof *x), *v = malloc(n * sizeof *v);
    nl_model *m;
    nl_krige_plan *p = NULL;
    for (size_t i = 0; i < n; i++)
        x[i] = (double)i, v[i] = 1;
    cr_assert_eq(nl_model_parse("markov", &m), NL_OK);
    setenv("NOISELAB_MEMORY_LIMIT", "10000000", 1); /* 4 n^2 doubles = 128 MB > 10 MB */
    REFUSED(NL_ETOOBIG, "covariance matrix", nl_krige_plan_alloc(m, 1, n, x, v, 0, 0, 0, &p));
    nl_model_free(m);
    free(x), free(v);
}

Test(hostile_moments, constant_and_overflowing_samples)
{
    size_t n = 8;
    nl_field *f = nl_field_alloc(1, &n, NULL, NULL);
    nl_moments mo;
    for (size_t i = 0; i < n; i++)
        f->data[i] = 3;
    cr_assert_eq(nl_moments_compute(f, &mo), NL_OK);
    cr_expect_eq(mo.variance, 0);
    cr_expect(isnan(mo.skewness) && isnan(mo.kurtosis), "a constant field has no skewness or kurtosis");
    f->data[0] = 1e200, f->data[1] = -1e200;
    REFUSED(NL_EINVAL, "variance overflows", nl_moments_compute(f, &mo));
    REFUSED(NL_EINVAL, "expected deviations below 9.48e+153", nl_moments_compute(f, &mo));
    for (size_t i = 0; i < n; i++)
        f->data[i] = i % 2 ? 1e308 : -1e308;
    REFUSED(NL_EINVAL, "by up to 1e+308", nl_moments_compute(f, &mo));
    /* the stated bound suffices: deviations of 0.99 sqrt(DBL_MAX / 2) */
    for (size_t i = 0; i < n; i++)
        f->data[i] = (i % 2 ? 0.99 : -0.99) * sqrt(DBL_MAX / 2);
    cr_expect_eq(nl_moments_compute(f, &mo), NL_OK, "%s", nl_errmsg());
    cr_expect(isfinite(mo.variance) && isfinite(mo.kurtosis), "variance %g kurtosis %g", mo.variance, mo.kurtosis);
    nl_field_free(f);
}

/* A constant field beyond 2^53 (v + 1 == v) still gets bins of positive
 * width: strictly increasing edges and finite densities that integrate to 1
 * (exact properties but for the rounding of count / (N w) w, hence 1e-9). */
Test(hostile_moments, histogram_of_a_huge_constant_field)
{
    const double vals[] = {-1e308, 1e308, DBL_MAX, -DBL_MAX, 0x1p53, -0x1p60, 1e15, -3e14, 4.9e-324, 0};
    const size_t bins_list[] = {1, 7, 1000};
    size_t n = 9;
    nl_field *f = nl_field_alloc(1, &n, NULL, NULL);
    nl_moments mo;
    for (size_t v = 0; v < sizeof vals / sizeof *vals; v++)
        for (size_t b = 0; b < 3; b++) {
            size_t bins = bins_list[b];
            double *mid = malloc(bins * sizeof *mid), *dens = malloc(bins * sizeof *dens);
            double *gauss = malloc(bins * sizeof *gauss), *edges = malloc((bins + 1) * sizeof *edges), total = 0;
            double *counts = malloc(bins * sizeof *counts);
            for (size_t i = 0; i < n; i++)
                f->data[i] = vals[v];
            cr_assert_eq(nl_moments_compute(f, &mo), NL_OK, "%s", nl_errmsg());
            cr_assert_eq(nl_hist(f, bins, edges, counts), NL_OK, "%s", nl_errmsg());
            for (size_t i = 0; i < bins; i++)
                cr_expect(edges[i + 1] > edges[i], "v %g, %zu bins: edges %zu, %zu are %g, %g", vals[v], bins, i,
                          i + 1, edges[i], edges[i + 1]);
            cr_assert_eq(nl_hist_density(f, &mo, bins, mid, dens, gauss), NL_OK, "%s", nl_errmsg());
            for (size_t i = 0; i < bins; i++) {
                cr_expect(isfinite(dens[i]) && dens[i] >= 0, "v %g: density %zu is %g", vals[v], i, dens[i]);
                cr_expect(mid[i] >= edges[i] && mid[i] <= edges[i + 1], "v %g: bin %zu's middle is %g", vals[v], i,
                          mid[i]);
                total += dens[i] * (edges[i + 1] - edges[i]);
            }
            cr_expect(fabs(total - 1) < 1e-9, "v %g, %zu bins: the density integrates to %.17g", vals[v], bins, total);
            free(mid), free(dens), free(gauss), free(edges), free(counts);
        }
    nl_field_free(f);
}

/* The bound of nl_estimate_check_range, D <= sqrt(DBL_MAX / 16) / N, is
 * sufficient where it is tightest: every sample at D from the given mean 0
 * puts all of N D into the zero frequency, and the 3D autocorrelation sums
 * 8 N^2 D^2 = DBL_MAX / 2 there; every estimate must come back finite (an
 * exact property: no tolerance).  Just above the bound each is refused with
 * a message naming the deviation and the bound. */
static void estimates_at_the_bound(int dim, const size_t *n)
{
    int st;
    nl_field *f = nl_field_alloc(dim, n, NULL, &st), *out = NULL;
    cr_assert_not_null(f);
    double bound = sqrt(DBL_MAX / 16.0) / (double)f->count, val[3];
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = bound;
    cr_assert_eq(nl_acf_full(f, 0, 0, &out), NL_OK, "%dD: %s", dim, nl_errmsg());
    for (size_t i = 0; i < out->count; i++)
        cr_assert(isfinite(out->data[i]), "%dD acf: sample %zu is %g", dim, i, out->data[i]);
    nl_field_free(out);
    cr_assert_eq(nl_psd_periodogram(f, 0, &out), NL_OK, "%dD: %s", dim, nl_errmsg());
    for (size_t i = 0; i < out->count; i++)
        cr_assert(isfinite(out->data[i]), "%dD periodogram: sample %zu is %g", dim, i, out->data[i]);
    nl_field_free(out);
    cr_assert_eq(nl_acf_direct(f, 0, 1, 0, 2, val), NL_OK, "%dD: %s", dim, nl_errmsg());
    cr_expect(isfinite(val[0]) && isfinite(val[2]), "%dD direct: %g %g", dim, val[0], val[2]);
    if (dim < 3) {
        cr_assert_eq(nl_psd_welch(f, 4, 0, &out, NULL), NL_OK, "%dD: %s", dim, nl_errmsg());
        for (size_t i = 0; i < out->count; i++)
            cr_assert(isfinite(out->data[i]), "%dD welch: sample %zu is %g", dim, i, out->data[i]);
        nl_field_free(out);
    }
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = 1.01 * bound;
    REFUSED(NL_EINVAL, "sums of squares", nl_acf_full(f, 0, 0, &out));
    REFUSED(NL_EINVAL, "expected deviations below", nl_psd_periodogram(f, 0, &out));
    REFUSED(NL_EINVAL, "expected deviations below", nl_acf_direct(f, 0, 1, 0, 2, val));
    cr_expect_null(out);
    nl_field_free(f);
}

Test(hostile_estimates, finite_up_to_the_stated_bound)
{
    size_t n1[1] = {64}, n2[2] = {8, 6}, n3[3] = {4, 6, 5};
    estimates_at_the_bound(1, n1);
    estimates_at_the_bound(2, n2);
    estimates_at_the_bound(3, n3);
}

Test(hostile_estimates, values_around_1e200_refused)
{
    size_t n = 4;
    nl_field *f = nl_field_alloc(1, &n, NULL, NULL), *out = NULL;
    nl_moments mo;
    f->data[0] = 1e200, f->data[1] = -1e200, f->data[2] = 1e200, f->data[3] = 5e199;
    REFUSED(NL_EINVAL, "by up to 1.375e+200", nl_acf_full(f, NAN, 0, &out));
    REFUSED(NL_EINVAL, "expected deviations below 8.38e+152", nl_psd_periodogram(f, NAN, &out));
    REFUSED(NL_EINVAL, "variance overflows", nl_moments_compute(f, &mo));
    cr_expect_null(out);
    nl_field_free(f);
}

Test(hostile_estimates, sums_of_squares_that_overflow_refused)
{
    size_t n = 64;
    nl_field *f = nl_field_alloc(1, &n, NULL, NULL), *out = NULL;
    for (size_t i = 0; i < n; i++)
        f->data[i] = sin((double)i);
    REFUSED(NL_EINVAL, "mean 1e+300", nl_acf_full(f, 1e300, 0, &out));
    REFUSED(NL_EINVAL, "mean 1e+300", nl_psd_periodogram(f, 1e300, &out));
    cr_expect_null(out);
    cr_assert_eq(nl_acf_full(f, NAN, 0, &out), NL_OK);
    nl_field_free(out);
    nl_field_free(f);
}

Test(hostile_nonlin, divergent_or_degenerate_expansions_refused)
{
    static const char *bad[][2] = {{"lognormal:sigma=5", "too heavy"},
                                   {"lognormal:sigma=50", "overflows"},
                                   {"gauss:sd=1e300", "overflows"},
                                   {"power:p=1e-300", "constant to rounding"}};
    nl_hermite h;
    nl_dist *d;
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        cr_assert_eq(nl_dist_parse(bad[i][0], &d), NL_OK, "%s: %s", bad[i][0], nl_errmsg());
        REFUSED(NL_EINVAL, bad[i][1], nl_hermite_expand(d, 24, &h));
        nl_dist_free(d);
    }
    cr_assert_eq(nl_dist_parse("lognormal", &d), NL_OK);
    cr_expect_eq(nl_hermite_expand(d, 24, &h), NL_OK, "%s", nl_errmsg());
    nl_dist_free(d);
}

Test(hostile_dist, infinite_tail_quantiles_refused)
{
    nl_dist *d = NULL;
    REFUSED(NL_EINVAL, "laplace:a=1e308", nl_dist_parse("laplace:a=1e308", &d));
    REFUSED(NL_EINVAL, "uniform:a=-1e308,b=1e308", nl_dist_parse("uniform:a=-1e308,b=1e308", &d));
    cr_expect_null(d);
    cr_assert_eq(nl_dist_parse("chi2-1", &d), NL_OK, "%s", nl_errmsg());
    nl_dist_free(d);
}
