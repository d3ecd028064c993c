/* The families of the literature and of GSTools (askey, wendland, bohman,
 * dampedcos, jbessel, sinc, dagum, cauchy, rational, hyperspherical,
 * superspherical, tplstable, tplgaussian, tplexponential, lgd): R against
 * RandomFields' RFcov where it has the model and against quadratures
 * written here where it has not, closed-form spectra against the
 * numerical Hankel transform (nl_model_spectrum_iso), and the dimensions
 * each family is refused in. */
#include "../analysis/fit.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>
#include <gsl/gsl_sf_hyperg.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* 20 lags in units of the scale: the origin, the inner range, both sides
 * of a compact support's end at 1, and a tail out to 12 scales. */
static const double lags[] = {0,   0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9,
                              0.99, 1.0, 1.1,  1.3, 1.7, 2.2, 3,    4.5, 7,   12};
#define NLAGS (sizeof lags / sizeof *lags)

static double acf1(const nl_model *m, double r)
{
    double lag[1] = {r};
    return nl_model_acf(m, 1, lag);
}

/* |a - b| within tol of |b|, or of var 1e-12 where b is (nearly) 0: the
 * hole effects cross zero, where a relative test has no meaning; 1e-12 of
 * R(0) is some thousand ulps of the largest value either side computes. */
static int close_to(double a, double b, double tol, double var)
{
    return fabs(a - b) <= tol * fmax(fabs(b), 1e-12 * var / tol);
}

/* Our spec, its scale, and RandomFields' model of the same R (var and
 * scale with the same meaning: R(r) = var C(r / scale)). */
typedef struct {
    const char *spec;
    double scale, var;
    const char *rf;
} rf_case;

static const rf_case rf_cases[] = {
    {"askey:nu=2.5,scale=1.7,var=2", 1.7, 2, "RMaskey(alpha=2.5, scale=1.7, var=2)"},
    {"tplsimple:nu=1,scale=3", 3, 1, "RMaskey(alpha=1, scale=3)"},
    {"wendland:k=0,mu=1.5,scale=2", 2, 1, "RMgengneiting(kappa=0, mu=1.0, scale=2)"},
    {"wendland:k=1,mu=2.7,scale=2,var=3", 2, 3, "RMgengneiting(kappa=1, mu=1.2, scale=2, var=3)"},
    {"wendland:k=2,mu=3.5,scale=0.8", 0.8, 1, "RMgengneiting(kappa=2, mu=1.0, scale=0.8)"},
    {"wendland:k=3,mu=4.8,scale=1.3", 1.3, 1, "RMgengneiting(kappa=3, mu=1.3, scale=1.3)"},
    {"dampedcos:lambda=1.2,scale=0.8", 0.8, 1, "RMdampedcos(lambda=1.2, scale=0.8)"},
    {"dampedcos:lambda=0,scale=2,var=0.5", 2, 0.5, "RMdampedcos(lambda=0, scale=2, var=0.5)"},
    {"jbessel:nu=1.3,scale=2", 2, 1, "RMbessel(nu=1.3, scale=2)"},
    {"jbessel:nu=-0.3,scale=0.7", 0.7, 1, "RMbessel(nu=-0.3, scale=0.7)"},
    {"jbessel:nu=0,scale=1.5", 1.5, 1, "RMbessel(nu=0, scale=1.5)"},
    {"jbessel:nu=12.5,scale=0.2", 0.2, 1, "RMbessel(nu=12.5, scale=0.2)"},
    {"sinc:scale=1.5,var=4", 1.5, 4, "RMwave(scale=1.5, var=4)"},
    {"dagum:beta=0.6,gamma=0.8,scale=2", 2, 1, "RMdagum(beta=0.6, gamma=0.8, scale=2)"},
    {"dagum:beta=1,gamma=0.3", 1, 1, "RMdagum(beta=1, gamma=0.3)"},
    {"cauchy:gamma=0.7,scale=3", 3, 1, "RMcauchy(gamma=0.7, scale=3)"},
    {"cauchy:gamma=4,scale=0.5,var=2", 0.5, 2, "RMcauchy(gamma=4, scale=0.5, var=2)"},
    {"rational:alpha=2.5,scale=1.3", 1.3, 1, "RMcauchy(gamma=2.5, scale=1.3*sqrt(2.5))"},
    {"lgd:alpha=0.7,beta=1.5,scale=2", 2, 1, "RMlgd(alpha=0.7, beta=1.5, scale=2)"},
    {"lgd:alpha=1,beta=0.4", 1, 1, "RMlgd(alpha=1, beta=0.4)"},
    {"hyperspherical:dim=3,scale=4", 4, 1, "RMspheric(scale=4)"},
    {"hyperspherical:dim=2,scale=4", 4, 1, "RMcircular(scale=4)"},
    {"hyperspherical:dim=1,scale=4", 4, 1, "RMaskey(alpha=1, scale=4)"},
    {"superspherical:kappa=1,scale=2.5", 2.5, 1, "RMspheric(scale=2.5)"},
    {"superspherical:kappa=0.5,scale=2.5", 2.5, 1, "RMcircular(scale=2.5)"},
    /* RandomFields' names with their own keys */
    {"RMaskey:alpha=1.7,var=2,scale=1.5", 1.5, 2, "RMaskey(alpha=1.7, var=2, scale=1.5)"},
    {"RMgengneiting:kappa=2,mu=1.5,var=1.7,scale=3", 3, 1.7, "RMgengneiting(kappa=2, mu=1.5, var=1.7, scale=3)"},
    {"RMgengneiting:kappa=3,mu=0.5,scale=3", 3, 1, "RMgengneiting(kappa=3, mu=0.5, scale=3)"},
    {"RMdampedcos:lambda=2,var=1.7,scale=3", 3, 1.7, "RMdampedcos(lambda=2, var=1.7, scale=3)"},
    {"RMbessel:nu=0.8,var=1.7,scale=3", 3, 1.7, "RMbessel(nu=0.8, var=1.7, scale=3)"},
    {"RMwave:var=1.7,scale=3", 3, 1.7, "RMwave(var=1.7, scale=3)"},
    {"RMdagum:beta=0.9,gamma=0.2,var=1.7,scale=3", 3, 1.7, "RMdagum(beta=0.9, gamma=0.2, var=1.7, scale=3)"},
    {"RMcauchy:gamma=1.5,var=1.7,scale=3", 3, 1.7, "RMcauchy(gamma=1.5, var=1.7, scale=3)"},
    {"RMlgd:alpha=0.3,beta=2.5,var=1.7,scale=3", 3, 1.7, "RMlgd(alpha=0.3, beta=2.5, var=1.7, scale=3)"},
};
#define NRF (sizeof rf_cases / sizeof *rf_cases)

static int randomfields_available(void)
{
    if (system("Rscript -e 'suppressMessages(library(RandomFields))' >/dev/null 2>&1") == 0)
        return 1;
    fprintf(stderr, "skip: R against RFcov: Rscript with RandomFields is not installed\n");
    return 0;
}

/* RandomFields computes R in double precision with R's own Bessel, beta
 * and power functions: both sides agree to rounding, far inside 1e-10. */
Test(families_lit_slow, r_matches_randomfields)
{
    static char script[16384];
    static double v[NRF * NLAGS + 1];
    size_t len;
    if (!randomfields_available())
        return;
    len = (size_t)snprintf(script, sizeof script,
                           "suppressMessages(library(RandomFields))\nRFoptions(spConform=FALSE)\n");
    for (size_t c = 0; c < NRF; c++) {
        len += (size_t)snprintf(script + len, sizeof script - len, "x <- %.17g * c(", rf_cases[c].scale);
        for (size_t i = 0; i < NLAGS; i++)
            len += (size_t)snprintf(script + len, sizeof script - len, "%s%.17g", i ? "," : "", lags[i]);
        len += (size_t)snprintf(script + len, sizeof script - len,
                                ")\ncat(sprintf('%%.17g', RFcov(%s, x=x)), '\\n')\n", rf_cases[c].rf);
    }
    cr_assert_lt(len, sizeof script);
    cr_assert_eq(gstat_run(script, v, NRF * NLAGS + 1), (long)(NRF * NLAGS), "RandomFields failed");
    for (size_t c = 0; c < NRF; c++) {
        nl_model *m = test_model(rf_cases[c].spec);
        for (size_t i = 0; i < NLAGS; i++) {
            double r = lags[i] * rf_cases[c].scale, ours = acf1(m, r), ref = v[c * NLAGS + i];
            cr_expect(close_to(ours, ref, 1e-10, rf_cases[c].var), "%s at %g: %.17g, RFcov %.17g", rf_cases[c].spec,
                      r, ours, ref);
        }
        nl_model_free(m);
    }
}

/* gstat's Wav and Hol (sinc's peer names) against variogramLine(covariance
 * = TRUE), which prints 17 digits of psill - gamma(h). */
Test(families_lit_slow, gstat_wave_and_hole)
{
    static const char *spec[] = {"Wav:psill=1.7,range=3", "Hol:psill=1.7,range=3", "Wav:psill=0.4,range=0.5"};
    static double v[3 * NLAGS + 1];
    char script[4096];
    size_t len;
    if (!gstat_available("Wav and Hol against variogramLine"))
        return;
    len = (size_t)snprintf(script, sizeof script, "suppressMessages(library(gstat))\nh <- 3 * c(");
    for (size_t i = 0; i < NLAGS; i++)
        len += (size_t)snprintf(script + len, sizeof script - len, "%s%.17g", i ? "," : "", lags[i]);
    snprintf(script + len, sizeof script - len,
             ")\nfor (m in list(vgm(1.7, 'Wav', 3), vgm(1.7, 'Hol', 3), vgm(0.4, 'Wav', 0.5)))\n"
             "  cat(sprintf('%%.17g', variogramLine(m, dist_vector = h, covariance = TRUE)$gamma), '\\n')\n");
    cr_assert_eq(gstat_run(script, v, 3 * NLAGS + 1), (long)(3 * NLAGS), "gstat failed");
    for (size_t c = 0; c < 3; c++) {
        nl_model *m = test_model(spec[c]);
        double var = acf1(m, 0);
        for (size_t i = 0; i < NLAGS; i++) {
            double r = 3 * lags[i], ours = acf1(m, r), ref = v[c * NLAGS + i];
            cr_expect(close_to(ours, ref, 1e-10, var), "%s at %g: %.17g, gstat %.17g", spec[c], r, ours, ref);
        }
        nl_model_free(m);
    }
}

/* ---- R by quadrature where RandomFields has no model ---- */

typedef struct {
    double h, alpha, a, k;
} quad_arg;

static double integrate(double (*f)(double, void *), quad_arg *arg, double lo, double hi)
{
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(2000);
    gsl_function F = {f, arg};
    double val, err;
    gsl_integration_qags(&F, lo, hi, 1e-15, 1e-13, 2000, w, &val, &err);
    gsl_integration_workspace_free(w);
    return val;
}

/* The mode mixture itself: l^(2h-1) exp(-(r/l)^alpha) (Hesse et al. 2014). */
static double tpl_integrand(double l, void *p)
{
    const quad_arg *q = p;
    return pow(l, 2 * q->h - 1) * exp(-pow(q->a / l, q->alpha));
}

static double tpl_reference(double h, double alpha, double lo, double hi, double r)
{
    quad_arg q = {h, alpha, r, 0};
    return integrate(tpl_integrand, &q, lo, hi) / ((pow(hi, 2 * h) - pow(lo, 2 * h)) / (2 * h));
}

/* Quadrature to 1e-13 of integrands without cancellation: agreement to
 * 1e-9 leaves room for GSL's incomplete gamma (about 1e-12 near a = -b). */
Test(families_lit, tpl_matches_its_mode_mixture)
{
    static const struct {
        const char *spec;
        double h, alpha, lo, hi;
    } c[] = {
        {"tplgaussian:hurst=0.5", 0.5, 2, 0, 1},
        {"tplgaussian:hurst=0.2,scale=3,var=2", 0.2, 2, 0, 3},
        {"tplexponential:hurst=0.25,scale=2", 0.25, 1, 0, 2},
        {"tplexponential:hurst=0.5,scale=2", 0.5, 1, 0, 2},
        {"tplstable:hurst=0.4,alpha=1.5,scale=2", 0.4, 1.5, 0, 2},
        {"tplstable:hurst=0.3,alpha=0.7,scale=5,lower=1", 0.3, 0.7, 1, 5},
        {"tplgaussian:hurst=0.7,scale=4,lower=0.5", 0.7, 2, 0.5, 4},
        /* b = 2 hurst / alpha above 1, whole and not */
        {"tplexponential:hurst=1", 1, 1, 0, 1},
        {"tplstable:hurst=0.9,alpha=0.5", 0.9, 0.5, 0, 1},
    };
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        nl_model *m = test_model(c[k].spec);
        double var = acf1(m, 0);
        for (size_t i = 0; i < NLAGS; i++) {
            double r = lags[i] * c[k].hi, ours = acf1(m, r);
            double ref = var * (r == 0 ? 1 : tpl_reference(c[k].h, c[k].alpha, c[k].lo, c[k].hi, r));
            cr_expect(close_to(ours, ref, 1e-9, var), "%s at %g: %.17g, quadrature %.17g", c[k].spec, r, ours, ref);
        }
        nl_model_free(m);
    }
}

/* GSTools' cor(h), h = r / len_scale (rescale 1 for these models), as
 * gstools/covmodel/models.py writes it: JBessel Gamma(nu+1) J_nu(h) /
 * (h/2)^nu, Rational (1 + h^2/alpha)^-alpha, TPLSimple (1-h)_+^nu,
 * Hyper- and SuperSpherical 1 - h 2F1(1/2, -nu; 3/2; h^2) / 2F1(1/2, -nu;
 * 3/2; 1), nu = (dim-1)/2 for HyperSpherical, 2F1 at 1 by Gauss's sum
 * Gamma(3/2) Gamma(1+nu) / Gamma(3/2+nu). */
static double gstools_cor(const char *model, double h, double nu)
{
    if (strcmp(model, "JBessel") == 0)
        return h == 0 ? 1 : exp(lgamma(nu + 1) - nu * log(h / 2)) * gsl_sf_bessel_Jnu(nu, h);
    if (strcmp(model, "Rational") == 0)
        return pow(1 + h * h / nu, -nu);
    if (strcmp(model, "TPLSimple") == 0)
        return pow(fmax(1 - h, 0), nu);
    if (h >= 1)
        return 0;
    if (strcmp(model, "HyperSpherical") == 0)
        nu = (nu - 1) / 2;
    return 1 - h * gsl_sf_hyperg_2F1(0.5, -nu, 1.5, h * h) /
                   exp(lgamma(1.5) + lgamma(1 + nu) - lgamma(1.5 + nu));
}

/* GSTools' names with len_scale (2F1 near h = 1 and J_nu by GSL: 1e-10 of
 * the sill); the TPL models by GSTools' combination of the two cut-offs,
 * len_up = len_low + len_scale, each term the mode mixture above. */
Test(families_lit, gstools_names)
{
    static const struct {
        const char *model;
        double shape;
    } c[] = {{"JBessel", 1.5}, {"JBessel", 0.3}, {"Rational", 0.7}, {"Rational", 12}, {"TPLSimple", 2.5},
             {"HyperSpherical", 3}, {"HyperSpherical", 2}, {"HyperSpherical", 6}, {"SuperSpherical", 1.7},
             {"SuperSpherical", 0.25}};
    static const char *key[] = {"nu", "nu", "alpha", "alpha", "nu", "dim", "dim", "dim", "nu", "nu"};
    double var = 1.7, len = 3;
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        char spec[128];
        snprintf(spec, sizeof spec, "%s:var=%g,len_scale=%g,%s=%g", c[k].model, var, len, key[k], c[k].shape);
        nl_model *m = test_model(spec);
        for (size_t i = 0; i < NLAGS; i++) {
            double r = lags[i] * len, ours = acf1(m, r), ref = var * gstools_cor(c[k].model, lags[i], c[k].shape);
            cr_expect(close_to(ours, ref, 1e-10, var), "%s at %g: %.17g, GSTools' cor %.17g", spec, r, ours, ref);
        }
        nl_model_free(m);
    }
    static const struct {
        const char *spec;
        double h, alpha, len, low;
    } t[] = {
        {"TPLGaussian:var=1.7,len_scale=3", 0.5, 2, 3, 0},
        {"TPLGaussian:var=1.7,len_scale=3,hurst=0.3,len_low=1", 0.3, 2, 3, 1},
        {"TPLExponential:var=1.7,len_scale=3", 0.25, 1, 3, 0},
        {"TPLExponential:var=1.7,len_scale=2,hurst=0.6,len_low=0.5", 0.6, 1, 2, 0.5},
        {"TPLStable:var=1.7,len_scale=3", 0.5, 1.5, 3, 0},
        {"TPLStable:var=1.7,len_scale=3,hurst=0.2,alpha=0.8,len_low=2", 0.2, 0.8, 3, 2},
    };
    for (size_t k = 0; k < sizeof t / sizeof *t; k++) {
        nl_model *m = test_model(t[k].spec);
        double up = t[k].low + t[k].len, wu = pow(up, 2 * t[k].h), wl = pow(t[k].low, 2 * t[k].h);
        for (size_t i = 0; i < NLAGS; i++) {
            double r = lags[i] * up, ours = acf1(m, r), ref;
            if (r == 0)
                ref = 1;
            else if (t[k].low == 0)
                ref = tpl_reference(t[k].h, t[k].alpha, 0, up, r);
            else  /* GSTools: (up^2H cor(r; up) - low^2H cor(r; low)) / (up^2H - low^2H) */
                ref = (wu * tpl_reference(t[k].h, t[k].alpha, 0, up, r) -
                       wl * tpl_reference(t[k].h, t[k].alpha, 0, t[k].low, r)) / (wu - wl);
            cr_expect(close_to(ours, 1.7 * ref, 1e-9, 1.7), "%s at %g: %.17g, GSTools' form %.17g", t[k].spec, r,
                      ours, 1.7 * ref);
        }
        nl_model_free(m);
    }
}

/* Bohman's R as the autocorrelation of cos(pi x) on |x| < 1/2, over its
 * value 1/2 at 0 (Bohman 1960). */
static double bohman_integrand(double x, void *p)
{
    const quad_arg *q = p;
    return cos(M_PI * x) * cos(M_PI * (x - q->a));
}

/* The spherical models as the integral of (1 - u^2)^kappa from a to 1
 * over that from 0 (the cap of the (2 kappa + 1)-ball, Matern 1960). */
static double cap_integrand(double u, void *p)
{
    const quad_arg *q = p;
    return pow(1 - u * u, q->k);
}

static double cap_reference(double kappa, double a)
{
    quad_arg q = {0, 0, 0, kappa};
    return a >= 1 ? 0 : integrate(cap_integrand, &q, a, 1) / integrate(cap_integrand, &q, 0, 1);
}

Test(families_lit, compact_models_match_their_constructions)
{
    nl_model *b = test_model("bohman:scale=2,var=1.5");
    for (size_t i = 0; i < NLAGS; i++) {
        double a = lags[i], ref = 0;
        quad_arg q = {0, 0, a, 0};
        if (a < 1)
            ref = 1.5 * 2 * integrate(bohman_integrand, &q, a - 0.5, 0.5);
        cr_expect(close_to(acf1(b, 2 * a), ref, 1e-10, 1.5), "bohman at %g: %.17g, quadrature %.17g", 2 * a,
                  acf1(b, 2 * a), ref);
    }
    nl_model_free(b);
    static const struct {
        const char *spec;
        double kappa;
    } c[] = {
        {"superspherical:kappa=0.3", 0.3},  {"superspherical:kappa=2.75", 2.75}, {"hyperspherical:dim=5", 2},
        {"superspherical:kappa=0", 0},      {"hyperspherical:dim=8", 3.5},       {"superspherical:kappa=20", 20},
    };
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        nl_model *m = test_model(c[k].spec);
        for (size_t i = 0; i < NLAGS; i++) {
            double ours = acf1(m, lags[i]), ref = cap_reference(c[k].kappa, lags[i]);
            cr_expect(close_to(ours, ref, 1e-10, 1), "%s at %g: %.17g, quadrature %.17g", c[k].spec, lags[i], ours,
                      ref);
        }
        nl_model_free(m);
    }
    /* dim=3 is the spherical family's polynomial to rounding */
    nl_model *h = test_model("hyperspherical:scale=3"), *s = test_model("spherical:scale=3");
    for (double r = 0; r < 4; r += 0.0625)
        cr_expect(close_to(acf1(h, r), acf1(s, r), 1e-12, 1), "at %g: %.17g vs %.17g", r, acf1(h, r), acf1(s, r));
    nl_model_free(h);
    nl_model_free(s);
}

/* Closed forms written here: sinc is jbessel at nu = 1/2, wendland at
 * k = 0 is askey, rational tends to the Gaussian. */
Test(families_lit, special_cases_agree)
{
    nl_model *a = test_model("sinc:scale=0.7"), *b = test_model("jbessel:nu=0.5,scale=0.7");
    nl_model *c = test_model("jbessel:nu=-0.5,scale=0.7");
    for (size_t i = 0; i < NLAGS; i++) {
        double r = lags[i] * 0.7 * 3, x = r / 0.7;
        cr_expect(close_to(acf1(a, r), x == 0 ? 1 : sin(x) / x, 1e-14, 1), "sinc at %g", r);
        cr_expect(close_to(acf1(b, r), acf1(a, r), 1e-12, 1), "jbessel 1/2 at %g: %.17g vs %.17g", r, acf1(b, r),
                  acf1(a, r));
        cr_expect(close_to(acf1(c, r), cos(x), 1e-12, 1), "jbessel -1/2 at %g: %.17g vs cos %.17g", r, acf1(c, r),
                  cos(x));
    }
    /* at 3 pi / 2, where GSL 2.7's J_1/2 is NaN */
    {
        nl_model *j = test_model("jbessel:nu=0.5");
        cr_expect(close_to(acf1(j, 1.5 * M_PI), sin(1.5 * M_PI) / (1.5 * M_PI), 1e-12, 1), "at 3 pi/2: %g",
                  acf1(j, 1.5 * M_PI));
        nl_model_free(j);
    }
    nl_model_free(a);
    nl_model_free(b);
    nl_model_free(c);
    {
        nl_model *h = test_model("hyperspherical:dim=1,scale=2");
        double f[1] = {0.75}, ref = 8 / (9 * M_PI * M_PI);  /* the triangle's s (sin(pi f s) / (pi f s))^2 */
        cr_expect(close_to(nl_model_spectrum(h, 1, f), ref, 1e-12, 1), "dim=1 at pi s f = 3 pi/2: %g, expected %g",
                  nl_model_spectrum(h, 1, f), ref);
        nl_model_free(h);
    }
    /* (1 + r^2/alpha)^-alpha -> exp(-r^2) within r^4 / (2 alpha) */
    a = test_model("rational:alpha=1e6");
    b = test_model("gauss");
    for (double r = 0; r < 3; r += 0.25)
        cr_expect(fabs(acf1(a, r) - acf1(b, r)) <= pow(r, 4) / 2e6 * exp(-r * r) * 1.01 + 1e-15, "at %g", r);
    nl_model_free(a);
    nl_model_free(b);
}

/* ---- spectra ---- */

/* Closed-form spectra against the Hankel transform of R (GSL quadrature
 * to 1e-9 relative, core/model_hankel.c): agreement to 1e-7 of the
 * spectrum's value at 0 leaves a factor 100 for the truncation of R's
 * tail at 1e-12 R(0) and the oscillating integrands. */
Test(families_lit, spectra_match_the_hankel_transform)
{
    static const struct {
        const char *spec;
        int dim;
        double s;
    } c[] = {
        {"bohman:scale=2", 1, 2},
        {"dampedcos:lambda=0.5,scale=1.5", 1, 1.5},
        {"dampedcos:lambda=2,var=2", 3, 1},
        {"dampedcos:lambda=1.8,scale=0.5", 3, 0.5},
        /* jbessel decays like r^-(nu+1/2): nu large enough for the
         * transform to converge (R below 1e-12 R(0) by lag 1e7) */
        {"jbessel:nu=6.5,scale=0.5", 1, 0.5},
        {"jbessel:nu=7,scale=0.5", 2, 0.5},
        {"jbessel:nu=7.5,scale=0.5", 3, 0.5},
        {"cauchy:gamma=2.5,scale=0.5", 1, 0.5},
        {"cauchy:gamma=2.5,scale=0.5", 2, 0.5},
        {"cauchy:gamma=4,scale=2,var=3", 3, 2},
        {"rational:alpha=3,scale=0.7", 2, 0.7},
        {"hyperspherical:dim=1,scale=2", 1, 2},
        {"hyperspherical:dim=2,scale=2", 2, 2},
        {"hyperspherical:dim=3,scale=2", 3, 2},
        {"superspherical:kappa=0.5,scale=3", 2, 3},
    };
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        nl_model *m = test_model(c[k].spec);
        double zero[3] = {0, 0, 0}, s0 = nl_model_spectrum(m, c[k].dim, zero);
        cr_assert(isfinite(s0) && s0 > 0, "%s in %dD: S(0) = %g", c[k].spec, c[k].dim, s0);
        for (int i = 0; i <= 24; i += 2) {
            double f = i * 0.1 / c[k].s, fv[3] = {f, 0, 0};
            double ours = nl_model_spectrum(m, c[k].dim, fv), ref = nl_model_spectrum_iso(m, c[k].dim, f);
            cr_expect(fabs(ours - ref) <= 1e-7 * s0, "%s in %dD at f=%g: %.12g, Hankel %.12g", c[k].spec, c[k].dim, f,
                      ours, ref);
        }
        nl_model_free(m);
    }
}

/* jbessel's and sinc's spectra at small nu (discontinuous or singular at
 * k0 = 1/(2 pi scale), where the Hankel transform of the slowly decaying R
 * does not converge): their integral is var.  The midpoint rule in u,
 * k = k0 (1 - u^2), takes the singularity (1 - k^2/k0^2)^(nu - d/2),
 * nu - d/2 >= -1/2, into the bounded u^(2 nu - d + 1): on 1e5 cells it is
 * off by O(1e-10) for smooth integrands, by 1e-6 at most for u^0 kinks. */
Test(families_lit, band_limited_spectra_integrate_to_var)
{
    static const struct {
        const char *spec;
        int dim;
    } c[] = {{"sinc:scale=0.5,var=2", 1}, {"sinc:scale=0.5,var=2", 2}, {"jbessel:nu=0.8,scale=0.5,var=2", 2},
             {"jbessel:nu=1.2,scale=0.5,var=2", 3}, {"jbessel:nu=0,scale=0.5,var=2", 1}};
    static const double shell[] = {0, 2, 2 * M_PI, 4 * M_PI};
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        nl_model *m = test_model(c[k].spec);
        double k0 = 1 / (2 * M_PI * 0.5), sum = 0, n = 1e5, h = 1 / n;
        for (int i = 0; i < n; i++) {
            double u = (i + 0.5) * h, f = k0 * (1 - u * u), fv[3] = {f, 0, 0};
            sum += shell[c[k].dim] * pow(f, c[k].dim - 1) * nl_model_spectrum(m, c[k].dim, fv) * 2 * k0 * u * h;
        }
        cr_expect(fabs(sum - 2) < 2e-6, "%s in %dD: integral %.12g, expected 2", c[k].spec, c[k].dim, sum);
        {
            double out[3] = {1.01 * k0, 0, 0};
            cr_expect_eq(nl_model_spectrum(m, c[k].dim, out), 0.0, "%s: 0 beyond k0", c[k].spec);
        }
        nl_model_free(m);
    }
    /* nu = (d-2)/2: the sphere itself, no density */
    nl_model *s = test_model("sinc");
    double f[3] = {0.01, 0, 0};
    cr_expect(isnan(nl_model_spectrum(s, 3, f)));
    nl_model_free(s);
}

/* Where the family's closed-form spectrum decides validity, it does so at
 * the bound check_dim enforces: the damped cosine's 3D S(0) changes sign
 * at lambda = sqrt(3); jbessel's 2D spectrum is a density down to nu = 0. */
Test(families_lit, spectra_change_sign_at_the_bounds)
{
    nl_model *lo = test_model("dampedcos:lambda=1.6454482671904334"), *hi = test_model("dampedcos:lambda=1.8186533479473213");
    double f[3] = {0, 0, 0};
    cr_expect_lt(nl_model_spectrum(lo, 3, f), 0, "0.95 sqrt(3): S(0) < 0");
    for (int i = 0; i <= 400; i++) {
        f[0] = i * 0.005;
        cr_expect_geq(nl_model_spectrum(hi, 3, f), 0, "1.05 sqrt(3): S(%g) >= 0", f[0]);
    }
    nl_model_free(lo);
    nl_model_free(hi);
}

/* Bohman's R is not positive definite in 2D or 3D: the Hankel transform
 * of R is negative at f scale = 1.5 (2D) and 1.75 (3D) by 1.9e-3 and
 * 2.3e-3 of its value at 0, ten thousand times its quadrature error. */
Test(families_lit, bohman_is_not_positive_definite_in_2d_and_3d)
{
    nl_model *m = test_model("bohman:scale=2");
    double s2 = nl_model_spectrum_iso(m, 2, 0.75), s3 = nl_model_spectrum_iso(m, 3, 0.875);
    cr_expect_lt(s2, -1e-3 * nl_model_spectrum_iso(m, 2, 0), "2D: %g", s2);
    cr_expect_lt(s3, -1e-3 * nl_model_spectrum_iso(m, 3, 0), "3D: %g", s3);
    cr_expect_eq(nl_model_check_dim(m, 1), NL_OK);
    cr_expect_eq(nl_model_check_dim(m, 2), NL_ENOTPD);
    cr_expect_eq(nl_model_check_dim(m, 3), NL_ENOTPD);
    nl_model_free(m);
}

/* ---- validity by dimension ---- */

/* Each family's dimension rule, both sides of each bound (Askey and
 * Wendland at their bound +- 0.1, the damped cosine +- 5%). */
Test(families_lit, check_dim_follows_the_literature)
{
    static const struct {
        const char *spec;
        int ok[3];
    } c[] = {
        {"askey:nu=1", {1, 0, 0}},
        {"askey:nu=0.9", {0, 0, 0}},
        {"askey:nu=1.4", {1, 0, 0}},
        {"askey:nu=1.6", {1, 1, 0}},
        {"askey:nu=1.9", {1, 1, 0}},
        {"askey:nu=2", {1, 1, 1}},
        {"tplsimple:nu=2.1", {1, 1, 1}},
        {"wendland:k=1,mu=1.9", {0, 0, 0}},
        {"wendland:k=1,mu=2.1", {1, 0, 0}},
        {"wendland:k=1,mu=2.6", {1, 1, 0}},
        {"wendland:k=2,mu=3.9", {1, 1, 0}},
        {"wendland:k=2,mu=4.1", {1, 1, 1}},
        {"wendland:k=3,mu=4.1", {1, 0, 0}},
        {"wendland:k=0,mu=1.5", {1, 1, 0}},
        {"bohman", {1, 0, 0}},
        {"dampedcos:lambda=0", {1, 0, 0}},
        {"dampedcos:lambda=0.95", {1, 0, 0}},
        {"dampedcos:lambda=0.9999999", {1, 0, 0}},
        {"dampedcos:lambda=1", {1, 1, 0}},
        {"dampedcos:lambda=1.7320508", {1, 1, 0}},
        {"dampedcos:lambda=1.05", {1, 1, 0}},
        {"dampedcos:lambda=1.6454482671904334", {1, 1, 0}},
        {"dampedcos:lambda=1.7320508075688772", {1, 1, 1}},
        {"dampedcos:lambda=1.8186533479473213", {1, 1, 1}},
        {"jbessel:nu=-0.5", {1, 0, 0}},
        {"jbessel:nu=-0.1", {1, 0, 0}},
        {"jbessel:nu=0", {1, 1, 0}},
        {"jbessel:nu=0.4", {1, 1, 0}},
        {"jbessel:nu=0.5", {1, 1, 1}},
        {"sinc", {1, 1, 1}},
        {"dagum:beta=1,gamma=1", {1, 1, 1}},
        {"cauchy:gamma=0.01", {1, 1, 1}},
        {"rational:alpha=0.2", {1, 1, 1}},
        {"lgd:alpha=1,beta=2", {1, 0, 0}},
        {"lgd:alpha=0.6,beta=2", {1, 0, 0}},
        {"lgd:alpha=0.5,beta=2", {1, 1, 0}},
        {"hyperspherical:dim=1", {1, 0, 0}},
        {"hyperspherical:dim=2", {1, 1, 0}},
        {"hyperspherical", {1, 1, 1}},
        {"superspherical:kappa=0", {1, 0, 0}},
        {"superspherical:kappa=0.45", {1, 0, 0}},
        {"superspherical:kappa=0.5", {1, 1, 0}},
        {"superspherical:kappa=1", {1, 1, 1}},
        {"tplgaussian:hurst=0.3", {1, 1, 1}},
        {"tplexponential:hurst=0.3", {1, 1, 1}},
        {"tplstable:hurst=0.3,alpha=2", {1, 1, 1}},
    };
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        nl_model *m = test_model(c[k].spec);
        for (int d = 1; d <= 3; d++) {
            int st = nl_model_check_dim(m, d);
            cr_expect_eq(st == NL_OK, c[k].ok[d - 1], "%s in %dD: %s", c[k].spec, d, st ? nl_errmsg() : "ok");
            cr_expect(st == NL_OK || st == NL_ENOTPD, "%s in %dD: status %d", c[k].spec, d, st);
        }
        nl_model_free(m);
    }
}

/* Parameters outside the families' ranges are refused at parsing. */
Test(families_lit, out_of_range_parameters_are_refused)
{
    static const char *bad[] = {"wendland:k=1.5,mu=3",  "wendland:k=4,mu=9",   "wendland:mu=3",
                                "jbessel:nu=-0.6",      "lgd:alpha=1.2,beta=1", "dagum:beta=1.1,gamma=0.5",
                                "dagum:beta=0.5,gamma=1.5", "tplgaussian:hurst=0.5,lower=1",
                                "tplstable:hurst=0.5,alpha=2.5", "hyperspherical:dim=2.5",
                                "hyperspherical:dim=0", "superspherical:kappa=-1", "askey:nu=0",
                                "cauchy:gamma=0", "tplexponential:hurst=0"};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        nl_model *m = NULL;
        cr_expect_eq(nl_model_parse(bad[k], &m), NL_EINVAL, "%s", bad[k]);
        cr_expect_null(m);
    }
}

/* ---- fits ---- */

/* WLS on an exact 1D semivariogram of 30 bins recovers every parameter of
 * each fit family (var, scale and the shapes, all free) to 1e-4: the data
 * have no noise, so only the optimiser's stopping rule (1e-5 relative in
 * the parameters' transforms) separates the fit from the truth. */
Test(families_lit, wls_recovers_the_parameters, .timeout = 120)
{
    static const struct {
        const char *family, *spec;
        double truth[4];  /* var, scale, then the shapes in params[] order */
        int n;
    } c[] = {
        {"askey", "askey:nu=2.385,scale=9.3,var=1.4", {1.4, 9.3, 2.385}, 3},
        {"bohman", "bohman:scale=8.7,var=1.4", {1.4, 8.7}, 2},
        {"dampedcos", "dampedcos:lambda=0.63,scale=2.1,var=1.4", {1.4, 2.1, 0.63}, 3},
        {"jbessel", "jbessel:nu=1.37,scale=1.9,var=1.4", {1.4, 1.9, 1.37}, 3},
        {"sinc", "sinc:scale=1.9,var=1.4", {1.4, 1.9}, 2},
        {"dagum", "dagum:beta=0.73,gamma=0.41,scale=3.2,var=1.4", {1.4, 3.2, 0.73, 0.41}, 4},
        {"cauchy", "cauchy:gamma=1.63,scale=3.2,var=1.4", {1.4, 3.2, 1.63}, 3},
        {"rational", "rational:alpha=2.3,scale=3.2,var=1.4", {1.4, 3.2, 2.3}, 3},
        {"superspherical", "superspherical:kappa=1.71,scale=9.3,var=1.4", {1.4, 9.3, 1.71}, 3},
        {"lgd", "lgd:alpha=0.61,beta=1.7,scale=3.2,var=1.4", {1.4, 3.2, 0.61, 1.7}, 4},
    };
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        double h[30], g[30], n[30], zero = 0;
        nl_fit_options o = {.family = c[i].family};
        nl_fit_result r;
        nl_model *m = test_model(c[i].spec);
        for (int k = 0; k < 30; k++) {
            h[k] = 0.5 * k + 0.2;
            g[k] = nl_model_acf(m, 1, &zero) - nl_model_acf(m, 1, &h[k]);
            n[k] = 100 + 20 * k;
        }
        nl_model_free(m);
        cr_assert_eq(nl_fit_variogram(h, g, n, 30, 1, &o, &r), NL_OK, "%s: %s", c[i].family, nl_errmsg());
        cr_expect(r.converged, "%s", c[i].family);
        cr_assert_eq(r.np, (size_t)c[i].n, "%s", c[i].family);
        for (int k = 0; k < c[i].n; k++)
            cr_expect(fabs(r.param[k].value - c[i].truth[k]) <= 1e-4 * c[i].truth[k], "%s: %s = %.10g, truth %g",
                      c[i].family, r.param[k].name, r.param[k].value, c[i].truth[k]);
        nl_fit_result_free(&r);
    }
}
