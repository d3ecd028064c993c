/* Statistical test: FFT-synthesised fields reproduce their target
 * autocorrelation (the derivation of the tolerance is in tests/stat.h).
 * FFT synthesis on a periodic grid has covariance exactly R at the wrapped
 * lag.  The targets are written here from their closed forms, independently
 * of the model layer. */
#include "stat.h"
#include "../core/model.h"
#include "../synth/fft.h"

#include <criterion/criterion.h>
#include <math.h>

static double r_markov(double x, double y) { return exp(-hypot(x, y) / 8); }
static double r_gauss(double x, double y) { return exp(-(x * x + y * y) / 36); }
static double r_osc(double x, double y) { return cos(0.5 * x) * exp(-fabs(x) / 10) * cos(0.5 * y) * exp(-fabs(y) / 10); }
static double r1_osc(double x, double y) { (void)y; return cos(0.5 * x) * exp(-fabs(x) / 10); }
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

static int run_fft(void *ctx, uint64_t seed, nl_field *out) { return nl_synth_fft_execute(ctx, seed, out); }

static void check(const char *spec, stat_profile R, int dim)
{
    size_t n[2] = {dim == 1 ? 4096 : 128, dim == 1 ? 1 : 128};
    long lags[64][2];
    size_t L = dim == 1 ? stat_lags_1d(lags) : stat_lags_2d(lags);
    nl_model *m;
    nl_synth_fft_plan *p;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, dim, n, NULL, 0, &p), 0, "%s", spec);
    stat_check_acf(spec, run_fft, p, n, R, 1, dim == 1 ? 200 : 64, (const long(*)[2])lags, L);
    nl_synth_fft_plan_free(p);
    nl_model_free(m);
}

Test(fft_stat, markov_1d) { check("markov:scale=8", r_markov, 1); }
Test(fft_stat, gauss_1d) { check("gauss:scale=6", r_gauss, 1); }
Test(fft_stat, oscillatory_1d) { check("oscillatory:omega=0.5,scale=10", r1_osc, 1); }
Test(fft_stat, expr_1d) { check("expr:1.5*exp(-abs(t)/5)*(1+abs(t)/5)", r_expr, 1); }
Test(fft_stat_slow, markov_2d) { check("markov:scale=8", r_markov, 2); }
Test(fft_stat, gauss_2d) { check("gauss:scale=6", r_gauss, 2); }
Test(fft_stat, oscillatory_2d_separable) { check("oscillatory:omega=0.5,scale=10,sep", r_osc, 2); }
Test(fft_stat_slow, expr_2d) { check("expr:1.5*exp(-r/5)*(1+r/5)", r_expr, 2); }
Test(fft_stat, ellipsoidal_2d) { check("markov:scale=8,angle=30,ratio=0.4", r_ellipse, 2); }

static double r_gosc1(double x, double y) { (void)y; return cos(0.4 * x) * exp(-x * x / 36); }
static double r_gosc2(double x, double y) { return r_gosc1(x, 0) * r_gosc1(y, 0); }
static double r_matern(double x, double y)
{
    double u = sqrt(3.0) * hypot(x, y) / 5;
    return (1 + u) * exp(-u);
}

Test(fft_stat, gauss_osc_1d) { check("gauss-osc:omega=0.4,scale=6", r_gosc1, 1); }
Test(fft_stat_slow, gauss_osc_2d_separable) { check("gauss-osc:omega=0.4,scale=6,sep", r_gosc2, 2); }
Test(fft_stat, matern_1d) { check("matern:nu=1.5,scale=5", r_matern, 1); }
Test(fft_stat, matern_2d) { check("matern:nu=1.5,scale=5", r_matern, 2); }
