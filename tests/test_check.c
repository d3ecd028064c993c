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
