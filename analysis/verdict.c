/* Ensemble ACF against a target, with the tolerance from the estimator's variance. */
#include "verdict.h"
#include "acf.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct nl_verdict {
    nl_acf_plan *acf;  /* unbiased ACF of one realization, planned */
    nl_field *full;    /* its output grid */
    size_t nlags;      /* lags read */
    size_t *at;        /* their indices in full */
    size_t M;          /* realizations added */
    double *s1, *s2;   /* sums of r and r^2 per lag */
};

void nl_verdict_free(nl_verdict *v)
{
    if (!v)
        return;
    nl_acf_plan_free(v->acf);
    nl_field_free(v->full);
    free(v->at), free(v->s1), free(v->s2), free(v);
}

/* Index of lag (lx, ly, lz) in the full estimate of m[0] x m[1] x m[2]
 * samples, or SIZE_MAX outside it. */
static size_t lag_index(int dim, const size_t *m, const long *l)
{
    size_t at = 0;
    for (int a = dim - 1; a >= 0; a--) {
        if (labs(l[a]) >= (long)(m[a] / 2))
            return SIZE_MAX;
        at = at * m[a] + (size_t)(l[a] < 0 ? l[a] + (long)m[a] : l[a]);
    }
    for (int a = dim; a < 3; a++)
        if (l[a])
            return SIZE_MAX;
    return at;
}

int nl_verdict_alloc3(int dim, const size_t *n, size_t nlags, const long (*lags)[3], nl_verdict **out)
{
    nl_verdict *v;
    int st;
    *out = NULL;
    if (nlags == 0)
        return NL_ERROR(NL_EINVAL, "verdict: expected at least one lag");
    if (!(v = calloc(1, sizeof *v)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the verdict");
    if ((st = nl_acf_plan_alloc(dim, n, &v->acf)) || !(v->full = nl_acf_plan_output_alloc(v->acf, NULL, &st))) {
        nl_verdict_free(v);
        return st;
    }
    v->nlags = nlags;
    v->at = malloc(nlags * sizeof *v->at);
    v->s1 = calloc(nlags, sizeof *v->s1);
    v->s2 = calloc(nlags, sizeof *v->s2);
    if (!v->at || !v->s1 || !v->s2) {
        nl_verdict_free(v);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu lags", nlags);
    }
    for (size_t i = 0; i < nlags; i++)
        if ((v->at[i] = lag_index(dim, v->full->n, lags[i])) == SIZE_MAX) {
            nl_verdict_free(v);
            return NL_ERROR(NL_EINVAL, "verdict: lag (%ld, %ld, %ld) is outside the field", lags[i][0], lags[i][1],
                            lags[i][2]);
        }
    *out = v;
    return NL_OK;
}

int nl_verdict_alloc(int dim, const size_t *n, size_t nlags, const long (*lags)[2], nl_verdict **out)
{
    long (*l3)[3];
    int st;
    *out = NULL;
    if (nlags == 0)
        return NL_ERROR(NL_EINVAL, "verdict: expected at least one lag");
    if (!(l3 = malloc(nlags * sizeof *l3)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu lags", nlags);
    for (size_t i = 0; i < nlags; i++)
        l3[i][0] = lags[i][0], l3[i][1] = lags[i][1], l3[i][2] = 0;
    st = nl_verdict_alloc3(dim, n, nlags, (const long (*)[3])l3, out);
    free(l3);
    return st;
}

int nl_verdict_add(nl_verdict *v, const nl_field *x)
{
    int st = nl_acf_plan_execute(v->acf, x, 0.0, NL_ACF_UNBIASED, v->full);
    if (st)
        return st;
    for (size_t i = 0; i < v->nlags; i++) {
        double r = v->full->data[v->at[i]];
        v->s1[i] += r, v->s2[i] += r * r;
    }
    v->M++;
    return NL_OK;
}

size_t nl_verdict_count(const nl_verdict *v) { return v->M; }

int nl_verdict_stats(const nl_verdict *v, double *mean, double *se)
{
    double M = (double)v->M;
    if (v->M < (se ? 2u : 1u))
        return NL_ERROR(NL_EINVAL, "verdict: expected at least %d realizations, got %zu", se ? 2 : 1, v->M);
    for (size_t i = 0; i < v->nlags; i++) {
        double mu = v->s1[i] / M;
        mean[i] = mu;
        if (se)
            se[i] = sqrt(fmax(0, (v->s2[i] - M * mu * mu) / (M - 1))) / sqrt(M);
    }
    return NL_OK;
}

double nl_verdict_zmax(size_t L, const double *mean, const double *se, const double *target, size_t *worst)
{
    double zmax = 0;
    size_t w = 0;
    for (size_t i = 0; i < L; i++) {
        double z = fabs(mean[i] - target[i]) / fmax(se[i], 1e-300);
        if (z > zmax)
            zmax = z, w = i;
    }
    if (worst)
        *worst = w;
    return zmax;
}

double nl_verdict_threshold(double alpha, size_t ntests, size_t dof)
{
    double q;
    if (!(alpha > 0 && alpha < 1) || ntests == 0)
        return NAN;
    q = alpha / (2.0 * (double)ntests);
    nl_gsl_enter();
    q = dof ? gsl_cdf_tdist_Qinv(q, (double)dof) : gsl_cdf_ugaussian_Qinv(q);
    nl_gsl_leave();
    return q;
}

double nl_verdict_isserlis_var(nl_verdict_cov C, void *ctx, const size_t *n, long lx, long ly)
{
    long mx = (long)n[0] - lx, my = (long)n[1] - ly;
    double s = 0;
    for (long dy = -(my - 1); dy <= my - 1; dy++)
        for (long dx = -(mx - 1); dx <= mx - 1; dx++) {
            double w = (double)(mx - labs(dx)) * (double)(my - labs(dy)), c = C(dx, dy, ctx);
            s += w * (c * c + C(dx + lx, dy + ly, ctx) * C(dx - lx, dy - ly, ctx));
        }
    return s / ((double)mx * mx * (double)my * my);
}
