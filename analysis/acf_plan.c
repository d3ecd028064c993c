/* Planned autocorrelation estimates (Lewis 1987, eq. (15)) on the wrapped grid. */
#include "acf.h"
#include "../core/autocorr.h"
#include "../core/autocorr_plan.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdlib.h>

struct nl_acf_plan {
    nl_autocorr_plan *sums; /* the lag-product sums, planned */
};

int nl_acf_plan_alloc(int dim, const size_t *n, nl_acf_plan **out)
{
    nl_acf_plan *p;
    int st;
    *out = NULL;
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the autocorrelation plan");
    if ((st = nl_autocorr_plan_alloc(dim, n, &p->sums))) {
        free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

void nl_acf_plan_free(nl_acf_plan *p)
{
    if (!p)
        return;
    nl_autocorr_plan_free(p->sums);
    free(p);
}

nl_field *nl_acf_plan_output_alloc(const nl_acf_plan *p, const double *h, int *status)
{
    size_t m[3];
    int dim;
    nl_autocorr_plan_grid(p->sums, &dim, m);
    return nl_field_alloc(dim, m, h, status);
}

int nl_acf_plan_execute(nl_acf_plan *p, const nl_field *x, double mean, int unbiased, nl_field *c)
{
    int st = nl_estimate_check_range(x, mean, 0);
    if (!st)
        st = nl_autocorr_plan_execute(p->sums, x, isnan(mean) ? nl_field_mean(x) : mean, c);
    if (st)
        return st;
    for (size_t k = 0; k < c->n[2]; k++)
        for (size_t j = 0; j < c->n[1]; j++)
            for (size_t i = 0; i < c->n[0]; i++) {
                size_t idx[3] = {i, j, k};
                double w = unbiased ? 1.0 : (double)x->count;
                for (int a = 0; unbiased && a < x->dim; a++) {
                    long l = nl_wrap(idx[a], c->n[a]);
                    w *= (double)x->n[a] - fabs((double)l);
                }
                c->data[(k * c->n[1] + j) * c->n[0] + i] /= w > 0 ? w : 1.0;
            }
    return NL_OK;
}

int nl_acf_full(const nl_field *x, double mean, int unbiased, nl_field **out)
{
    nl_acf_plan *p;
    nl_field *c;
    int st;
    *out = NULL;
    if ((st = nl_acf_plan_alloc(x->dim, x->n, &p)))
        return st;
    c = nl_acf_plan_output_alloc(p, x->h, &st);
    if (c && (st = nl_acf_plan_execute(p, x, mean, unbiased, c))) {
        nl_field_free(c);
        c = NULL;
    }
    nl_acf_plan_free(p);
    *out = c;
    return c ? NL_OK : st;
}
