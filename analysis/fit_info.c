/* Is an information matrix invertible?  The eigenvalues of the information
 * of the transformed (log or logit, hence unit-free) parameters: a
 * direction whose curvature is below NL_FIT_RCOND_MIN = sqrt(DBL_EPSILON)
 * of the largest carries no information the finite differences that made
 * the matrix can resolve (a second difference keeps about half of the
 * digits of the objective), so its inverse would be rounding noise. */
#include "fit_internal.h"

#include <gsl/gsl_eigen.h>
#include <math.h>
#include <string.h>

double nl_fit_info_check(const double *info, size_t k, unsigned *flags, double *cov)
{
    size_t idx[NL_FIT_MAX_PARAMS], m = 0;
    int finite = 1;
    double a[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS], lmax = 0, lmin = INFINITY;
    gsl_eigen_symmv_workspace *w;
    gsl_vector_view ev;
    gsl_matrix_view A, V;
    double eval[NL_FIT_MAX_PARAMS], evec[NL_FIT_MAX_PARAMS * NL_FIT_MAX_PARAMS];
    for (size_t i = 0; i < k; i++)
        for (size_t j = 0; j < k; j++)
            if (!isfinite(info[i * k + j]))
                flags[i] |= NL_FIT_PARAM_SINGULAR, flags[j] |= NL_FIT_PARAM_SINGULAR, finite = 0;
    for (size_t i = 0; i < k; i++)
        if (!flags[i])
            idx[m++] = i;
    if (cov)
        for (size_t i = 0; i < k * k; i++)
            cov[i] = NAN;
    if (m == 0)
        return 0;
    for (size_t i = 0; i < m; i++)
        for (size_t j = 0; j < m; j++)
            a[i * m + j] = info[idx[i] * k + idx[j]];
    if (!(w = gsl_eigen_symmv_alloc(m)))
        return -1;
    A = gsl_matrix_view_array(a, m, m);
    V = gsl_matrix_view_array(evec, m, m);
    ev = gsl_vector_view_array(eval, m);
    gsl_eigen_symmv(&A.matrix, &ev.vector, &V.matrix, w);
    gsl_eigen_symmv_free(w);
    for (size_t e = 0; e < m; e++)
        lmax = fmax(lmax, eval[e]), lmin = fmin(lmin, eval[e]);
    for (size_t e = 0; e < m; e++) {
        if (lmax > 0 && eval[e] >= NL_FIT_RCOND_MIN * lmax)
            continue;
        for (size_t i = 0; i < m; i++)
            if (evec[i * m + e] * evec[i * m + e] > NL_FIT_NULL_SHARE)
                flags[idx[i]] |= NL_FIT_PARAM_SINGULAR;
    }
    for (size_t i = 0; cov && i < m; i++)
        for (size_t j = 0; j < m; j++) {
            double c = 0;
            if (flags[idx[i]] | flags[idx[j]])
                continue;
            for (size_t e = 0; e < m; e++)
                if (lmax > 0 && eval[e] >= NL_FIT_RCOND_MIN * lmax)
                    c += evec[i * m + e] * evec[j * m + e] / eval[e];
            cov[idx[i] * k + idx[j]] = c;
        }
    return finite && lmax > 0 ? fmax(0, lmin / lmax) : 0;
}
