/* The family registry (core/family.h): every descriptor is complete and
 * consistent with the catalogue, parsing follows each descriptor's
 * parameters (defaults, required ones, ranges, aliases), and the
 * generalized Cauchy family, added through the registry alone, evaluates,
 * checks and fits. */
#include "../analysis/check.h"
#include "../analysis/fit.h"
#include "../core/family.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* A spec of family f with its required parameters at their examples and
 * `extra` (",key=value" or "") appended. */
static void spec_of(const nl_family *f, const char *extra, char *buf, size_t size)
{
    size_t len = (size_t)snprintf(buf, size, "%s", f->name);
    int first = 1;
    for (size_t k = 0; k < f->nparams; k++)
        if (f->params[k].placeholder) {
            len += (size_t)snprintf(buf + len, size - len, "%s%s=%s", first ? ":" : ",", f->params[k].name,
                                    f->params[k].example);
            first = 0;
        }
    if (*extra)
        snprintf(buf + len, size - len, "%s%s", first ? ":" : ",", extra + 1);
}

Test(family, descriptors_are_complete)
{
    cr_assert_gt(nl_family_count(), 0);
    cr_assert_null(nl_family_get(nl_family_count()));
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = nl_family_get(i);
        int arg = (f->flags & NL_FAMILY_ARGUMENT) != 0;
        cr_assert(f->name && *f->name && f->formula && *f->formula && f->validity && *f->validity && f->aliases,
                  "family %zu", i);
        cr_assert_leq(f->nparams, NL_FAMILY_MAX_PARAMS, "%s", f->name);
        cr_assert_eq(arg, f->parse_argument != NULL, "%s: argument flag and parser", f->name);
        cr_assert(!arg || (f->argument && f->usage), "%s", f->name);
        /* R is computable unless the family is defined by its spectrum */
        cr_assert(f->profile || f->acf || (f->flags & NL_FAMILY_SPECTRAL), "%s: no R", f->name);
        cr_assert(!(f->flags & NL_FAMILY_SPECTRAL) || f->spectrum, "%s: spectral without S", f->name);
        if (f->flags & NL_FAMILY_FIT)
            cr_assert(f->profile && nl_family_role_index(f, NL_ROLE_VARIANCE) >= 0 &&
                      nl_family_role_index(f, NL_ROLE_SCALE) >= 0, "%s: fit needs R, var and scale", f->name);
        for (size_t k = 0; k < f->nparams; k++) {
            const nl_family_param *p = &f->params[k];
            cr_assert_eq(isnan(p->def), p->placeholder != NULL, "%s.%s: required iff no default", f->name, p->name);
            cr_assert(!p->placeholder || p->example, "%s.%s: a required parameter needs an example", f->name,
                      p->name);
            cr_assert(p->range != NL_RANGE_UPTO || (p->hi > 0 && p->why), "%s.%s", f->name, p->name);
            cr_assert_eq(nl_family_param_index(f, p->name), (int)k, "%s.%s: names are unique", f->name, p->name);
        }
        /* names and aliases are unique across the registry */
        for (size_t j = 0; j < nl_family_count(); j++)
            cr_assert(j == i || strcmp(f->name, nl_family_get(j)->name) != 0, "%s twice", f->name);
        cr_assert_eq(nl_family_find(f->name, strlen(f->name)), f, "%s", f->name);
    }
}

/* The catalogue is the registry, entry for entry. */
Test(family, catalogue_is_the_registry)
{
    size_t n;
    const nl_model_info *c = nl_model_catalogue(&n);
    cr_assert_eq(n, nl_family_count());
    for (size_t i = 0; i < n; i++) {
        const nl_family *f = nl_family_get(i);
        char name[64];
        snprintf(name, sizeof name, (f->flags & NL_FAMILY_ARGUMENT) ? "%s:%s" : "%s", f->name, f->argument);
        cr_assert_str_eq(c[i].name, name);
        cr_assert_str_eq(c[i].formula, f->formula);
        for (size_t k = 0; k < f->nparams; k++)
            cr_assert(strstr(c[i].params, f->params[k].name), "%s: %s lacks %s", f->name, c[i].params,
                      f->params[k].name);
    }
}

/* Every named family parses with its required parameters, holds its
 * defaults, refuses a missing required parameter by name and every
 * parameter outside its range by name; aliases name the same family. */
Test(family, parsing_follows_the_descriptors)
{
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = nl_family_get(i);
        char spec[256];
        nl_model *m;
        if (f->flags & NL_FAMILY_ARGUMENT)
            continue;
        spec_of(f, "", spec, sizeof spec);
        cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
        cr_assert_eq(nl_model_family(m), f);
        for (size_t k = 0; k < f->nparams; k++) {
            double v;
            cr_assert_eq(nl_model_param(m, f->params[k].name, &v), NL_OK);
            if (!f->params[k].placeholder)
                cr_assert_eq(v, f->params[k].def, "%s.%s default", f->name, f->params[k].name);
        }
        if (!(f->flags & (NL_FAMILY_SPECTRAL | NL_FAMILY_INTRINSIC))) {
            double zero[3] = {0, 0, 0}, var;
            nl_model_param(m, "var", &var);
            cr_assert_float_eq(nl_model_acf(m, 1, zero), var, 1e-15, "%s: R(0) = var", f->name);
        }
        nl_model_free(m);
        for (size_t k = 0; k < f->nparams; k++) {
            const nl_family_param *p = &f->params[k];
            double bad[2] = {NAN, NAN};
            char extra[64];
            if (p->placeholder) {
                char partial[256];
                size_t len = (size_t)snprintf(partial, sizeof partial, "%s:", f->name);
                for (size_t q = 0; q < f->nparams; q++)
                    if (q != k && f->params[q].placeholder)
                        len += (size_t)snprintf(partial + len, sizeof partial - len, "%s=%s,", f->params[q].name,
                                                f->params[q].example);
                partial[len - 1] = 0;
                cr_assert_eq(nl_model_parse(partial, &m), NL_EINVAL, "%s", partial);
                cr_assert(strstr(nl_errmsg(), p->name) && strstr(nl_errmsg(), "missing"), "%s: %s", partial,
                          nl_errmsg());
            }
            if (p->range == NL_RANGE_POSITIVE || p->range == NL_RANGE_UPTO)
                bad[0] = 0;
            if (p->range == NL_RANGE_NONNEG)
                bad[0] = -1;
            if (p->range == NL_RANGE_UPTO)
                bad[1] = p->hi * 1.01;
            for (int b = 0; b < 2; b++) {
                if (isnan(bad[b]))
                    continue;
                snprintf(extra, sizeof extra, ",%s=%g", p->name, bad[b]);
                spec_of(f, extra, spec, sizeof spec);
                cr_assert_eq(nl_model_parse(spec, &m), NL_EINVAL, "%s should be refused", spec);
                cr_assert(strstr(nl_errmsg(), p->name), "%s: %s", spec, nl_errmsg());
            }
        }
        for (const char *a = f->aliases; *a;) {
            size_t len = strcspn(a, " ");
            cr_assert_eq(nl_family_find(a, len), f, "alias %.*s", (int)len, a);
            a += len;
            a += strspn(a, " ");
        }
    }
}

/* The generalized Cauchy family against its formula computed here, and
 * its special cases: alpha = 2, beta = 2 is the Cauchy 1 / (1 + a^2);
 * alpha = beta = 1 is 1 / (1 + a). */
Test(family, gencauchy_values)
{
    nl_model *m;
    double lags[] = {0, 0.3, 1, 2.5, 7, 40};
    cr_assert_eq(nl_model_parse("gencauchy:alpha=1.3,beta=0.7,scale=2.5,var=1.6", &m), NL_OK, "%s", nl_errmsg());
    for (size_t i = 0; i < sizeof lags / sizeof *lags; i++) {
        double t = lags[i], want = 1.6 * pow(1 + pow(t / 2.5, 1.3), -0.7 / 1.3), neg = -t;
        cr_assert_float_eq(nl_model_acf(m, 1, &t), want, 1e-15 * 1.6, "R(%g)", t);
        cr_assert_float_eq(nl_model_acf(m, 1, &neg), want, 1e-15 * 1.6, "R(-%g)", t);
    }
    /* isotropic in 3D: R of the lag's norm */
    {
        double lag[3] = {1, 2, 2}, r = 3, want = nl_model_acf(m, 1, &r);
        cr_assert_float_eq(nl_model_acf(m, 3, lag), want, 1e-15);
    }
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("gencauchy:alpha=2,beta=2,scale=3", &m), NL_OK);
    for (double t = 0; t < 20; t += 1.7)
        cr_assert_float_eq(nl_model_acf(m, 1, &t), 1 / (1 + t * t / 9), 1e-15);
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("generalized-cauchy:alpha=1,beta=1", &m), NL_OK, "the alias");
    for (double t = 0; t < 20; t += 1.7)
        cr_assert_float_eq(nl_model_acf(m, 1, &t), 1 / (1 + t), 1e-15);
    nl_model_free(m);
}

/* check measures it positive definite in 1D to 3D (it is, for every
 * 0 < alpha <= 2, beta > 0: Gneiting and Schlather 2004) at a rough and a
 * smooth alpha.  Tails slower than |t|^-dim (beta < dim) are left out:
 * check's transform of such a tail is not reliable yet. */
Test(family, gencauchy_check)
{
    const char *specs[] = {"gencauchy:alpha=0.5,beta=3,scale=4", "gencauchy:alpha=2,beta=3.5,scale=4"};
    for (int s = 0; s < 2; s++)
        for (int dim = 1; dim <= 3; dim++) {
            nl_model *m;
            nl_check c;
            cr_assert_eq(nl_model_parse(specs[s], &m), NL_OK);
            cr_assert_eq(nl_check_model(m, dim, &c), NL_OK, "%s", nl_errmsg());
            cr_expect(c.positive_definite, "%s in %dD", specs[s], dim);
            nl_model_free(m);
        }
}

/* WLS on its exact semivariogram recovers all four parameters, both shape
 * parameters free (the objective is 0 at the truth; 1e-5 relative leaves
 * room for the finite-difference Jacobian's last steps). */
Test(family, gencauchy_wls_recovers_both_shapes)
{
    const char *names[] = {"var", "scale", "alpha", "beta"};
    double truth[] = {1.4, 3.2, 1.3, 2.1}, h[30], g[30], n[30], zero = 0;
    nl_model *m;
    nl_fit_options o = {.family = "gencauchy"};
    nl_fit_result r;
    cr_assert_eq(nl_model_parse("gencauchy:alpha=1.3,beta=2.1,scale=3.2,var=1.4", &m), NL_OK);
    for (int k = 0; k < 30; k++) {
        h[k] = 0.5 * k + 0.2;
        g[k] = nl_model_acf(m, 1, &zero) - nl_model_acf(m, 1, &h[k]);
        n[k] = 100 + 20 * k;
    }
    nl_model_free(m);
    cr_assert_eq(nl_fit_variogram(h, g, n, 30, 2, &o, &r), NL_OK, "%s", nl_errmsg());
    cr_assert(r.converged);
    cr_assert_eq(r.np, 4);
    cr_assert_eq(r.nfree, 4);
    for (size_t k = 0; k < 4; k++) {
        cr_assert_str_eq(r.param[k].name, names[k]);
        cr_expect_float_eq(r.param[k].value, truth[k], 1e-5 * truth[k], "%s = %.10g", names[k], r.param[k].value);
    }
    cr_assert(strncmp(r.spec, "gencauchy:alpha=", 16) == 0, "%s", r.spec);
    nl_fit_result_free(&r);
}

enum { NPTS = 150 };

/* NPTS points uniform in [0, 30]^2 and a realisation of spec at them
 * (the Cholesky factor of the covariance times N(0, 1) numbers). */
static void gaussian_data(const char *spec, double *x, double *z)
{
    nl_model *m;
    gsl_matrix *C = gsl_matrix_alloc(NPTS, NPTS);
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK);
    for (int i = 0; i < NPTS; i++) {
        x[2 * i] = 30 * nl_rng_uniform(11, 1, (uint64_t)i);
        x[2 * i + 1] = 30 * nl_rng_uniform(11, 2, (uint64_t)i);
    }
    for (int i = 0; i < NPTS; i++)
        for (int j = 0; j < NPTS; j++) {
            double lag[2] = {x[2 * i] - x[2 * j], x[2 * i + 1] - x[2 * j + 1]};
            gsl_matrix_set(C, i, j, nl_model_acf(m, 2, lag));
        }
    cr_assert_eq(gsl_linalg_cholesky_decomp1(C), 0);
    for (int i = 0; i < NPTS; i++) {
        z[i] = 0;
        for (int j = 0; j <= i; j++)
            z[i] += gsl_matrix_get(C, i, j) * nl_rng_gauss(11, 3, (uint64_t)j);
    }
    gsl_matrix_free(C);
    nl_model_free(m);
}

/* ML with both shape parameters free reaches a likelihood at least as high
 * as with them held at the truth (a larger model's optimum cannot be
 * worse: a shortfall is the optimiser stopping early), and its profile
 * intervals hold its own estimates.  Tolerance 0.01 in -2 l: the simplex
 * stops at size 1e-5 in log units. */
Test(family_slow, gencauchy_ml_both_shapes_free, .timeout = 300)
{
    double x[2 * NPTS], z[NPTS];
    nl_fit_options o = {.family = "gencauchy", .intervals = NL_FIT_INTERVALS_ALL};
    nl_fit_options fx = {.family = "gencauchy", .nfix = 2, .fix_name = {"alpha", "beta"}, .fix_value = {1.5, 1.5}};
    nl_fit_result r, rf;
    gaussian_data("gencauchy:alpha=1.5,beta=1.5,scale=4", x, z);
    cr_assert_eq(nl_fit_ml(x, z, NPTS, 2, &o, &r), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_fit_ml(x, z, NPTS, 2, &fx, &rf), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(r.nfree, 4);
    cr_assert_eq(rf.nfree, 2);
    cr_expect_leq(r.objective, rf.objective + 0.01, "free %.6f, shapes fixed %.6f", r.objective, rf.objective);
    for (size_t k = 0; k < r.np; k++)
        cr_expect(r.param[k].lower <= r.param[k].value && r.param[k].value <= r.param[k].upper,
                  "%s %g outside [%g, %g]", r.param[k].name, r.param[k].value, r.param[k].lower, r.param[k].upper);
    nl_fit_result_free(&r);
    nl_fit_result_free(&rf);
}

/* Every closed-form spectrum a family gives (1D to 3D, continuous part)
 * against the Hankel transform of its R (nl_model_spectrum_iso, GSL
 * quadrature to ~1e-10 relative), at frequencies spanning its decay, for
 * the example parameters and scale 2.5: agreement to 1e-6 of the largest
 * closed-form value over those frequencies (the quadrature's tolerance
 * with room for its oscillatory tail).
 * Families defined by S (power, spectrum:) have nothing to compare. */
Test(family_slow, closed_form_spectra, .timeout = 120)
{
    int compared = 0;
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = nl_family_get(i);
        char spec[256];
        nl_model *m;
        if (!f->spectrum || (f->flags & (NL_FAMILY_SPECTRAL | NL_FAMILY_ARGUMENT)))
            continue;
        spec_of(f, nl_family_role_index(f, NL_ROLE_SCALE) >= 0 ? ",scale=2.5" : "", spec, sizeof spec);
        cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
        for (int dim = 1; dim <= 3; dim++) {
            double zero[3] = {0, 0, 0}, s0 = nl_model_spectrum(m, dim, zero), smax = s0;
            double far[3] = {1e6, 0, 0};
            /* R still above 1e-9 R(0) at lag 1e6 (sinc's 1/r): the transform's
             * quadrature does not converge (tests/test_families_lit.c
             * integrates those band-limited spectra instead) */
            if (isnan(s0) || (f->max_dim && dim > f->max_dim) || nl_model_check_dim(m, dim) != NL_OK ||
                nl_model_acf(m, dim, zero) <= 0 || fabs(nl_model_acf(m, dim, far)) > 1e-9 * nl_model_acf(m, dim, zero))
                continue;
            for (double w = 0.01; w < 2; w *= 1.7)
                smax = fmax(smax, nl_model_spectrum(m, dim, (double[3]){w, 0, 0}));
            for (double w = 0.01; w < 2; w *= 1.7) {
                double fv[3] = {w, 0, 0}, s = nl_model_spectrum(m, dim, fv), h = nl_model_spectrum_iso(m, dim, w);
                cr_expect(fabs(s - h) <= 1e-6 * smax, "%s %dD at |f| = %g: closed form %.10g, transform %.10g", spec,
                          dim, w, s, h);
            }
            compared++;
        }
        nl_model_free(m);
    }
    cr_assert_geq(compared, 3, "%d spectra compared", compared);
}
