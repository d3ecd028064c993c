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

/* -2 l at the current parameters (ML_BAD where C or X' C^-1 X is not
 * positive definite).  With L L' = C, y = L^-1 z, A = L^-1 X, M = A' A:
 * beta = M^-1 A' y (GLS), r' C^-1 r = y' y - w' w with w = L_M^-1 A' y, and
 *   -2 l_ML   = n ln 2 pi + ln|C| + r' C^-1 r,
 *   -2 l_REML = (n - q) ln 2 pi + ln|C| + ln|X' C^-1 X| + r' C^-1 r
 * (Harville 1974, eq. (2) without its constant -ln|X' X|; Patterson and
 * Thompson 1971 for X = 1). */
static double minus2l(ml_data *d)
{
    double logdet = 0, logm = 0, yy, ww = 0, q, n = (double)d->n;
    if (fill_cov(d) || gsl_linalg_cholesky_decomp1(d->C))
        return ML_BAD;
    for (size_t i = 0; i < d->n; i++) {
        logdet += 2 * log(gsl_matrix_get(d->C, i, i));
        gsl_vector_set(d->y, i, d->z[i]);
    }
    gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, d->C, d->y);
    gsl_blas_ddot(d->y, d->y, &yy);
    if (d->q) {
        gsl_matrix_memcpy(d->A, d->X);
        gsl_blas_dtrsm(CblasLeft, CblasLower, CblasNoTrans, CblasNonUnit, 1.0, d->C, d->A);
        gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, d->A, d->A, 0.0, d->M);
        gsl_blas_dgemv(CblasTrans, 1.0, d->A, d->y, 0.0, d->beta);
        if (gsl_linalg_cholesky_decomp1(d->M))
            return ML_BAD;
        for (size_t a = 0; a < d->q; a++)
            logm += 2 * log(gsl_matrix_get(d->M, a, a));
        gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, d->M, d->beta);
        gsl_blas_ddot(d->beta, d->beta, &ww);
        gsl_blas_dtrsv(CblasLower, CblasTrans, CblasNonUnit, d->M, d->beta);
    }
    q = d->quad = yy - ww;
    q = d->lik == NL_FIT_REML ? (n - (double)d->q) * log(2 * M_PI) + logdet + logm + q
                              : n * log(2 * M_PI) + logdet + q;
    return isfinite(q) ? q : ML_BAD;
}

double nl_fit_ml_minus2l_u(nl_fit_mldata *d, const double *u)
{
    nl_fit_params_from_u(d->p, u);
    return minus2l(d);
}

double nl_fit_ml_penalty(const nl_fit_params *p, const double *u, size_t skip)
{
    double pen = 0;
    for (size_t k = 0; k < p->nfree; k++) {
        size_t i = p->free_idx[k];
        double out = u[k] > p->uhi[i] ? u[k] - p->uhi[i] : u[k] < p->ulo[i] ? p->ulo[i] - u[k] : 0;
        if (k != skip)
            pen += out * out;
    }
    return pen;
}

double nl_fit_ml_minus2l_box(nl_fit_mldata *d, const double *u, size_t skip)
{
    double f = nl_fit_ml_minus2l_u(d, u);
    return f < ML_BAD ? f + nl_fit_ml_penalty(d->p, u, skip) : f;
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

/* The smallest and largest distance between two data (O(n^2)). */
static void pair_range(const double *x, size_t n, int dim, double *hmin, double *hmax)
{
    size_t dd = (size_t)dim;
    *hmin = INFINITY, *hmax = 0;
    for (size_t i = 1; i < n; i++)
        for (size_t j = 0; j < i; j++) {
            double h = 0;
            for (size_t a = 0; a < dd; a++)
                h = hypot(h, x[i * dd + a] - x[j * dd + a]);
            if (h > 0)
                *hmin = fmin(*hmin, h), *hmax = fmax(*hmax, h);
        }
}

/* Automatic start: the sample variance as the sill, the scale a tenth of
 * the largest distance (a fifth for the spherical model's range), shape
 * parameters 1; then the search box. */
static void ml_start(ml_data *d, const double *start)
{
    double mean = 0, var = 0;
    size_t n = d->n;
    for (size_t i = 0; i < n; i++)
        mean += d->z[i] / (double)n;
    for (size_t i = 0; i < n; i++)
        var += (d->z[i] - mean) * (d->z[i] - mean) / (double)(n - 1);
    var = var > 0 ? var : 1;
    pair_range(d->x, n, d->p->dim, &d->hmin, &d->hmax);
    nl_fit_params_start(d->p, var, d->hmax / 10, start);
    nl_fit_params_box(d->p, d->hmin, d->hmax, var);
}

/* The drift coefficients and their standard errors into res (M holds the
 * Cholesky factor of X' C^-1 X at the optimum). */
static int drift_result(ml_data *d, nl_fit_result *res)
{
    size_t q = d->q;
    gsl_matrix *Mi;
    res->mean = q ? gsl_vector_get(d->beta, 0) : 0;
    if (!q)
        return NL_OK;
    res->drift = malloc(q * sizeof *res->drift);
    res->drift_se = malloc(q * sizeof *res->drift_se);
    if (!res->drift || !res->drift_se || !(Mi = gsl_matrix_alloc(q, q)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    res->ndrift = q;
    gsl_matrix_memcpy(Mi, d->M);
    gsl_linalg_cholesky_invert(Mi);
    for (size_t a = 0; a < q; a++) {
        res->drift[a] = gsl_vector_get(d->beta, a);
        res->drift_se[a] = sqrt(gsl_matrix_get(Mi, a, a));
    }
    gsl_matrix_free(Mi);
    return NL_OK;
}

/* Restarts from a lower profile point at most. */
#define ML_RESTARTS 3

/* The covariance of the estimates and the intervals at u; from a lower
 * profile point, a local optimisation and again. */
static int ml_finish(ml_data *d, const nl_fit_options *o, nl_fit_result *res, double *u, double *cov, double *lower,
                     double *upper, unsigned *flags, double *rcond)
{
    for (;;) {
        double better[NL_FIT_MAX_PARAMS];
        int st, conv;
        memset(flags, 0, d->p->nfree * sizeof *flags);
        nl_fit_ml_minus2l_u(d, u);
        nl_fit_params_at_bound(d->p, flags);
        *rcond = ml_covariance(d, u, res->objective, cov, flags);
        if (!o->intervals)
            return NL_OK;
        st = nl_fit_profile(d, u, res->objective, cov, o->intervals, lower, upper, flags, better);
        if (st != NL_FIT_PROFILE_LOWER || res->restarts >= ML_RESTARTS)
            return st == NL_FIT_PROFILE_LOWER ? NL_OK : st;
        res->restarts++;
        memcpy(u, better, d->p->nfree * sizeof *u);
        res->objective = nl_fit_ml_refine(d, u, 4, &conv, &res->iterations);
        res->starts++;
        res->gradient = nl_fit_ml_gradient(d, u);
        res->converged = conv;
        for (size_t k = 0; k < d->p->nfree; k++)
            if (nl_fit_params_runaway(d->p, k))
                res->converged = 0;
    }
}

static int fit_ml(const double *x, const double *z, size_t n, int dim, const double *design, size_t np,
                  const nl_fit_options *o, nl_fit_result *res)
{
    nl_fit_params p;
    ml_data d = {0};
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
    if ((unsigned)o->search > NL_FIT_SEARCH_LOCAL)
        return NL_ERROR(NL_EINVAL, "fit: search: expected global (0) or local (1), got %d", (int)o->search);
    if ((st = nl_fit_ml_check(&p, x, z, n, o)) || (st = nl_size_check(2, nn, sizeof(double), 1, NULL)))
        return st;
    if ((st = nl_fit_drift_design(o->drift, x, n, dim, design, np, p.nfree, &d.X)))
        return st;
    d.p = &p, d.x = x, d.z = z, d.n = n, d.lik = o->likelihood, d.q = d.X ? d.X->size2 : 0;
    d.C = gsl_matrix_alloc(n, n), d.y = gsl_vector_alloc(n);
    if (d.q)
        d.A = gsl_matrix_alloc(n, d.q), d.M = gsl_matrix_alloc(d.q, d.q), d.beta = gsl_vector_alloc(d.q);
    if (!d.C || !d.y || (d.q && (!d.A || !d.M || !d.beta)))
        st = NL_ERROR(NL_ENOMEM, "out of memory for the %zu x %zu covariance matrix", n, n);
    if (!st)
        ml_start(&d, o->start);
    if (!st && !(st = nl_fit_ml_search(&d, o->search != NL_FIT_SEARCH_LOCAL, res, u, flags)) &&
        !(st = ml_finish(&d, o, res, u, cov, lower, upper, flags, &rcond))) {
        res->nobs = n;
        /* the free covariance parameters and the drift coefficients */
        res->aic = res->objective + 2.0 * (double)(p.nfree + d.q);
        if (!(st = nl_fit_params_result(&p, cov, lower, upper, res))) {
            nl_fit_result_flags(&p, flags, res);
            res->rcond = rcond;
            nl_fit_ml_minus2l_u(&d, u);
            st = drift_result(&d, res);
        }
    }
    if (st)
        nl_fit_result_free(res);
    gsl_vector_free(d.beta);
    gsl_matrix_free(d.M);
    gsl_matrix_free(d.A);
    gsl_matrix_free(d.X);
    gsl_vector_free(d.y);
    gsl_matrix_free(d.C);
    return st;
}

int nl_fit_ml_design(const double *coords, const double *values, size_t n, int dim, const double *design, size_t p,
                     const nl_fit_options *o, nl_fit_result *res)
{
    int st;
    nl_gsl_enter();
    st = fit_ml(coords, values, n, dim, design, p, o, res);
    nl_gsl_leave();
    return st;
}

int nl_fit_ml(const double *coords, const double *values, size_t n, int dim, const nl_fit_options *o,
              nl_fit_result *res)
{
    return nl_fit_ml_design(coords, values, n, dim, NULL, 0, o, res);
}
