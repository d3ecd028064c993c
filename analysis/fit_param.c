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

/* A parameter of structure t's family: a positive one is optimised as its
 * logarithm, one with an upper end hi as the logistic hi / (1 + e^-u).
 * given: the spec's value, a start (NaN: none). */
static void add(nl_fit_params *p, const nl_family_param *fp, size_t t, double given)
{
    if (p->composite)
        snprintf(p->name[p->np], sizeof p->name[0], "%s.%zu", fp->name, t + 1);
    else
        snprintf(p->name[p->np], sizeof p->name[0], "%s", fp->name);
    p->tr[p->np] = fp->range == NL_RANGE_UPTO ? NL_FIT_LOGIT : NL_FIT_LOG;
    p->hi[p->np] = fp->range == NL_RANGE_UPTO ? fp->hi : INFINITY;
    p->param[p->np] = fp;
    p->term[p->np] = t;
    p->given[p->np] = given;
    p->value[p->np] = NAN;
    p->np++;
}

static int apply_fixes(const nl_fit_options *o, nl_fit_params *p)
{
    for (size_t i = 0; i < o->nfix; i++) {
        int k = nl_fit_params_find(p, o->fix_name[i]);
        double v = o->fix_value[i];
        if (k < 0) {
            char list[512] = "";
            for (size_t j = 0; j < p->np; j++)
                snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", j ? ", " : "", p->name[j]);
            return NL_ERROR(NL_EINVAL, "fix: %s has no parameter \"%s\" (expected one of: %s)", p->family,
                            o->fix_name[i], list);
        }
        if (!isfinite(v) || v < 0 || (v == 0 && p->param[k]->role != NL_ROLE_NUGGET) ||
            (p->tr[k] == NL_FIT_LOGIT && v > p->hi[k]))
            return NL_ERROR(NL_EINVAL, "fix: %s=%g is out of range for %s", o->fix_name[i], v, p->family);
        p->value[k] = v;
        p->fixed[k] = 1;
    }
    return NL_OK;
}

/* Is nugget fixed, by name, in o? */
static int fix_named(const nl_fit_options *o, const nl_fit_params *p, size_t t)
{
    char name[24];
    if (p->composite)
        snprintf(name, sizeof name, "nugget.%zu", t + 1);
    else
        snprintf(name, sizeof name, "nugget");
    return fix_index(o, name) >= 0;
}

/* White noise alone (the nugget family): one parameter, the nugget's. */
static int pure_nugget(const nl_family *f)
{
    return f && f->nparams == 1 && f->params[0].role == NL_ROLE_NUGGET &&
           !(f->flags & (NL_FAMILY_SPECTRAL | NL_FAMILY_ARGUMENT | NL_FAMILY_INTRINSIC));
}

/* The value of key in the structure s's spec, where its spec gives one
 * (NAME=... after ':' or ','); NaN otherwise, and for s NULL. */
static double given(const nl_model *s, const char *key)
{
    const char *spec = s ? nl_model_spec(s) : NULL, *q = spec;
    size_t len = strlen(key);
    double v;
    while (q && (q = strstr(q, key)) != NULL) {
        if (q > spec && (q[-1] == ':' || q[-1] == ',') && q[len] == '=')
            return nl_model_param(s, key, &v) ? NAN : v;
        q += len;
    }
    return NAN;
}

/* The family's fitted parameters of structure t: var, scale, the nugget
 * (asked for, fixed, or given by the structure's spec), then the shape
 * parameters; s the structure's model (NULL: a bare family name, no
 * values given). */
static void add_family(const nl_fit_options *o, nl_fit_params *p, const nl_family *f, size_t t, const nl_model *s)
{
    static const nl_param_role first[] = {NL_ROLE_VARIANCE, NL_ROLE_SCALE};
    int nug = nl_family_role_index(f, NL_ROLE_NUGGET);
    for (size_t i = 0; i < 2; i++) {
        int k = nl_family_role_index(f, first[i]);
        if (k >= 0)
            add(p, &f->params[k], t, given(s, f->params[k].name));
    }
    if (pure_nugget(f))
        add(p, &f->params[0], t, given(s, f->params[0].name));
    else if (nug >= 0 && ((o->nugget && t == p->nugget_term) || fix_named(o, p, t) || !isnan(given(s, "nugget"))))
        add(p, &f->params[nug], t, given(s, "nugget"));
    for (size_t k = 0; k < f->nparams; k++)
        if (f->params[k].role == NL_ROLE_SHAPE)
            add(p, &f->params[k], t, given(s, f->params[k].name));
}

static int refuse_family(const nl_fit_options *o, const char *what)
{
    char list[512];
    nl_family_names(NL_FAMILY_FIT, 0, " or ", list, sizeof list);
    return NL_ERROR(NL_EINVAL, "model: expected %s, or a sum of them, got \"%s\"%s", list, o->family ? o->family : "",
                    what);
}

static int fittable(const nl_family *f)
{
    return f && (((f->flags & NL_FAMILY_FIT) && nl_family_role_index(f, NL_ROLE_VARIANCE) >= 0 &&
                  f->nparams <= NL_FAMILY_MAX_PARAMS) || pure_nugget(f));
}

/* A model spec (one structure with values, or a sum or product): every
 * structure of a family that can be fitted, isotropic; its values are
 * the starts (as gstat's vgm). */
static int init_spec(const nl_fit_options *o, nl_fit_params *p)
{
    nl_model *m;
    size_t n;
    int st = nl_model_parse(o->family, &m);
    if (st) {
        char why[512];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        return NL_ERROR(st, "model: %s", why);
    }
    n = nl_model_structures(m);
    if (n > NL_FIT_MAX_STRUCTURES) {
        nl_model_free(m);
        return NL_ERROR(NL_EINVAL, "model: %zu structures in \"%s\"; a fit takes at most %d", n, o->family,
                        NL_FIT_MAX_STRUCTURES);
    }
    p->nstruct = n;
    p->composite = n > 1;
    /* --nugget: on the first structure that takes nugget=, unless one is white noise already */
    p->nugget_term = NL_FIT_MAX_STRUCTURES;
    for (size_t t = n; t-- > 0;) {
        const nl_family *f = nl_model_family(nl_model_structure(m, t));
        if (pure_nugget(f)) {
            p->nugget_term = NL_FIT_MAX_STRUCTURES;
            break;
        }
        if (nl_family_role_index(f, NL_ROLE_NUGGET) >= 0)
            p->nugget_term = t;
    }
    for (size_t t = 0; t < n && !st; t++) {
        const nl_model *s = nl_model_structure(m, t);
        const nl_family *f = nl_model_family(s);
        char why[160];
        snprintf(why, sizeof why, " (structure %zu, %s%s)", t + 1, nl_model_spec(s),
                 fittable(f) ? ": anisotropy keys are not fitted" : "");
        if (!fittable(f) || !nl_model_is_isotropic(s) || p->np + f->nparams > NL_FIT_MAX_PARAMS)
            st = refuse_family(o, why);
        else {
            p->fam[t] = f;
            p->op[t] = nl_model_operator(m, t);
            add_family(o, p, f, t, s);
        }
    }
    nl_model_free(m);
    return st;
}

int nl_fit_params_init(const nl_fit_options *o, int dim, nl_fit_params *p)
{
    const nl_family *f;
    int st;
    memset(p, 0, sizeof *p);
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    if (o->nfix > NL_FIT_MAX_FIX)
        return NL_ERROR(NL_EINVAL, "fix: expected at most %d fixed parameters, got %zu", NL_FIT_MAX_FIX, o->nfix);
    p->family = o->family;
    p->dim = dim;
    if (o->family && o->family[strcspn(o->family, ":+*")]) {
        if ((st = init_spec(o, p)))
            return st;
    } else {
        f = o->family ? nl_family_find(o->family, strlen(o->family)) : NULL;
        if (!fittable(f) || nl_family_role_index(f, NL_ROLE_SCALE) < 0)
            return refuse_family(o, "");
        p->family = f->name;
        p->nstruct = 1;
        p->fam[0] = f;
        add_family(o, p, f, 0, NULL);
    }
    if ((st = apply_fixes(o, p)))
        return st;
    for (size_t k = 0; k < p->np; k++) {
        p->ulo[k] = -700, p->uhi[k] = 700;
        if (!p->fixed[k])
            p->free_idx[p->nfree++] = k;
    }
    return NL_OK;
}

void nl_fit_params_box(nl_fit_params *p, double hmin, double hmax, double var)
{
    for (size_t k = 0; k < p->np; k++) {
        nl_param_role r = p->param[k]->role;
        if (p->tr[k] != NL_FIT_LOG)
            continue;
        if (r == NL_ROLE_SCALE && hmin > 0 && hmax > 0)
            p->ulo[k] = log(hmin / 10), p->uhi[k] = log(NL_FIT_SCALE_REACH * hmax);
        if ((r == NL_ROLE_VARIANCE || r == NL_ROLE_NUGGET) && var > 0)
            p->uhi[k] = log(NL_FIT_VAR_REACH * var);
        /* a nugget this small is 0 (nl_fit_params_at_bound): no further */
        if (r == NL_ROLE_NUGGET && var > 0)
            p->ulo[k] = log(NL_FIT_NUGGET_FLOOR * var);
    }
}

/* Within this of an end of the search box (transformed units): at it. */
#define NL_FIT_BOX_TOL 1e-3

int nl_fit_params_runaway(const nl_fit_params *p, size_t k)
{
    size_t i = p->free_idx[k];
    nl_param_role r = p->param[i]->role;
    double u = p->tr[i] == NL_FIT_LOG ? log(p->value[i]) : 0;
    if (p->tr[i] != NL_FIT_LOG || p->uhi[i] >= 700)
        return 0;
    if ((r == NL_ROLE_SCALE || r == NL_ROLE_VARIANCE || r == NL_ROLE_NUGGET) && u >= p->uhi[i] - NL_FIT_BOX_TOL)
        return 1;
    return r == NL_ROLE_SCALE && u <= p->ulo[i] + NL_FIT_BOX_TOL;
}

/* A value held to its family's fit range (none: as is). */
static double clamp_fit(const nl_family_param *fp, double v)
{
    return fp->fit_hi > 0 ? fmin(fmax(v, fp->fit_lo), fp->fit_hi) : v;
}

/* Automatic starts: the sill split 9:1 between the variances and the
 * nuggets (all of it to the variances without a nugget), equally among
 * the structures with a variance; the scale times the family's factor,
 * spread over factors 2 apart among the structures of a sum. */
void nl_fit_params_start(nl_fit_params *p, double sill, double scale, const double *start)
{
    int nugget = nl_fit_params_has_nugget(p) || nl_fit_params_find(p, p->composite ? "nugget.1" : "nugget") >= 0;
    double nvar = 0;
    for (size_t k = 0; k < p->np; k++)
        nvar += p->param[k]->role == NL_ROLE_VARIANCE;
    for (size_t k = 0; k < p->np; k++) {
        const nl_family_param *fp = p->param[k];
        double spread = pow(2, (double)p->term[k] - 0.5 * (double)(p->nstruct - 1));
        double v = fp->role == NL_ROLE_SCALE ? scale * fp->start * spread : fp->role == NL_ROLE_NUGGET ? 0.1 * sill
                 : fp->role == NL_ROLE_VARIANCE ? (nugget ? 0.9 : 1) * sill / fmax(nvar, 1)
                 : fp->start_per_scale ? fp->start / scale : fp->start;
        if (isfinite(p->given[k]) && p->given[k] > 0)
            v = p->given[k];
        if (start && isfinite(start[k]) && start[k] > 0)
            v = start[k];
        if (!p->fixed[k])
            p->value[k] = clamp_fit(fp, v);
    }
}

int nl_fit_params_has_nugget(const nl_fit_params *p)
{
    for (size_t k = 0; k < p->np; k++)
        if (p->param[k]->role == NL_ROLE_NUGGET && (!p->fixed[k] || p->value[k] > 0))
            return 1;
    return 0;
}

/* At a bound: within NL_FIT_BOUND_REL of an end (a logistic parameter
 * approaches its upper end without reaching it); a nugget at its lower
 * end 0 when below NL_FIT_RCOND_MIN var (it changes C's diagonal by less
 * than the relative precision the information matrix keeps). */
#define NL_FIT_BOUND_REL 1e-4

void nl_fit_params_at_bound(const nl_fit_params *p, unsigned *flags)
{
    double var = 0;
    for (size_t k = 0; k < p->np; k++)
        if (p->param[k]->role == NL_ROLE_VARIANCE)
            var = fmax(var, p->value[k]);
    for (size_t k = 0; k < p->nfree; k++) {
        const nl_family_param *fp = p->param[p->free_idx[k]];
        double v = p->value[p->free_idx[k]];
        if (fp->fit_hi > 0 && (v <= fp->fit_lo * (1 + NL_FIT_BOUND_REL) || v >= fp->fit_hi * (1 - NL_FIT_BOUND_REL)))
            flags[k] |= NL_FIT_PARAM_AT_BOUND;
        if (fp->role == NL_ROLE_NUGGET && v <= NL_FIT_RCOND_MIN * var)
            flags[k] |= NL_FIT_PARAM_AT_BOUND;
        if (nl_fit_params_runaway(p, k))
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

/* Transformed coordinates are clamped to the search box (by default
 * -700..700, so that values stay normal doubles: a nugget heading to 0
 * stops at e^-700 var-units instead of underflowing), and shape parameters
 * to their family's fit range. */
void nl_fit_params_from_u(nl_fit_params *p, const double *u)
{
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        double x = fmax(p->ulo[i], fmin(p->uhi[i], u[k]));
        p->value[i] = clamp_fit(p->param[i], p->tr[i] == NL_FIT_LOG ? exp(x) : p->hi[i] / (1 + exp(-x)));
    }
}

double nl_fit_params_dvalue(const nl_fit_params *p, size_t k)
{
    size_t i = p->free_idx[k];
    double v = p->value[i];
    return p->tr[i] == NL_FIT_LOG ? v : v * (1 - v / p->hi[i]);
}

/* The spec of the current values: each structure's family and values
 * (its shape parameters first, as the catalogue writes them, when
 * shape_first), joined by its operator; prec significant digits. */
static int write_spec(const nl_fit_params *p, char *buf, size_t size, int prec, int shape_first)
{
    size_t len = 0;
    for (size_t t = 0; t < p->nstruct; t++) {
        len += (size_t)snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0, "%s:", p->fam[t]->name);
        for (int pass = 0; pass < 2; pass++)
            for (size_t k = 0; k < p->np; k++) {
                int shape = p->param[k]->role == NL_ROLE_SHAPE;
                if (p->term[k] != t || (shape_first && shape != (pass == 0)) || (!shape_first && pass))
                    continue;
                if (len < size)
                    len += (size_t)snprintf(buf + len, size - len, "%s%s=%.*g", buf[len - 1] == ':' ? "" : ",",
                                            p->param[k]->name, prec, p->value[k]);
            }
        if (t + 1 < p->nstruct && len < size)
            len += (size_t)snprintf(buf + len, size - len, " %c ", p->op[t]);
    }
    if (len >= size)
        return NL_ERROR(NL_EINVAL, "fit: the model spec does not fit in %zu bytes", size);
    return NL_OK;
}

int nl_fit_params_spec(const nl_fit_params *p, char *buf, size_t size) { return write_spec(p, buf, size, 8, 1); }

int nl_fit_params_model(const nl_fit_params *p, nl_model **m)
{
    char spec[1024];
    int st = write_spec(p, spec, sizeof spec, 17, 0);
    *m = NULL;
    return st ? st : nl_model_parse(spec, m);
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
    free(res->drift);
    free(res->drift_se);
    res->param = NULL;
    res->drift = res->drift_se = NULL;
    res->np = res->ndrift = 0;
}

int nl_fit_check_options(const nl_fit_options *o, int dim)
{
    nl_fit_params p;
    int st = nl_fit_params_init(o, dim, &p);
    if (!st && p.nfree == 0)
        st = NL_ERROR(NL_EINVAL, "fix: every parameter of %s is fixed; expected at least one free", p.family);
    return st;
}
