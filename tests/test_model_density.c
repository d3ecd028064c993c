/* nl_model_spectral_density: closed forms, the Hankel route through the
 * anisotropy, sums, and where it has no answer. */
#include "../core/field.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <criterion/criterion.h>
#include <math.h>

static nl_model *parse_ok(const char *spec)
{
    nl_model *m = NULL;
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
    return m;
}

/* The d-dimensional transform of var exp(-|x|/s), cycles per unit:
 * var 2^d pi^((d-1)/2) Gamma((d+1)/2) s^d / (1 + (2 pi k s)^2)^((d+1)/2). */
static double markov_density(double var, double s, int d, double k)
{
    double q = 2 * M_PI * k * s;
    return var * pow(2, d) * pow(M_PI, (d - 1) / 2.0) * tgamma((d + 1) / 2.0) * pow(s, d) / pow(1 + q * q, (d + 1) / 2.0);
}

/* markov has a closed form in 1D only: 2D and 3D go through the Hankel
 * transform, converged to 1e-9 relative (core/model_hankel.c): 1e-8. */
Test(model_density, markov_every_dimension)
{
    nl_model *m = parse_ok("markov:scale=2.385,var=1.7");
    const double k[] = {0, 0.01, 0.13, 0.9};
    for (int d = 1; d <= 3; d++)
        for (size_t i = 0; i < sizeof k / sizeof *k; i++) {
            double f[3] = {0.6 * k[i], 0.8 * k[i], 0}, want = markov_density(1.7, 2.385, d, k[i]);
            if (d == 1)
                f[0] = -k[i];
            if (d == 3)
                f[0] = 0.48 * k[i], f[1] = 0.64 * k[i], f[2] = 0.6 * k[i]; /* |f| = k */
            double got = nl_model_spectral_density(m, d, f);
            cr_assert(fabs(got - want) <= 1e-8 * want, "%dD k=%g: %.12g, expected %.12g", d, k[i], got, want);
        }
    nl_model_free(m);
}

/* Anisotropic: the ellipsoid's linear map turns the density by the angle,
 * stretches it by the ratios and scales it by ratio zratio (core/model.h),
 * so S(f) = ratio zratio S_iso(|(u, ratio v, zratio w)|); the separable
 * model is the product of stretched 1D Lorentzians over var^(dim-1). */
Test(model_density, anisotropic_and_separable)
{
    nl_model *m = parse_ok("markov:scale=3,angle=30,ratio=0.5,zratio=0.25");
    nl_model *s = parse_ok("markov:scale=3,sep,ratio=0.5,var=2");
    double a = M_PI / 6, f[3] = {0.05, -0.02, 0.03};
    double u = cos(a) * f[0] + sin(a) * f[1], v = (-sin(a) * f[0] + cos(a) * f[1]) * 0.5, w = f[2] * 0.25;
    double want = 0.5 * 0.25 * markov_density(1, 3, 3, sqrt(u * u + v * v + w * w));
    double got = nl_model_spectral_density(m, 3, f);
    cr_assert(fabs(got - want) <= 1e-8 * want, "ellipsoid: %.12g, expected %.12g", got, want);
    want = markov_density(2, 3, 1, f[0]) * 0.5 * markov_density(2, 3, 1, 0.5 * f[1]) / 2;
    got = nl_model_spectral_density(s, 2, f);
    cr_assert(fabs(got - want) <= 1e-13 * want, "sep: %.15g, expected %.15g", got, want);
    nl_model_free(m), nl_model_free(s);
}

/* A sum adds its terms' densities (the nugget's is 0); a product, an
 * expression of x and y, and dim 4 have none. */
Test(model_density, sums_and_refusals)
{
    nl_model *sum = parse_ok("nugget:var=0.3 + markov:scale=2 + gauss:scale=1.5,var=0.5");
    nl_model *prod = parse_ok("markov:scale=2 * gauss:scale=3");
    nl_model *xy = parse_ok("expr:exp(-abs(x)-y^2)");
    double f[2] = {0.07, 0.02}, k = hypot(f[0], f[1]);
    double g = 0.5 * M_PI * 1.5 * 1.5 * exp(-pow(M_PI * 1.5 * k, 2)); /* 2D gauss transform */
    double want = markov_density(1, 2, 2, k) + g, got = nl_model_spectral_density(sum, 2, f);
    cr_assert(fabs(got - want) <= 1e-8 * want, "sum: %.12g, expected %.12g", got, want);
    cr_assert(isnan(nl_model_spectral_density(prod, 1, f)));
    cr_assert(isnan(nl_model_spectral_density(xy, 2, f)));
    cr_assert(isnan(nl_model_spectral_density(sum, 4, f)));
    nl_model_free(sum), nl_model_free(prod), nl_model_free(xy);
}
