/* Ensemble ACF against the target with Isserlis-derived bands. */
#include "stat.h"
#include "../analysis/verdict.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

typedef struct {
    stat_profile R; /* the target */
    const size_t *n; /* grid */
    int periodic;    /* wrap offsets onto the torus */
} cov_ctx;

static double cov(long dx, long dy, void *ctx)
{
    const cov_ctx *c = ctx;
    if (c->periodic) {
        dx = ((dx % (long)c->n[0]) + (long)c->n[0]) % (long)c->n[0];
        dy = ((dy % (long)c->n[1]) + (long)c->n[1]) % (long)c->n[1];
        if (dx > (long)c->n[0] / 2) dx -= (long)c->n[0];
        if (dy > (long)c->n[1] / 2) dy -= (long)c->n[1];
    }
    return c->R((double)dx, (double)dy);
}

double stat_check_acf(const char *name, stat_synth fn, void *ctx, const size_t *n, stat_profile R, int periodic,
                      size_t M, const long (*lags)[2], size_t L)
{
    int dim = n[1] > 1 ? 2 : 1;
    nl_field *x = nl_field_alloc(dim, n, NULL, NULL);
    double *mean = calloc(L, sizeof *mean), *se = calloc(L, sizeof *se), *target = calloc(L, sizeof *target);
    double zcrit, zmax;
    size_t worst;
    cov_ctx cc = {R, n, periodic};
    nl_verdict *v;
    cr_assert_eq(nl_verdict_alloc(dim, n, L, lags, &v), 0);
    for (size_t s = 1; s <= M; s++) {
        cr_assert_eq(fn(ctx, s, x), 0, "%s: synthesis failed", name);
        cr_assert_eq(nl_verdict_add(v, x), 0);
    }
    cr_assert_eq(nl_verdict_stats(v, mean, NULL), 0);
    zcrit = nl_verdict_threshold(1e-3, L, 0);
    for (size_t i = 0; i < L; i++) {
        target[i] = R((double)lags[i][0], (double)lags[i][1]);
        se[i] = sqrt(nl_verdict_isserlis_var(cov, &cc, n, lags[i][0], lags[i][1]) / (double)M);
    }
    zmax = nl_verdict_zmax(L, mean, se, target, &worst);
    cr_log_info("%s: max |z| = %.2f at lag (%ld, %ld) over %zu lags, z_crit = %.2f", name, zmax, lags[worst][0],
                lags[worst][1], L, zcrit);
    cr_expect_leq(zmax, zcrit, "%s: ensemble ACF at lag (%ld, %ld) is %.2f standard errors from the target "
                  "(threshold %.2f)", name, lags[worst][0], lags[worst][1], zmax, zcrit);
    nl_verdict_free(v);
    nl_field_free(x);
    free(mean), free(se), free(target);
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
