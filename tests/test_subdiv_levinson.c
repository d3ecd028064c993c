/* The 1D automatic neighbourhood grown by Levinson's recursion (Lewis 1987,
 * "Neighborhood Size") against the direct re-solve of every N.
 *
 * Property: for each model, spacing and stopping rule, the N that
 * nl_subdiv_coeffs_alloc_rule chooses is the N that solving eq. (4)
 * directly for N = 1, 2, ... and applying the same rule to the variances
 * (7) chooses, and Levinson's coefficients at that N equal the direct
 * solve's.  Tolerance 1e-10 on the coefficients: both solves are backward
 * stable, so they differ by about eps times the condition number, which is
 * at most 1e5 for the well-conditioned cases here (measured differences
 * 3e-15 to 8e-14); past condition 1e5 (the Gaussian at N = 12, 1.9e8)
 * the bound is 64 eps cond max|a| instead.  The Gaussian at a fine spacing exercises the path where
 * the recursion breaks down (singular) and direct, pseudo-inverted solves
 * take over; there only the chosen N is compared. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"

#include <criterion/criterion.h>
#include <float.h>
#include <math.h>

/* The reference rule: every N solved directly, one level at spacing s. */
static int direct_choice(const nl_model *m, double s, int rule, double tol, int nmax)
{
    double zero = 0, r0 = nl_model_acf(m, 1, &zero), prev = NAN;
    for (int N = 1; N <= nmax; N++) {
        nl_subdiv_coeffs *c;
        double v;
        cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 1, s, N, 1e-4, 16, &c), NL_OK, "%s", nl_errmsg());
        v = c->level[0].cls[0].variance;
        nl_subdiv_coeffs_free(c);
        if (rule == NL_SUBDIV_STOP_IMPROVEMENT && N > 1 && prev - v < tol * r0)
            return N - 1;
        if (rule == NL_SUBDIV_STOP_VARIANCE && v < tol * r0)
            return N;
        prev = v;
    }
    return nmax;
}

static const struct {
    const char *spec;
    double s;
} cases[] = {
    {"markov:scale=8", 1},         {"markaussian:alpha=1.4,scale=8", 1}, {"markaussian:alpha=1.4,scale=8", 4},
    {"expr:100*cos(10*t)*exp(-abs(t))", 0.05}, {"expr:100*cos(10*t)*exp(-abs(t))", 0.47},
    {"matern:nu=1.5,scale=4", 1},  {"matern:nu=2.5,scale=4", 0.5},       {"gauss:scale=3", 1},
    {"gauss:scale=3", 0.25},       {"expr:cos(t)*exp(-0.1*abs(t))", 0.8},
};

Test(subdiv_levinson, auto_equals_direct_resolve)
{
    static const struct {
        int rule;
        double tol;
    } rules[] = {{NL_SUBDIV_STOP_IMPROVEMENT, 1e-4}, {NL_SUBDIV_STOP_IMPROVEMENT, 1e-2},
                 {NL_SUBDIV_STOP_VARIANCE, 0.3},     {NL_SUBDIV_STOP_VARIANCE, 0.05},
                 {NL_SUBDIV_STOP_VARIANCE, 1e-3},    {NL_SUBDIV_STOP_NONE, 1}};
    int compared = 0;
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        nl_model *m;
        cr_assert_eq(nl_model_parse(cases[i].spec, &m), 0);
        for (size_t r = 0; r < sizeof rules / sizeof *rules; r++) {
            nl_subdiv_coeffs *c;
            int want = rules[r].rule == NL_SUBDIV_STOP_NONE ? 12 : direct_choice(m, cases[i].s, rules[r].rule,
                                                                                rules[r].tol, 12);
            cr_assert_eq(nl_subdiv_coeffs_alloc_rule(m, 1, 1, cases[i].s, 0, rules[r].rule, rules[r].tol, 12, &c),
                         NL_OK, "%s", nl_errmsg());
            cr_expect_eq(c->level[0].N, want, "%s s=%g rule %d tol %g: N %d, direct %d", cases[i].spec, cases[i].s,
                         rules[r].rule, rules[r].tol, c->level[0].N, want);
            if (!(c->level[0].cls[0].flags & (NL_SUBDIV_SINGULAR | NL_SUBDIV_NOT_PD))) {
                int N = c->level[0].N, nout;
                double a[24], var[12];
                cr_assert_eq(nl_subdiv_levinson(m, cases[i].s, N, NL_SUBDIV_STOP_NONE, 0, a, var, &nout), NL_OK);
                cr_assert_eq(nout, N);
                double amax = 0, cond = c->level[0].cls[0].condition, bound;
                for (int k = 0; k < 2 * N; k++)
                    amax = fmax(amax, fabs(a[k]));
                bound = cond <= 1e5 ? 1e-10 : 64 * DBL_EPSILON * cond * amax;
                for (int k = 0; k < 2 * N; k++)
                    cr_expect(fabs(a[k] - c->level[0].cls[0].a[k]) <= bound, "%s N=%d a[%d] %.17g vs %.17g",
                              cases[i].spec, N, k, a[k], c->level[0].cls[0].a[k]);
                compared += cond <= 1e5;
            }
            nl_subdiv_coeffs_free(c);
        }
        nl_model_free(m);
    }
    cr_expect_geq(compared, 40, "coefficients compared in %d cases", compared);
}

/* The singular case takes the direct path past the breakdown: the
 * Gaussian at spacing 0.25 with N grown to the cap is flagged singular and
 * solved by the pseudo-inverse, as a fixed N of the same size is. */
Test(subdiv_levinson, singular_goes_through_pseudo_inverse)
{
    nl_model *m;
    nl_subdiv_coeffs *a, *d;
    cr_assert_eq(nl_model_parse("gauss:scale=3", &m), 0);
    cr_assert_eq(nl_subdiv_coeffs_alloc_rule(m, 1, 1, 0.25, 0, NL_SUBDIV_STOP_NONE, 1, 8, &a), NL_OK);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 1, 0.25, 8, 1e-4, 16, &d), NL_OK);
    cr_expect_eq(a->level[0].N, 8);
    cr_expect(a->level[0].cls[0].flags & NL_SUBDIV_PINV, "flags %#x", a->level[0].cls[0].flags);
    for (int k = 0; k < 16; k++)
        cr_expect_eq(a->level[0].cls[0].a[k], d->level[0].cls[0].a[k]);
    nl_subdiv_coeffs_free(a), nl_subdiv_coeffs_free(d), nl_model_free(m);
}

Test(subdiv_levinson, bad_rule)
{
    nl_model *m;
    nl_subdiv_coeffs *c;
    cr_assert_eq(nl_model_parse("markov", &m), 0);
    cr_expect_eq(nl_subdiv_coeffs_alloc_rule(m, 1, 2, 1, 0, 7, 1e-4, 8, &c), NL_EINVAL);
    cr_expect_null(c);
    nl_model_free(m);
}
