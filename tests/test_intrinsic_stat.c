/* synth intrinsic (synth/intrinsic.h) reproduces the power variogram:
 * over an ensemble, the mean squared increment at each lag equals
 * 2 gamma(h) = 2 c |h|^alpha, and its log-log slope and constant are alpha
 * and log(2 c).
 *
 * Band, derived from the ensemble itself (honest under any dependence
 * within a realization): realization r gives v_r(h), the mean of
 * (Z(x+h) - Z(x))^2 over all pairs at lag h; the M realizations are
 * independent, so mean_r v_r(h) has standard error sd_r(v_r(h)) / sqrt(M)
 * and z(h) = (mean - 2 gamma(h)) / se is close to N(0, 1) (CLT, M = 200).
 * The slope and intercept of least squares of log mean v(h) on log |h|
 * over the L lags have their standard errors by the delete-one jackknife
 * over realizations.  Family-wise false alarm 1e-3 over the L lags plus
 * the 2 fit numbers (Bonferroni): |z| <= Phi^-1(1 - 1e-3 / (2 (L + 2))),
 * 4.41 for L = 96 (2D: x, y, diagonal), 4.18 for L = 32 (1D).
 * Power: the same statistics reject the data when told alpha + 0.2 (each
 * test asserts it), and they fail with the plane term of the 2D
 * construction dropped (synth/intrinsic.c, add_plane: tried). */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/intrinsic.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

#define M 200      /* realizations */
#define LMAX 32    /* lags 1..LMAX per direction */
#define MAXL (3 * LMAX)

typedef struct {
    int dim;
    size_t n[2];
    long lag[MAXL][2]; /* lag vectors in samples */
    size_t L;
    double v[M][MAXL]; /* v_r(h) */
} ensemble;

/* Mean squared increment of f at lag (dx, dy) samples, dx, dy >= 0. */
static double sq_increment(const nl_field *f, long dx, long dy)
{
    size_t n0 = f->n[0], n1 = f->dim == 2 ? f->n[1] : 1, c = 0;
    double s = 0;
    for (size_t j = 0; j + (size_t)dy < n1; j++)
        for (size_t i = 0; i + (size_t)dx < n0; i++, c++) {
            double d = f->data[(j + dy) * n0 + i + dx] - f->data[j * n0 + i];
            s += d * d;
        }
    return s / (double)c;
}

static void run(ensemble *e, const char *spec)
{
    nl_model *m = test_model(spec);
    nl_synth_intrinsic_plan *p;
    int st;
    cr_assert_eq(nl_synth_intrinsic_plan_alloc(m, e->dim, e->n, NULL, &p), NL_OK, "%s", nl_errmsg());
    nl_field *f = nl_field_alloc(e->dim, e->n, NULL, &st);
    cr_assert(f);
    e->L = 0;
    for (long h = 1; h <= LMAX; h++) {
        e->lag[e->L][0] = h, e->lag[e->L++][1] = 0;
        if (e->dim == 2) {
            e->lag[e->L][0] = 0, e->lag[e->L++][1] = h;
            e->lag[e->L][0] = h, e->lag[e->L++][1] = h;
        }
    }
    for (int r = 0; r < M; r++) {
        cr_assert_eq(nl_synth_intrinsic_execute(p, 1000 + (uint64_t)r, f), NL_OK, "%s", nl_errmsg());
        for (size_t l = 0; l < e->L; l++)
            e->v[r][l] = sq_increment(f, e->lag[l][0], e->lag[l][1]);
    }
    nl_field_free(f), nl_synth_intrinsic_plan_free(p), nl_model_free(m);
}

/* Least squares of log(mean v) on log|h| over the ensemble less
 * realization `skip` (-1: none): slope and intercept. */
static void loglog(const ensemble *e, int skip, double *slope, double *icept)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, k = (double)e->L;
    for (size_t l = 0; l < e->L; l++) {
        double mean = 0, x = 0.5 * log((double)(e->lag[l][0] * e->lag[l][0] + e->lag[l][1] * e->lag[l][1]));
        for (int r = 0; r < M; r++)
            mean += r == skip ? 0 : e->v[r][l];
        double y = log(mean / (M - (skip >= 0)));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    *slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    *icept = (sy - *slope * sx) / k;
}

/* The largest |z| of the lags and, without a nugget, of the slope and
 * constant, for the model 2 (nugget + c |h|^alpha); prints the fit with
 * its band. */
static double largest_z(const ensemble *e, double alpha, double c, double nugget, const char *what)
{
    double zmax = 0, b, a, jb[M], ja[M], mb = 0, ma = 0, sb = 0, sa = 0;
    for (size_t l = 0; l < e->L; l++) {
        double mean = 0, ss = 0, h = hypot((double)e->lag[l][0], (double)e->lag[l][1]);
        for (int r = 0; r < M; r++)
            mean += e->v[r][l] / M;
        for (int r = 0; r < M; r++)
            ss += (e->v[r][l] - mean) * (e->v[r][l] - mean);
        zmax = fmax(zmax, fabs(mean - 2 * (nugget + c * pow(h, alpha))) / sqrt(ss / (M - 1) / M));
    }
    if (nugget > 0)
        return zmax;
    loglog(e, -1, &b, &a);
    for (int r = 0; r < M; r++)
        loglog(e, r, jb + r, ja + r), mb += jb[r] / M, ma += ja[r] / M;
    for (int r = 0; r < M; r++)
        sb += (jb[r] - mb) * (jb[r] - mb), sa += (ja[r] - ma) * (ja[r] - ma);
    sb = sqrt((M - 1.0) / M * sb), sa = sqrt((M - 1.0) / M * sa);
    fprintf(stderr, "%s, told alpha=%g: slope %.4f +- %.4f, 2c = exp(intercept) %.4f (log +- %.4f), "
            "largest lag |z| %.2f\n", what, alpha, b, sb, exp(a), sa, zmax);
    zmax = fmax(zmax, fabs(b - alpha) / sb);
    return fmax(zmax, fabs(a - log(2 * c)) / sa);
}

static void check(int dim, size_t n0, size_t n1, double alpha, double c, double nugget)
{
    static ensemble e;
    char spec[128], what[256];
    e.dim = dim, e.n[0] = n0, e.n[1] = n1;
    snprintf(spec, sizeof spec, "powvar:alpha=%g,c=%g,nugget=%g", alpha, c, nugget);
    run(&e, spec);
    double zc = gsl_cdf_ugaussian_Qinv(1e-3 / (2.0 * (double)(e.L + 2)));
    snprintf(what, sizeof what, "%s on %zux%zu, %d realizations (band |z| <= %.2f)", spec, n0, n1, M, zc);
    double z = largest_z(&e, alpha, c, nugget, what), zwrong = largest_z(&e, alpha + 0.2, c, nugget, what);
    cr_expect_leq(z, zc, "%s: largest |z| %.2f", what, z);
    cr_expect_gt(zwrong, zc, "%s: told alpha=%g, the test does not reject (|z| %.2f)", what, alpha + 0.2, zwrong);
}

Test(intrinsic_stat_slow, power_variogram_2d_alpha_1, .timeout = 60) { check(2, 128, 128, 1.0, 1.0, 0); }
Test(intrinsic_stat_slow, power_variogram_2d_alpha_1_5, .timeout = 60) { check(2, 128, 128, 1.5, 2.385, 0); }
Test(intrinsic_stat_slow, power_variogram_2d_alpha_1_8, .timeout = 60) { check(2, 128, 128, 1.8, 1.0, 0); }
Test(intrinsic_stat, power_variogram_1d_alpha_0_5, .timeout = 60) { check(1, 1024, 1, 0.5, 1.0, 0); }
Test(intrinsic_stat, power_variogram_1d_alpha_1_5, .timeout = 60) { check(1, 1024, 1, 1.5, 0.7, 0); }
/* the nugget adds white noise: 2 gamma(h) = 2 (nugget + c |h|^alpha) off lag 0 */
Test(intrinsic_stat, power_variogram_1d_nugget, .timeout = 60) { check(1, 1024, 1, 1.0, 0.5, 0.25); }
