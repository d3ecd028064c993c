/* Distribution shaping and goodness-of-fit tests.
 * Inputs are white Gaussian fields (independent samples, as KS and
 * chi-square assume).  Each of the 8 target checks passes at p > 1e-3 / 8
 * (Bonferroni over the family) and the mismatched case must fail at p <
 * 1e-6: with n = 65536 a Laplace sample is far from Gaussian (D ~ 0.05). */
#include "../analysis/gof.h"
#include "../core/dist.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/shape.h"

#include <criterion/criterion.h>
#include <math.h>

static nl_field *white(size_t n, uint64_t seed)
{
    size_t nn[1] = {n};
    nl_field *f = nl_field_alloc(1, nn, NULL, NULL);
    for (size_t i = 0; i < n; i++)
        f->data[i] = 2.385 + 0.7 * nl_rng_gauss(seed, 9, i);
    return f;
}

static nl_dist *dist(const char *spec)
{
    nl_dist *d;
    cr_assert_eq(nl_dist_parse(spec, &d), 0, "%s: %s", spec, nl_errmsg());
    return d;
}

Test(shape, reaches_every_target_distribution)
{
    const char *targets[] = {"uniform:a=-1,b=3", "laplace:a=2", "hyperbolic", "lognormal:zeta=0.5,sigma=0.4",
                             "chi2-1", "power:p=2.5", "gauss:mean=3,sd=2"};
    for (int emp = 0; emp <= 1; emp++)
        for (size_t i = 0; i < sizeof targets / sizeof *targets; i++) {
            nl_field *f = white(65536, 3 + i);
            nl_dist *d = dist(targets[i]);
            nl_gof g;
            cr_assert_eq(nl_synth_shape(f, d, emp), 0);
            cr_assert_eq(nl_gof_test(f->data, f->count, d, 40, &g), 0);
            cr_expect_gt(g.p_ks, 1e-3 / 16, "%s%s: KS D = %g, p = %g", targets[i], emp ? " (empirical)" : "", g.D,
                         g.p_ks);
            cr_expect_gt(g.p_chi2, 1e-3 / 16, "%s: chi2 = %g, p = %g", targets[i], g.chi2, g.p_chi2);
            nl_field_free(f);
            nl_dist_free(d);
        }
}

/* The test must be able to fail: a Laplace field is not Gaussian. */
Test(shape, goodness_of_fit_rejects_the_wrong_distribution)
{
    nl_field *f = white(65536, 1);
    nl_dist *l = dist("laplace"), *g = dist("gauss:mean=0,sd=1.4142135623730951");
    nl_gof r;
    cr_assert_eq(nl_synth_shape(f, l, 0), 0);
    cr_assert_eq(nl_gof_test(f->data, f->count, g, 40, &r), 0);
    cr_expect_lt(r.p_ks, 1e-6, "KS p = %g", r.p_ks);
    cr_expect_lt(r.p_chi2, 1e-6, "chi2 p = %g", r.p_chi2);
    nl_field_free(f);
    nl_dist_free(l);
    nl_dist_free(g);
}

/* GI '86, section 4: the squared Gaussian has the density
 * p(y) = (2 pi y)^(-1/2) exp(-y/2), y > 0. */
Test(shape, squared_gaussian_density_is_the_papers)
{
    nl_dist *d = dist("chi2-1");
    for (double y = 0.01; y < 12; y *= 1.37)
        cr_expect_float_eq(nl_dist_pdf(d, y), exp(-y / 2) / sqrt(2 * M_PI * y), 1e-13, "y = %g", y);
    /* and squaring a standard Gaussian field follows it */
    nl_field *f = white(65536, 7);
    nl_gof r;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = pow((f->data[i] - 2.385) / 0.7, 2);
    cr_assert_eq(nl_gof_test(f->data, f->count, d, 40, &r), 0);
    cr_expect_gt(r.p_ks, 1e-3, "KS p = %g", r.p_ks);
    nl_field_free(f);
    nl_dist_free(d);
}

/* Quantile and CDF are inverses; the hyperbolic secant has unit variance. */
Test(shape, distributions_are_consistent)
{
    const char *all[] = {"uniform", "laplace:a=0.5", "hyperbolic", "lognormal", "chi2-1", "power:p=0.3", "gauss"};
    for (size_t i = 0; i < sizeof all / sizeof *all; i++) {
        nl_dist *d = dist(all[i]);
        for (double u = 0.01; u < 1; u += 0.0731)
            cr_expect_float_eq(nl_dist_cdf(d, nl_dist_quantile(d, u)), u, 1e-9, "%s u=%g", all[i], u);
        nl_dist_free(d);
    }
    nl_dist *h = dist("hyperbolic");
    double s = 0, dy = 1e-3;
    for (double y = -40; y < 40; y += dy)
        s += y * y * nl_dist_pdf(h, y) * dy;
    cr_expect_float_eq(s, 1.0, 1e-6);
    nl_dist_free(h);
}

Test(shape, bad_distributions_are_refused)
{
    nl_dist *d;
    cr_expect_eq(nl_dist_parse("cauchy", &d), NL_EINVAL);
    cr_expect_eq(nl_dist_parse("laplace:a=-1", &d), NL_EINVAL);
    cr_expect_eq(nl_dist_parse("power", &d), NL_EINVAL);
    cr_expect_eq(nl_dist_parse("uniform:a=2,b=1", &d), NL_EINVAL);
    cr_expect_eq(nl_dist_parse("gauss:colour=1", &d), NL_EINVAL);
    cr_expect_eq(nl_dist_parse("table:/nonexistent.tsv", &d), NL_EINPUT);
}
