/* Trans-Gaussian kriging (Cressie 1993, section 3.2.2, eq. (3.2.40)) with
 * the Box-Cox transform, as gstat's R/krigeTg.R: ordinary kriging of the
 * transformed data, back-transformed with the bias correction around the
 * neighbourhood's generalised-least-squares mean. */
#include "krige_flavours.h"
#include "krige_flavours_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* krigeTg.R's phi, phiPrime and phiDouble; NAN where lambda y + 1 <= 0. */
static double phi(double y, double lambda)
{
    return lambda == 0 ? exp(y) : lambda * y + 1 > 0 ? pow(lambda * y + 1, 1 / lambda) : NAN;
}

static double phi1(double y, double lambda)
{
    return lambda == 0 ? exp(y) : lambda * y + 1 > 0 ? pow(lambda * y + 1, 1 / lambda - 1) : NAN;
}

static double phi2(double y, double lambda)
{
    return lambda == 0 ? exp(y) : lambda * y + 1 > 0 ? (1 - lambda) * pow(lambda * y + 1, 1 / lambda - 2) : NAN;
}

static int check_lambda(double lambda)
{
    if (!(fabs(lambda) <= 5))
        return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: Box-Cox lambda %g; expected a number in [-5, 5]", lambda);
    return NL_OK;
}

int nl_krige_tg_transform(double lambda, size_t n, const double *val, double *out)
{
    int st = check_lambda(lambda);
    if (st)
        return st;
    for (size_t i = 0; i < n; i++) {
        double z = val[i], y;
        if (!(z > 0) || !isfinite(z))
            return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: the value of point %zu is %g; expected a finite "
                            "positive value (Box-Cox)", i + 1, z);
        y = lambda == 0 ? log(z) : (pow(z, lambda) - 1) / lambda;
        if (!isfinite(y))
            return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: the value of point %zu, %g, transforms to %g with "
                            "lambda %g; expected a finite transform", i + 1, z, y, lambda);
        out[i] = y;
    }
    return NL_OK;
}

/* Cressie (3.2.40) at one location; NL_EINVAL where phi is undefined. */
static int back(const nl_krige_local *k, const nl_kf_out *o, double lambda, const double *x, double *est, double *var)
{
    double e = phi(o->est, lambda) + phi2(o->mu, lambda) * (o->var / 2 - o->lag);
    double d = phi1(o->mu, lambda), v = d * d * o->var;
    char at[64];
    if (!isfinite(e) || !isfinite(v))
        return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: at %s the estimate %g (mean %g) has no back-transform with "
                        "lambda %g (lambda y + 1 must be positive); expected data nearer a Box-Cox normal, or "
                        "another lambda", nl_kl_where(k, x, at), o->est, o->mu, lambda);
    *est = e;
    if (var)
        *var = v;
    return NL_OK;
}

/* The kriged transforms at count locations (cv: the data, each left out). */
static int tg_run(const nl_krige_local *k, const nl_krige_block *b, double lambda, size_t count, const double *x,
                  int cv, double *est, double *var)
{
    nl_kf_support s;
    int st = check_lambda(lambda);
    if (st)
        return st;
    if (k->o.drift != NL_DRIFT_CONSTANT)
        return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: expected ordinary kriging (a constant unknown mean, as "
                        "krigeTg), got %s", k->o.drift == NL_DRIFT_NONE ? "simple kriging" : "a polynomial drift");
    if ((st = nl_kf_support_init(k, b, &s)))
        return st;
    nl_kf_out *o = malloc((count ? count : 1) * sizeof *o);
    if (!o) {
        nl_kf_support_free(&s);
        return NL_ERROR(NL_ENOMEM, "trans-Gaussian kriging: out of memory for %zu locations", count);
    }
    if (!(st = nl_kf_run(k, &s, count, x, cv, o)))
        for (size_t t = 0; t < count && !st; t++)
            st = back(k, &o[t], lambda, (cv ? k->pts : x) + t * (size_t)k->dim, &est[t], var ? &var[t] : NULL);
    free(o);
    nl_kf_support_free(&s);
    return st;
}

int nl_krige_tg_eval(const nl_krige_local *k, const nl_krige_block *b, double lambda, size_t count, const double *x,
                     double *est, double *var)
{
    return tg_run(k, b, lambda, count, x, 0, est, var);
}

int nl_krige_tg_cv(const nl_krige_local *k, double lambda, const double *orig, double *pred, double *var,
                   nl_krige_cv_summary *s)
{
    int st = tg_run(k, NULL, lambda, k->n, NULL, 1, pred, var);
    if (st)
        return st;
    double se = 0, sz = 0, se2 = 0, sz2 = 0, n = (double)k->n;
    for (size_t i = 0; i < k->n; i++) {
        if (!(var[i] > 0))
            return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: cross-validation: the variance at datum %zu is %g; "
                            "expected a positive variance (duplicate points?)", i + 1, var[i]);
        double e = orig[i] - pred[i], z = e / sqrt(var[i]);
        se += e, sz += z, se2 += e * e, sz2 += z * z;
    }
    s->mean_error = se / n, s->mean_z = sz / n, s->rmse = sqrt(se2 / n);
    s->var_error = (se2 - se * se / n) / (n - 1), s->var_z = (sz2 - sz * sz / n) / (n - 1);
    if (!(isfinite(s->rmse) && isfinite(s->var_error) && isfinite(s->var_z)))
        return NL_ERROR(NL_EINVAL, "trans-Gaussian kriging: cross-validation: the squared errors overflow (mean "
                        "error %g); expected values of smaller magnitude", s->mean_error);
    return NL_OK;
}
