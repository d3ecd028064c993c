/* Error paths of core/, after GSL's test_trap: every NL_E* code a core header
 * lists is triggered here, and every GSL failure the library can meet comes
 * back as a status (or NAN) although no test turns GSL's handler off: GSL's
 * default handler, which prints and aborts, is in place for the whole suite,
 * so a path that reached it unguarded would crash its test (with the guard
 * made a no-op, the Cholesky, quadrature and chi-square tests abort and the
 * handler tests fail).
 *
 * Codes listed but not triggered one by one: NL_ENOMEM of the readers,
 * parsers and wk/autocorr scratch, which all allocate through nl_alloc as
 * nl_field_alloc does (errors_field/enomem triggers it there by limiting the
 * address space); NL_EFAIL of FFTW planning, which does not fail for any
 * size with FFTW_ESTIMATE or FFTW_MEASURE (the headers say so). */
#include "../core/autocorr.h"
#include "../core/dist.h"
#include "../core/field.h"
#include "../core/gsl_guard_internal.h"
#include "../core/io.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/wk.h"
#include "../synth/cholesky.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

/* ---- GSL failures inside the library ---- */

/* R(t) = 1 - |t|/3 is not a covariance: the Cholesky of its 64 x 64 matrix
 * fails (GSL_EDOM), which must be NL_ENOTPD with GSL's reason, not abort. */
Test(gsl_guard, cholesky_not_pd_is_a_status)
{
    nl_model *m = test_model("expr:1-abs(t)/3");
    nl_synth_cholesky_plan *p = (void *)1;
    size_t n = 64;
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 1, &n, NULL, &p), NL_ENOTPD);
    cr_assert_null(p);
    cr_assert(strstr(nl_errmsg(), "not positive definite"), "message: %s", nl_errmsg());
    cr_assert(strstr(nl_errmsg(), "GSL"), "message carries GSL's reason: %s", nl_errmsg());
    nl_model_free(m);
}

static int caller_calls;
static void caller_handler(const char *reason, const char *file, int line, int err)
{
    (void)reason, (void)file, (void)line, (void)err;
    caller_calls++;
}

/* The caller's handler is not called for the library's GSL errors, and is
 * back in place when the call returns. */
Test(gsl_guard, restores_the_callers_handler)
{
    nl_model *m = test_model("expr:1-abs(t)/3");
    nl_synth_cholesky_plan *p;
    size_t n = 64;
    gsl_set_error_handler(caller_handler);
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 1, &n, NULL, &p), NL_ENOTPD);
    cr_assert_eq(caller_calls, 0);
    cr_assert_eq(gsl_set_error_handler(NULL), caller_handler);
    nl_model_free(m);
}

/* The power model's R by quadrature: in 1D at 1e9 QAWO meets roundoff: NAN,
 * with GSL's reason recorded, and the process goes on.  (In 2D a lag of 1e6,
 * where the J0 integrand oscillates half a million times over the band, goes
 * to Hankel's expansion of J0 and is finite.) */
Test(gsl_guard, power_quadrature_failure_is_nan)
{
    nl_model *m = test_model("power:d=2.5");
    double far2[3] = {1e6, 0, 0}, far1[3] = {1e9, 0, 0}, near[3] = {3, 0, 0};
    cr_assert(fabs(nl_model_acf(m, 2, far2)) < 1e-5);
    cr_assert(isnan(nl_model_acf(m, 1, far1)));
    cr_assert(strstr(nl_gsl_reason(0), "roundoff"), "reason: %s", nl_gsl_reason(0));
    /* tolerance: the quadrature's relative accuracy is 1e-11 */
    cr_assert(fabs(nl_model_acf(m, 2, near) - 0.911082) < 1e-6);
    nl_model_free(m);
}

/* Matern with large and small nu: Bessel K and log Gamma under the guard;
 * R(0) = 1 and R decreases (no GSL error arises in this range, and none may
 * abort). */
Test(gsl_guard, matern_extreme_nu)
{
    const char *specs[] = {"matern:nu=1e-3", "matern:nu=100", "matern:nu=1e6"};
    for (int s = 0; s < 3; s++) {
        nl_model *m = test_model(specs[s]);
        double prev = INFINITY;
        for (double t = 0.01; t < 1e9; t *= 7.3) {
            double lag[1] = {t}, r = nl_model_acf(m, 1, lag);
            cr_assert(isfinite(r) && r >= 0 && r <= prev, "%s at %g: %g", specs[s], t, r);
            prev = r;
        }
        nl_model_free(m);
    }
}

/* The chi-square quantile's inverse does not converge below u ~ 1e-300:
 * GSL reports it, the library returns a number or NAN and goes on. */
Test(gsl_guard, chi2_quantile_failure)
{
    nl_dist *d;
    cr_assert_eq(nl_dist_parse("chi2-1", &d), NL_OK);
    (void)nl_dist_quantile(d, 1e-300);
    cr_assert(strstr(nl_gsl_reason(0), "converge"), "reason: %s", nl_gsl_reason(0));
    cr_assert(fabs(nl_dist_quantile(d, 0.5) - 0.45493642311957) < 1e-9);
    nl_dist_free(d);
}

static void *failing_quadratures(void *arg)
{
    nl_model *m = arg;
    double far1[3] = {1e9, 0, 0};
    for (int i = 0; i < 4; i++)
        if (!isnan(nl_model_acf(m, 1, far1)))
            return (void *)1;
    return NULL;
}

/* Four threads failing at once: none aborts, and the caller's handler is
 * back after the last one returns. */
Test(gsl_guard, threads)
{
    nl_model *m = test_model("power:d=2.5");
    pthread_t t[4];
    void *r;
    gsl_set_error_handler(caller_handler);
    for (int i = 0; i < 4; i++)
        cr_assert_eq(pthread_create(&t[i], NULL, failing_quadratures, m), 0);
    for (int i = 0; i < 4; i++) {
        cr_assert_eq(pthread_join(t[i], &r), 0);
        cr_assert_null(r);
    }
    cr_assert_eq(caller_calls, 0);
    cr_assert_eq(gsl_set_error_handler(NULL), caller_handler);
    nl_model_free(m);
}

/* Nested brackets: only the outermost restores. */
Test(gsl_guard, nesting)
{
    gsl_set_error_handler(caller_handler);
    nl_gsl_enter();
    nl_gsl_enter();
    nl_gsl_leave();
    gsl_error("inner failure", __FILE__, __LINE__, GSL_EFAILED);
    cr_assert_eq(caller_calls, 0);
    cr_assert(strstr(nl_gsl_reason(GSL_EFAILED), "inner failure"));
    nl_gsl_leave();
    cr_assert_eq(gsl_set_error_handler(NULL), caller_handler);
}

/* ---- field.h ---- */

Test(errors_field, einval_etoobig)
{
    size_t bad[3] = {4, 0, 4}, huge[3] = {SIZE_MAX / 2, 4, 1}, n = 1000000, c;
    double h[1] = {-1};
    int st;
    cr_assert_eq(nl_size_check(4, bad, 8, 1, &c), NL_EINVAL);
    cr_assert_eq(nl_size_check(3, bad, 8, 1, &c), NL_EINVAL);
    cr_assert_eq(nl_size_check(2, huge, 8, 1, &c), NL_ETOOBIG);
    cr_assert(strstr(nl_errmsg(), "overflow"), "%s", nl_errmsg());
    cr_assert_null(nl_field_alloc(1, &n, h, &st));
    cr_assert_eq(st, NL_EINVAL);
    cr_assert_null(nl_field_alloc(0, &n, NULL, &st));
    cr_assert_eq(st, NL_EINVAL);
    setenv("NOISELAB_MEMORY_LIMIT", "1000000", 1);
    cr_assert_null(nl_field_alloc(1, &n, NULL, &st));
    cr_assert_eq(st, NL_ETOOBIG);
    cr_assert(strstr(nl_errmsg(), "available"), "%s", nl_errmsg());
}

/* NL_ENOMEM: the size passes the check against available memory, but the
 * process's address space is limited below it, so the allocation fails.
 * (Not under AddressSanitizer, whose allocator dies instead of failing.) */
#if !defined(__SANITIZE_ADDRESS__)
Test(errors_field, enomem)
{
    struct rlimit rl = {(rlim_t)1 << 30, (rlim_t)1 << 30};
    size_t n = (size_t)1 << 28;  /* 2 GiB of doubles */
    int st;
    if (nl_mem_available() < ((size_t)1 << 31) + ((size_t)1 << 28))
        cr_skip_test("less than 2.25 GiB available: the size check would refuse first");
    cr_assert_eq(setrlimit(RLIMIT_AS, &rl), 0);
    cr_assert_null(nl_field_alloc(1, &n, NULL, &st));
    cr_assert_eq(st, NL_ENOMEM);
}
#endif

/* ---- io.h ---- */

static nl_field *small_field(void)
{
    size_t n[2] = {4, 3};
    int st;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    cr_assert_not_null(f);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = 0.125 * (double)i - 0.3;
    return f;
}

static const char *scratch(const char *name, const char *content)
{
    static char path[4][512];
    static int k;
    char *p = path[k++ % 4];
    snprintf(p, 512, "%s/%s", scratch_dir(), name);
    if (content) {
        FILE *fp = fopen(p, "w");
        cr_assert_not_null(fp);
        fputs(content, fp);
        fclose(fp);
    }
    return p;
}

Test(errors_io, eio_unwritable)
{
    nl_field *f = small_field();
    const char *bad = "/nonexistent-dir/x";
    const char *names[] = {"a"};
    const double *cols[] = {f->data};
    uint8_t pix[12] = {0};
    cr_assert_eq(nl_exr_write(bad, f, NULL), NL_EIO);
    cr_assert(strstr(nl_errmsg(), bad), "%s", nl_errmsg());
    cr_assert_eq(nl_png_write_gray8(bad, 4, 3, pix), NL_EIO);
    cr_assert_eq(nl_png_write_field(bad, f, -1, 1), NL_EIO);
    cr_assert_eq(nl_tsv_write(bad, NULL, 1, names, f->count, cols), NL_EIO);
    nl_field_free(f);
}

Test(errors_io, einval_etoobig)
{
    nl_field *f = small_field(), big = *f;
    uint8_t pix[3] = {0};
    cr_assert_eq(nl_png_write_field(scratch("p.png", NULL), f, 1, 1), NL_EINVAL);
    /* the size is refused before any sample is read */
    big.n[0] = (size_t)INT32_MAX + 1;
    cr_assert_eq(nl_exr_write(scratch("big.exr", NULL), &big, NULL), NL_ETOOBIG);
    cr_assert_eq(nl_png_write_rgb8(scratch("big.png", NULL), (size_t)1 << 31, 1, pix), NL_ETOOBIG);
    nl_field_free(f);
}

Test(errors_io, einput_malformed)
{
    nl_field *f = (void *)1;
    const char *junk = scratch("junk.bin", "\x76\x2f\x31\x01 not an image\n");
    cr_assert_eq(nl_exr_read(junk, &f, NULL), NL_EINPUT);
    cr_assert_eq(nl_png_read(junk, &f), NL_EINPUT);
    cr_assert_eq(nl_tsv_read_field(scratch("none.tsv", NULL), &f), NL_EINPUT);
    cr_assert_eq(nl_tsv_read_field(scratch("empty.tsv", ""), &f), NL_EINPUT);
    cr_assert_eq(nl_tsv_read_field(scratch("cols.tsv", "t\tvalue\n0\t1\n1\n"), &f), NL_EINPUT);
    cr_assert_eq(nl_tsv_read_field(scratch("nan.tsv", "t\tvalue\n0\t1\n1\tfoo\n"), &f), NL_EINPUT);
    cr_assert_eq(nl_tsv_read_field(scratch("one.tsv", "value\n1\n"), &f), NL_EINPUT);
    cr_assert_eq(nl_field_read(scratch("inf.tsv", "value\n1\ninf\n2\n"), &f, NULL), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "inf") || strstr(nl_errmsg(), "finite"), "%s", nl_errmsg());
}

/* ---- model.h ---- */

Test(errors_model, einval_einput)
{
    nl_model *m = (void *)1;
    const char *bad[] = {"", "nosuch", "markov:scale=-1", "markov:scale=abc", "matern", "power:d=2,fmin=0.5,fmax=0.1",
                         "expr:", "expr:1+*", "image:"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        cr_assert_eq(nl_model_parse(bad[i], &m), NL_EINVAL, "%s", bad[i]);
        cr_assert_neq(nl_errmsg()[0], 0);
    }
    cr_assert_eq(nl_model_parse("image:/nonexistent-dir/x.png", &m), NL_EINPUT);
    m = test_model("markov");
    cr_assert_eq(nl_model_check_dim(m, 4), NL_EINVAL);
    nl_model_free(m);
    m = test_model("power:d=2,angle=30");
    cr_assert_eq(nl_model_check_dim(m, 2), NL_EINVAL);
    nl_model_free(m);
}

/* ---- dist.h ---- */

Test(errors_dist, einval_einput)
{
    nl_dist *d;
    cr_assert_eq(nl_dist_parse("nosuch", &d), NL_EINVAL);
    cr_assert_eq(nl_dist_parse("gauss:sd=-1", &d), NL_EINVAL);
    cr_assert_eq(nl_dist_parse("uniform:a=2,b=1", &d), NL_EINVAL);
    cr_assert_eq(nl_dist_parse("table:/nonexistent-dir/t.tsv", &d), NL_EINPUT);
    char spec[600];
    snprintf(spec, sizeof spec, "table:%s", scratch("dec.tsv", "u\ty\n0\t1\n0.5\t0\n1\t2\n"));
    cr_assert_eq(nl_dist_parse(spec, &d), NL_EINPUT);
}

/* ---- wk.h and autocorr.h ---- */

Test(errors_wk, einval)
{
    size_t n[2] = {8, 8}, n2[2] = {8, 4};
    int st;
    nl_field *R = nl_field_alloc(2, n, NULL, &st), *S = nl_field_alloc(2, n2, NULL, &st);
    nl_model *m = test_model("expr:1/t");  /* infinite at lag 0 */
    double *half;
    cr_assert_eq(nl_wk_sample_acf(m, R), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "not finite"), "%s", nl_errmsg());
    cr_assert_eq(nl_wk_acf_to_spectrum(R, S), NL_EINVAL);
    cr_assert_eq(nl_wk_spectrum_to_acf(R, S), NL_EINVAL);
    cr_assert_eq(nl_wk_sample_spectrum_half(m, 4, n, NULL, &half), NL_EINVAL);
    cr_assert_null(half);
    nl_model_free(m);
    nl_field_free(R), nl_field_free(S);
}

Test(errors_autocorr, etoobig)
{
    size_t n = 1000;
    int st;
    nl_field *x = nl_field_alloc(1, &n, NULL, &st), *c = (void *)1;
    setenv("NOISELAB_MEMORY_LIMIT", "20000", 1);  /* 2 x 2000 doubles do not fit */
    cr_assert_eq(nl_autocorr_sums(x, 0, &c), NL_ETOOBIG);
    cr_assert_null(c);
    nl_field_free(x);
}

/* NL_ETOOBIG from the size a file declares: a 64 x 64 PNG read under a
 * memory limit of 1000 bytes, directly, as a field and as an exemplar. */
Test(errors_io, etoobig_on_read)
{
    static uint8_t pix[64 * 64];
    const char *png = scratch("big.png", NULL);
    char spec[600];
    nl_field *f;
    nl_model *m;
    for (size_t i = 0; i < sizeof pix; i++)
        pix[i] = (uint8_t)(i * 37 % 251);
    cr_assert_eq(nl_png_write_gray8(png, 64, 64, pix), NL_OK);
    setenv("NOISELAB_MEMORY_LIMIT", "1000", 1);
    cr_assert_eq(nl_png_read(png, &f), NL_ETOOBIG);
    cr_assert_null(f);
    cr_assert_eq(nl_field_read(png, &f, NULL), NL_ETOOBIG);
    snprintf(spec, sizeof spec, "image:%s", png);
    cr_assert_eq(nl_model_parse(spec, &m), NL_ETOOBIG);
}

/* NL_ETOOBIG from the scratch grid of a spectral model's conversion. */
Test(errors_wk, etoobig)
{
    size_t n[2] = {64, 64};
    int st;
    nl_field *R = nl_field_alloc(2, n, NULL, &st);
    nl_model *m = test_model("power:d=2.5");
    setenv("NOISELAB_MEMORY_LIMIT", "30000", 1);  /* R (32768 bytes) is made; the spectrum grid does not fit */
    cr_assert_eq(nl_wk_sample_acf(m, R), NL_ETOOBIG);
    nl_model_free(m);
    nl_field_free(R);
}

/* A field's spacing is a positive finite length: inf (which the radial
 * estimators would turn into an out-of-range bin index) is refused. */
Test(field_errors, infinite_spacing_refused)
{
    size_t n[2] = {8, 8};
    double h[2] = {1, INFINITY};
    int st = NL_OK;
    cr_assert_null(nl_field_alloc(2, n, h, &st));
    cr_assert_eq(st, NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "inf") != NULL, "%s", nl_errmsg());
}
