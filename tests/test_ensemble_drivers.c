/* The ensemble drivers (analysis/ensemble.h) against the direct
 * computation they stand for: each field's estimate by the one-field
 * functions, then nl_ensemble_mean_se.  The drivers call the same
 * functions in the same order, so the numbers must agree exactly (==, not
 * to a tolerance: acf, psd and hist print them and must not change).
 * Welford's one-pass mean and variance agree with the two-pass ones to
 * rounding: 1e-12 relative on values of order 1 from 7 fields. */
#include "../analysis/acf.h"
#include "../analysis/ensemble.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/spectral.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { K = 5 };

/* K Gaussian fields of nx x ny (spacing 0.37, 0.61), offset 2.385 k so that
 * their moments differ. */
static void make_fields(nl_field **x, size_t nx, size_t ny)
{
    size_t n[2] = {nx, ny};
    double h[2] = {0.37, 0.61};
    for (int k = 0; k < K; k++) {
        x[k] = nl_field_alloc(ny > 1 ? 2 : 1, n, h, NULL);
        cr_assert_not_null(x[k]);
        for (size_t i = 0; i < x[k]->count; i++)
            x[k]->data[i] = 2.385 * k + 1.3 * nl_rng_gauss(70 + (uint64_t)k, 0, i);
    }
}

static void free_fields(nl_field **x)
{
    for (int k = 0; k < K; k++)
        nl_field_free(x[k]);
}

static nl_ensemble_source array_source(nl_field **x)
{
    return (nl_ensemble_source){.K = K, .fields = (const nl_field *const *)x};
}

/* A callback source over x that records what it was asked for. */
typedef struct {
    nl_field **x;
    size_t asked, handed_back, fail_at;
} counting;

static int get(void *ctx, size_t k, const nl_field **out)
{
    counting *c = ctx;
    cr_expect_eq(k, c->asked, "fields are asked for in order, once each");
    c->asked++;
    if (k == c->fail_at)
        return NL_ERROR(NL_EINPUT, "field %zu: unreadable", k);
    *out = c->x[k];
    return NL_OK;
}

static void put(void *ctx, size_t k, const nl_field *f)
{
    counting *c = ctx;
    cr_expect_eq(f, c->x[k]);
    c->handed_back++;
}

Test(ensemble_drivers, acf_equals_the_direct_computation)
{
    nl_field *x[K];
    double lag[9], val[9], se[9], dlag[9], rows[K * 9], dval[9], dse[9];
    nl_ensemble_acf_opts o = {.mean = NAN, .unbiased = 1, .axis = 1, .nlag = 9};
    make_fields(x, 24, 20);
    for (int k = 0; k < K; k++) {
        nl_field *full;
        cr_assert_eq(nl_acf_full(x[k], NAN, 1, &full), NL_OK);
        cr_assert_eq(nl_acf_axis(full, 1, 8, dlag, rows + k * 9), NL_OK);
        nl_field_free(full);
    }
    cr_assert_eq(nl_ensemble_mean_se(rows, K, 9, dval, dse), NL_OK);
    nl_ensemble_source src = array_source(x);
    size_t bad = 99;
    cr_assert_eq(nl_ensemble_acf(&src, &o, lag, val, se, &bad), NL_OK, "%s", nl_errmsg());
    for (int i = 0; i < 9; i++) {
        cr_expect(lag[i] == dlag[i] && val[i] == dval[i] && se[i] == dse[i], "lag %d: %g %g %g vs %g %g %g", i,
                  lag[i], val[i], se[i], dlag[i], dval[i], dse[i]);
    }
    /* the same through a callback, and the radial average through both */
    counting c = {.x = x, .fail_at = K};
    nl_ensemble_source cb = {.K = K, .get = get, .put = put, .ctx = &c};
    double val2[9], se2[9];
    cr_assert_eq(nl_ensemble_acf(&cb, &o, lag, val2, se2, NULL), NL_OK);
    cr_expect_eq(memcmp(val, val2, sizeof val), 0);
    cr_expect_eq(memcmp(se, se2, sizeof se), 0);
    cr_expect(c.asked == K && c.handed_back == K);
    free_fields(x);
}

Test(ensemble_drivers, psd_equals_the_direct_computation)
{
    nl_field *x[K], *P, *sum = NULL;
    size_t nmax = 64 + 48 + 1, nf, dnf, segs = 0, cnt[113];
    double freq[113], val[113], se[113], dfreq[113], dval[113], dse[113], *rows;
    nl_ensemble_psd_opts o = {.mean = NAN, .welch = 0};
    make_fields(x, 64, 48);
    rows = malloc(K * nmax * sizeof *rows);
    for (int k = 0; k < K; k++) {
        nl_field *Pk;
        cr_assert_eq(nl_psd_periodogram(x[k], NAN, &Pk), NL_OK);
        cr_assert_eq(nl_psd_profile(Pk, dfreq, rows + k * nl_psd_profile_size(Pk), cnt, &dnf), NL_OK);
        if (!sum)
            sum = Pk;
        else {
            for (size_t i = 0; i < Pk->count; i++)
                sum->data[i] += Pk->data[i];
            nl_field_free(Pk);
        }
    }
    for (size_t i = 0; i < sum->count; i++)
        sum->data[i] /= K;
    cr_assert_eq(nl_ensemble_mean_se(rows, K, dnf, dval, dse), NL_OK);
    nl_ensemble_source src = array_source(x);
    cr_assert_eq(nl_ensemble_psd(&src, &o, &P, freq, val, se, &nf, &segs, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nf, dnf);
    cr_expect_eq(segs, 1);
    cr_expect_eq(memcmp(P->data, sum->data, sum->count * sizeof *sum->data), 0, "the mean spectrum");
    for (size_t i = 0; i < nf; i++)
        cr_expect((freq[i] == dfreq[i] || (isnan(freq[i]) && isnan(dfreq[i]))) &&
                  (val[i] == dval[i] || (isnan(val[i]) && isnan(dval[i]))) &&
                  (se[i] == dse[i] || (isnan(se[i]) && isnan(dse[i]))), "frequency %zu", i);
    nl_field_free(P), nl_field_free(sum), free(rows);
    free_fields(x);
}

Test(ensemble_drivers, moments_and_hist_equal_the_direct_computation)
{
    nl_field *x[K];
    nl_moments m, s, one;
    double v[4 * K], mu[4], sd[4], edges[12], counts[11], se[11], dedges[12], dcounts[11], dse[11], c[K * 11];
    make_fields(x, 300, 1);
    nl_ensemble_source src = array_source(x);
    cr_assert_eq(nl_ensemble_moments(&src, &m, &s, NULL), NL_OK);
    double lo = INFINITY, hi = -INFINITY;
    size_t n = 0;
    for (int k = 0; k < K; k++) {
        cr_assert_eq(nl_moments_compute(x[k], &one), NL_OK);
        v[4 * k] = one.mean, v[4 * k + 1] = one.variance, v[4 * k + 2] = one.skewness, v[4 * k + 3] = one.kurtosis;
        lo = fmin(lo, one.min), hi = fmax(hi, one.max), n += one.n;
    }
    cr_assert_eq(nl_ensemble_mean_se(v, K, 4, mu, sd), NL_OK);
    cr_expect(m.mean == mu[0] && m.variance == mu[1] && m.skewness == mu[2] && m.kurtosis == mu[3]);
    cr_expect(s.mean == sd[0] && s.variance == sd[1] && s.skewness == sd[2] && s.kurtosis == sd[3]);
    cr_expect(m.n == n && m.min == lo && m.max == hi);

    cr_assert_eq(nl_ensemble_hist(&src, 11, m.min, m.max, edges, counts, se, NULL), NL_OK);
    nl_field *span = nl_field_alloc(1, (size_t[]){2}, NULL, NULL);
    span->data[0] = lo, span->data[1] = hi;
    cr_assert_eq(nl_hist(span, 11, dedges, dcounts), NL_OK);
    for (int k = 0; k < K; k++)
        cr_assert_eq(nl_hist_count(x[k], dedges, 11, c + k * 11), NL_OK);
    cr_assert_eq(nl_ensemble_mean_se(c, K, 11, dcounts, dse), NL_OK);
    cr_expect_eq(memcmp(edges, dedges, sizeof edges), 0);
    cr_expect_eq(memcmp(counts, dcounts, sizeof counts), 0);
    cr_expect_eq(memcmp(se, dse, sizeof se), 0);
    double total = 0;
    for (int b = 0; b < 11; b++)
        total += counts[b];
    cr_expect_float_eq(total, 300, 1e-9, "the mean counts add up to one field's samples");

    /* one field: its own moments, standard errors undefined */
    src.K = 1;
    cr_assert_eq(nl_ensemble_moments(&src, &m, &s, NULL), NL_OK);
    cr_assert_eq(nl_moments_compute(x[0], &one), NL_OK);
    cr_expect_eq(memcmp(&m, &one, sizeof m), 0);
    cr_expect(isnan(s.mean));
    nl_field_free(span);
    free_fields(x);
}

/* What failed, and which field: the callers name it. */
Test(ensemble_drivers, failures_name_the_field)
{
    nl_field *x[K], *odd;
    double lag[4], val[4], se[4];
    nl_ensemble_acf_opts o = {.mean = NAN, .nlag = 4};
    size_t bad = 99;
    make_fields(x, 16, 16);
    counting c = {.x = x, .fail_at = 3};
    nl_ensemble_source cb = {.K = K, .get = get, .put = put, .ctx = &c};
    cr_expect_eq(nl_ensemble_acf(&cb, &o, lag, val, se, &bad), NL_EINPUT);
    cr_expect_eq(bad, 3);
    cr_expect_eq(c.handed_back, 3, "every field lent was handed back");

    odd = nl_field_alloc(2, (size_t[]){16, 15}, NULL, NULL);
    nl_field *keep = x[2];
    x[2] = odd;
    nl_ensemble_source src = array_source(x);
    cr_expect_eq(nl_ensemble_acf(&src, &o, lag, val, se, &bad), NL_EINVAL);
    cr_expect_eq(bad, 2);
    x[2] = keep;

    src.K = 1;
    cr_expect_eq(nl_ensemble_acf(&src, &o, lag, val, se, &bad), NL_EINVAL);
    cr_expect_eq(bad, 1, "no one field is at fault: bad = K");
    nl_field_free(odd);
    free_fields(x);
}

/* NOISELAB_MEMORY_LIMIT bounds the K estimates held: refused before any
 * field is asked for. */
Test(ensemble_drivers, estimates_beyond_memory_are_refused_first)
{
    nl_field *x[K];
    double lag[4], val[4], se[4];
    nl_ensemble_acf_opts o = {.mean = NAN, .nlag = 4};
    size_t bad = 99;
    make_fields(x, 16, 16);
    counting c = {.x = x, .fail_at = K};
    nl_ensemble_source cb = {.K = (size_t)1 << 60, .get = get, .put = put, .ctx = &c};
    cr_expect_eq(nl_ensemble_acf(&cb, &o, lag, val, se, &bad), NL_ETOOBIG);
    cr_expect_eq(bad, cb.K);
    cr_expect_eq(c.asked, 0);
    free_fields(x);
}

Test(ensemble_drivers, welford_equals_two_passes)
{
    nl_field *x[K], *var;
    nl_welford *w;
    make_fields(x, 40, 30);
    cr_assert_eq(nl_welford_alloc(2, x[0]->n, x[0]->h, &w), NL_OK);
    cr_expect_eq(nl_welford_variance(w, &var), NL_OK);
    cr_expect_eq(var->data[7], 0, "no realization: variance 0");
    nl_field_free(var);
    for (int k = 0; k < K; k++)
        cr_assert_eq(nl_welford_add(w, x[k]), NL_OK);
    cr_expect_eq(nl_welford_count(w), K);
    cr_assert_eq(nl_welford_variance(w, &var), NL_OK);
    const nl_field *mean = nl_welford_mean(w);
    cr_expect_eq(mean->h[1], x[0]->h[1]);
    for (size_t i = 0; i < x[0]->count; i++) {
        double s = 0, ss = 0;
        for (int k = 0; k < K; k++)
            s += x[k]->data[i];
        s /= K;
        for (int k = 0; k < K; k++)
            ss += (x[k]->data[i] - s) * (x[k]->data[i] - s);
        cr_expect(fabs(mean->data[i] - s) <= 1e-12 * (1 + fabs(s)), "sample %zu: mean %g vs %g", i,
                  mean->data[i], s);
        cr_expect(fabs(var->data[i] - ss / (K - 1)) <= 1e-12 * (1 + ss), "sample %zu: variance", i);
    }
    nl_field *odd = nl_field_alloc(2, (size_t[]){40, 29}, NULL, NULL);
    cr_expect_eq(nl_welford_add(w, odd), NL_EINVAL);
    cr_expect_eq(nl_welford_count(w), K, "nothing added");
    nl_field_free(odd), nl_field_free(var);
    nl_welford_free(w);
    free_fields(x);
}
