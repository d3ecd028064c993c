/* expr: an autocorrelation given as an expression of the lag
 * (core/expr_internal.h); a removable singularity (sin(r)/r at 0) is
 * evaluated as its limit. */
#include "families_internal.h"
#include "../expr_internal.h"
#include "../nl_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const nl_family_param params[] = {NL_PARAM_NUGGET};

static const char *const acf_names[] = {"t", "x", "y", "z", "r"};

typedef struct {
    const nl_model *m;
    nl_expr_vars_fn vars;
} at_ctx;

static double at(void *ctx, const double *p)
{
    const at_ctx *c = ctx;
    double v[5];
    c->vars(p, v);
    return nl_expr_eval(c->m->eval, v);
}

double nl_expr_model_eval(const nl_model *m, nl_expr_vars_fn vars, const double *p, int dim)
{
    at_ctx c = {m, vars};
    double y = at(&c, p), l;
    if (isfinite(y))
        return y;
    l = nl_expr_limit(at, &c, p, dim);
    return isnan(l) ? y : l;
}

int nl_expr_model_compile(nl_model *m, const char *arg, const char *const *names, size_t n)
{
    const char *name = m->fam->name, *bad;
    int st;
    if (!*arg)
        return NL_ERROR(NL_EINVAL, "%s: expected an expression after \"%s:\"", name, name);
    if ((st = nl_expr_create(name, arg, &m->eval)))
        return st;
    if ((bad = nl_expr_bind(m->eval, names, n))) {
        char list[64] = "";
        for (size_t i = 0; i < n; i++)
            snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", i ? " " : "", names[i]);
        return NL_ERROR(NL_EINVAL, "%s: unknown variable \"%s\" in \"%s\" (expected %s)", name, bad, arg, list);
    }
    return NL_OK;
}

static int parse_argument(nl_model *m, const char *arg) { return nl_expr_model_compile(m, arg, acf_names, 5); }

/* the 1D lag t: x = t, r = |t| */
static void vars_1d(const double *p, double *v)
{
    v[0] = v[1] = p[0], v[2] = v[3] = 0, v[4] = fabs(p[0]);
}

/* the stretched lag (u, v, w): t = r = its norm */
static void vars_3d(const double *p, double *v)
{
    v[0] = v[4] = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    v[1] = p[0], v[2] = p[1], v[3] = p[2];
}

static double profile(const nl_model *m, double t) { return nl_expr_model_eval(m, vars_1d, &t, 1); }

static double acf_stretched(const nl_model *m, double u, double v, double w, double r)
{
    double p[3] = {u, v, w};
    (void)r;
    /* in 2D w is 0: approach a singular point in the plane */
    return nl_expr_model_eval(m, vars_3d, p, w == 0 ? 2 : 3);
}

int nl_expr_isotropic(const nl_model *m)
{
    for (size_t i = 0; i < nl_expr_nvars(m->eval); i++) {
        const char *v = nl_expr_var(m->eval, i);
        if (strchr("xyz", v[0]) || strcmp(v, "fx") == 0 || strcmp(v, "fy") == 0 || strcmp(v, "fz") == 0)
            return 0;
    }
    return 1;
}

static double profile_at(void *m, const double *t) { return profile(m, *t); }

/* d^2 R / dt^2 of the 1D profile by extrapolated central differences
 * (core/expr_limit.c): within 1e-9 of -2 for exp(-t^2) at 0, about 1e-10
 * relative for the smooth profiles check meets; NAN at a kink. */
static double acf_d2(const nl_model *m, double t) { return nl_expr_d2(profile_at, (void *)m, t); }

const nl_family nl_family_expr = {
    .name = "expr",
    .aliases = "",
    .argument = "EXPR",
    .usage = "variables t, x, y, z, r",
    .formula = "R = EXPR (syntax and functions, Bessel and gamma functions among them: docs/expressions.md), "
               "e.g. expr:cos(10*t)*exp(-abs(t)) or expr:besselj(0, r); a removable singularity (sin(r)/r at 0) "
               "is taken as its limit",
    .flags = NL_FAMILY_EXPRESSION | NL_FAMILY_ARGUMENT,
    .validity = "as the expression: noiselab check measures it",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .parse_argument = parse_argument,
    .profile = profile,
    .acf_stretched = acf_stretched,
    .isotropic = nl_expr_isotropic,
    .acf_d2 = acf_d2,
};
