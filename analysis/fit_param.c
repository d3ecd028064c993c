/* The parameters of a fit: names by family, fixes, transforms, specs. */
#include "fit_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

static int fix_index(const nl_fit_options *o, const char *name)
{
    for (size_t i = 0; i < o->nfix; i++)
        if (strcmp(o->fix_name[i], name) == 0)
            return (int)i;
    return -1;
}

/* A parameter of the family: a positive one is optimised as its
 * logarithm, one with an upper end hi as the logistic hi / (1 + e^-u). */
static void add(nl_fit_params *p, const nl_family_param *fp)
{
    p->name[p->np] = fp->name;
    p->tr[p->np] = fp->range == NL_RANGE_UPTO ? NL_FIT_LOGIT : NL_FIT_LOG;
    p->hi[p->np] = fp->range == NL_RANGE_UPTO ? fp->hi : INFINITY;
    p->param[p->np] = fp;
    p->value[p->np] = NAN;
    p->np++;
}

static int apply_fixes(const nl_fit_options *o, nl_fit_params *p)
{
    for (size_t i = 0; i < o->nfix; i++) {
        int k = nl_fit_params_find(p, o->fix_name[i]);
        double v = o->fix_value[i];
        if (k < 0) {
            char list[64] = "";
            for (size_t j = 0; j < p->np; j++)
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", j ? ", " : "", p->name[j]);
            return NL_ERROR(NL_EINVAL, "fix: %s has no parameter \"%s\" (expected one of: %s)", p->family,
                            o->fix_name[i], list);
        }
        if (!isfinite(v) || v < 0 || (v == 0 && strcmp(p->name[k], "nugget") != 0) ||
            (p->tr[k] == NL_FIT_LOGIT && v > p->hi[k]))
            return NL_ERROR(NL_EINVAL, "fix: %s=%g is out of range for %s", o->fix_name[i], v, p->family);
        p->value[k] = v;
        p->fixed[k] = 1;
    }
    return NL_OK;
}

int nl_fit_params_init(const nl_fit_options *o, int dim, nl_fit_params *p)
{
    const nl_family *f;
    int nug;
    memset(p, 0, sizeof *p);
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    if (o->nfix > NL_FIT_MAX_FIX)
        return NL_ERROR(NL_EINVAL, "fix: expected at most %d fixed parameters, got %zu", NL_FIT_MAX_FIX, o->nfix);
    f = o->family ? nl_family_find(o->family, strlen(o->family)) : NULL;
    if (!f || !(f->flags & NL_FAMILY_FIT) || nl_family_role_index(f, NL_ROLE_VARIANCE) < 0 ||
        nl_family_role_index(f, NL_ROLE_SCALE) < 0 || f->nparams > NL_FIT_MAX_PARAMS) {
        char list[512];
        nl_family_names(NL_FAMILY_FIT, 0, " or ", list, sizeof list);
        return NL_ERROR(NL_EINVAL, "model: expected %s, got \"%s\"", list, o->family ? o->family : "");
    }
    p->family = f->name;
    p->dim = dim;
    /* var, scale, the nugget when asked for, then the shape parameters */
    add(p, &f->params[nl_family_role_index(f, NL_ROLE_VARIANCE)]);
    add(p, &f->params[nl_family_role_index(f, NL_ROLE_SCALE)]);
    nug = nl_family_role_index(f, NL_ROLE_NUGGET);
    if (nug >= 0 && (o->nugget || fix_index(o, "nugget") >= 0))
        add(p, &f->params[nug]);
    for (size_t k = 0; k < f->nparams; k++)
        if (f->params[k].role == NL_ROLE_SHAPE)
            add(p, &f->params[k]);
    {
        int st = apply_fixes(o, p);
        if (st)
            return st;
    }
    for (size_t k = 0; k < p->np; k++)
        if (!p->fixed[k])
            p->free_idx[p->nfree++] = k;
    return NL_OK;
}

/* A value held to its family's fit range (none: as is). */
static double clamp_fit(const nl_family_param *fp, double v)
{
    return fp->fit_hi > 0 ? fmin(fmax(v, fp->fit_lo), fp->fit_hi) : v;
}

void nl_fit_params_start(nl_fit_params *p, double sill, double scale, const double *start)
{
    int nugget = nl_fit_params_find(p, "nugget") >= 0;
    for (size_t k = 0; k < p->np; k++) {
        const nl_family_param *fp = p->param[k];
        double v = fp->role == NL_ROLE_SCALE ? scale * fp->start : fp->role == NL_ROLE_NUGGET ? 0.1 * sill
                 : fp->role == NL_ROLE_VARIANCE ? (nugget ? 0.9 : 1) * sill
                 : fp->start_per_scale ? fp->start / scale : fp->start;
        if (start && isfinite(start[k]) && start[k] > 0)
            v = start[k];
        if (!p->fixed[k])
            p->value[k] = clamp_fit(fp, v);
    }
}

/* At a bound: within NL_FIT_BOUND_REL of an end (a logistic parameter
 * approaches its upper end without reaching it); a nugget at its lower
 * end 0 when below NL_FIT_RCOND_MIN var (it changes C's diagonal by less
 * than the relative precision the information matrix keeps). */
#define NL_FIT_BOUND_REL 1e-4

void nl_fit_params_at_bound(const nl_fit_params *p, unsigned *flags)
{
    for (size_t k = 0; k < p->nfree; k++) {
        const nl_family_param *fp = p->param[p->free_idx[k]];
        double v = p->value[p->free_idx[k]];
        if (fp->fit_hi > 0 && (v <= fp->fit_lo * (1 + NL_FIT_BOUND_REL) || v >= fp->fit_hi * (1 - NL_FIT_BOUND_REL)))
            flags[k] |= NL_FIT_PARAM_AT_BOUND;
        if (fp->role == NL_ROLE_NUGGET && v <= NL_FIT_RCOND_MIN * p->value[0])
            flags[k] |= NL_FIT_PARAM_AT_BOUND;
    }
}

int nl_fit_params_find(const nl_fit_params *p, const char *name)
{
    for (size_t k = 0; k < p->np; k++)
        if (strcmp(p->name[k], name) == 0)
            return (int)k;
    return -1;
}

void nl_fit_params_to_u(const nl_fit_params *p, double *u)
{
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        double v = p->value[i];
        u[k] = p->tr[i] == NL_FIT_LOG ? log(v) : -log(p->hi[i] / v - 1);
    }
}

/* Transformed coordinates are clamped so that values stay normal doubles
 * (a nugget heading to 0 stops at e^-700 var-units instead of underflowing),
 * and shape parameters to their family's fit range. */
void nl_fit_params_from_u(nl_fit_params *p, const double *u)
{
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        double x = fmax(-700, fmin(700, u[k]));
        p->value[i] = clamp_fit(p->param[i], p->tr[i] == NL_FIT_LOG ? exp(x) : p->hi[i] / (1 + exp(-x)));
    }
}

double nl_fit_params_dvalue(const nl_fit_params *p, size_t k)
{
    size_t i = p->free_idx[k];
    double v = p->value[i];
    return p->tr[i] == NL_FIT_LOG ? v : v * (1 - v / p->hi[i]);
}

int nl_fit_params_spec(const nl_fit_params *p, char *buf, size_t size)
{
    size_t len = (size_t)snprintf(buf, size, "%s:", p->family);
    /* the shape parameter first, as the catalogue writes it */
    for (size_t pass = 0; pass < 2; pass++)
        for (size_t k = 0; k < p->np; k++) {
            int shape = k >= 2 && strcmp(p->name[k], "nugget") != 0;
            if ((size_t)shape != 1 - pass)
                continue;
            if (len < size)
                len += (size_t)snprintf(buf + len, size - len, "%s%s=%.8g", buf[len - 1] == ':' ? "" : ",",
                                        p->name[k], p->value[k]);
        }
    if (len >= size)
        return NL_ERROR(NL_EINVAL, "fit: the model spec does not fit in %zu bytes", size);
    return NL_OK;
}

int nl_fit_params_model(const nl_fit_params *p, nl_model **m)
{
    char spec[512];
    size_t len = (size_t)snprintf(spec, sizeof spec, "%s:", p->family);
    for (size_t k = 0; k < p->np && len < sizeof spec; k++)
        len += (size_t)snprintf(spec + len, sizeof spec - len, "%s%s=%.17g", k ? "," : "", p->name[k], p->value[k]);
    *m = NULL;
    if (len >= sizeof spec)
        return NL_ERROR(NL_EINVAL, "fit: the model spec does not fit in %zu bytes", sizeof spec);
    return nl_model_parse(spec, m);
}

int nl_fit_params_result(const nl_fit_params *p, const double *cov, const double *lower, const double *upper,
                         nl_fit_result *res)
{
    int st;
    res->param = calloc(p->np, sizeof *res->param);
    if (!res->param)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    res->np = p->np;
    res->nfree = p->nfree;
    for (size_t k = 0; k < p->np; k++) {
        nl_fit_param *q = &res->param[k];
        snprintf(q->name, sizeof q->name, "%s", p->name[k]);
        q->value = p->value[k];
        q->fixed = p->fixed[k];
        q->se = 0;
        q->lower = lower ? lower[k] : NAN;
        q->upper = upper ? upper[k] : NAN;
    }
    for (size_t k = 0; k < p->nfree; k++) {
        double c = cov ? cov[k * p->nfree + k] : NAN;
        res->param[p->free_idx[k]].se = c >= 0 && isfinite(c) ? fabs(nl_fit_params_dvalue(p, k)) * sqrt(c) : NAN;
    }
    st = nl_fit_params_spec(p, res->spec, sizeof res->spec);
    if (st)
        nl_fit_result_free(res);
    return st;
}

void nl_fit_result_flags(const nl_fit_params *p, const unsigned *flags, nl_fit_result *res)
{
    res->flags = 0;
    for (size_t k = 0; k < p->nfree; k++) {
        nl_fit_param *q = &res->param[p->free_idx[k]];
        q->flags = flags[k];
        res->flags |= flags[k];
        if (flags[k])
            q->se = NAN;
        if (flags[k] & NL_FIT_PARAM_SINGULAR)
            q->lower = q->upper = NAN;
    }
}

void nl_fit_result_free(nl_fit_result *res)
{
    if (!res)
        return;
    free(res->param);
    res->param = NULL;
    res->np = 0;
}

int nl_fit_check_options(const nl_fit_options *o, int dim)
{
    nl_fit_params p;
    int st = nl_fit_params_init(o, dim, &p);
    if (!st && p.nfree == 0)
        st = NL_ERROR(NL_EINVAL, "fix: every parameter of %s is fixed; expected at least one free", p.family);
    return st;
}
