/* noiselab check on R that decays like a power of r or not at all, on
 * compactly supported R near the boundary of validity, and what synthesis
 * refuses with it; each verdict both ways.  The wider catalogue, with its
 * citations, is tests/check/run.sh. */
#include "../analysis/check.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static nl_check run(const char *spec, int dim)
{
    nl_model *m;
    nl_check c;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s: %s", spec, nl_errmsg());
    cr_assert_eq(nl_check_model(m, dim, &c), 0, "%s: %s", spec, nl_errmsg());
    nl_model_free(m);
    return c;
}

/* Known verdicts where R decays slowly: (1 + r^a)^(-b/a) is positive
 * definite in every dimension iff a <= 2 (Gneiting and Schlather 2004);
 * alpha > 2 dips to -4.3e-3 of the peak near 1 cycle per unit.
 * 1/(1 + log(1 + r)) is completely monotone in r (a Bernstein function
 * inside 1/(1 + x)), so valid in every dimension.  The old scale (where
 * |R| < 1e-8 R(0)) sampled these 1e2 to 1e5 units apart and got each
 * wrong. */
Test(check_tails, power_law_tails)
{
    static const struct {
        const char *spec;
        int dim, valid;
    } cases[] = {
        {"expr:(1+r^2.5)^-1", 1, 0},        {"expr:(1+r^2.1)^(-2/2.1)", 2, 0}, {"expr:(1+r^2.5)^-1", 3, 0},
        {"expr:(1+r^2)^-0.3", 2, 1},        {"expr:(1+r^2)^-0.1", 3, 1},       {"expr:1/(1+log(1+r))", 3, 1},
        {"expr:(1+r^1.5)^(-0.5/1.5)", 2, 1}, {"expr:exp(-r^0.3)", 3, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        nl_check c = run(cases[i].spec, cases[i].dim);
        cr_expect_eq(c.positive_definite, cases[i].valid, "%s in %dD: expected %s (min spectrum %g at k %g)",
                     cases[i].spec, cases[i].dim, cases[i].valid ? "valid" : "not", c.min_spectrum,
                     c.min_spectrum_k);
    }
}

/* A negative power-law tail r^-b with b <= d: the integral of R diverges
 * to -infinity (b = 2 in 2D, logarithmically), so no field has it; in 1D
 * the same R has S = 2/(1+w^2) - 0.05 pi e^-|w| > 0. */
Test(check_tails, negative_power_tail)
{
    nl_check c = run("expr:exp(-r)-0.05/(1+r^2)", 2);
    cr_expect_not(c.positive_definite);
    cr_expect_eq(c.why, NL_CHECK_NEG_INTEGRAL, "why %d", c.why);
    c = run("expr:exp(-r)-0.05/(1+r^2)", 1);
    cr_expect(c.positive_definite, "1D: min spectrum %g", c.min_spectrum);
}

/* cos(r) (Schoenberg's Omega_1): positive definite in 1D (two spectral
 * lines), below min J0 = -0.403 in 2D and min sin(x)/x = -0.217 in 3D;
 * sin(r)/r = Omega_3 is valid up to 3D.  Both are smooth at 0. */
Test(check_tails, non_decaying)
{
    nl_check c = run("expr:cos(r)", 1);
    cr_expect(c.positive_definite, "cos 1D: why %d, min spectrum %g", c.why, c.min_spectrum);
    cr_expect_eq(c.differentiable_order, -1, "cos: order %d", c.differentiable_order);
    cr_expect(fabs(c.r2 + 1) < 1e-6, "cos: R''(0) = %g, expected -1", c.r2);
    for (int dim = 2; dim <= 3; dim++) {
        c = run("expr:cos(r)", dim);
        cr_expect_not(c.positive_definite, "cos in %dD", dim);
        cr_expect_not(c.isotropic_bound_ok, "cos in %dD: min R %g", dim, c.min_r);
    }
    for (int dim = 1; dim <= 3; dim++) {
        c = run("expr:sin(r)/(r+step(-r))+step(-r)", dim);
        cr_expect(c.positive_definite, "sinc in %dD: why %d", dim, c.why);
    }
    c = run("expr:(1+r^2)^-1", 1);
    cr_expect_eq(c.differentiable_order, -1, "(1+r^2)^-1: order %d", c.differentiable_order);
    cr_expect(fabs(c.r2 + 2) < 1e-6, "(1+r^2)^-1: R''(0) = %g, expected -2", c.r2);
}

/* The isotropic bound is the minimum of Schoenberg's Omega_d: J0 at its
 * first minimum j_{1,1} = 3.8317 (J0' = -J1) in 2D, sin(x)/x at the root
 * of tan x = x, 4.4934, in 3D; the constants are those values rounded
 * down (the bound must not exclude Omega_d itself). */
Test(check_tails, isotropic_bound_is_min_omega)
{
    double j11 = gsl_sf_bessel_zero_J1(1), x = 4.493409457909064, j0 = gsl_sf_bessel_J0(j11);
    cr_expect(nl_check_isotropic_bound(2) <= j0 && nl_check_isotropic_bound(2) > j0 - 1e-15, "%.17g vs J0 %.17g",
              nl_check_isotropic_bound(2), j0);
    cr_expect(nl_check_isotropic_bound(3) <= sin(x) / x && nl_check_isotropic_bound(3) > sin(x) / x - 1e-15,
              "%.17g vs %.17g", nl_check_isotropic_bound(3), sin(x) / x);
    cr_expect_eq(nl_check_isotropic_bound(1), -1);
}

/* Compact support near the boundary: (1-r)_+^nu is valid in d iff nu >=
 * (d+1)/2 (Askey 1973, Zastavnyi 2000); Wendland's psi_{mu,1} =
 * (1-r)_+^(mu+1) (1 + (mu+1) r) iff mu >= (d+3)/2 (Zastavnyi 2006).  Their
 * negative lobes below the bound lie beyond any sampled spectrum (1e-12 of
 * the peak at k ~ 240 for nu = 1.9 in 3D): the edge asymptotics decide. */
Test(check_tails, compact_support_boundary)
{
    nl_check c = run("expr:step(1-r)*abs(1-r)^1.9", 3);
    cr_expect_not(c.positive_definite);
    cr_expect_eq(c.why, NL_CHECK_EDGE, "why %d", c.why);
    cr_expect(run("expr:step(1-r)*abs(1-r)^2.1", 3).positive_definite);
    cr_expect_not(run("expr:step(1-r)*abs(1-r)^2.9*(1+2.9*r)", 1).positive_definite);
    cr_expect(run("expr:step(1-r)*abs(1-r)^3.1*(1+3.1*r)", 1).positive_definite);
    /* spherical in 3D: the edge's s^2 and the origin's r balance (no verdict) */
    cr_expect(run("expr:step(1-r)*(1-1.5*r+0.5*r^3)", 3).positive_definite);
}

/* A message longer than the buffer keeps its start and its reason. */
Test(check_tails, long_expression_keeps_its_reason)
{
    size_t n = 6000;
    char *spec = malloc(n + 64);
    nl_model *m;
    nl_check c;
    strcpy(spec, "expr:exp(-r)");
    while (strlen(spec) < n)
        strcat(spec, "+0*r");
    strcat(spec, "-2*exp(-r)");
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", nl_errmsg());
    cr_expect_eq(nl_check_model(m, 1, &c), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "expected a positive variance"), "%s", nl_errmsg());
    cr_expect(strncmp(nl_errmsg(), "expr:exp(-r)+0*r", 16) == 0, "%.40s", nl_errmsg());
    cr_expect(strstr(nl_errmsg(), "bytes left out"), "%.2000s", nl_errmsg());
    cr_expect_lt(strlen(nl_errmsg()), (size_t)NL_ERRMSG_MAX);
    nl_model_free(m);
    free(spec);
}

static char out[8192], err[8192];

/* Subdivision refuses what check finds not positive definite: Bohman's
 * model, the self-convolution of a cosine bump, is valid in 1D only (its
 * 2D spectrum dips below 0 near 1.6 cycles per unit of its range); the
 * levels' local matrices and the coarse level never saw it.  --clamp
 * synthesises anyway; the FFT method refuses it too. */
Test(check_tails, subdiv_refuses_what_check_refuses)
{
    const char *boh = "'expr:step(1-r/8)*((1-r/8)*cos(3.141592653589793*r/8)+sin(3.141592653589793*r/8)/"
                      "3.141592653589793)'";
    char args[1024];
    const char *d = scratch_dir();
    nl_check c = run("expr:step(1-r/8)*((1-r/8)*cos(3.141592653589793*r/8)+sin(3.141592653589793*r/8)/"
                     "3.141592653589793)", 2);
    cr_expect_not(c.positive_definite);
    snprintf(args, sizeof args, "synth subdiv --acf %s --size 64x64 --seed 1 -o %s/bohman.exr", boh, d);
    cr_expect_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 2, "%s", err);
    cr_expect(strstr(err, "not positive definite in 2D"), "%s", err);
    snprintf(args, sizeof args, "synth subdiv --acf %s --size 64x64 --seed 1 --nonperiodic -o %s/bohman.exr", boh,
             d);
    cr_expect_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 2, "%s", err);
    snprintf(args, sizeof args, "synth subdiv --acf %s --size 64x64 --seed 1 --clamp -o %s/bohman.exr", boh, d);
    cr_expect_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 0, "%s", err);
    snprintf(args, sizeof args, "synth subdiv --acf %s --size 256 --seed 1 -o %s/bohman.tsv", boh, d);
    cr_expect_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 0, "1D: %s", err);
    snprintf(args, sizeof args, "synth subdiv --acf oscillatory:omega=1.05 --size 64x64 --seed 1 -o %s/osc.exr", d);
    cr_expect_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 2, "%s", err);
    snprintf(args, sizeof args, "synth subdiv --acf oscillatory:omega=0.95 --size 64x64 --seed 1 -o %s/osc.exr", d);
    cr_expect_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 0, "%s", err);
}
