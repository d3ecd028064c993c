/* Ensemble ACF against the target with Isserlis-derived bands. */
#include "stat.h"
#include "../analysis/acf.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

static double cov(stat_profile R, const size_t *n, int periodic, long dx, long dy)
{
    if (periodic) {
        dx = ((dx % (long)n[0]) + (long)n[0]) % (long)n[0];
        dy = ((dy % (long)n[1]) + (long)n[1]) % (long)n[1];
        if (dx > (long)n[0] / 2) dx -= (long)n[0];
        if (dy > (long)n[1] / 2) dy -= (long)n[1];
    }
    return R((double)dx, (double)dy);
}

static double est_variance(stat_profile R, const size_t *n, int periodic, long lx, long ly)
{
    long mx = (long)n[0] - lx, my = (long)n[1] - ly;
    double s = 0;
    for (long dy = -(my - 1); dy <= my - 1; dy++)
        for (long dx = -(mx - 1); dx <= mx - 1; dx++) {
            double w = (double)(mx - labs(dx)) * (double)(my - labs(dy)), c = cov(R, n, periodic, dx, dy);
            s += w * (c * c + cov(R, n, periodic, dx + lx, dy + ly) * cov(R, n, periodic, dx - lx, dy - ly));
        }
    return s / ((double)mx * mx * (double)my * my);
}

double stat_check_acf(const char *name, stat_synth fn, void *ctx, const size_t *n, stat_profile R, int periodic,
                      size_t M, const long (*lags)[2], size_t L)
{
    int dim = n[1] > 1 ? 2 : 1;
    nl_field *x = nl_field_alloc(dim, n, NULL, NULL), *full;
    double *sum = calloc(L, sizeof *sum), zcrit, zmax = 0;
    size_t worst = 0;
    for (size_t s = 1; s <= M; s++) {
        cr_assert_eq(fn(ctx, s, x), 0, "%s: synthesis failed", name);
        cr_assert_eq(nl_acf_full(x, 0.0, NL_ACF_UNBIASED, &full), 0);
        for (size_t i = 0; i < L; i++)
            sum[i] += full->data[(size_t)lags[i][1] * full->n[0] + (size_t)lags[i][0]];
        nl_field_free(full);
    }
    zcrit = gsl_cdf_ugaussian_Qinv(1e-3 / (2.0 * (double)L));
    for (size_t i = 0; i < L; i++) {
        double target = R((double)lags[i][0], (double)lags[i][1]);
        double sd = sqrt(est_variance(R, n, periodic, lags[i][0], lags[i][1]) / (double)M);
        double z = (sum[i] / (double)M - target) / sd;
        if (fabs(z) > zmax)
            zmax = fabs(z), worst = i;
    }
    cr_log_info("%s: max |z| = %.2f at lag (%ld, %ld) over %zu lags, z_crit = %.2f", name, zmax, lags[worst][0],
                lags[worst][1], L, zcrit);
    cr_expect_leq(zmax, zcrit, "%s: ensemble ACF at lag (%ld, %ld) is %.2f standard errors from the target "
                  "(threshold %.2f)", name, lags[worst][0], lags[worst][1], zmax, zcrit);
    nl_field_free(x);
    free(sum);
    return zmax;
}

size_t stat_lags_1d(long (*lags)[2])
{
    for (int i = 0; i < 33; i++)
        lags[i][0] = i, lags[i][1] = 0;
    return 33;
}

size_t stat_lags_2d(long (*lags)[2])
{
    size_t k = 0;
    for (int i = 0; i <= 10; i++)
        lags[k][0] = i, lags[k++][1] = 0;
    for (int i = 1; i <= 10; i++)
        lags[k][0] = 0, lags[k++][1] = i;
    for (int i = 1; i <= 10; i++)
        lags[k][0] = i, lags[k++][1] = i;
    return k;
}
