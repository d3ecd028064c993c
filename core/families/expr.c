/* expr: an autocorrelation given as a libmatheval expression of the lag. */
#include "families_internal.h"
#include "../matheval_internal.h"
#include "../nl_error.h"

#include <matheval.h>
#include <stdlib.h>
#include <string.h>

static const nl_family_param params[] = {NL_PARAM_NUGGET};

static const char *const acf_names[] = {"t", "x", "y", "z", "r"};

double nl_expr_eval(const nl_model *m, const char *const *names, double *values, int n)
{
    return evaluator_evaluate(m->eval, n, (char **)names, values);
}

int nl_expr_compile(nl_model *m, const char *arg, const char *allowed)
{
    const char *name = m->fam->name;
    char **names;
    int count, st;
    if (!*arg)
        return NL_ERROR(NL_EINVAL, "%s: expected an expression after \"%s:\"", name, name);
    if ((st = nl_matheval_create(name, arg, &m->eval)))
        return st;
    evaluator_get_variables(m->eval, &names, &count);
    for (int i = 0; i < count; i++)
        if (!nl_model_word_in(allowed, names[i], strlen(names[i])))
            return NL_ERROR(NL_EINVAL, "%s: unknown variable \"%s\" in \"%s\" (expected %s)", name, names[i], arg,
                            allowed);
    return NL_OK;
}

static int parse_argument(nl_model *m, const char *arg) { return nl_expr_compile(m, arg, "t x y z r"); }

static double profile(const nl_model *m, double t)
{
    double v[] = {t, t, 0, 0, fabs(t)};
    return nl_expr_eval(m, acf_names, v, 5);
}

static double acf_stretched(const nl_model *m, double u, double v, double w, double r)
{
    double x[] = {r, u, v, w, r};
    return nl_expr_eval(m, acf_names, x, 5);
}

int nl_expr_isotropic(const nl_model *m)
{
    char **names;
    int n;
    evaluator_get_variables(m->eval, &names, &n);
    for (int i = 0; i < n; i++)
        if (strchr("xyz", names[i][0]) || strcmp(names[i], "fx") == 0 || strcmp(names[i], "fy") == 0 ||
            strcmp(names[i], "fz") == 0)
            return 0;
    return 1;
}

/* R is a function of t (= x in 1D) and r = |t|: d/dt = d/dt + sign(t) d/dr,
 * by libmatheval's symbolic derivative. */
static double acf_d2(const nl_model *m, double t)
{
    double v[] = {t, t, 0, 0, fabs(t)}, y;
    void *d1, *d2, *dr1, *dr2;
    d1 = evaluator_derivative(m->eval, "t");
    dr1 = evaluator_derivative(m->eval, "r");
    if (!d1 || !dr1) {
        if (d1) evaluator_destroy(d1);
        if (dr1) evaluator_destroy(dr1);
        return NAN;
    }
    d2 = evaluator_derivative(d1, "t");
    dr2 = evaluator_derivative(dr1, "r");
    y = d2 && dr2 ? evaluator_evaluate(d2, 5, (char **)acf_names, v) + evaluator_evaluate(dr2, 5, (char **)acf_names, v)
                  : NAN;
    if (d2) evaluator_destroy(d2);
    if (dr2) evaluator_destroy(dr2);
    evaluator_destroy(d1);
    evaluator_destroy(dr1);
    return y;
}

const nl_family nl_family_expr = {
    .name = "expr",
    .aliases = "",
    .argument = "EXPR",
    .usage = "variables t, x, y, z, r",
    .formula = "R = EXPR (libmatheval syntax), e.g. expr:cos(10*t)*exp(-abs(t))",
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
