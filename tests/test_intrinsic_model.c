/* The intrinsic family powvar (core/families/powvar.c): parsing and its
 * peers' names, the generalized spectrum against the variogram it must
 * give, and check's verdict (analysis/check_intrinsic.h). */
#include "../analysis/check.h"
#include "../analysis/check_intrinsic.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "gstat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_sf_bessel.h>
#include <math.h>
#include <string.h>

/* The peers' names with their keys against the peers' own variograms:
 * gstat's variogramLine(vgm(psill, "Pow", range, nugget)) and
 * RandomFields' RFvariogram(RMfbm(alpha, var, scale)), printed by R with
 * 17 digits; agreement to 1e-10 relative (one pow each side). */
Test(intrinsic_model_slow, peers_names_against_gstat_and_randomfields)
{
    const double h[5] = {0.37, 1, 2.2, 7.9, 21};
    const char *specs[] = {"powvar:alpha=1.385,c=2.5,nugget=0.3", "Pow:psill=2.5,range=1.385,nugget=0.3",
                           "RMfbm:alpha=0.7,var=2,scale=3"};
    double want[3][5], v[10];
    for (int i = 0; i < 5; i++)
        want[0][i] = want[1][i] = 0.3 + 2.5 * pow(h[i], 1.385), want[2][i] = 2 * pow(h[i] / 3, 0.7);
    if (gstat_available("Pow against gstat's variogramLine")) {
        cr_assert_eq(gstat_run("suppressMessages(library(gstat))\n"
                               "v <- variogramLine(vgm(2.5, 'Pow', 1.385, 0.3), dist_vector = c(0.37, 1, 2.2, 7.9, 21))\n"
                               "cat(sprintf('%.17g', v$gamma), '\\n')\n"
                               "if (requireNamespace('RandomFields', quietly = TRUE)) {\n"
                               "  suppressMessages(library(RandomFields))\n"
                               "  cat(sprintf('%.17g', RFvariogram(RMfbm(alpha = 0.7, var = 2, scale = 3), "
                               "x = c(0.37, 1, 2.2, 7.9, 21))), '\\n')\n}\n",
                               v, 10),
                     10, "R's output (gstat and RandomFields)");
        for (int i = 0; i < 5; i++) {
            cr_expect_float_eq(v[i], want[1][i], 1e-10 * want[1][i], "gstat at %g: %.17g", h[i], v[i]);
            cr_expect_float_eq(v[5 + i], want[2][i], 1e-10 * want[2][i], "RandomFields at %g: %.17g", h[i], v[5 + i]);
        }
    }
    for (int k = 0; k < 3; k++) {
        nl_model *m = test_model(specs[k]);
        cr_expect(nl_model_is_intrinsic(m), "%s", specs[k]);
        for (int i = 0; i < 5; i++) {
            double lag[2] = {h[i] * 0.6, -h[i] * 0.8};
            cr_expect_float_eq(nl_model_variogram(m, 2, lag), want[k][i], 1e-12 * want[k][i], "%s at %g", specs[k],
                               h[i]);
        }
        nl_model_free(m);
    }
}

Test(intrinsic_model, range_refused)
{
    nl_model *m = NULL;
    cr_expect_eq(nl_model_parse("powvar:alpha=2.01", &m), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "conditionally negative definite only for 0 < alpha <= 2"), "%s", nl_errmsg());
    cr_expect_eq(nl_model_parse("Pow:psill=1,range=2.5", &m), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "range is the exponent"), "%s", nl_errmsg());
    cr_expect_eq(nl_model_parse("powvar:alpha=1,sep", &m), NL_EINVAL);
    cr_expect_eq(nl_model_parse("powvar", &m), NL_EINVAL);
}

/* gamma(h) = int (1 - cos 2 pi f.h) S(f) df, radially: the kernel is
 * 1 - cos (1D), 1 - J0 (2D), 1 - sinc (3D) of 2 pi k h, the shell
 * 2, 2 pi k, 4 pi k^2.  Midpoint rule in u = log k over k in
 * [e^-30, e^12] (the integrand ~ k^(2 - alpha) at 0, its shell-weighted
 * S ~ k^-(1 + alpha) above), plus the tail above K taken with the kernel's
 * mean 1: S(K) shell(K) K / alpha, whose neglected oscillating part is
 * below 1e-6 of gamma here, and the part below e^-30 with the kernel's
 * leading term (2 pi k h)^2 / (2 d) (5% of gamma at alpha = 1.9).  Agreement to 2e-4 relative: the step 1e-3
 * in u on an oscillating kernel near k ~ 1/h leaves ~1e-5. */
static double gamma_from_spectrum(const nl_model *m, int dim, double alpha, double h)
{
    double lo = -30, hi = 12, du = 1e-3, sum = 0, f[3] = {0, 0, 0};
    for (double u = lo + du / 2; u < hi; u += du) {
        double k = exp(u), x = 2 * M_PI * k * h, kern, shell;
        f[0] = k;
        /* without cancellation at small x: 1 - cos x = 2 sin^2(x/2), the series of the others */
        if (dim == 1)
            kern = 2 * sin(x / 2) * sin(x / 2);
        else if (x < 1e-3)
            kern = dim == 2 ? x * x / 4 * (1 - x * x / 16) : x * x / 6 * (1 - x * x / 20);
        else
            kern = dim == 2 ? 1 - gsl_sf_bessel_J0(x) : 1 - sin(x) / x;
        shell = dim == 1 ? 2 : dim == 2 ? 2 * M_PI * k : 4 * M_PI * k * k;
        sum += kern * nl_model_spectrum(m, dim, f) * shell * k * du;
    }
    double K = exp(hi), k0 = exp(lo), x0 = 2 * M_PI * h;
    f[0] = K;
    double shellK = dim == 1 ? 2 : dim == 2 ? 2 * M_PI * K : 4 * M_PI * K * K, upper;
    upper = nl_model_spectrum(m, dim, f) * shellK * K / alpha;
    f[0] = k0;
    double shell0 = dim == 1 ? 2 : dim == 2 ? 2 * M_PI * k0 : 4 * M_PI * k0 * k0;
    /* below k0 the kernel is (2 pi k h)^2 / (2 d) to O(k^4) */
    double lower = x0 * x0 / (2 * dim) * nl_model_spectrum(m, dim, f) * shell0 * k0 * k0 * k0 / (2 - alpha);
    return sum + upper + lower;
}

Test(intrinsic_model, generalized_spectrum_gives_the_variogram)
{
    const double alphas[] = {0.7, 1.3, 1.9}, h = 2.385;
    for (int i = 0; i < 3; i++)
        for (int dim = 1; dim <= 3; dim++) {
            char spec[64];
            snprintf(spec, sizeof spec, "powvar:alpha=%g,c=1.7", alphas[i]);
            nl_model *m = test_model(spec);
            double g = gamma_from_spectrum(m, dim, alphas[i], h), want = 1.7 * pow(h, alphas[i]);
            cr_expect_float_eq(g, want, 2e-4 * want, "%s in %dD: %.10g, expected %.10g", spec, dim, g, want);
            nl_model_free(m);
        }
}

Test(intrinsic_model, check_states_validity)
{
    nl_model *m = test_model("powvar:alpha=1.5,c=0.01");
    nl_check_intrinsic k;
    nl_check c;
    for (int dim = 1; dim <= 3; dim++) {
        cr_assert_eq(nl_check_intrinsic_model(m, dim, &k), NL_OK, "%s", nl_errmsg());
        cr_expect(k.valid && k.min_spectrum > 0, "%dD", dim);
        cr_expect_float_eq(k.fractal_dimension, dim + 1 - 0.75, 1e-15);
    }
    cr_expect_eq(nl_check_model(m, 2, &c), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "intrinsic (no covariance)"), "%s", nl_errmsg());
    nl_model_free(m);
    m = test_model("markov:scale=2");
    cr_expect_eq(nl_check_intrinsic_model(m, 2, &k), NL_EINVAL);
    nl_model_free(m);
}
