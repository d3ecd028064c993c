/* Validation of a model's synthesis (analysis/validate.h): correct methods
 * pass, a wrong target fails, refusals are results, and every NL_E* code of
 * the header is reached.
 *
 * Why the verdicts are deterministic and trustworthy: a method whose fields
 * have covariance R gives z(l) = |mean - R(l)| / se(l) distributed as
 * Student's t(M - 1) at each lag (analysis/verdict.h), so max |z| over the 33
 * lags exceeds the Bonferroni threshold with probability at most alpha =
 * 1e-3; the seeds are fixed (1..M), so a pass is reproducible, not lucky
 * each run.  A wrong target must be off by many standard errors: see
 * wrong_target_fails. */
#include "../analysis/validate.h"
#include "../analysis/verdict.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

static void count_progress(void *ctx, int method, size_t done, size_t total)
{
    size_t *calls = ctx;
    cr_assert(method >= 0 && method < NL_VALIDATE_METHODS && done < total);
    calls[method]++;
}

/* markov in 1D: every method reproduces R, subdivision exactly (Markovian
 * in 1D), and its exact expected ACF is R up to the coarse grid's
 * periodisation (exp(-256/4) is negligible: 1e-9 of R(0)).  The threshold
 * is nl_verdict_threshold(1e-3, 33, M - 1); the progress callback sees each
 * realization once. */
Test(validate, markov_passes)
{
    nl_model *m = test_model("markov:scale=4");
    nl_validate_options o;
    nl_validate_result r;
    size_t n[2] = {256, 1}, calls[NL_VALIDATE_METHODS] = {0};
    nl_validate_options_default(&o);
    o.realizations = 16, o.progress = count_progress, o.progress_ctx = calls;
    cr_assert_eq(nl_validate_model(m, 1, n, 1, &o, &r), NL_OK);
    cr_expect_eq(r.threshold, nl_verdict_threshold(1e-3, NL_VALIDATE_LAGS, 15));
    cr_expect_float_eq(r.target[4], exp(-1.0), 1e-15);
    for (int k = 0; k < NL_VALIDATE_METHODS; k++) {
        const nl_validate_method_result *x = &r.method[k];
        cr_expect(x->ran && x->status == NL_OK, "%s: %s", nl_validate_method_name(k), x->why);
        cr_expect(x->pass && x->zmax <= r.threshold, "%s: max |z| %g", nl_validate_method_name(k), x->zmax);
        cr_expect_eq(calls[k], 16, "%s: %zu progress calls", nl_validate_method_name(k), calls[k]);
    }
    cr_expect(r.have_exact);
    for (int i = 0; i < NL_VALIDATE_LAGS; i++)
        cr_expect_float_eq(r.exact[i], r.target[i], 1e-9, "lag %d: %g vs %g", i, r.exact[i], r.target[i]);
    nl_model_free(m);
}

/* Fields of markov:scale=8 judged against the R of scale 4.  At lag 4 the
 * two differ by e^-0.5 - e^-1 = 0.24 of R(0); one realization's estimate
 * has sd about sqrt(2 * 8 / 1024) = 0.125 (Bartlett, tau = 8), so the
 * ensemble se is about 0.125 / sqrt(32) = 0.022 (0.020 measured) and z
 * about 11 there (max |z| 12.3 to 12.9 measured over the four methods),
 * against the threshold t(31) at 1e-3 / 66, 4.88.  So every method must
 * fail, and by a wide margin (1.5 x the threshold), not marginally; a
 * correct target gives max |z| near 2 (markov_passes). */
Test(validate, wrong_target_fails)
{
    nl_model *m = test_model("markov:scale=8"), *wrong = test_model("markov:scale=4");
    nl_validate_options o;
    nl_validate_result r;
    size_t n[2] = {1024, 1};
    nl_validate_options_default(&o);
    cr_assert_eq(nl_validate_init(m, 1, n, 1, &o, &r), NL_OK);
    for (int i = 0; i < NL_VALIDATE_LAGS; i++)
        r.target[i] = nl_model_acf(wrong, 1, (double[3]){i, 0, 0});
    for (int k = 0; k < NL_VALIDATE_METHODS; k++) {
        cr_assert_eq(nl_validate_method(m, k, &o, &r), NL_OK);
        cr_expect(r.method[k].ran, "%s: %s", nl_validate_method_name(k), r.method[k].why);
        cr_expect(!r.method[k].pass && r.method[k].zmax > 1.5 * r.threshold, "%s: max |z| %g, threshold %g",
                  nl_validate_method_name(k), r.method[k].zmax, r.threshold);
    }
    nl_model_free(m);
    nl_model_free(wrong);
}

/* Refusals are results: the caller's "not positive definite" refuses every
 * method with NL_ENOTPD; gauss:scale=20 on 64 x 64 is refused by the FFT
 * methods (its wrapped spectrum goes negative) while subdivision's exact ACF
 * is still reported (its levels are positive definite); 1 - |t|/3 in 1D has
 * subdivision levels that are not, so no exact ACF. */
Test(validate, refusals)
{
    nl_model *m = test_model("gauss:scale=20"), *tri = test_model("expr:1-abs(t)/3");
    nl_validate_options o;
    nl_validate_result r;
    size_t n[2] = {64, 64};
    nl_validate_options_default(&o);
    o.realizations = 4;
    cr_assert_eq(nl_validate_model(m, 2, n, 0, &o, &r), NL_OK);
    for (int k = 0; k < NL_VALIDATE_METHODS; k++)
        cr_expect(!r.method[k].ran && r.method[k].status == NL_ENOTPD, "%s", nl_validate_method_name(k));
    cr_assert_eq(nl_validate_model(m, 2, n, 1, &o, &r), NL_OK);
    cr_expect(!r.method[NL_VALIDATE_FFT].ran && r.method[NL_VALIDATE_FFT].status == NL_ENOTPD);
    cr_expect(!r.method[NL_VALIDATE_SUBDIV].ran && r.method[NL_VALIDATE_SUBDIV].status == NL_ENOTPD);
    cr_expect(strstr(r.method[NL_VALIDATE_SUBDIV].why, "not positive definite on this grid"), "%s",
              r.method[NL_VALIDATE_SUBDIV].why);
    cr_expect(r.method[NL_VALIDATE_CIRCULANT].ran, "%s", r.method[NL_VALIDATE_CIRCULANT].why);
    cr_expect(r.have_exact && fabs(r.exact[0] - 1) < 1e-3);
    cr_assert_eq(nl_validate_model(tri, 1, (size_t[]){128, 1}, 1, &o, &r), NL_OK);
    cr_expect(!r.method[NL_VALIDATE_SUBDIV].ran && r.method[NL_VALIDATE_SUBDIV].status == NL_ENOTPD);
    cr_expect(!r.have_exact);
    nl_model_free(m);
    nl_model_free(tri);
}

/* Every NL_E* code of validate.h: NL_EINVAL for each argument it checks,
 * with *out left as it was by nl_validate_method. */
Test(validate, error_paths)
{
    nl_model *m = test_model("markov:scale=3");
    nl_validate_options o;
    nl_validate_result r, copy;
    nl_validate_options_default(&o);
    cr_expect_eq(nl_validate_init(m, 3, (size_t[]){64, 64, 64}, 1, &o, &r), NL_EINVAL);
    cr_expect_eq(nl_validate_init(m, 0, (size_t[]){64}, 1, &o, &r), NL_EINVAL);
    cr_expect_eq(nl_validate_init(m, 1, (size_t[]){NL_VALIDATE_LAGS - 1}, 1, &o, &r), NL_EINVAL);
    cr_expect_eq(nl_validate_init(m, 2, (size_t[]){64, NL_VALIDATE_LAGS - 1}, 1, &o, &r), NL_EINVAL);
    cr_expect_eq(nl_validate_model(m, 2, (size_t[]){NL_VALIDATE_LAGS - 1, 64}, 1, &o, &r), NL_EINVAL);
    o.realizations = 1;
    cr_expect_eq(nl_validate_init(m, 1, (size_t[]){64}, 1, &o, &r), NL_EINVAL);
    o.realizations = 4, o.alpha = 0;
    cr_expect_eq(nl_validate_init(m, 1, (size_t[]){64}, 1, &o, &r), NL_EINVAL);
    o.alpha = 1;
    cr_expect_eq(nl_validate_init(m, 1, (size_t[]){64}, 1, &o, &r), NL_EINVAL);
    o.alpha = NAN;
    cr_expect_eq(nl_validate_init(m, 1, (size_t[]){64}, 1, &o, &r), NL_EINVAL);
    o.alpha = 1e-3;
    cr_assert_eq(nl_validate_init(m, 1, (size_t[]){64}, 1, &o, &r), NL_OK);
    memcpy(&copy, &r, sizeof r);
    cr_expect_eq(nl_validate_method(m, -1, &o, &r), NL_EINVAL);
    cr_expect_eq(nl_validate_method(m, NL_VALIDATE_METHODS, &o, &r), NL_EINVAL);
    o.realizations = 5;
    cr_expect_eq(nl_validate_method(m, NL_VALIDATE_FFT, &o, &r), NL_EINVAL);
    cr_expect(memcmp(&copy, &r, sizeof r) == 0, "a refused call changed the result");
    cr_expect_null(nl_validate_method_name(NL_VALIDATE_METHODS));
    cr_expect_str_eq(nl_validate_method_name(NL_VALIDATE_SPARSE), "sparse");
    cr_expect_str_eq(r.method[NL_VALIDATE_SUBDIV].name, "subdiv");
    nl_model_free(m);
}
