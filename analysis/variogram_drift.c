/* Residuals of a drift fitted by ordinary least squares, for the residual
 * variogram: gstat's variogram(z ~ x + y) or variogram(z ~ c1 + c2), whose
 * src/sem.c (alloc_exp_variogram) replaces the values by
 * make_residuals_lm's OLS residuals before the pairs are binned.  The drift:
 * a polynomial in the coordinates, then external covariates. */
#include "variogram_internal.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_multifit.h>
#include <math.h>
#include <stdlib.h>

/* The drift's terms: 1, the coordinates, then (quadratic) their squares
 * and cross products, the coordinates centred on and scaled by their box
 * (the residuals do not depend on that: the same column space; it keeps
 * the columns of a quadratic in metres comparable). */
static size_t terms(int dim, int drift)
{
    size_t d = (size_t)dim;
    if (drift == NL_VARIOGRAM_DRIFT_CONSTANT)
        return 1;
    return 1 + d + (drift == NL_VARIOGRAM_DRIFT_QUADRATIC ? d * (d + 1) / 2 : 0);
}

/* Row i of the design: the polynomial terms, then the q covariates as
 * given (GSL's SVD balances the columns first: a covariate of 1e100 is
 * compared with the others on one scale). */
static void fill_row(const double *x, int dim, int drift, const double *c, const double *s, const double *cov,
                     size_t q, double *row)
{
    double u[3];
    size_t t = 0;
    row[t++] = 1;
    for (size_t j = 0; j < q; j++)
        row[terms(dim, drift) + j] = cov[j];
    if (drift == NL_VARIOGRAM_DRIFT_CONSTANT)
        return;
    for (int a = 0; a < dim; a++)
        u[a] = (x[a] - c[a]) / s[a], row[t++] = u[a];
    if (drift == NL_VARIOGRAM_DRIFT_QUADRATIC)
        for (int a = 0; a < dim; a++)
            for (int b = a; b < dim; b++)
                row[t++] = u[a] * u[b];
}

/* Least squares by GSL's truncated SVD (gsl_multifit_linear_tsvd): a rank
 * below the terms' count (singular values under 1e-10 of the largest) is
 * refused, as gstat refuses a singular trend model. */
static int solve(const gsl_matrix *X, const gsl_vector *y, gsl_vector *r, size_t *rank)
{
    size_t n = X->size1, p = X->size2;
    gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(n, p);
    gsl_vector *c = gsl_vector_alloc(p);
    gsl_matrix *cov = gsl_matrix_alloc(p, p);
    double chisq;
    int st = NL_OK, gst;
    if (!w || !c || !cov)
        st = NL_ERROR(NL_ENOMEM, "variogram: out of memory for the drift's least squares");
    else if ((gst = gsl_multifit_linear_tsvd(X, y, 1e-10, c, cov, &chisq, rank, w)) ||
             (gst = gsl_multifit_linear_residuals(X, y, c, r)))
        st = NL_ERROR(NL_EFAIL, "variogram: the drift's least squares failed: %s", nl_gsl_reason(gst));
    gsl_matrix_free(cov);
    gsl_vector_free(c);
    gsl_multifit_linear_free(w);
    return st;
}

/* The drift's name for messages. */
static const char *drift_name(int drift, size_t q)
{
    if (drift == NL_VARIOGRAM_DRIFT_CONSTANT)
        return q ? "covariate" : "constant";
    return drift == NL_VARIOGRAM_DRIFT_QUADRATIC ? "quadratic" : "linear";
}

/* NL_EINVAL naming a non-finite covariate. */
static int check_cov(size_t n, const double *cov, size_t q)
{
    for (size_t i = 0; i < n * q; i++)
        if (!isfinite(cov[i]))
            return NL_ERROR(NL_EINVAL, "variogram: drift: covariate %zu of point %zu is %g; expected finite numbers",
                            i % q + 1, i / q + 1, cov[i]);
    return NL_OK;
}

int nl_vg_residuals(int dim, size_t n, const double *pts, const double *z, int drift, const double *cov, size_t q,
                    double *r)
{
    size_t p = terms(dim, drift) + q, rank = 0;
    double c[3], s[3];
    int st;
    if (n <= p)
        return NL_ERROR(NL_EINVAL, "variogram: drift: %zu points for a %s drift of %zu terms; expected more points "
                        "than terms", n, drift_name(drift, q), p);
    if ((st = check_cov(n, cov, q)))
        return st;
    for (int a = 0; a < dim; a++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < n; i++)
            lo = fmin(lo, pts[i * dim + a]), hi = fmax(hi, pts[i * dim + a]);
        c[a] = 0.5 * (lo + hi), s[a] = hi > lo ? 0.5 * (hi - lo) : 1;
    }
    gsl_matrix *X = gsl_matrix_alloc(n, p);
    if (!X)
        return NL_ERROR(NL_ENOMEM, "variogram: out of memory for the drift's %zu x %zu terms", n, p);
    for (size_t i = 0; i < n; i++)
        fill_row(pts + i * (size_t)dim, dim, drift, c, s, q ? cov + i * q : NULL, q, gsl_matrix_ptr(X, i, 0));
    gsl_vector_const_view y = gsl_vector_const_view_array(z, n);
    gsl_vector_view res = gsl_vector_view_array(r, n);
    nl_gsl_enter();
    st = solve(X, &y.vector, &res.vector, &rank);
    nl_gsl_leave();
    gsl_matrix_free(X);
    if (!st && rank < p)
        st = NL_ERROR(NL_EINVAL, "variogram: drift: its %zu terms have rank %zu at the points (%s); expected terms "
                      "that determine a %s drift", p, rank, q ? "a covariate constant or a combination of the other "
                      "terms?" : "collinear points?", drift_name(drift, q));
    return st;
}
