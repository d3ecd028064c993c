/* Lewis 1987, eq. (14) (Matheron): the isotropic 2D correlation swept from
 * a 1D profile, against closed forms.
 *   C1 = cos(t)        -> C2 = J0(r)   ((2/pi) int_0^(pi/2) cos(r sin phi) dphi)
 *   C1 = exp(-t^2)     -> C2 = exp(-r^2/2) I0(r^2/2)
 *   C1 = exp(-|t|)     -> C2 = I0(r) - L0(r)  (L0 the modified Struve function)
 *   C1 = 1 - t^2       -> C2 = 1 - r^2/2      ((2/pi) int_0^1 v^2 / sqrt(1 - v^2) dv = 1/2)
 * Tolerance 1e-10: the quadrature is asked for 1e-12 relative and 1e-13
 * absolute (R(0) = 1), the closed forms are accurate to a few ulps (GSL's
 * Bessel functions; the Struve series below to 1e-15 for r <= 6), so 1e-10
 * leaves two orders of margin without hiding a wrong formula (a factor or
 * a missing Jacobian is off by far more). */
#include "../analysis/check.h"
#include "../analysis/subdiv_exact.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>
#include <stdlib.h>

/* L0(x) = sum_k (x/2)^(2k+1) / Gamma(k + 3/2)^2 */
static double struve_l0(double x)
{
    double s = 0;
    for (int k = 0; k < 60; k++) {
        double g = gsl_sf_gamma(k + 1.5);
        s += pow(x / 2, 2 * k + 1) / (g * g);
    }
    return s;
}

static void against(const char *spec, double rmax, double (*closed)(double))
{
    nl_model *m;
    double r[25], c2[25];
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    for (int i = 0; i < 25; i++)
        r[i] = rmax * i / 24;
    cr_assert_eq(nl_check_matheron_2d(m, 25, r, c2), NL_OK, "%s: %s", spec, nl_errmsg());
    for (int i = 0; i < 25; i++)
        cr_expect(fabs(c2[i] - closed(r[i])) <= 1e-10, "%s r=%g: %.15g vs %.15g", spec, r[i], c2[i], closed(r[i]));
    nl_model_free(m);
}

static double bessel_j0(double r) { return gsl_sf_bessel_J0(r); }
static double gauss2(double r) { return gsl_sf_bessel_I0_scaled(r * r / 2); }
static double markov2(double r) { return gsl_sf_bessel_I0(r) - struve_l0(r); }
static double poly2(double r) { return 1 - r * r / 2; }

Test(lewis87, eq14_closed_forms)
{
    against("expr:cos(t)", 30, bessel_j0);
    against("gauss", 4, gauss2);
    against("markov", 6, markov2);
    against("expr:1-t^2", 3, poly2);
}

/* Scale: sweeping R(t / a) gives C2(r / a). */
static double gauss2_scale2(double r) { return gauss2(r / 2); }

Test(lewis87, eq14_scales)
{
    against("gauss:scale=2", 8, gauss2_scale2);
}

Test(lewis87, eq14_refuses)
{
    nl_model *m;
    double r = -1, c;
    cr_assert_eq(nl_model_parse("markov", &m), 0);
    cr_expect_eq(nl_check_matheron_2d(m, 1, &r, &c), NL_EINVAL);
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("spectrum:exp(-f^2)", &m), 0);
    r = 1;
    cr_expect_eq(nl_check_matheron_2d(m, 1, &r, &c), NL_EINVAL);
    nl_model_free(m);
}

/* The exact covariance averaged over random neighbourhoods
 * (analysis/subdiv_exact.c), on alternatives whose answer is known:
 * (a) two copies of the standard 4x4 block give the standard result;
 * (b) the block and a "predict zero, displace by R(0)" alternative: each
 *     new point is, with probability 1/2, the standard one and otherwise
 *     independent white noise of variance R(0), so its variance is the mean
 *     (V_std + R(0)) / 2 and the lag-0 average over the field is
 *     (lag0_std + R(0)) / 2 (a quarter of the points are kept, their
 *     variance R(0) either way); the mean stencil alone would give
 *     V_std / 4 + ... instead.
 * Both are sums of the same products in another order: 1e-12. */
static void set_alternatives(nl_subdiv_coeffs *c, int white)
{
    for (int j = 0; j < c->level[0].nclass; j++) {
        nl_subdiv_class *cl = &c->level[0].cls[j];
        int w = 2 * c->level[0].N, n = (int)cl->n;
        cl->nalt = 2;
        cl->offx = malloc(2 * n * sizeof *cl->offx), cl->offy = malloc(2 * n * sizeof *cl->offy);
        cl->alt_a = malloc(2 * n * sizeof *cl->alt_a), cl->alt_var = malloc(2 * sizeof *cl->alt_var);
        cr_assert(cl->offx && cl->offy && cl->alt_a && cl->alt_var);
        for (int a = 0; a < 2; a++) {
            for (int i = 0; i < n; i++) {
                cl->offx[a * n + i] = i % w + 1 - c->level[0].N;
                cl->offy[a * n + i] = i / w + 1 - c->level[0].N;
                cl->alt_a[a * n + i] = a && white ? 0 : cl->a[i];
            }
            cl->alt_var[a] = a && white ? c->r0 : cl->variance;
        }
    }
}

Test(lewis87, exact_random_neighbourhoods)
{
    nl_model *m;
    long lags[6] = {0, 0, 1, 0, 2, 1};
    double std[3], same[3], half[3];
    cr_assert_eq(nl_model_parse("markov:scale=3", &m), 0);
    for (int white = -1; white <= 1; white++) {
        nl_subdiv_coeffs *c;
        cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 1, 2.0, 2, 1e-4, 8, &c), NL_OK);
        if (white >= 0)
            set_alternatives(c, white);
        cr_assert_eq(nl_subdiv_exact_acf(c, m, 8, 8, 3, lags, white < 0 ? std : white ? half : same), NL_OK, "%s",
                     nl_errmsg());
        nl_subdiv_coeffs_free(c);
    }
    for (int i = 0; i < 3; i++)
        cr_expect(fabs(same[i] - std[i]) <= 1e-12, "lag %d: %.15g vs %.15g", i, same[i], std[i]);
    cr_expect(fabs(half[0] - (std[0] + 1) / 2) <= 1e-12, "lag 0: %.15g vs %.15g", half[0], (std[0] + 1) / 2);
    cr_expect(half[1] < std[1] - 0.05, "lag (1, 0) loses correlation: %g vs %g", half[1], std[1]);
    nl_model_free(m);
}
