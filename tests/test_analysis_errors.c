/* Error paths of the estimators and model checks, after GSL's test_trap:
 * every NL_E* code their headers list is triggered here and comes back
 * with a message, except NL_EFAIL from FFTW refusing to plan or from the
 * eigensolver not converging, which no input reaches.  NL_ETOOBIG comes
 * from NOISELAB_MEMORY_LIMIT (or a size that overflows), NL_ENOMEM from an
 * address-space limit that lets the size check pass but makes the
 * allocation fail (not under AddressSanitizer, which reserves its own
 * address space).  Criterion runs each test in its own process, so the
 * limits do not leak. */
#include "../analysis/acf.h"
#include "../analysis/check.h"
#include "../analysis/fftshift.h"
#include "../analysis/gof.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../analysis/slope.h"
#include "../analysis/spectral.h"
#include "../analysis/subdiv_exact.h"
#include "../analysis/verdict.h"
#include "../analysis/welch.h"
#include "../core/autocorr_plan.h"
#include "../core/dist.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>

#define TRAP(code, expr)                                                                                               \
    do {                                                                                                               \
        int st_ = (expr);                                                                                              \
        cr_expect_eq(st_, (code), "%s: expected status %d, got %d (%s)", #expr, (code), st_, nl_errmsg());             \
        cr_expect_neq(nl_errmsg()[0], '\0', "%s: no message", #expr);                                                  \
    } while (0)

#if defined(__SANITIZE_ADDRESS__)
#define NO_RLIMIT 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NO_RLIMIT 1
#endif
#endif

/* Let the process grow by `extra` bytes of address space at most; 0 when
 * that cannot be arranged (then the ENOMEM checks are skipped). */
static int limit_memory(size_t extra)
{
#ifdef NO_RLIMIT
    (void)extra;
    return 0;
#else
    unsigned long pages;
    FILE *fp = fopen("/proc/self/statm", "r");
    if (!fp || fscanf(fp, "%lu", &pages) != 1) {
        if (fp)
            fclose(fp);
        return 0;
    }
    fclose(fp);
    struct rlimit r = {(rlim_t)pages * 4096 + extra, (rlim_t)pages * 4096 + extra};
    return setrlimit(RLIMIT_AS, &r) == 0;
#endif
}

static nl_field *field(int dim, size_t n0, size_t n1)
{
    nl_field *f = nl_field_alloc(dim, (size_t[]){n0, n1, 1}, NULL, NULL);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(2.385 * (double)i);
    return f;
}

Test(analysis_errors, acf)
{
    nl_acf_plan *p;
    nl_field *x = field(1, 40, 1), *y = field(1, 41, 1), *o, *full;
    double a[64], b[64], c[64];
    TRAP(NL_EINVAL, nl_acf_plan_alloc(0, (size_t[]){8}, &p));
    TRAP(NL_EINVAL, nl_acf_plan_alloc(4, (size_t[]){8, 8, 8, 8}, &p));
    TRAP(NL_EINVAL, nl_acf_plan_alloc(1, (size_t[]){0}, &p));
    TRAP(NL_ETOOBIG, nl_acf_plan_alloc(2, (size_t[]){SIZE_MAX / 2, 4}, &p));
    cr_assert_eq(nl_acf_plan_alloc(1, (size_t[]){40}, &p), 0);
    int st;
    cr_assert_null(nl_acf_plan_output_alloc(p, (double[]){-1}, &st));
    TRAP(NL_EINVAL, st);
    o = nl_acf_plan_output_alloc(p, NULL, &st);
    TRAP(NL_EINVAL, st == 0 ? nl_acf_plan_execute(p, y, NAN, 0, o) : st);
    TRAP(NL_EINVAL, nl_acf_plan_execute(p, x, NAN, 0, x));
    nl_acf_plan_free(p);
    nl_field_free(o);
    nl_acf_plan_free(NULL);
    cr_assert_eq(nl_acf_full(x, NAN, 0, &full), 0);
    TRAP(NL_EINVAL, nl_acf_axis(full, 1, 3, a, b));
    TRAP(NL_EINVAL, nl_acf_axis(full, 0, 40, a, b));
    TRAP(NL_EINVAL, nl_acf_direct(x, NAN, 0, 2, 3, a));
    TRAP(NL_EINVAL, nl_acf_direct(x, NAN, 0, 0, 40, a));
    TRAP(NL_EINVAL, nl_acf_bartlett(full->data, 10, 40, 5, a));
    TRAP(NL_EINVAL, nl_acf_bartlett_band(full, 40, 20, b, a, c));
    nl_field *f2 = field(2, 8, 8), *full2;
    cr_assert_eq(nl_acf_full(f2, NAN, 0, &full2), 0);
    TRAP(NL_EINVAL, nl_acf_bartlett_band(full2, 64, 2, b, a, c));
    nl_field *big = field(1, 20000, 1);
    setenv("NOISELAB_MEMORY_LIMIT", "100000", 1);
    TRAP(NL_ETOOBIG, nl_acf_full(big, NAN, 0, &o));
    cr_assert_null(o);
    nl_field_free(x), nl_field_free(y), nl_field_free(full), nl_field_free(f2), nl_field_free(full2);
    nl_field_free(big);
}

Test(analysis_errors, acf_model_values)
{
    nl_model *m;
    double lag[2] = {0, 1}, out[2];
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    TRAP(NL_EINVAL, nl_acf_model_values(m, 1, (size_t[]){8}, NULL, 1, lag, 2, out));
    TRAP(NL_EINVAL, nl_acf_model_values(m, 4, (size_t[]){8, 8, 8, 8}, NULL, 0, lag, 2, out));
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("spectrum:exp(-f*f*20)", &m), 0);
    setenv("NOISELAB_MEMORY_LIMIT", "100000", 1);
    TRAP(NL_ETOOBIG, nl_acf_model_values(m, 1, (size_t[]){20000}, (double[]){1}, 0, lag, 2, out));
    nl_model_free(m);
}

Test(analysis_errors, psd_welch)
{
    nl_psd_plan *p;
    nl_welch_plan *w;
    nl_field *x = field(2, 16, 12), *y = field(2, 12, 16), *P = field(2, 16, 12), *W = field(2, 8, 8), *o;
    nl_field *x3 = field(1, 8, 1);
    TRAP(NL_EINVAL, nl_psd_plan_alloc(0, (size_t[]){8}, &p));
    TRAP(NL_EINVAL, nl_psd_plan_alloc(1, (size_t[]){0}, &p));
    TRAP(NL_ETOOBIG, nl_psd_plan_alloc(2, (size_t[]){SIZE_MAX / 2, 4}, &p));
    cr_assert_eq(nl_psd_plan_alloc(2, x->n, &p), 0);
    TRAP(NL_EINVAL, nl_psd_plan_execute(p, y, NAN, P));
    TRAP(NL_EINVAL, nl_psd_plan_execute(p, x, NAN, y));
    TRAP(NL_EINVAL, nl_psd_plan_execute(p, x3, NAN, P));
    nl_psd_plan_free(p);
    nl_psd_plan_free(NULL);
    TRAP(NL_EINVAL, nl_welch_plan_alloc(3, 8, &w));
    TRAP(NL_EINVAL, nl_welch_plan_alloc(1, 3, &w));
    cr_assert_eq(nl_welch_plan_alloc(2, 8, &w), 0);
    TRAP(NL_EINVAL, nl_welch_plan_execute(w, x, NAN, P, NULL));
    TRAP(NL_EINVAL, nl_welch_plan_execute(w, x3, NAN, W, NULL));
    nl_welch_plan_free(w);
    nl_field *W16 = field(2, 16, 16);
    cr_assert_eq(nl_welch_plan_alloc(2, 16, &w), 0);
    TRAP(NL_EINVAL, nl_welch_plan_execute(w, x, NAN, W16, NULL)); /* x has 12 rows < 16 */
    nl_welch_plan_free(w);
    nl_field_free(W16);
    nl_welch_plan_free(NULL);
    nl_field *f3 = nl_field_alloc(3, (size_t[]){8, 8, 8}, NULL, NULL);
    TRAP(NL_EINVAL, nl_psd_welch(f3, 4, NAN, &o, NULL));
    TRAP(NL_EINVAL, nl_psd_welch(x, 13, NAN, &o, NULL));
    TRAP(NL_EINVAL, nl_psd_welch(x, 2, NAN, &o, NULL));
    cr_assert_null(o);
    nl_field *big = field(1, 20000, 1);
    setenv("NOISELAB_MEMORY_LIMIT", "100000", 1);
    TRAP(NL_ETOOBIG, nl_psd_periodogram(big, NAN, &o));
    nl_field_free(x), nl_field_free(y), nl_field_free(P), nl_field_free(W), nl_field_free(x3), nl_field_free(f3);
    nl_field_free(big);
}

/* Plans, verdicts and centred copies whose allocation fails. */
Test(analysis_errors, out_of_memory)
{
    nl_acf_plan *a;
    nl_psd_plan *p;
    nl_welch_plan *w;
    nl_autocorr_plan *c;
    nl_verdict *v;
    nl_field *big = field(1, (size_t)1 << 22, 1), *o;
    long lag[1][2] = {{0, 0}};
    double s[4], an;
    nl_gof g;
    nl_slope sl;
    nl_dist *d;
    nl_model *m;
    cr_assert_eq(nl_dist_parse("gauss", &d), 0);
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    nl_subdiv_coeffs *sc;
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 2, 4.0, 2, 1e-4, 6, &sc), 0);
    nl_field *bigfull = nl_field_alloc(1, (size_t[]){(size_t)1 << 22}, NULL, NULL), *sq = field(2, 8, 8);
    if (!limit_memory((size_t)16 << 20)) {
        nl_field_free(big), nl_field_free(bigfull), nl_field_free(sq);
        nl_subdiv_coeffs_free(sc), nl_model_free(m), nl_dist_free(d);
        cr_skip_test("no address-space limit here");
    }
    TRAP(NL_ENOMEM, nl_autocorr_plan_alloc(1, big->n, &c));
    TRAP(NL_ENOMEM, nl_acf_plan_alloc(1, big->n, &a));
    TRAP(NL_ENOMEM, nl_psd_plan_alloc(1, (size_t[]){(size_t)1 << 23}, &p));
    TRAP(NL_ENOMEM, nl_welch_plan_alloc(1, (size_t)1 << 22, &w));
    TRAP(NL_ENOMEM, nl_verdict_alloc(1, big->n, 1, (const long (*)[2])lag, &v));
    TRAP(NL_ENOMEM, nl_fftshift_alloc(big, &o));
    TRAP(NL_ENOMEM, nl_psd_model_profile(m, 1, big->n, NULL, s, &(size_t){0}));
    TRAP(NL_ENOMEM, nl_psd_sectors(sq, (size_t)1 << 28, 0, 0.5, s, &an));
    TRAP(NL_ENOMEM, nl_gof_test(big->data, (size_t)1 << 27, d, 4, &g));
    TRAP(NL_ENOMEM, nl_psd_slope(big->data, big->data, (size_t)1 << 27, 1, 2, 1, &sl));
    TRAP(NL_ENOMEM, nl_subdiv_exact_acf(sc, m, 4096, 1, 1, (long[]){0, 0}, s));
    TRAP(NL_ENOMEM, nl_acf_centred_alloc(bigfull, &o));
    nl_field_free(big), nl_field_free(bigfull), nl_field_free(sq);
    nl_subdiv_coeffs_free(sc), nl_model_free(m), nl_dist_free(d);
}

Test(analysis_errors, verdict)
{
    nl_verdict *v;
    long lags[2][2] = {{0, 0}, {8, 0}}, lag2[1][2] = {{0, 1}};
    double mean[2], se[2];
    nl_field *x = field(1, 8, 1), *y = field(1, 9, 1);
    TRAP(NL_EINVAL, nl_verdict_alloc(1, (size_t[]){8}, 0, (const long (*)[2])lags, &v));
    TRAP(NL_EINVAL, nl_verdict_alloc(1, (size_t[]){8}, 2, (const long (*)[2])lags, &v));
    TRAP(NL_EINVAL, nl_verdict_alloc(1, (size_t[]){8}, 1, (const long (*)[2])lag2, &v));
    TRAP(NL_EINVAL, nl_verdict_alloc(0, (size_t[]){8}, 1, (const long (*)[2])lags, &v));
    setenv("NOISELAB_MEMORY_LIMIT", "100000", 1);
    TRAP(NL_ETOOBIG, nl_verdict_alloc(1, (size_t[]){20000}, 1, (const long (*)[2])lags, &v));
    unsetenv("NOISELAB_MEMORY_LIMIT");
    cr_assert_eq(nl_verdict_alloc(1, (size_t[]){8}, 1, (const long (*)[2])lags, &v), 0);
    TRAP(NL_EINVAL, nl_verdict_stats(v, mean, NULL));
    TRAP(NL_EINVAL, nl_verdict_add(v, y));
    cr_assert_eq(nl_verdict_add(v, x), 0);
    TRAP(NL_EINVAL, nl_verdict_stats(v, mean, se));
    cr_assert_eq(nl_verdict_stats(v, mean, NULL), 0);
    nl_verdict_free(v);
    nl_verdict_free(NULL);
    nl_field_free(x), nl_field_free(y);
}

Test(analysis_errors, autocorr_plan)
{
    nl_autocorr_plan *p;
    nl_field *x = field(1, 8, 1), *c = field(1, 16, 1), *bad = field(1, 15, 1);
    TRAP(NL_EINVAL, nl_autocorr_plan_alloc(0, (size_t[]){8}, &p));
    TRAP(NL_ETOOBIG, nl_autocorr_plan_alloc(2, (size_t[]){SIZE_MAX / 2, 4}, &p));
    setenv("NOISELAB_MEMORY_LIMIT", "100000", 1);
    TRAP(NL_ETOOBIG, nl_autocorr_plan_alloc(1, (size_t[]){20000}, &p));
    unsetenv("NOISELAB_MEMORY_LIMIT");
    cr_assert_eq(nl_autocorr_plan_alloc(1, (size_t[]){8}, &p), 0);
    TRAP(NL_EINVAL, nl_autocorr_plan_execute(p, x, 0, bad));
    TRAP(NL_EINVAL, nl_autocorr_plan_execute(p, bad, 0, c));
    cr_assert_eq(nl_autocorr_plan_execute(p, x, 0, c), 0);
    nl_autocorr_plan_free(p);
    nl_field_free(x), nl_field_free(c), nl_field_free(bad);
}

Test(analysis_errors, centred_and_spectral)
{
    nl_field *odd = field(1, 7, 1), *P = field(2, 16, 16), *o, *f1 = field(1, 16, 1);
    double s[18], a, v[64];
    size_t nf;
    nl_model *m;
    TRAP(NL_EINVAL, nl_acf_centred_alloc(odd, &o));
    cr_assert_null(o);
    TRAP(NL_EINVAL, nl_psd_sectors(f1, 18, 0.05, 0.45, s, &a));
    TRAP(NL_EINVAL, nl_psd_sectors(P, 0, 0.05, 0.45, s, &a));
    TRAP(NL_EINVAL, nl_psd_sectors(P, 18, 0.45, 0.05, s, &a));
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    TRAP(NL_EINVAL, nl_psd_model_profile(m, 1, (size_t[]){0}, NULL, v, &nf));
    nl_field *big = field(1, 20000, 1), *bigfull = field(1, 40000, 1);
    setenv("NOISELAB_MEMORY_LIMIT", "100000", 1);
    TRAP(NL_ETOOBIG, nl_psd_model_profile(m, 1, (size_t[]){20000}, NULL, v, &nf));
    TRAP(NL_ETOOBIG, nl_fftshift_alloc(big, &o));
    TRAP(NL_ETOOBIG, nl_acf_centred_alloc(bigfull, &o));
    nl_model_free(m);
    nl_field_free(odd), nl_field_free(P), nl_field_free(f1), nl_field_free(big), nl_field_free(bigfull);
}

Test(analysis_errors, radial_hist_gof_slope)
{
    nl_field *x = field(2, 8, 8), *one = field(1, 1, 1);
    double r[8], v[8], e[9], c[8];
    size_t cnt[8];
    nl_moments mo;
    nl_gof g;
    nl_slope sl;
    nl_dist *d;
    TRAP(NL_EINVAL, nl_radial(x, NL_GRID_LAG, 0, 8, r, v, cnt));
    TRAP(NL_EINVAL, nl_radial(x, NL_GRID_FREQ, NAN, 8, r, v, cnt));
    TRAP(NL_EINVAL, nl_moments_compute(one, &mo));
    TRAP(NL_EINVAL, nl_hist(x, 0, e, c));
    nl_moments m2 = {0};
    TRAP(NL_EINVAL, nl_hist_density(x, &m2, 0, e, c, r));
    x->data[3] = NAN;
    TRAP(NL_EINVAL, nl_hist(x, 8, e, c));
    x->data[3] = INFINITY;
    TRAP(NL_EINVAL, nl_hist(x, 8, e, c));
    cr_assert_eq(nl_dist_parse("gauss", &d), 0);
    TRAP(NL_EINVAL, nl_gof_test(x->data, 1, d, 4, &g));
    TRAP(NL_EINVAL, nl_gof_test(x->data, 64, d, 1, &g));
    e[0] = 0, e[1] = 1, e[2] = 1;
    TRAP(NL_EINVAL, nl_gof_bin_density(d, e, 2, c));
    double f[4] = {1, 2, 3, 4}, p[4] = {1, 1, 1, 1};
    TRAP(NL_EINVAL, nl_psd_slope(f, p, 4, 1.5, 2.5, 1, &sl));
    nl_field *g4 = field(2, 4, 4);
    TRAP(NL_EINVAL, nl_psd_slope_grid(g4, 100, 200, &sl));
    nl_dist_free(d);
    nl_field_free(x), nl_field_free(one), nl_field_free(g4);
}

Test(analysis_errors, check_and_subdiv_exact)
{
    nl_model *m;
    nl_check k;
    nl_subdiv_coeffs *c;
    double out[2];
    cr_assert_eq(nl_model_parse("expr:-exp(-abs(t))", &m), 0);
    TRAP(NL_EINVAL, nl_check_model(m, 1, &k));
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    TRAP(NL_EINVAL, nl_check_model(m, 0, &k));
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 2, 4.0, 2, 1e-4, 6, &c), 0);
    TRAP(NL_ETOOBIG, nl_subdiv_exact_acf(c, m, 8192, 1, 1, (long[]){0, 0}, out));
    TRAP(NL_EINVAL, nl_subdiv_exact_acf(c, m, 30, 1, 1, (long[]){0, 0}, out));
    nl_subdiv_coeffs_free(c);
    nl_model_free(m);
}
