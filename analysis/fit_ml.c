/* Maximum likelihood and REML fits of a covariance model to scattered data
 * (Patterson and Thompson 1971; Mardia and Marshall 1984), with GSL's
 * Cholesky factorisation and Nelder-Mead simplex. */
#include "fit_internal.h"
#include "../core/field.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multimin.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Central-difference step of the Hessian in the transformed coordinates. */
#define ML_HSTEP 2e-3
#define ML_BAD NL_FIT_ML_BAD

typedef nl_fit_mldata ml_data;

/* C_ij = R(x_i - x_j), the nugget on the diagonal only: two data at one
 * place share the continuous part, not the white noise (the model's R(0)
 * has the nugget, so it is taken off there). */
static int fill_cov(ml_data *d)
{
    nl_model *m;
    int st = nl_fit_params_model(d->p, &m), dim = d->p->dim;
    double nugget;
    if (st)
        return st;
    nugget = nl_model_nugget(m);
    for (size_t i = 0; i < d->n; i++)
        for (size_t j = 0; j <= i; j++) {
            double lag[3] = {0, 0, 0}, c;
            for (int a = 0; a < dim; a++)
                lag[a] = d->x[i * (size_t)dim + (size_t)a] - d->x[j * (size_t)dim + (size_t)a];
            c = nl_model_acf(m, dim, lag);
            if (i != j && lag[0] == 0 && lag[1] == 0 && lag[2] == 0)
                c -= nugget;
            gsl_matrix_set(d->C, i, j, c);
        }
    nl_model_free(m);
    return NL_OK;
}

/* -2 l at the current parameters (ML_BAD where C is not positive definite). */
static double minus2l(ml_data *d)
{
    double logdet = 0, aa, ay, yy, q, n = (double)d->n;
    if (fill_cov(d) || gsl_linalg_cholesky_decomp1(d->C))
        return ML_BAD;
    for (size_t i = 0; i < d->n; i++) {
        logdet += 2 * log(gsl_matrix_get(d->C, i, i));
        gsl_vector_set(d->y, i, d->z[i]);
        gsl_vector_set(d->a, i, 1);
    }
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, d->C, d->y);
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, d->C, d->a);
    gsl_blas_ddot(d->a, d->a, &aa);
    gsl_blas_ddot(d->a, d->y, &ay);
    gsl_blas_ddot(d->y, d->y, &yy);
    d->beta = ay / aa;
    q = yy - ay * ay / aa;
    q = d->lik == NL_FIT_REML ? (n - 1) * log(2 * M_PI) + logdet + log(aa) + q : n * log(2 * M_PI) + logdet + q;
    return isfinite(q) ? q : ML_BAD;
}

double nl_fit_ml_minus2l_u(nl_fit_mldata *d, const double *u)
{
    nl_fit_params_from_u(d->p, u);
    return minus2l(d);
}

static double objective(const gsl_vector *u, void *params)
{
    return nl_fit_ml_minus2l_u(params, u->data);
}

static double at_u(ml_data *d, const double *u0, size_t i, double di, size_t j, double dj)
{
    double u[NL_FIT_MAX_PARAMS];
    gsl_vector_view v = gsl_vector_view_array(u, d->p->nfree);
    memcpy(u, u0, d->p->nfree * sizeof *u);
    u[i] += di;
    u[j] += dj;
    return objective(&v.vector, d);
}

/* A stencil value, NaN where the covariance is not positive definite (the
 * curvature there is not the likelihood's). */
static double stencil(ml_data *d, const double *u0, size_t i, double di, size_t j, double dj)
{
    double f = at_u(d, u0, i, di, j, dj);
    return f < ML_BAD ? f : NAN;
}

/* The covariance of u: the inverse of the Hessian of -l = (-2 l) / 2 by
 * central differences, where it is regular (nl_fit_info_check: flags the
 * free parameters in directions it is not, their entries NaN, the others
 * from the pseudo-inverse).  Returns the reciprocal condition number. */
static double ml_covariance(ml_data *d, const double *u0, double f0, double *cov, unsigned *flags)
{
    size_t k = d->p->nfree;
    double h = ML_HSTEP, hh[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS], info[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS];
    double rcond;
    int any = 0;
    gsl_matrix_view H = gsl_matrix_view_array(hh, k, k);
    for (size_t i = 0; i < k; i++)
        for (size_t j = 0; j <= i; j++) {
            double v = i == j ? (stencil(d, u0, i, h, j, 0) - 2 * f0 + stencil(d, u0, i, -h, j, 0)) / (h * h)
                              : (stencil(d, u0, i, h, j, h) - stencil(d, u0, i, h, j, -h) -
                                 stencil(d, u0, i, -h, j, h) + stencil(d, u0, i, -h, j, -h)) / (4 * h * h);
            hh[i * k + j] = hh[j * k + i] = v / 2;
        }
    memcpy(info, hh, k * k * sizeof *info);
    rcond = nl_fit_info_check(info, k, flags, cov);
    for (size_t i = 0; i < k; i++)
        any |= flags[i] != 0;
    /* all regular: the Cholesky inverse of the whole */
    if (!any && !gsl_linalg_cholesky_decomp1(&H.matrix) && !gsl_linalg_cholesky_invert(&H.matrix))
        memcpy(cov, hh, k * k * sizeof *cov);
    nl_fit_ml_minus2l_u(d, u0); /* restore the parameters (and beta) of u0 */
    return rcond;
}

/* Nelder-Mead from the current parameters, restarted once from its optimum
 * (a simplex can collapse before it reaches the minimum). */
static int ml_minimise(ml_data *d, nl_fit_result *res, double *u_out)
{
    size_t k = d->p->nfree;
    gsl_multimin_function F = {objective, k, d};
    gsl_multimin_fminimizer *s = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, k);
    gsl_vector *u = gsl_vector_alloc(k), *step = gsl_vector_alloc(k);
    int st = NL_OK;
    if (!s || !u || !step) {
        st = NL_ERROR(NL_ENOMEM, "out of memory");
        goto done;
    }
    nl_fit_params_to_u(d->p, u->data);
    for (int round = 0; round < 2; round++) {
        int it = 0, test = GSL_CONTINUE;
        gsl_vector_set_all(step, round ? 0.1 : 0.5);
        gsl_multimin_fminimizer_set(s, &F, u, step);
        while (test == GSL_CONTINUE && it++ < 2000) {
            if (gsl_multimin_fminimizer_iterate(s))
                break;
            test = gsl_multimin_test_size(gsl_multimin_fminimizer_size(s), 1e-5);
        }
        res->iterations += it;
        res->converged = test == GSL_SUCCESS;
        gsl_vector_memcpy(u, gsl_multimin_fminimizer_x(s));
    }
    memcpy(u_out, u->data, k * sizeof *u_out);
    res->objective = gsl_multimin_fminimizer_minimum(s);
    if (!(res->objective < ML_BAD))
        st = NL_ERROR(NL_EFAIL, "fit: no parameters of %s give a positive definite covariance of the data",
                      d->p->family);
done:
    gsl_vector_free(step);
    gsl_vector_free(u);
    gsl_multimin_fminimizer_free(s);
    return st;
}

/* Automatic start: the sample variance as the sill, the scale a tenth of the bounding box's diagonal (a fifth for the
 * spherical model's range), shape parameters 1. */
static void ml_start(nl_fit_params *p, const double *x, const double *z, size_t n, const double *start)
{
    double mean = 0, var = 0, diag = 0, safe = 0;
    for (size_t i = 0; i < n; i++)
        mean += z[i] / (double)n;
    for (size_t i = 0; i < n; i++)
        var += (z[i] - mean) * (z[i] - mean) / (double)(n - 1);
    for (int a = 0; a < p->dim; a++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < n; i++)
            lo = fmin(lo, x[i * (size_t)p->dim + (size_t)a]), hi = fmax(hi, x[i * (size_t)p->dim + (size_t)a]);
        diag += (hi - lo) * (hi - lo);
        safe = hypot(safe, hi - lo);
    }
    var = var > 0 ? var : 1;
    /* the sum of squares where it neither overflows nor underflows */
    diag = isfinite(diag) && diag >= DBL_MIN ? sqrt(diag) : safe;
    nl_fit_params_start(p, var, diag / 10, start);
}

static int fit_ml(const double *x, const double *z, size_t n, int dim, const nl_fit_options *o, nl_fit_result *res)
{
    nl_fit_params p;
    ml_data d;
    double u[NL_FIT_MAX_PARAMS], cov[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS];
    double lower[NL_FIT_MAX_PARAMS], upper[NL_FIT_MAX_PARAMS], rcond = 0;
    unsigned flags[NL_FIT_MAX_PARAMS] = {0};
    size_t nn[2] = {n, n};
    int st;
    memset(res, 0, sizeof *res);
    for (size_t k = 0; k < NL_FIT_MAX_PARAMS; k++)
        lower[k] = upper[k] = NAN;
    if ((st = nl_fit_params_init(o, dim, &p)))
        return st;
    if (p.nfree == 0)
        return NL_ERROR(NL_EINVAL, "fix: every parameter of %s is fixed; expected at least one free", p.family);
    if ((st = nl_fit_ml_check(&p, x, z, n, o)) || (st = nl_size_check(2, nn, sizeof(double), 1, NULL)))
        return st;
    ml_start(&p, x, z, n, o->start);
    d = (ml_data){&p, x, z, n, o->likelihood, gsl_matrix_alloc(n, n), gsl_vector_alloc(n), gsl_vector_alloc(n), 0};
    if (!d.C || !d.y || !d.a)
        st = NL_ERROR(NL_ENOMEM, "out of memory for the %zu x %zu covariance matrix", n, n);
    if (!st && !(st = ml_minimise(&d, res, u))) {
        nl_fit_params_at_bound(&p, flags);
        rcond = ml_covariance(&d, u, res->objective, cov, flags);
        if (o->intervals && (st = nl_fit_profile(&d, u, res->objective, cov, o->intervals, lower, upper, flags)))
            goto done;
        res->mean = d.beta;
        res->nobs = n;
        /* ML: the free covariance parameters and the mean */
        res->aic = res->objective + 2.0 * (double)(p.nfree + 1);
        if (!(st = nl_fit_params_result(&p, cov, lower, upper, res))) {
            nl_fit_result_flags(&p, flags, res);
            res->rcond = rcond;
        }
    }
done:
    gsl_vector_free(d.a);
    gsl_vector_free(d.y);
    gsl_matrix_free(d.C);
    return st;
}

int nl_fit_ml(const double *coords, const double *values, size_t n, int dim, const nl_fit_options *o,
              nl_fit_result *res)
{
    int st;
    nl_gsl_enter();
    st = fit_ml(coords, values, n, dim, o, res);
    nl_gsl_leave();
    return st;
}
