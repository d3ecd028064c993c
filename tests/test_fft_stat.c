/* Statistical test: FFT-synthesised fields reproduce their target
 * autocorrelation.
 *
 * Property.  FFT synthesis on a periodic grid gives a zero-mean Gaussian
 * field whose covariance is C(d) = R(wrap(d)), the target R at the wrapped
 * lag.  With the known mean 0, the unbiased lag-product estimate
 *     r(l) = (1/P) sum_j x_j x_{j+l},  P = prod_a (n_a - l_a) pairs,
 * has E r(l) = C(l) = R(l) for l_a <= n_a / 2.
 *
 * Tolerance, derived.  By Isserlis' theorem,
 *     Cov(x_a x_b, x_c x_d) = C(a-c) C(b-d) + C(a-d) C(b-c),
 * so, grouping the pairs (j, k) of products by their offset d = j - k,
 *     Var r(l) = (1/P^2) sum_d prod_a (n_a - l_a - |d_a|) [C(d)^2 + C(d+l) C(d-l)],
 * exactly, for |d_a| < n_a - l_a.  The mean of M independent realizations
 * (seeds 1..M) has variance Var r(l) / M, and by the central limit theorem
 *     z(l) = (mean_M r(l) - R(l)) / sqrt(Var r(l) / M)
 * is close to N(0, 1).  We test L lags at once; with a family-wise false
 * alarm rate alpha = 1e-3 the Bonferroni bound gives the threshold
 *     z_crit = Phi^-1(1 - alpha / (2 L)),
 * e.g. 4.17 for L = 33.  (Estimates at nearby lags are positively
 * correlated, which makes Bonferroni conservative.)  The seeds are fixed,
 * so the outcome is deterministic; the threshold says that a correct
 * synthesis fails this test for at most one seed set in a thousand.
 *
 * The targets R are written here from their closed forms, independently of
 * the model layer. */
#include "../analysis/acf.h"
#include "../core/model.h"
#include "../synth/fft.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef double (*profile_fn)(double x, double y);

static double r_markov(double x, double y) { return exp(-hypot(x, y) / 8); }
static double r_gauss(double x, double y) { return exp(-(x * x + y * y) / 36); }
static double r_osc(double x, double y) { return cos(0.5 * x) * exp(-fabs(x) / 10) * cos(0.5 * y) * exp(-fabs(y) / 10); }
static double r_expr(double x, double y)
{
    double r = hypot(x, y);
    return 1.5 * exp(-r / 5) * (1 + r / 5);
}
static double r_ellipse(double x, double y)
{
    double a = 30 * M_PI / 180, u = cos(a) * x + sin(a) * y, v = (-sin(a) * x + cos(a) * y) / 0.4;
    return exp(-hypot(u, v) / 8);
}

/* C(d) on the periodic grid */
static double cov(profile_fn R, const size_t *n, long dx, long dy)
{
    dx = ((dx % (long)n[0]) + (long)n[0]) % (long)n[0];
    dy = ((dy % (long)n[1]) + (long)n[1]) % (long)n[1];
    if (dx > (long)n[0] / 2) dx -= (long)n[0];
    if (dy > (long)n[1] / 2) dy -= (long)n[1];
    return R((double)dx, (double)dy);
}

/* Exact variance of the unbiased estimate at lag (lx, ly) (Isserlis). */
static double est_variance(profile_fn R, const size_t *n, long lx, long ly)
{
    long mx = (long)n[0] - lx, my = (long)n[1] - ly;
    double s = 0;
    for (long dy = -(my - 1); dy <= my - 1; dy++)
        for (long dx = -(mx - 1); dx <= mx - 1; dx++) {
            double w = (double)(mx - labs(dx)) * (double)(my - labs(dy)), c = cov(R, n, dx, dy);
            s += w * (c * c + cov(R, n, dx + lx, dy + ly) * cov(R, n, dx - lx, dy - ly));
        }
    return s / ((double)mx * mx * (double)my * my);
}

/* Synthesise M realizations of `spec` on an n[0] x n[1] grid (n[1] = 1: 1D)
 * and test the ensemble-mean ACF at the given lags against R. */
static void check_model(const char *spec, profile_fn R, const size_t *n, size_t M, const long (*lags)[2],
                        size_t L)
{
    int dim = n[1] > 1 ? 2 : 1;
    nl_model *m;
    synth_fft_plan *p;
    nl_field *x, *full;
    double *sum = calloc(L, sizeof *sum), zcrit, zmax = 0;
    size_t worst = 0;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    cr_assert_eq(synth_fft_plan_alloc(m, dim, n, NULL, 0, &p), 0, "%s", spec);
    x = nl_field_alloc(dim, n, NULL, NULL);
    for (size_t s = 1; s <= M; s++) {
        cr_assert_eq(synth_fft_execute(p, s, x), 0);
        cr_assert_eq(an_acf_full(x, 0.0, AN_ACF_UNBIASED, &full), 0);
        for (size_t i = 0; i < L; i++) {
            /* the full estimate is wrapped on a 2n grid; lags here are >= 0 */
            sum[i] += full->data[(size_t)lags[i][1] * full->n[0] + (size_t)lags[i][0]];
        }
        nl_field_free(full);
    }
    zcrit = gsl_cdf_ugaussian_Qinv(1e-3 / (2.0 * (double)L));
    for (size_t i = 0; i < L; i++) {
        double target = R((double)lags[i][0], (double)lags[i][1]);
        double sd = sqrt(est_variance(R, n, lags[i][0], lags[i][1]) / (double)M);
        double z = (sum[i] / (double)M - target) / sd;
        if (fabs(z) > zmax)
            zmax = fabs(z), worst = i;
    }
    cr_log_info("%s: max |z| = %.2f at lag (%ld, %ld) over %zu lags, z_crit = %.2f", spec, zmax, lags[worst][0],
                lags[worst][1], L, zcrit);
    cr_expect_leq(zmax, zcrit, "%s: ensemble ACF at lag (%ld, %ld) is %.2f standard errors from the target "
                  "(threshold %.2f)", spec, lags[worst][0], lags[worst][1], zmax, zcrit);
    nl_field_free(x);
    synth_fft_plan_free(p);
    nl_model_free(m);
    free(sum);
}

static void check_1d(const char *spec, profile_fn R)
{
    static const size_t n[2] = {4096, 1};
    long lags[33][2];
    for (int i = 0; i < 33; i++)
        lags[i][0] = i, lags[i][1] = 0;
    check_model(spec, R, n, 200, (const long(*)[2])lags, 33);
}

/* 2D: lags along x, along y and along the diagonal, 0..10 each. */
static void check_2d(const char *spec, profile_fn R)
{
    static const size_t n[2] = {128, 128};
    long lags[31][2];
    int k = 0;
    for (int i = 0; i <= 10; i++)
        lags[k][0] = i, lags[k++][1] = 0;
    for (int i = 1; i <= 10; i++)
        lags[k][0] = 0, lags[k++][1] = i;
    for (int i = 1; i <= 10; i++)
        lags[k][0] = i, lags[k++][1] = i;
    check_model(spec, R, n, 64, (const long(*)[2])lags, 31);
}

static double r1_osc(double x, double y) { (void)y; return cos(0.5 * x) * exp(-fabs(x) / 10); }

Test(fft_stat, markov_1d) { check_1d("markov:scale=8", r_markov); }
Test(fft_stat, gauss_1d) { check_1d("gauss:scale=6", r_gauss); }
Test(fft_stat, oscillatory_1d) { check_1d("oscillatory:omega=0.5,scale=10", r1_osc); }
Test(fft_stat, expr_1d) { check_1d("expr:1.5*exp(-abs(t)/5)*(1+abs(t)/5)", r_expr); }
Test(fft_stat, markov_2d) { check_2d("markov:scale=8", r_markov); }
Test(fft_stat, gauss_2d) { check_2d("gauss:scale=6", r_gauss); }
Test(fft_stat, oscillatory_2d_separable) { check_2d("oscillatory:omega=0.5,scale=10,sep", r_osc); }
Test(fft_stat, expr_2d) { check_2d("expr:1.5*exp(-r/5)*(1+r/5)", r_expr); }
Test(fft_stat, ellipsoidal_2d) { check_2d("markov:scale=8,angle=30,ratio=0.4", r_ellipse); }
