/* Sums and products of structures (core/model.h, "Sums and products"):
 * R against the structures evaluated separately, the split rule's edge
 * cases, parameter names, spectra, refusals. */
#include "../analysis/validate.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "util.h"

#include <jansson.h>

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static nl_model *parse_ok(const char *spec)
{
    nl_model *m = NULL;
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
    return m;
}

static void parse_bad(const char *spec, const char *needle)
{
    nl_model *m = (nl_model *)1;
    cr_assert_eq(nl_model_parse(spec, &m), NL_EINVAL, "%s should be refused", spec);
    cr_assert_null(m);
    cr_assert(strstr(nl_errmsg(), needle), "%s: \"%s\" should name \"%s\"", spec, nl_errmsg(), needle);
}

/* Lags in 1, 2 and 3D, the origin among them (where nuggets count). */
static const double lags[][3] = {{0, 0, 0}, {0.37, 0, 0}, {-1.3, 0.8, 0}, {2.385, -4.1, 0.6}, {0, 0, 1e-9},
                                 {7.5, 3.25, -2}, {0.001, 0.002, 0.003}};
#define NLAGS (sizeof lags / sizeof *lags)

/* R of the composite equals the sum (op '+') or product of the parts'
 * R, each parsed alone, exactly: the composite adds the same doubles in
 * the same order (starting from 0, or multiplies from 1: exact). */
static void same_as_parts(const char *spec, const char *const *parts, const char *ops, size_t n)
{
    nl_model *m = parse_ok(spec), *p[8];
    for (size_t i = 0; i < n; i++)
        p[i] = parse_ok(parts[i]);
    for (int dim = 1; dim <= 3; dim++)
        for (size_t l = 0; l < NLAGS; l++) {
            /* '*' first: a sum of products, left to right */
            double total = 0, prod = nl_model_acf(p[0], dim, lags[l]);
            for (size_t i = 1; i <= n; i++) {
                if (i == n || ops[i - 1] == '+') {
                    total += prod;
                    if (i < n)
                        prod = nl_model_acf(p[i], dim, lags[l]);
                } else
                    prod *= nl_model_acf(p[i], dim, lags[l]);
            }
            double r = nl_model_acf(m, dim, lags[l]);
            cr_expect(r == total || (isnan(r) && isnan(total)), "%s, %dD, lag %zu: %.17g, parts %.17g", spec, dim, l,
                      r, total);
        }
    cr_expect_eq(nl_model_structures(m), n, "%s", spec);
    for (size_t i = 0; i < n; i++) {
        cr_expect_str_eq(nl_model_spec(nl_model_structure(m, i)), parts[i]);
        cr_expect_eq(nl_model_operator(m, i), i + 1 < n ? ops[i] : 0, "%s: operator %zu", spec, i);
    }
    cr_expect_null(nl_model_structure(m, n));
    for (size_t i = 0; i < n; i++)
        nl_model_free(p[i]);
    nl_model_free(m);
}

Test(model_sum, acf_is_the_sum_or_product_of_the_parts)
{
    const char *a[] = {"spherical:var=0.59,scale=8.97,nugget=0.05", "markov:scale=2.385,var=0.3"};
    same_as_parts("spherical:var=0.59,scale=8.97,nugget=0.05 + markov:scale=2.385,var=0.3", a, "+", 2);
    same_as_parts("spherical:var=0.59,scale=8.97,nugget=0.05+markov:scale=2.385,var=0.3", a, "+", 2);
    const char *b[] = {"markov:scale=3", "oscillatory:omega=2,scale=1.5"};
    same_as_parts("markov:scale=3 * oscillatory:omega=2,scale=1.5", b, "*", 2);
    /* '*' before '+', each structure its own anisotropy and nugget */
    const char *c[] = {"gauss:scale=0.5,var=0.1,angle=30,ratio=0.4", "markov:scale=3,zratio=2.5",
                       "oscillatory:omega=2", "spherical:scale=4,sep", "matern:nu=1.5,scale=2",
                       "gauss:scale=0.8,nugget=0.2"};
    same_as_parts("gauss:scale=0.5,var=0.1,angle=30,ratio=0.4 + markov:scale=3,zratio=2.5*oscillatory:omega=2 + "
                  "spherical:scale=4,sep * matern:nu=1.5,scale=2 + gauss:scale=0.8,nugget=0.2", c, "+*+*+", 6);
    /* argument families: the last structure, or ended by ';' */
    const char *d[] = {"markov:scale=2", "expr:0.5*exp(-t^2)+0.25*exp(-abs(t))"};
    same_as_parts("markov:scale=2 + expr:0.5*exp(-t^2)+0.25*exp(-abs(t))", d, "+", 2);
    const char *e[] = {"expr:0.5*exp(-t^2)+0.1;", "markov:scale=2"};
    same_as_parts("expr:0.5*exp(-t^2)+0.1; + markov:scale=2", e, "+", 2);
    const char *f[] = {"expr:0.5*exp(-r^2);ratio=2", "markov:scale=2"};
    same_as_parts("expr:0.5*exp(-r^2);ratio=2 * markov:scale=2", f, "*", 2);
    /* a number's sign is no operator */
    const char *g[] = {"markov:scale=1e+1,var=+2", "gauss:scale=2.5E+0"};
    same_as_parts("markov:scale=1e+1,var=+2+gauss:scale=2.5E+0", g, "+", 2);
}

/* R(0) of a sum is every var and nugget added; nl_model_nugget the
 * nuggets; the parameters by NAME.I. */
Test(model_sum, variance_nugget_and_parameter_names)
{
    nl_model *m = parse_ok("spherical:var=0.59,scale=897,nugget=0.05 + markov:var=0.2,scale=300,nugget=0.01");
    double zero[2] = {0, 0}, v = 0;
    cr_expect_eq(nl_model_acf(m, 2, zero), (0.59 + 0.05) + (0.2 + 0.01));
    cr_expect_float_eq(nl_model_nugget(m), 0.06, 1e-15);
    cr_assert_eq(nl_model_param(m, "var.2", &v), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(v, 0.2);
    cr_assert_eq(nl_model_param(m, "scale.1", &v), NL_OK);
    cr_expect_eq(v, 897);
    cr_assert_eq(nl_model_param(m, "nugget.1", &v), NL_OK);
    cr_expect_eq(v, 0.05);
    cr_assert_eq(nl_model_param(m, "ratio.2", &v), NL_OK);
    cr_expect_eq(v, 1);
    v = 42;
    static const char *const bad[] = {"var", "var.0", "var.3", "var.", ".1", "var.1x", "nu.1", "var.-1"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        cr_expect_eq(nl_model_param(m, bad[i], &v), NL_EINVAL, "%s", bad[i]);
        cr_expect_eq(v, 42, "%s left *value", bad[i]);
    }
    cr_expect(nl_model_is_isotropic(m));
    cr_expect(nl_model_is_reentrant(m));
    cr_expect(nl_model_has_acf(m));
    cr_expect(!nl_model_is_spectral(m));
    cr_expect_eq(nl_model_check_dim(m, 3), NL_OK);
    nl_model_free(m);
    m = parse_ok("markov:scale=2 + expr:exp(-r^2)*x");
    cr_expect(!nl_model_is_isotropic(m), "an expression in x makes the sum anisotropic");
    cr_expect(!nl_model_is_reentrant(m), "an expression makes the sum not reentrant");
    nl_model_free(m);
    m = parse_ok("markov:scale=2 + gauss:ratio=0.5");
    cr_expect(!nl_model_is_isotropic(m));
    nl_model_free(m);
}

/* S of a sum: the sum of the closed forms (the 1D markov and gauss
 * spectra, exactly); NAN where a term has none or for a product. */
Test(model_sum, spectra)
{
    nl_model *m = parse_ok("markov:scale=3,var=0.7 + gauss:scale=1.5"), *a = parse_ok("markov:scale=3,var=0.7"),
             *b = parse_ok("gauss:scale=1.5");
    for (double f = 0; f < 2; f += 0.137)
        cr_expect_eq(nl_model_spectrum(m, 1, &f), nl_model_spectrum(a, 1, &f) + nl_model_spectrum(b, 1, &f));
    nl_model_free(m);
    double f2[2] = {0.1, 0.2}, f1 = 0.1;
    m = parse_ok("markov:scale=3 + spherical:scale=2");
    cr_expect(isnan(nl_model_spectrum(m, 1, &f1)), "spherical has no closed form: the sum has none");
    nl_model_free(m);
    m = parse_ok("markov:scale=3 * gauss:scale=2");
    cr_expect(isnan(nl_model_spectrum(m, 1, &f1)), "a product's spectrum is a convolution: not given");
    cr_expect(isnan(nl_model_spectrum(m, 2, f2)));
    nl_model_free(m);
    nl_model_free(a);
    nl_model_free(b);
}

Test(model_sum, split_refusals)
{
    parse_bad("markov:scale=3 +", "structure 2 of");
    parse_bad("+ markov:scale=3", "structure 1 of");
    parse_bad("markov + + gauss", "structure 2 of");
    parse_bad("markov * + gauss", "is empty");
    parse_bad("markov +  ", "is empty");
    parse_bad("markov:scale=3 * (gauss + markov)", "parentheses");
    parse_bad("(markov + gauss)", "parentheses");
    parse_bad("power:d=2 + markov", "defined by its spectrum");
    parse_bad("markov + spectrum:exp(-f^2)", "defined by its spectrum");
    parse_bad("markov + image:no-such-file.png", "reads a file (image:)");
    parse_bad("markov:nugget=0.1 * gauss", "a nugget inside a product");
    parse_bad("markov * gauss:nugget=0.1 + gauss", "a nugget inside a product");
    /* a structure's own message */
    parse_bad("markov + gauss:scale=-1", "gauss: scale: expected a positive number");
    parse_bad("markov + nosuch:scale=1", "unknown model \"nosuch\"");
    /* an expression takes the rest of the spec: here "exp(-t) * markov" */
    parse_bad("expr:exp(-t) * markov", "markov");
    /* scale=2e+gauss: the sign of an exponent, so one malformed number */
    parse_bad("markov:scale=2e+gauss", "expected a finite number");
}

/* 64 structures parse (a 2300-byte spec); a 65th is refused. */
Test(model_sum, many_structures)
{
    char *spec = malloc(80 * 70);
    size_t len = 0;
    double zero[1] = {0};
    cr_assert(spec);
    for (int i = 0; i < NL_MODEL_MAX_STRUCTURES; i++)
        len += (size_t)sprintf(spec + len, "%smarkov:scale=%d.5,var=0.015625", i ? " + " : "", i + 1);
    nl_model *m = parse_ok(spec);
    cr_expect_eq(nl_model_structures(m), NL_MODEL_MAX_STRUCTURES);
    cr_expect_eq(nl_model_acf(m, 1, zero), 1.0, "64 x 1/64");
    nl_model_free(m);
    sprintf(spec + len, "*gauss");
    parse_bad(spec, "more than 64 structures");
    free(spec);
}

/* The ensemble of fft and circulant fields of Nug + Sph + Exp has the
 * sum's ACF: analysis/validate.h's z test finds no error at its
 * family-wise rate 1e-3 over every tested lag (lag 0 holds the nugget),
 * and the effect size's simultaneous 95% interval reaches 0; subdivision
 * and sparse convolution refuse the nugget.  Fixed seeds 1..48. */
static nl_validate_result vres;

Test(model_sum, ensemble_of_a_nested_model)
{
    nl_model *m = parse_ok("spherical:var=0.59,scale=8,nugget=0.05 + markov:var=0.3,scale=3");
    nl_validate_options o;
    size_t n[2] = {64, 64};
    nl_validate_options_default(&o);
    o.realizations = 48;
    cr_assert_eq(nl_validate_model(m, 2, n, 1, &o, &vres), NL_OK, "%s", nl_errmsg());
    cr_expect_float_eq(vres.target[NL_VALIDATE_X][0], 0.59 + 0.05 + 0.3, 1e-15);
    for (int k = 0; k < nl_validate_method_count(); k++) {
        const nl_validate_method_result *x = &vres.method[k];
        const char *name = nl_validate_method_name(k);
        if (strcmp(name, "fft") == 0 || strcmp(name, "circulant") == 0) {
            cr_expect(x->ran && x->pass, "%s: max |z| %g over %zu lags (threshold %g): %s", name, x->all.zmax,
                      vres.ntests, vres.threshold, x->why);
            cr_expect(x->all.effect.lo == 0, "%s: effect %g [%g, %g]", name, x->all.effect.est, x->all.effect.lo,
                      x->all.effect.hi);
            fprintf(stderr, "nested Nug+Sph+Exp, %s: max |z| %.3g (threshold %.3g, %zu lags, M = 48), effect %.3g "
                    "[%.3g, %.3g], variance ratio %.4f [%.4f, %.4f]\n", name, x->all.zmax, vres.threshold,
                    vres.ntests, x->all.effect.est, x->all.effect.lo, x->all.effect.hi, x->variance.est,
                    x->variance.lo, x->variance.hi);
        } else
            cr_expect(!x->ran && strstr(x->why, "nugget"), "%s: ran=%d why \"%s\"", name, x->ran, x->why);
    }
    nl_model_free(m);
}

/* A nested fit whose second structure is held at a negligible variance
 * (1e-12 of the sill) is the single structure's fit: WLS and ML reach the
 * same optimum.  Tolerance: WLS resolves parameters to about 1e-5 of
 * their scale (tests/test_fit_gstat.c), the ML simplex stops at a size of
 * 1e-5 in log units, so 1e-4 relative for both; the held structure moves
 * R by 1e-12, far below either. */
static double param_of(json_t *j, const char *name)
{
    json_t *v = json_object_get(json_object_get(j, "parameters"), name);
    cr_assert(v, "no parameter %s", name);
    return json_real_value(v);
}

Test(model_sum_slow, negligible_structure_fits_as_one)
{
    static const char *const methods[] = {"wls", "ml"};
    static const char *const one[] = {"var", "scale", "nugget"}, *const two[] = {"var.1", "scale.1", "nugget.1"};
    cr_assert_eq(run_noiselab("synth circulant --acf markov:scale=8,nugget=0.3 --size 128x128 --seed 3 -o f.exr",
                              NULL, 0, NULL, 0), 0);
    cr_assert_eq(run_noiselab("sample f.exr --random 300 --seed 5 --interpolation nearest -o p.tsv", NULL, 0, NULL, 0),
                 0);
    for (int k = 0; k < 2; k++) {
        char cmd[512];
        snprintf(cmd, sizeof cmd, "fit p.tsv --model markov --nugget --method %s --json", methods[k]);
        json_t *a = run_noiselab_json(cmd);
        snprintf(cmd, sizeof cmd, "fit p.tsv --model 'markov + spherical:scale=5' --nugget --fix var.2=1e-12 "
                 "--fix scale.2=5 --method %s --json", methods[k]);
        json_t *b = run_noiselab_json(cmd);
        for (int i = 0; i < 3; i++) {
            double x = param_of(a, one[i]), y = param_of(b, two[i]);
            cr_expect(fabs(x - y) <= 1e-4 * fabs(x), "%s: %s %.10g, nested %s %.10g", methods[k], one[i], x, two[i], y);
        }
        json_decref(a);
        json_decref(b);
    }
}

/* A sum with an intrinsic structure is intrinsic (a variogram: methods that
 * need a covariance refuse it by nl_model_check_stationary, naming powvar);
 * its intrinsic structure is the powvar term when the rest is white noise
 * only; a product refuses one. */
Test(model_sum, intrinsic_terms)
{
    nl_model *m = parse_ok("nugget:var=0.1 + powvar:alpha=1.5,c=0.01");
    double v;
    cr_expect(nl_model_is_intrinsic(m));
    cr_expect_eq(nl_model_intrinsic_structure(m), nl_model_structure(m, 1));
    cr_expect_float_eq(nl_model_nugget(m), 0.1, 1e-15);
    cr_expect_eq(nl_model_param(nl_model_intrinsic_structure(m), "alpha", &v), NL_OK);
    cr_expect_eq(v, 1.5);
    cr_expect_eq(nl_model_check_stationary(m, "synth fft"), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "powvar is intrinsic"), "%s", nl_errmsg());
    nl_model_free(m);
    m = parse_ok("markov:scale=2 + powvar:alpha=1.5");
    cr_expect(nl_model_is_intrinsic(m));
    cr_expect_null(nl_model_intrinsic_structure(m), "a covariance beside it: only kriging takes it");
    nl_model_free(m);
    m = parse_ok("expr:0.1*exp(-abs(t)); + powvar:alpha=1.5");
    cr_expect_null(nl_model_intrinsic_structure(m), "an expression is not white noise");
    nl_model_free(m);
    m = parse_ok("markov:scale=2 + gauss");
    cr_expect(!nl_model_is_intrinsic(m));
    cr_expect_null(nl_model_intrinsic_structure(m));
    cr_expect_eq(nl_model_check_stationary(m, "synth fft"), NL_OK);
    nl_model_free(m);
    parse_bad("markov * powvar:alpha=1.5", "an intrinsic model inside a product");
}
