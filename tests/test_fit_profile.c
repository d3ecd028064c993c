/* Profile-likelihood intervals of ML and REML fits: the closed form of a
 * one-parameter profile, the defining property at each end of a
 * multi-parameter one, and the command's output. */
#include "../analysis/fit.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

enum { N = 60 };

/* 60 points uniform in [0, 10]^2 with a smooth pattern plus noise as
 * values (a finite correlation scale for the fits to find). */
static void make_data(double *x, double *z)
{
    for (int i = 0; i < N; i++) {
        x[2 * i] = 10 * nl_rng_uniform(7, 1, (uint64_t)i);
        x[2 * i + 1] = 10 * nl_rng_uniform(7, 2, (uint64_t)i);
        z[i] = sin(0.7 * x[2 * i]) + cos(0.5 * x[2 * i + 1]) + 1.5 * nl_rng_uniform(7, 3, (uint64_t)i);
    }
}

/* The root x of dof (ln x + 1 / x - 1) = 3.841459 on (lo, hi) by bisection
 * (the function is monotone on each side of x = 1). */
static double closed_end(double dof, double lo, double hi)
{
    double flo = dof * (log(lo) + 1 / lo - 1) - 3.841458820694124;
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi), f = dof * (log(mid) + 1 / mid - 1) - 3.841458820694124;
        if ((f < 0) == (flo < 0))
            lo = mid, flo = f;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* With the correlation fixed, C = var P and -2 l = dof ln var + q / var +
 * const (dof = n for ML, n - 1 for REML; q = r' P^-1 r), minimal at
 * var^ = q / dof: the profile is dof (ln x + 1/x - 1) in x = var / var^, so
 * the interval is var^ times the two roots of that = 3.841.  Brent stops
 * when its bracket is under 1e-3 in log var, so each end is within 1e-3
 * relative (e^0.001 - 1 = 1.0005e-3); the optimum var^ itself is within
 * 1e-5 (simplex size), hence 1.1e-3. */
Test(fit_profile, one_parameter_closed_form)
{
    double x[2 * N], z[N];
    make_data(x, z);
    for (int reml = 0; reml < 2; reml++) {
        nl_fit_options o = {.family = "markov", .nfix = 1, .fix_name = {"scale"}, .fix_value = {2.5},
                            .likelihood = reml ? NL_FIT_REML : NL_FIT_ML, .intervals = NL_FIT_INTERVALS_ALL};
        nl_fit_result r;
        cr_assert_eq(nl_fit_ml(x, z, N, 2, &o, &r), NL_OK, "%s", nl_errmsg());
        double dof = reml ? N - 1 : N, v = r.param[0].value;
        double lo = v * closed_end(dof, 1e-3, 1), hi = v * closed_end(dof, 1, 1e3);
        cr_expect(fabs(r.param[0].lower / lo - 1) < 1.1e-3, "reml %d: lower %.8g, closed form %.8g", reml,
                  r.param[0].lower, lo);
        cr_expect(fabs(r.param[0].upper / hi - 1) < 1.1e-3, "reml %d: upper %.8g, closed form %.8g", reml,
                  r.param[0].upper, hi);
        cr_expect(isnan(r.param[1].lower) && isnan(r.param[1].upper), "the fixed scale has no interval");
        nl_fit_result_free(&r);
    }
}

/* At a finite end theta_e of parameter j, the profile -2 l is the minimum +
 * 3.841: a fit with j fixed at theta_e (the others free) must have an
 * objective 3.841 above the full fit's.  Tolerance: the end is within
 * du = 1e-3 of the root in the transformed coordinate u; near the end the
 * profile's slope is about 2 x 1.96 / se(u) (its quadratic approximation),
 * so the objective is off by at most that x du; plus 0.01 for the inner
 * optimisations (simplex 1e-3, or a gain under 1e-4 per 10 steps) and the
 * fixed fit's own simplex. */
Test(fit_profile, ends_sit_at_the_cutoff)
{
    double x[2 * N], z[N];
    make_data(x, z);
    for (int fam = 0; fam < 2; fam++) {
        nl_fit_options o = {.family = fam ? "spherical" : "markov", .nugget = !fam,
                            .intervals = NL_FIT_INTERVALS_ALL};
        nl_fit_result r, rf;
        int checked = 0;
        double start[NL_FAMILY_MAX_PARAMS];
        cr_assert_eq(nl_fit_ml(x, z, N, 2, &o, &r), NL_OK, "%s", nl_errmsg());
        for (size_t j = 0; j < r.np; j++)
            start[j] = r.param[j].value;
        for (size_t j = 0; j < r.np; j++) {
            cr_expect(r.param[j].lower <= r.param[j].value && r.param[j].value <= r.param[j].upper,
                      "%s: %g outside [%g, %g]", r.param[j].name, r.param[j].value, r.param[j].lower,
                      r.param[j].upper);
            for (int side = 0; side < 2; side++) {
                double e = side ? r.param[j].upper : r.param[j].lower, se_u = r.param[j].se / r.param[j].value;
                if (!(e > 0 && isfinite(e) && isfinite(se_u) && se_u > 0))
                    continue;
                nl_fit_options f = {.family = o.family, .nugget = o.nugget, .nfix = 1,
                                    .fix_name = {r.param[j].name}, .fix_value = {e}, .start = start};
                cr_assert_eq(nl_fit_ml(x, z, N, 2, &f, &rf), NL_OK, "%s", nl_errmsg());
                double d = rf.objective - r.objective, tol = 2 * 1.96 / se_u * 1e-3 + 0.01;
                cr_expect(fabs(d - 3.841459) < tol, "%s %s %s end %.6g: -2 l rises by %.5f, expected 3.8415 +- %.3f",
                          o.family, r.param[j].name, side ? "upper" : "lower", e, d, tol);
                checked++;
                nl_fit_result_free(&rf);
            }
        }
        nl_fit_result_free(&r);
        cr_expect(checked >= 3, "%s: only %d finite ends", o.family, checked);
    }
}

/* The command prints the intervals: JSON's "intervals" holds [lower, upper]
 * per free parameter for ml and reml (existing keys unchanged), wls has
 * none. */
Test(fit_profile, cli_reports_intervals)
{
    double x[2 * N], z[N];
    char path[512];
    make_data(x, z);
    snprintf(path, sizeof path, "%s/pts.tsv", scratch_dir());
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(f, "x\ty\tvalue\n");
    for (int i = 0; i < N; i++)
        fprintf(f, "%.17g\t%.17g\t%.17g\n", x[2 * i], x[2 * i + 1], z[i]);
    fclose(f);
    json_t *j = run_noiselab_json("fit pts.tsv --model spherical --method reml --json");
    json_t *iv = json_object_get(j, "intervals"), *par = json_object_get(j, "parameters");
    static const char *keys[] = {"model", "parameters", "standard_errors", "objective", "aic", "method", "n", "mean"};
    for (size_t k = 0; k < sizeof keys / sizeof *keys; k++)
        cr_expect(json_object_get(j, keys[k]), "key %s missing", keys[k]);
    cr_assert(json_is_object(iv), "no intervals object");
    for (int k = 0; k < 2; k++) {
        const char *nm = k ? "scale" : "var";
        json_t *a = json_object_get(iv, nm);
        double v = json_real_value(json_object_get(par, nm));
        cr_assert(json_array_size(a) == 2, "intervals.%s is not [lower, upper]", nm);
        cr_expect(json_real_value(json_array_get(a, 0)) <= v, "intervals.%s lower above the value", nm);
        cr_expect(json_is_null(json_array_get(a, 1)) || json_real_value(json_array_get(a, 1)) >= v,
                  "intervals.%s upper below the value", nm);
    }
    json_decref(j);
    j = run_noiselab_json("fit pts.tsv --model spherical --json");
    cr_expect(!json_object_get(j, "intervals"), "wls reports intervals");
    json_decref(j);
}
