/* The nugget and the spherical model: values, refusals, spectra, and the
 * synthesis methods that carry a nugget exactly. */
#include "../analysis/check.h"
#include "../core/field.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/wk.h"
#include "../synth/fft.h"
#include "../synth/lattice.h"
#include "../synth/rank1_model.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
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
    cr_assert(strstr(nl_errmsg(), needle), "%s: \"%s\" should name %s", spec, nl_errmsg(), needle);
}

/* The formula at a few lags, exactly (each is one or two roundings). */
Test(model_nugget, spherical_values)
{
    nl_model *m = parse_ok("spherical:scale=2.385,var=1.7");
    double t, lag3[3] = {0.6, 0.8, 0};  /* |lag| = 1 */
    t = 0;
    cr_assert_float_eq(nl_model_acf(m, 1, &t), 1.7, 1e-15);
    t = -2.385 / 2;
    cr_assert_float_eq(nl_model_acf(m, 1, &t), 1.7 * 0.3125, 1e-14);
    t = 2.385;
    cr_assert_eq(nl_model_acf(m, 1, &t), 0.0);
    t = 7;
    cr_assert_eq(nl_model_acf(m, 1, &t), 0.0);
    {
        double a = 1 / 2.385;
        cr_assert_float_eq(nl_model_acf(m, 3, lag3), 1.7 * (1 - 1.5 * a + 0.5 * a * a * a), 1e-14);
    }
    nl_model_free(m);
}

/* R(0) = var + nugget, R(lag != 0) = var rho(lag), in every dimension and
 * for the separable and expression forms too. */
Test(model_nugget, nugget_only_at_lag_zero)
{
    const char *specs[] = {"markov:scale=3,nugget=0.25", "gauss:scale=3,nugget=0.25,sep",
                           "spherical:scale=3,nugget=0.25", "expr:exp(-r/3);nugget=0.25",
                           "matern:nu=1.5,scale=3,nugget=0.25,ratio=0.5"};
    for (size_t i = 0; i < sizeof specs / sizeof *specs; i++) {
        nl_model *m = parse_ok(specs[i]);
        char plain[128];
        nl_model *p;
        double v;
        /* the same spec without the nugget */
        snprintf(plain, sizeof plain, "%s", specs[i]);
        {
            char *n = strstr(plain, "nugget=0.25");
            memmove(n, n + 11, strlen(n + 11) + 1);
            size_t l = strlen(plain);
            if (plain[l - 1] == ',' || plain[l - 1] == ';')
                plain[l - 1] = 0;
            char *cc = strstr(plain, ",,");
            if (cc)
                memmove(cc, cc + 1, strlen(cc));
        }
        p = parse_ok(plain);
        cr_assert_eq(nl_model_param(m, "nugget", &v), NL_OK);
        cr_assert_eq(v, 0.25);
        cr_assert_eq(nl_model_nugget(m), 0.25);
        for (int dim = 1; dim <= 3; dim++) {
            double zero[3] = {0, 0, 0}, lag[3] = {0, 1e-300, 0}, far[3] = {1.3, -0.4, 0.2};
            cr_assert_eq(nl_model_acf(m, dim, zero), nl_model_acf(p, dim, zero) + 0.25, "%s %dD", specs[i], dim);
            if (dim > 1)
                cr_assert_eq(nl_model_acf(m, dim, lag), nl_model_acf(p, dim, lag), "%s %dD", specs[i], dim);
            cr_assert_eq(nl_model_acf(m, dim, far), nl_model_acf(p, dim, far), "%s %dD", specs[i], dim);
        }
        nl_model_free(p);
        nl_model_free(m);
    }
}

Test(model_nugget, refusals)
{
    parse_bad("markov:nugget=-0.1", "nugget");
    parse_bad("markov:nugget=nan", "nugget");
    parse_bad("power:d=2,nugget=0.1", "nugget");
    parse_bad("spectrum:exp(-k);nugget=0.1", "nugget");
    parse_bad("spherical:scale=0", "scale");
    parse_bad("spherical:omega=3", "omega");
    parse_bad("sphere", "unknown model");
}

/* The header's convention: on a grid of cell volume h1 h2, the sampled
 * spectrum of a model with a nugget is that of the model without it plus
 * the constant nugget h1 h2 (to the FFT's rounding, ~1e-15 of the sum). */
Test(model_nugget, sampled_spectrum_gains_a_constant)
{
    nl_model *m = parse_ok("spherical:scale=5,var=2,nugget=0.3"), *p = parse_ok("spherical:scale=5,var=2");
    size_t n[2] = {24, 20};
    double h[2] = {0.7, 1.3};
    int st;
    nl_field *a = nl_field_alloc(2, n, h, &st), *b = nl_field_alloc(2, n, h, &st);
    cr_assert_eq(nl_wk_sample_spectrum(m, a), NL_OK);
    cr_assert_eq(nl_wk_sample_spectrum(p, b), NL_OK);
    for (size_t i = 0; i < a->count; i++)
        cr_assert_float_eq(a->data[i] - b->data[i], 0.3 * 0.7 * 1.3, 1e-12);
    nl_field_free(a);
    nl_field_free(b);
    nl_model_free(m);
    nl_model_free(p);
}

/* Closed forms of the spherical model's spectrum at 0 (the integral of R):
 * 1D 2 int_0^a = 0.75 a var, 3D 4 pi int_0^a r^2 = pi a^3 / 6 var (the
 * volume of a ball of diameter a: R is the overlap of two such balls).  The
 * quadrature is asked for 1e-9; 1e-7 leaves room for the kink at a.  In 3D
 * the spectrum, |FT of a ball|^2, is >= 0; in 4D it goes negative (the
 * model is not positive definite there): both by more than the quadrature's
 * error. */
Test(model_nugget, spherical_spectra)
{
    nl_model *m = parse_ok("spherical:scale=2.385,var=1.3");
    double a = 2.385, lo3 = INFINITY, lo4 = INFINITY, s3max = 0;
    cr_assert_float_eq(nl_model_spectrum_iso(m, 1, 0), 1.3 * 0.75 * a, 1e-7 * a);
    cr_assert_float_eq(nl_model_spectrum_iso(m, 3, 0), 1.3 * M_PI * a * a * a / 6, 1e-7 * a * a * a);
    for (double w = 0.01; w < 3; w += 0.0137) {
        double s3 = nl_model_spectrum_iso(m, 3, w), s4 = nl_model_spectrum_iso(m, 4, w);
        lo3 = fmin(lo3, s3);
        lo4 = fmin(lo4, s4);
        s3max = fmax(s3max, s3);
    }
    cr_assert(lo3 > -1e-8 * s3max, "3D spectrum min %g", lo3);
    cr_assert(lo4 < -1e-4 * s3max, "4D spectrum min %g should be negative", lo4);
    cr_assert_eq(nl_rank1_model_check(m, 3), NL_OK);
    cr_assert_eq(nl_rank1_model_check(m, 4), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "spherical"));
    nl_model_free(m);
}

/* check: spherical positive definite in 1D-3D; a nugget keeps a model
 * positive definite and makes it rough (not differentiable). */
Test(model_nugget, check_verdicts)
{
    nl_model *m = parse_ok("spherical:scale=10"), *n = parse_ok("gauss:scale=5,nugget=0.3");
    nl_check c;
    for (int dim = 1; dim <= 3; dim++) {
        cr_assert_eq(nl_check_model(m, dim, &c), NL_OK);
        cr_assert(c.positive_definite, "spherical %dD", dim);
    }
    cr_assert_eq(nl_check_model(n, 2, &c), NL_OK);
    cr_assert(c.positive_definite);
    cr_assert_eq(c.differentiable_order, 0);
    nl_model_free(m);
    nl_model_free(n);
}

/* Methods without a white-noise part refuse a nugget with one message
 * naming the method and the model. */
Test(model_nugget, methods_refuse)
{
    nl_model *m = parse_ok("markov:scale=4,nugget=0.5");
    nl_subdiv_coeffs *c;
    nl_synth_sparse_plan *s;
    nl_synth_lattice_plan l;
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 3, 8, 2, 0, 0, &c), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "subdiv") && strstr(nl_errmsg(), "nugget=0.5"), "%s", nl_errmsg());
    cr_assert_eq(nl_synth_sparse_plan_model(m, 2, NULL, SPARSE_OPTS(8, 0, 1), &s), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "sparse") && strstr(nl_errmsg(), "nugget=0.5"), "%s", nl_errmsg());
    cr_assert_eq(nl_synth_lattice_plan_init(m, 1, 16, 2, 0, &l), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "lattice") && strstr(nl_errmsg(), "nugget=0.5"), "%s", nl_errmsg());
    cr_assert_eq(nl_rank1_model_check(m, 2), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "rank1") && strstr(nl_errmsg(), "nugget=0.5"), "%s", nl_errmsg());
    nl_model_free(m);
}

/* FFT synthesis carries the nugget as white noise: on one 256 x 256 field
 * of markov:scale=4,var=1,nugget=0.5 (N = 65536 samples), the sample
 * variance estimates R(0) = 1.5 with sd <= sqrt(2 sum_k R(k)^2 / N), and the
 * mean of x_i^2 - x_i x_{i+1} (x neighbours) estimates R(0) - R(1) =
 * 0.5 + (1 - e^-0.25) = 0.721 with sd <= sqrt(8 sum_k R(k)^2 / N) (the
 * product of two such terms' covariances, Isserlis); sum_k R(k)^2 = 2 pi
 * (scale/2)^2 + 1.25 (the lag-0 excess) = 26.4, so the sds are 0.028 and
 * 0.057.  Bands of 5 sd; a lost nugget misses them by 0.5 (18 and 9 sd). */
Test(model_nugget, fft_carries_the_nugget)
{
    nl_model *m = parse_ok("markov:scale=4,nugget=0.5");
    nl_synth_fft_plan *p;
    nl_synth_fft_info fi;
    size_t n[2] = {256, 256};
    int st;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    double v = 0, d = 0;
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p), NL_OK, "%s", nl_errmsg());
    nl_synth_fft_plan_info(p, &fi);
    cr_assert_float_eq(fi.variance, 1.5, 1e-9);
    cr_assert_eq(nl_synth_fft_execute(p, 17, f), NL_OK);
    for (size_t j = 0; j < 256; j++)
        for (size_t i = 0; i < 256; i++) {
            double x = f->data[j * 256 + i], y = f->data[j * 256 + (i + 1) % 256];
            v += x * x;
            d += x * x - x * y;
        }
    v /= f->count;
    d /= f->count;
    cr_assert(fabs(v - 1.5) < 5 * 0.028, "variance %g", v);
    cr_assert(fabs(d - (0.5 + 1 - exp(-0.25))) < 5 * 0.056, "R(0) - R(1) %g", d);
    nl_field_free(f);
    nl_synth_fft_plan_free(p);
    nl_model_free(m);
}
