/* Unit tests of the model layer: parsing, errors, values, anisotropy. */
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>
#include <string.h>

static nl_model *parse_ok(const char *spec)
{
    nl_model *m = NULL;
    int st = nl_model_parse(spec, &m);
    cr_assert_eq(st, NL_OK, "%s: %s", spec, nl_errmsg());
    return m;
}

static void parse_bad(const char *spec, const char *needle)
{
    nl_model *m = (nl_model *)1;
    int st = nl_model_parse(spec, &m);
    cr_assert_eq(st, NL_EINVAL, "%s should be refused", spec);
    cr_assert_null(m);
    cr_assert(strstr(nl_errmsg(), needle) != NULL, "%s: message \"%s\" should name \"%s\"", spec, nl_errmsg(),
              needle);
}

static double at1(const nl_model *m, double t) { return nl_model_acf(m, 1, &t); }

Test(model, named_values)
{
    nl_model *m = parse_ok("markov:scale=2.385,var=1.7");
    cr_assert_float_eq(at1(m, 0), 1.7, 1e-15);
    cr_assert_float_eq(at1(m, -2.385), 1.7 * exp(-1), 1e-15);
    nl_model_free(m);
    m = parse_ok("gauss:scale=3");
    cr_assert_float_eq(at1(m, 1.5), exp(-0.25), 1e-15);
    nl_model_free(m);
    m = parse_ok("markaussian:alpha=1.4,scale=2");
    cr_assert_float_eq(at1(m, 3), exp(-pow(1.5, 1.4)), 1e-15);
    nl_model_free(m);
    m = parse_ok("oscillatory:omega=10");
    cr_assert_float_eq(at1(m, 0.3), cos(3) * exp(-0.3), 1e-15);
    nl_model_free(m);
    m = parse_ok("gauss-osc:omega=10");
    cr_assert_float_eq(at1(m, 0.3), cos(3) * exp(-0.09), 1e-15);
    nl_model_free(m);
}

/* Matern closed forms: nu = 1/2 is exp(-u), nu = 3/2 is (1 + u) exp(-u),
 * with u = sqrt(2 nu) t / scale. */
Test(model, matern_closed_forms)
{
    nl_model *a = parse_ok("matern:nu=0.5,scale=2");
    nl_model *b = parse_ok("matern:nu=1.5,scale=2");
    for (double t = 0; t < 20; t += 0.37) {
        double u = sqrt(3.0) * t / 2;
        cr_assert_float_eq(at1(a, t), exp(-t / 2), 1e-12, "t=%g", t);
        cr_assert_float_eq(at1(b, t), (1 + u) * exp(-u), 1e-12, "t=%g", t);
    }
    nl_model_free(a);
    nl_model_free(b);
}

Test(model, expression_variables)
{
    nl_model *e = parse_ok("expr:100*cos(10*t)*exp(-abs(t))");
    nl_model *r = parse_ok("expr:exp(-r)*(1+x*0)");
    double lag[2] = {0.3, 0.4};
    cr_assert_float_eq(at1(e, -0.2), 100 * cos(2) * exp(-0.2), 1e-12);
    cr_assert_float_eq(nl_model_acf(r, 2, lag), exp(-0.5), 1e-12);
    nl_model_free(e);
    nl_model_free(r);
    e = parse_ok("spectrum:1/(1+k^2)");
    lag[0] = 3, lag[1] = 4;
    cr_assert_float_eq(nl_model_spectrum(e, 2, lag), 1 / 26.0, 1e-15);
    cr_assert(nl_model_is_spectral(e));
    cr_assert(isnan(nl_model_acf(e, 2, lag)));
    nl_model_free(e);
}

/* Anisotropy: R at the lag rotated by `angle` along x equals R at distance
 * along x; along the rotated y axis the length is ratio times shorter. */
Test(model, ellipsoidal_and_separable)
{
    nl_model *m = parse_ok("markov:scale=2,angle=30,ratio=0.5");
    nl_model *s = parse_ok("gauss:scale=2,sep");
    nl_model *i = parse_ok("gauss:scale=2");
    double a = M_PI / 6, d = 1.7;
    double along[2] = {d * cos(a), d * sin(a)}, across[2] = {-d * sin(a), d * cos(a)};
    double l3[3] = {0.3, -0.8, 1.1};
    cr_assert_float_eq(nl_model_acf(m, 2, along), exp(-d / 2), 1e-14);
    cr_assert_float_eq(nl_model_acf(m, 2, across), exp(-d / 0.5 / 2), 1e-14);
    /* a Gaussian is both separable and isotropic */
    cr_assert_float_eq(nl_model_acf(s, 3, l3), nl_model_acf(i, 3, l3), 1e-14);
    nl_model_free(m);
    nl_model_free(s);
    nl_model_free(i);
    m = parse_ok("markov:zratio=0.25");
    l3[0] = 0, l3[1] = 0, l3[2] = 0.5;
    cr_assert_float_eq(nl_model_acf(m, 3, l3), exp(-2), 1e-14);
    nl_model_free(m);
}

/* Power law: the spectrum integrates to var in each dimension; the radial
 * integral is done by GSL's adaptive quadrature to 1e-10 relative. */
struct shell_arg {
    const nl_model *m;
    int dim;
};

static double shell_integrand(double k, void *p)
{
    static const double shell[] = {0, 2, 2 * M_PI, 4 * M_PI};
    const struct shell_arg *a = p;
    double f[3] = {k, 0, 0};
    return shell[a->dim] * pow(k, a->dim - 1) * nl_model_spectrum(a->m, a->dim, f);
}

/* Large nu: the Matern correlation against GSL's K_nu at nu = 2e6, past the
 * switch to the asymptotic form (nu > 1e6).  The reference loses about
 * nu ln(nu) * 1e-16 = 3e-9 to cancellation in its logarithms, hence 2e-8; the
 * pure Gauss limit exp(-a^2 / 2) is off by up to 0.23 / nu = 1.2e-7 at
 * a^2 = 1.17, so the test also sees the first correction. */
Test(model, matern_large_nu)
{
    double nu = 2e6, worst_gauss = 0;
    nl_model *m = parse_ok("matern:nu=2e6,scale=2");
    for (double t = 0.25; t < 8; t += 0.43) {
        double a = t / 2, u = sqrt(2 * nu) * a;
        double ref = exp((1 - nu) * M_LN2 - gsl_sf_lngamma(nu) + nu * log(u) + gsl_sf_bessel_lnKnu(nu, u));
        cr_assert_float_eq(at1(m, t), ref, 2e-8, "t=%g: %.12g, K_nu gives %.12g", t, at1(m, t), ref);
        worst_gauss = fmax(worst_gauss, fabs(exp(-a * a / 2) - ref));
    }
    cr_assert_gt(worst_gauss, 5e-8, "the first correction is visible at nu = 2e6");
    nl_model_free(m);
    m = parse_ok("matern:nu=1e300");
    cr_assert(isnan(at1(m, 1)), "nu above 1e15 is not evaluated");
    nl_model_free(m);
}

/* 2D power R at lags of thousands of periods of the band (the expansion of
 * J0, core/model_hankel.c) against the closed form of d = 0,
 *     R(r) = var (fmax J1(2 pi fmax r) - fmin J1(2 pi fmin r)) / (pi r (fmax^2 - fmin^2)),
 * to 1e-12 (measured: 1e-13 at worst, where R is 1e-8; the quadratures ask
 * for 1e-11 relative to the integrands' larger partial sums, and dropping
 * Hankel's Q series alone gives errors of 1e-10); and d = 1 with a denormal
 * fmin finite and below R(0). */
Test(model, power_2d_far_lags)
{
    nl_model *m = parse_ok("power:d=0,var=2");
    double lo = 1.0 / 1024, hi = 0.5;
    for (double r = 1500; r < 2e6; r *= 1.7) {
        double lag[2] = {r * 0.6, r * 0.8};
        double want = 2 * (hi * gsl_sf_bessel_J1(2 * M_PI * hi * r) - lo * gsl_sf_bessel_J1(2 * M_PI * lo * r)) /
                      (M_PI * r * (hi * hi - lo * lo));
        cr_assert_float_eq(nl_model_acf(m, 2, lag), want, 1e-12, "r=%g: %.12g, closed form %.12g", r,
                           nl_model_acf(m, 2, lag), want);
    }
    nl_model_free(m);
    m = parse_ok("power:d=1,fmin=4.9e-324");
    for (double r = 4096; r < 1e5; r *= 2.3) {
        double lag[2] = {r, 0}, v = nl_model_acf(m, 2, lag);
        cr_assert(isfinite(v) && fabs(v) < 1, "r=%g: %g", r, v);
    }
    nl_model_free(m);
}

Test(model, power_normalisation)
{
    nl_model *m = parse_ok("power:d=2.5,fmin=0.01,fmax=0.5,var=2.385");
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
    for (int dim = 1; dim <= 3; dim++) {
        struct shell_arg a = {m, dim};
        gsl_function F = {shell_integrand, &a};
        double sum, err;
        cr_assert_eq(gsl_integration_qags(&F, 0.01, 0.5, 0, 1e-10, 1000, w, &sum, &err), 0);
        cr_assert_float_eq(sum, 2.385, 2.385 * 1e-9, "dim %d: %.12g", dim, sum);
    }
    gsl_integration_workspace_free(w);
    nl_model_free(m);
}

Test(model, errors_name_the_bad_part)
{
    parse_bad("", "expected a model spec");
    parse_bad("foo:scale=1", "\"foo\"");
    parse_bad("markaussian", "missing parameter alpha");
    parse_bad("oscillatory:scale=2", "missing parameter omega");
    parse_bad("matern", "missing parameter nu");
    parse_bad("power", "missing parameter d");
    parse_bad("markov:scale=abc", "\"abc\"");
    parse_bad("markov:scale=-2", "-2");
    parse_bad("markov:scale=inf", "\"inf\"");
    parse_bad("markov:colour=3", "\"colour\"");
    parse_bad("markov:scale", "scale=VALUE");
    parse_bad("markov:sep=1", "sep takes no value");
    parse_bad("expr:cos(t", "malformed expression");
    parse_bad("expr:exp(-q)", "\"q\"");
    parse_bad("expr:", "expected an expression");
    parse_bad("spectrum:exp(-t)", "\"t\"");
    parse_bad("power:d=2,fmin=0", "fmin > 0");
    parse_bad("power:d=2,fmin=0.3,fmax=0.2", "fmin < fmax");
    parse_bad("image:", "expected a file name");
}

/* exp(-|t|^alpha) is positive definite only for 0 < alpha <= 2 (the
 * catalogue's range): the parser refuses the first double above 2 and the
 * largest, naming alpha and the range; 2 itself (the Gaussian) is kept. */
Test(model, markaussian_alpha_above_two_refused)
{
    parse_bad("markaussian:alpha=2.0000000000000004", "0 < alpha <= 2");
    parse_bad("markaussian:alpha=1e308", "alpha");
    parse_bad("markaussian:alpha=3,scale=4", "got 3");
    nl_model_free(parse_ok("markaussian:alpha=2"));
}

Test(model, dimension_checks)
{
    nl_model *m = parse_ok("power:d=2");
    cr_assert_eq(nl_model_check_dim(m, 2), NL_OK);
    cr_assert_eq(nl_model_check_dim(m, 4), NL_EINVAL);
    nl_model_free(m);
    m = parse_ok("spectrum:1;ratio=0.5");
    cr_assert_eq(nl_model_check_dim(m, 2), NL_EINVAL);
    nl_model_free(m);
}

Test(model, image_is_a_file_error)
{
    nl_model *m;
    cr_assert_eq(nl_model_parse("image:/nonexistent/x.png", &m), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "/nonexistent/x.png") != NULL);
}
