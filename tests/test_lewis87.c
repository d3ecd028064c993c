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
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>

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
