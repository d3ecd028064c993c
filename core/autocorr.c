/* FFT-based lag-product sums, one shot (core/autocorr_plan.c plans them). */
#include "autocorr.h"
#include "autocorr_plan.h"
#include "nl_error.h"

double nl_field_mean(const nl_field *x)
{
    double s = 0;
    for (size_t i = 0; i < x->count; i++)
        s += x->data[i];
    return s / (double)x->count;
}

int nl_autocorr_sums(const nl_field *x, double mean, nl_field **out)
{
    size_t m[3];
    int dim, st;
    nl_autocorr_plan *p;
    nl_field *c;

    *out = NULL;
    if ((st = nl_autocorr_plan_alloc(x->dim, x->n, &p)))
        return st;
    nl_autocorr_plan_grid(p, &dim, m);
    c = nl_field_alloc(dim, m, x->h, &st);
    if (c && (st = nl_autocorr_plan_execute(p, x, mean, c))) {
        nl_field_free(c);
        c = NULL;
    }
    nl_autocorr_plan_free(p);
    *out = c;
    return c ? NL_OK : st;
}
