/* The drift of a likelihood fit: the design matrix X of the mean X beta,
 * polynomial terms of the coordinates (as analysis/krige_local.c) followed
 * by the caller's covariate columns. */
#include "fit_internal.h"
#include "krige_local.h"
#include "../core/nl_error.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <math.h>

size_t nl_fit_drift_terms(int drift, int dim)
{
    size_t d = (size_t)dim;
    return drift == NL_DRIFT_NONE ? 0 : drift == NL_DRIFT_CONSTANT ? 1 : drift == NL_DRIFT_LINEAR ? d + 1
                                                                     : 1 + d + d * (d + 1) / 2;
}

/* Row i's polynomial terms: 1, u_a, u_a u_b (a <= b). */
static void poly_row(int drift, const double *x, int dim, const double *c, const double *s, double *f)
{
    double u[3];
    size_t t = 0;
    if (drift == NL_DRIFT_NONE)
        return;
    f[t++] = 1;
    if (drift == NL_DRIFT_CONSTANT)
        return;
    for (int a = 0; a < dim; a++)
        u[a] = (x[a] - c[a]) / s[a], f[t++] = u[a];
    if (drift == NL_DRIFT_QUADRATIC)
        for (int a = 0; a < dim; a++)
            for (int b = a; b < dim; b++)
                f[t++] = u[a] * u[b];
}

/* X' X after each column is divided by its norm: positive definite with a
 * reciprocal condition above ~1e-12 unless the columns are (nearly)
 * dependent. */
static int independent(const gsl_matrix *X)
{
    size_t q = X->size2;
    gsl_matrix *G = gsl_matrix_alloc(q, q);
    gsl_vector *nrm = gsl_vector_alloc(q);
    int ok = 0;
    if (!G || !nrm)
        goto done;
    gsl_blas_dsyrk(CblasLower, CblasTrans, 1.0, X, 0.0, G);
    for (size_t a = 0; a < q; a++)
        gsl_vector_set(nrm, a, sqrt(gsl_matrix_get(G, a, a)));
    for (size_t a = 0; a < q; a++)
        for (size_t b = 0; b <= a; b++) {
            double v = gsl_matrix_get(G, a, b) / (gsl_vector_get(nrm, a) * gsl_vector_get(nrm, b));
            gsl_matrix_set(G, a, b, v);
            gsl_matrix_set(G, b, a, v);
        }
    ok = 1;
    for (size_t a = 0; a < q && ok; a++)
        ok = isfinite(gsl_vector_get(nrm, a)) && gsl_vector_get(nrm, a) > 0;
    if (ok && !gsl_linalg_cholesky_decomp1(G)) {
        double lo = INFINITY, hi = 0;
        for (size_t a = 0; a < q; a++)
            lo = fmin(lo, gsl_matrix_get(G, a, a)), hi = fmax(hi, gsl_matrix_get(G, a, a));
        ok = lo / hi > 1e-6; /* the diagonal of the factor: about the square root of the condition */
    } else
        ok = 0;
done:
    gsl_vector_free(nrm);
    gsl_matrix_free(G);
    return ok;
}

int nl_fit_drift_design(int drift, const double *x, size_t n, int dim, const double *design, size_t p,
                        size_t nfree, gsl_matrix **Xout)
{
    size_t q0 = nl_fit_drift_terms(drift, dim), q = q0 + p, d = (size_t)dim;
    double c[3] = {0, 0, 0}, s[3] = {1, 1, 1};
    gsl_matrix *X;
    *Xout = NULL;
    if (drift < NL_DRIFT_NONE || drift > NL_DRIFT_QUADRATIC)
        return NL_ERROR(NL_EINVAL, "drift: expected constant, linear, quadratic or none, got %d", drift);
    if (p > 0 && !design)
        return NL_ERROR(NL_EINVAL, "drift: %zu covariate columns but no design matrix", p);
    if (q + nfree + 1 > n)
        return NL_ERROR(NL_EINVAL, "fit: %zu data; expected more than the %zu drift terms and %zu free parameters",
                        n, q, nfree);
    for (size_t i = 0; i < n * p; i++)
        if (!isfinite(design[i]))
            return NL_ERROR(NL_EINVAL, "drift: covariate %zu of point %zu is not finite (%g)", i % p + 1, i / p + 1,
                            design[i]);
    if (q == 0)
        return NL_OK;
    for (size_t a = 0; a < d; a++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < n; i++)
            lo = fmin(lo, x[i * d + a]), hi = fmax(hi, x[i * d + a]);
        c[a] = 0.5 * (lo + hi), s[a] = hi > lo ? 0.5 * (hi - lo) : 1;
    }
    if (!(X = gsl_matrix_alloc(n, q)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the %zu x %zu design", n, q);
    for (size_t i = 0; i < n; i++) {
        double *row = gsl_matrix_ptr(X, i, 0);
        poly_row(drift, x + i * d, dim, c, s, row);
        for (size_t k = 0; k < p; k++)
            row[q0 + k] = design[i * p + k];
    }
    if (!independent(X)) {
        gsl_matrix_free(X);
        return NL_ERROR(NL_EINVAL, "drift: the %zu drift columns (%zu of the coordinates, %zu covariates) are "
                        "linearly dependent on these data; expected independent columns", q, q0, p);
    }
    *Xout = X;
    return NL_OK;
}
