/* noiselab check, each verdict both ways. */
#include "../analysis/check.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>
#include <time.h>

static nl_check run(const char *spec, int dim)
{
    nl_model *m;
    nl_check c;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    cr_assert_eq(nl_check_model(m, dim, &c), 0, "%s: %s", spec, nl_errmsg());
    nl_model_free(m);
    return c;
}

Test(check, not_positive_definite)
{
    nl_check c = run("expr:cos(10*r)*exp(-r)", 2);  /* Lewis's example, below -1/2 */
    cr_expect_not(c.positive_definite);
    cr_expect_not(c.isotropic_bound_ok);
    cr_expect_lt(c.min_spectrum, -0.1);
    c = run("expr:step(1-abs(t))", 1);  /* a box: its spectrum is a sinc */
    cr_expect_not(c.positive_definite);
    cr_expect_lt(c.min_eigenvalue, 0);
    c = run("oscillatory:omega=3", 3);  /* isotropic 3D: an oscillatory spectrum is not allowed */
    cr_expect_not(c.positive_definite);
}

/* The boundary of validity, sharp: in 2D the integral of cos(omega r) e^-r
 * over the plane, S(0) / 2 pi = (1 - omega^2) / (1 + omega^2)^2, turns
 * negative at omega = 1 (about -0.016 of the peak at 1.01, +0.01 at 0.99,
 * both far beyond the -1e-6 threshold and the quadrature's 1e-9).  The
 * periodic grid alone, off by 2% of the peak at k = 0, passed 1.02. */
Test(check, sharp_boundary)
{
    cr_expect(run("oscillatory:omega=0.99", 2).positive_definite);
    nl_check c = run("oscillatory:omega=1.01", 2);
    cr_expect_not(c.positive_definite);
    cr_expect_eq(c.why, NL_CHECK_NEG_INTEGRAL);
}

Test(check, positive_definite)
{
    const char *ok[] = {"markov", "gauss", "matern:nu=1.5", "markaussian:alpha=1.4"};
    for (int i = 0; i < 4; i++)
        for (int dim = 1; dim <= 3; dim++) {
            nl_check c = run(ok[i], dim);
            cr_expect(c.positive_definite, "%s %dD: min spectrum %g, min eigenvalue %g", ok[i], dim, c.min_spectrum,
                      c.min_eigenvalue);
        }
}

/* Smoothness: Matern nu is m times differentiable for m < nu; exp(-|t|) and
 * the markaussian have a kink; the Gaussian is analytic with R''(0) = -2. */
Test(check, differentiability)
{
    cr_expect_eq(run("markov", 1).differentiable_order, 0);
    cr_expect_eq(run("markaussian:alpha=1.4", 2).differentiable_order, 0);
    cr_expect_eq(run("matern:nu=1.5", 1).differentiable_order, 1);
    cr_expect_eq(run("matern:nu=2.5", 2).differentiable_order, 2);
    cr_expect_eq(run("gauss", 1).differentiable_order, -1);
    cr_expect_float_eq(run("gauss", 1).r2, -2.0, 1e-6);
    cr_expect_float_eq(run("expr:exp(-t^2)", 1).r2, -2.0, 1e-9);  /* extrapolated differences */
    cr_expect(isinf(run("markov", 1).r2));
    /* along x, exp(-x^2 - 4 y^2) is exp(-x^2): R''(0) = -2 (it was 0, the
     * symbolic derivative in t of an expression in x); the finite
     * difference at d = 1e-4 L is off by d^2 < 1e-6 */
    cr_expect_float_eq(run("expr:exp(-x*x-4*y*y)", 2).r2, -2.0, 1e-6);
    cr_expect_float_eq(run("expr:exp(-x*x-4*y*y)", 3).r2, -2.0, 1e-6);
}

Test(check, singular_below_a_spacing)
{
    nl_check g = run("gauss", 1), m = run("markov", 1);
    cr_expect_gt(g.singular_below, 0.001, "gauss singular below %g", g.singular_below);
    cr_expect_lt(g.singular_below, 0.1);
    cr_expect_eq(m.singular_below, 0, "markov: %g", m.singular_below);
}

/* The spectral path against closed forms of named models: markov's 1D
 * density 2 / (1 + (2 pi f)^2) and 3D density 8 pi / (1 + (2 pi k)^2)^2
 * (variance 1, not differentiable, decays f^-2 and k^-4), and the
 * Gaussian's sqrt(pi) exp(-pi^2 f^2) with R''(0) = -2.  Variances and
 * R''(0) are quadratures to 1e-10 with an analytic tail beyond the band
 * (the tail of markov's 1D density beyond K = 1e5 is 1e-6 of the variance,
 * taken with the fitted exponent, good to 1e-3 of itself): 1e-6.  The tail
 * exponents are fitted where (2 pi k)^2 > 1e6, so within 1e-5 of 2 and 4:
 * 0.01 is loose. */
Test(check, spectral_path_agrees_with_named)
{
    nl_check c = run("spectrum:2/(1+(6.283185307179586*f)^2)", 1);
    cr_expect(c.spectral && c.positive_definite);
    cr_expect_float_eq(c.variance, 1.0, 1e-6);
    cr_expect_eq(c.differentiable_order, 0);
    cr_expect_float_eq(c.spectral_decay, 2.0, 0.01);
    c = run("spectrum:25.132741228718345/(1+(6.283185307179586*k)^2)^2", 3);
    cr_expect(c.positive_definite);
    cr_expect_float_eq(c.variance, 1.0, 1e-6);
    cr_expect_eq(c.differentiable_order, 0);
    cr_expect_float_eq(c.density_decay, 4.0, 0.01);
    cr_expect_float_eq(c.spectral_decay, 2.0, 0.01);
    c = run("spectrum:1.7724538509055159*exp(-9.869604401089358*f*f)", 1);
    cr_expect_eq(c.differentiable_order, -1);
    cr_expect_float_eq(c.variance, 1.0, 1e-6);
    cr_expect_float_eq(c.r2, -2.0, 1e-6);
    /* S = exp(-f^2): R(j) = sqrt(pi) exp(-pi^2 j^2) at unit spacing, so by
     * Poisson's sum the aliased spectrum is sum_j R(j) cos(2 pi j f), least
     * at f = 1/2 (on the zone's grid): 1 - 2 e^-pi^2 of R(0), the terms
     * j >= 2 (e^-4pi^2 = 7e-18) and aliases beyond 64 negligible; the
     * variance's quadrature is good to 1e-10. */
    c = run("spectrum:exp(-f*f)", 1);
    cr_expect_float_eq(c.min_eigenvalue, 1 - 2 * exp(-M_PI * M_PI), 1e-9);
    cr_expect_eq(c.eig_side, 0);
}

/* ---- Through the command line: every model kind in 1D, 2D and 3D. ---- */

#include "util.h"

#include <jansson.h>
#include <string.h>

static char out[1 << 16], err[1 << 12];

/* A word "nan" or "inf" (any case, any sign) in s: never printed. */
static int has_nonfinite(const char *s)
{
    for (const char *p = s; *p; p++) {
        int start = p == s || !((p[-1] | 32) >= 'a' && (p[-1] | 32) <= 'z');
        if (start && (strncasecmp(p, "nan", 3) == 0 || strncasecmp(p, "inf", 3) == 0) &&
            !((p[3] | 32) >= 'a' && (p[3] | 32) <= 'z'))
            return 1;
    }
    return 0;
}

/* Run check in text and JSON; the JSON object (caller frees) or NULL when
 * the command refused (exit 2, one line naming the model). */
static json_t *check_cli(const char *spec, int dim)
{
    char args[600];
    json_error_t je;
    json_t *o;
    int rc;
    snprintf(args, sizeof args, "check --acf '%s' --dim %d", spec, dim);
    rc = run_noiselab(args, out, sizeof out, err, sizeof err);
    cr_assert(rc == 0 || rc == 2, "%s: exit %d: %s", args, rc, err);
    if (rc == 2) {
        cr_expect_eq(count_lines(err), 1, "%s: %s", args, err);
        return NULL;
    }
    cr_expect_not(has_nonfinite(out), "%s printed a non-finite number:\n%s", args, out);
    snprintf(args, sizeof args, "check --acf '%s' --dim %d --json", spec, dim);
    cr_assert_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 0, "%s: %s", args, err);
    o = json_loads(out, 0, &je);
    cr_assert_not_null(o, "%s: not JSON (%s): %s", args, je.text, out);
    return o;
}

/* Each model's verdict in 1D, 2D, 3D: V positive definite, N not, R
 * refused with a message containing `needle`.  The invalid ones: the 2D and
 * 3D spectra of cos(omega r) e^-r (valid iff omega <= tan(pi / 2d)) and of
 * cos(omega r) e^-r^2 (valid in 3D iff omega <= sqrt 2) turn negative; a box
 * has a sinc spectrum; the triangle is valid in 1D only; cos(20 k) times a
 * Gaussian is a negative density; exemplars have no 3D table. */
static const struct {
    const char *spec, *verdict, *needle;
} kinds[] = {
    {"markov", "VVV", NULL},
    {"gauss", "VVV", NULL},
    {"markaussian:alpha=1.4", "VVV", NULL},
    {"matern:nu=1.5", "VVV", NULL},
    {"oscillatory:omega=3", "VNN", NULL},
    {"gauss-osc:omega=10", "VNN", NULL},
    {"gauss-osc:omega=1", "VVV", NULL},
    {"markov:scale=8,ratio=0.5,angle=30", "VVV", NULL},
    {"gauss:sep", "VVV", NULL},
    {"expr:exp(-abs(t))", "VVV", NULL},
    {"expr:cos(10*r)*exp(-r)", "VNN", NULL},
    {"expr:step(1-abs(t))", "NNN", NULL},
    {"expr:step(1-abs(t))*(1-abs(t))", "VNN", NULL},
    {"expr:exp(-x*x-4*y*y)", "VVV", NULL},
    {"spectrum:1/(1+k*k)^2", "VVV", NULL},
    {"spectrum:exp(-abs(f))", "VVV", NULL},
    {"spectrum:exp(-k*k)", "VVV", NULL},
    {"spectrum:step(0.25-k)", "VVV", NULL},
    {"spectrum:cos(20*k)*exp(-k*k)", "NNN", NULL},
    {"spectrum:exp(-fx*fx-4*fy*fy)", "VVV", NULL},
    {"spectrum:1/(1+k)", "RRR", "the variance"},
    {"power:d=3", "VVV", NULL},
    {"power:d=2.5", "VVV", NULL},
    {"power:d=1,fmin=0.01,fmax=0.2", "VVV", NULL},
    {"power:d=0.5", "VVV", NULL},
    {"image:img.exr", "VVR", "not 3D"},
};

/* One dimension of every kind (a test per dimension, so that they run
 * side by side). */
static void every_kind(int dim)
{
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x64 --seed 3 -o img.exr", NULL, 0, err,
                              sizeof err), 0, "%s", err);
    for (size_t i = 0; i < sizeof kinds / sizeof *kinds; i++) {
        char v = kinds[i].verdict[dim - 1];
        json_t *o = check_cli(kinds[i].spec, dim);
        if (v == 'R') {
            cr_expect_null(o, "%s %dD: expected a refusal", kinds[i].spec, dim);
            cr_expect(strstr(err, kinds[i].needle), "%s %dD: \"%s\" should say \"%s\"", kinds[i].spec, dim, err,
                      kinds[i].needle);
            json_decref(o);
            continue;
        }
        cr_assert_not_null(o, "%s %dD refused: %s", kinds[i].spec, dim, err);
        cr_expect_eq(json_is_true(json_object_get(o, "positive_definite")), v == 'V', "%s %dD: expected %s",
                     kinds[i].spec, dim, v == 'V' ? "valid" : "not positive definite");
        cr_expect_eq(json_is_null(json_object_get(o, "why")), v == 'V', "%s %dD: why", kinds[i].spec, dim);
        json_decref(o);
    }
}

Test(check_cli_slow, every_kind_1d) { every_kind(1); }
Test(check_cli_slow, every_kind_2d) { every_kind(2); }
Test(check_cli_slow, every_kind_3d) { every_kind(3); }

static json_t *must(const char *spec, int dim)
{
    json_t *o = check_cli(spec, dim);
    cr_assert_not_null(o, "%s %dD refused: %s", spec, dim, err);
    return o;
}

static double jnum(json_t *o, const char *key)
{
    json_t *v = json_object_get(o, key);
    cr_assert(json_is_number(v), "%s is not a number", key);
    return json_number_value(v);
}

/* power: in 1D exited 2 ("expected at least 3 frequencies"), in 2D it
 * printed min spectrum -inf and "NOT positive definite" after tens of
 * seconds: its R was sampled by quadrature over 2^20 lags and its spectrum
 * on a grid that missed its band.  A power spectrum is non-negative and
 * band-limited: positive definite, infinitely differentiable, the band's
 * exponent d as the density's decay. */
Test(check_cli, power_in_every_dim)
{
    for (int dim = 1; dim <= 3; dim++) {
        json_t *o = must("power:d=3", dim);
        cr_expect(json_is_true(json_object_get(o, "positive_definite")), "power:d=3 %dD", dim);
        cr_expect(json_is_true(json_object_get(o, "band_limited")));
        cr_expect_float_eq(jnum(o, "band_edge"), 0.5, 1e-12);
        cr_expect_float_eq(jnum(o, "density_decay"), 3.0, 1e-12);
        cr_expect_float_eq(jnum(o, "variance"), 1.0, 1e-12);
        cr_expect(json_is_null(json_object_get(o, "differentiable_order")));
        json_decref(o);
    }
    cr_expect_eq(run_noiselab("check --spectrum power:d=3 --dim 2", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_expect_not(has_nonfinite(out), "%s", out);
}

/* S = 1/(1 + k^2)^2 is the Matern density with nu = 2 - d/2: once
 * mean-square differentiable in 1D (nu = 1.5), not in 2D (nu = 1) or 3D
 * (nu = 0.5).  Before, 2D printed nan for the eigenvalue and R''(0) and
 * "infinitely differentiable".  The tail's fitted exponent is 4 k^2 /
 * (1 + k^2) > 3.999 over the fit band (k > 31), hence 0.01.  In 1D,
 * R''(0) = -4 pi^2 int f^2 S df = -2 pi^3; the quadrature is good to 1e-10
 * and the analytic tail beyond k = 1e3 (1e-3 of the moment) to 1e-3 of
 * itself, hence 1e-5 relative. */
Test(check_cli, k4_spectrum_smoothness)
{
    json_t *o = must("spectrum:1/(1+k*k)^2", 2);
    double l = jnum(o, "min_eigenvalue");
    cr_expect(l > 0 && l <= 1, "min eigenvalue %g", l);
    cr_expect_eq(json_integer_value(json_object_get(o, "differentiable_order")), 0);
    cr_expect(json_is_integer(json_object_get(o, "differentiable_order")));
    cr_expect(json_is_null(json_object_get(o, "r2")), "R''(0) does not exist in 2D");
    cr_expect_float_eq(jnum(o, "density_decay"), 4.0, 0.01);
    cr_expect_float_eq(jnum(o, "variance"), M_PI, 1e-8);  /* 2 pi int k / (1 + k^2)^2 dk */
    json_decref(o);
    o = must("spectrum:1/(1+k*k)^2", 1);
    cr_expect_eq(json_integer_value(json_object_get(o, "differentiable_order")), 1);
    cr_expect_float_eq(jnum(o, "r2"), -2 * pow(M_PI, 3), 2 * pow(M_PI, 3) * 1e-5);
    json_decref(o);
    o = must("spectrum:1/(1+k*k)^2", 3);
    cr_expect_eq(json_integer_value(json_object_get(o, "differentiable_order")), 0);
    json_decref(o);
}

/* markov: the line spectrum (of R along x) falls as f^-2 in every
 * dimension, the d-dimensional density (1 + (2 pi k)^2)^-(d+1)/2 as
 * k^-(d+1); before, only "spectrum ~ f^-1.99" was printed, the same in 1D,
 * 2D, 3D.  The fit over 16/L..128/L sees local slopes from 2 x^2 / (1 + x^2)
 * = 1.9 (x = 2 pi f = 4.4) to 2: 0.05 of tolerance.  The eigenvalue names
 * its matrix: side^d points spaced L / 16. */
Test(check_cli, markov_says_which_spectrum)
{
    static const int side[] = {0, 64, 16, 6};
    for (int dim = 1; dim <= 3; dim++) {
        json_t *o = must("markov", dim), *g;
        char needle[64];
        cr_expect_float_eq(jnum(o, "spectral_decay"), 2.0, 0.05);
        cr_expect_float_eq(jnum(o, "density_decay"), dim + 1.0, 0.05);
        g = json_object_get(o, "eigen_grid");
        cr_expect_eq(json_integer_value(json_object_get(g, "side")), side[dim]);
        cr_expect_float_eq(jnum(g, "spacing"), jnum(o, "scale") / 16, 1e-8 * jnum(o, "scale"));  /* JSON: 10 digits */
        json_decref(o);
        cr_assert_eq(run_noiselab(dim == 1 ? "check --acf markov --dim 1"
                                  : dim == 2 ? "check --acf markov --dim 2" : "check --acf markov --dim 3",
                                  out, sizeof out, err, sizeof err), 0);
        cr_expect(strstr(out, "line spectrum of R along x ~ f^-"), "%s", out);
        snprintf(needle, sizeof needle, "%d-point grid", side[dim]);
        cr_expect(strstr(out, needle), "%s", out);
        snprintf(needle, sizeof needle, "%dD density ~ |k|^-", dim);
        cr_expect(dim == 1 || strstr(out, needle), "%s", out);
    }
}

/* The neighbour of each is checked valid by check itself. */
static void neighbour_valid(json_t *o, int dim)
{
    json_t *a = json_object_get(o, "neighbours");
    cr_assert(json_array_size(a) > 0, "no neighbour");
    for (size_t i = 0; i < json_array_size(a); i++) {
        const char *s = json_string_value(json_array_get(a, i));
        json_t *n = must(s, dim);
        cr_expect(json_is_true(json_object_get(n, "positive_definite")), "neighbour %s not valid in %dD", s, dim);
        json_decref(n);
    }
}

/* The omega of the suggested neighbour, from "FAMILY:omega=W...". */
static double neighbour_omega(json_t *o)
{
    const char *s = json_string_value(json_array_get(json_object_get(o, "neighbours"), 0)), *p = NULL;
    cr_assert(s && (p = strstr(s, "omega=")), "first neighbour: %s", s ? s : "none");
    return strtod(p + 6, NULL);
}

/* Why, in words, and a valid neighbour.  Exact boundaries: cos(omega r)
 * e^-r^2 in 3D has S(0) proportional to (1 - omega^2/2) e^-omega^2/4, valid
 * up to omega = sqrt 2; cos(omega r) e^-r in 2D up to omega = tan(pi/4) = 1.
 * The neighbour is 2% inside the boundary found (by the radial spectrum,
 * exact at k = 0), 3 digits, rounded down: within 3% below the exact
 * boundary (5% allowed for gauss-osc, whose negative lobe the scan finds
 * with its frequency resolution). */
Test(check_cli_slow, says_why_and_a_valid_neighbour)
{
    json_t *o = must("gauss-osc:omega=10", 3);
    double w;
    cr_expect_str_eq(json_string_value(json_object_get(o, "why")), "negative-spectrum");
    w = neighbour_omega(o);
    cr_expect(w <= sqrt(2) && w >= 0.95 * sqrt(2), "gauss-osc neighbour omega %g", w);
    neighbour_valid(o, 3);
    json_decref(o);
    o = must("oscillatory:omega=3", 2);
    w = neighbour_omega(o);
    cr_expect(w <= 1 && w >= 0.97, "oscillatory neighbour omega %g", w);
    json_decref(o);
    o = must("expr:step(1-abs(t))*(1-abs(t))", 2);  /* a triangle: valid in 1D only */
    cr_expect_str_eq(json_string_value(json_array_get(json_object_get(o, "neighbours"), 0)),
                     "expr:step(1-r)*(1-1.5*r+0.5*r^3)");
    neighbour_valid(o, 2);
    json_decref(o);
    o = must("spectrum:-exp(-k*k)", 2);
    cr_expect_str_eq(json_string_value(json_object_get(o, "why")), "negative-integral");
    json_decref(o);
    cr_assert_eq(run_noiselab("check --acf 'expr:cos(10*r)*exp(-r)' --dim 2", out, sizeof out, err, sizeof err), 0);
    cr_expect(strstr(out, "why") && strstr(out, "2D spectrum") && strstr(out, "is negative at |k| ="), "%s", out);
    cr_expect(strstr(out, "expr:cos(10*r)*exp(-r);sep"), "%s", out);
}

/* Work bounded on a profile that never decays (cos(t)): the radial spectrum
 * of R is not integrated over 1e7 lags (its transform does not exist:
 * NaN, skipped), so the check of the model takes well under a second
 * instead of a minute; and eq. (14) at a lag of ten thousand periods is
 * refused with NL_ETOOBIG naming the lag, within the subintervals' limit,
 * while small lags still converge. */
Test(check, non_decaying_profile_bounded)
{
    nl_model *m;
    nl_check c;
    double r[3] = {0, 1.5, 62831.85}, c2[3];
    struct timespec t0, t1;
    cr_assert_eq(nl_model_parse("expr:cos(t)", &m), NL_OK, "%s", nl_errmsg());
    cr_expect(isnan(nl_model_spectrum_iso(m, 2, 1e-6)));
    clock_gettime(CLOCK_MONOTONIC, &t0);
    cr_assert_eq(nl_check_model(m, 2, &c), NL_OK, "%s", nl_errmsg());
    clock_gettime(CLOCK_MONOTONIC, &t1);
    cr_expect(!c.positive_definite, "cos(r) in 2D is not positive definite");
    cr_expect((double)(t1.tv_sec - t0.tv_sec) < 10, "the check took %ld s", (long)(t1.tv_sec - t0.tv_sec));
    cr_expect_eq(nl_check_matheron_2d(m, 3, r, c2), NL_ETOOBIG);
    cr_expect(strstr(nl_errmsg(), "at lag 62831") != NULL, "%s", nl_errmsg());
    cr_assert_eq(nl_check_matheron_2d(m, 2, r, c2), NL_OK, "%s", nl_errmsg());
    /* C2(r) = J0(r) for C1 = cos (the 2D sweep of a cosine) */
    cr_expect(fabs(c2[1] - 0.5118276717) < 1e-8, "C2(1.5) = %.10g, J0(1.5) = 0.5118276717", c2[1]);
    nl_model_free(m);
}
