/* noiselab check, each verdict both ways. */
#include "../analysis/check.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>

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
    cr_expect_float_eq(run("expr:exp(-t^2)", 1).r2, -2.0, 1e-9);  /* symbolic */
    cr_expect(isinf(run("markov", 1).r2));
}

Test(check, singular_below_a_spacing)
{
    nl_check g = run("gauss", 1), m = run("markov", 1);
    cr_expect_gt(g.singular_below, 0.001, "gauss singular below %g", g.singular_below);
    cr_expect_lt(g.singular_below, 0.1);
    cr_expect_eq(m.singular_below, 0, "markov: %g", m.singular_below);
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

Test(check_cli, every_kind_every_dim, .timeout = 600)
{
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x64 --seed 3 -o img.exr", NULL, 0, err,
                              sizeof err), 0, "%s", err);
    for (size_t i = 0; i < sizeof kinds / sizeof *kinds; i++)
        for (int dim = 1; dim <= 3; dim++) {
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
