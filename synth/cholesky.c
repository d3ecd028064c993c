/* Cholesky factorisation of the grid covariance matrix (GSL on an optimised
 * CBLAS: its recursive factorisation is level-3 BLAS). */
#include "cholesky.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <gsl/gsl_cblas.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

struct nl_synth_cholesky_plan {
    int dim;            /* 1..3 */
    size_t n[3];        /* grid */
    size_t count;       /* samples */
    gsl_matrix *L;      /* lower Cholesky factor (upper triangle unused) */
    double *z;          /* count white-noise samples: the execute workspace */
};

void nl_synth_cholesky_plan_free(nl_synth_cholesky_plan *p)
{
    if (!p)
        return;
    gsl_matrix_free(p->L);
    free(p->z);
    free(p);
}

static int cholesky_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                              nl_synth_cholesky_plan **out)
{
    nl_synth_cholesky_plan *p;
    size_t count, nn[2];
    double hh[3] = {1, 1, 1};
    int st;
    *out = NULL;
    if ((st = nl_size_check(dim, n, 1, 1, &count)))
        return st;
    if (count > NL_SYNTH_CHOLESKY_MAX)
        return NL_ERROR(NL_ETOOBIG, "cholesky: %zu samples need a %zu x %zu covariance matrix; expected at most "
                        "%d samples (use circulant for larger grids)", count, count, count, NL_SYNTH_CHOLESKY_MAX);
    nn[0] = nn[1] = count;
    if ((st = nl_size_check(2, nn, sizeof(double), 1, NULL)))
        return st;
    if ((st = nl_model_check_dim(m, dim)))
        return st;
    p = calloc(1, sizeof *p);
    if (!p || !(p->z = malloc(count * sizeof *p->z)) || !(p->L = gsl_matrix_alloc(count, count))) {
        if (p)
            free(p->z);
        free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory for the covariance matrix");
    }
    p->dim = dim;
    p->count = count;
    for (int a = 0; a < 3; a++) {
        p->n[a] = a < dim ? n[a] : 1;
        if (a < dim && h)
            hh[a] = h[a];
    }
    for (size_t i = 0; i < count; i++)
        for (size_t j = 0; j <= i; j++) {
            double lag[3];
            size_t pi[3] = {i % p->n[0], (i / p->n[0]) % p->n[1], i / (p->n[0] * p->n[1])};
            size_t pj[3] = {j % p->n[0], (j / p->n[0]) % p->n[1], j / (p->n[0] * p->n[1])};
            for (int a = 0; a < 3; a++)
                lag[a] = ((double)pi[a] - (double)pj[a]) * hh[a];
            double r = nl_model_acf(m, dim, lag);
            if (!isfinite(r)) {
                st = NL_ERROR(NL_EINVAL, "%s: the covariance is not finite (%g) at lag (%g, %g, %g)%s",
                              nl_model_spec(m), r, lag[0], lag[1], lag[2],
                              nl_model_is_spectral(m) ? "; cholesky needs the covariance at every lag of the "
                                                        "grid: use fft or circulant for this spectrum" : "");
                nl_synth_cholesky_plan_free(p);
                return st;
            }
            gsl_matrix_set(p->L, i, j, r);
            gsl_matrix_set(p->L, j, i, r);
        }
    if ((st = gsl_linalg_cholesky_decomp1(p->L)) != 0) {
        st = NL_ERROR(NL_ENOTPD, "%s: the %zu x %zu covariance matrix is not positive definite (Cholesky "
                      "failed: %s); the model is not valid on this grid, or it is singular at this spacing",
                      nl_model_spec(m), count, count, nl_gsl_reason(st));
        nl_synth_cholesky_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

int nl_synth_cholesky_execute(nl_synth_cholesky_plan *p, uint64_t seed, nl_field *out)
{
    double *z = p->z;
    if (out->count != p->count)
        return NL_ERROR(NL_EINVAL, "cholesky: the output field does not match the plan's grid");
    for (size_t j = 0; j < p->count; j++)
        z[j] = nl_rng_gauss(seed, NL_SYNTH_CHOLESKY_STREAM, j);
    memcpy(out->data, z, p->count * sizeof *z);
    /* x = L z in place by BLAS dtrmv on ONE thread.  We link OpenBLAS's
     * serial build, but a threaded one (its OpenMP build, chosen by the
     * system's alternatives) splits each row's sum between
     * omp_get_max_threads() threads, so its bits would depend on the thread
     * count: the setting of the calling thread is pinned and restored.  The
     * product is bound by memory (L is read once), not flops. */
    int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    cblas_dtrmv(CblasRowMajor, CblasLower, CblasNoTrans, CblasNonUnit, (int)p->count, p->L->data, (int)p->L->tda,
                out->data, 1);
    omp_set_num_threads(threads);
    return NL_OK;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): GSL reports by status, never aborts. */
int nl_synth_cholesky_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                                 nl_synth_cholesky_plan **out)
{
    int st;
    *out = NULL;
    if ((st = nl_model_check_stationary(m, "Cholesky synthesis")))
        return st;
    nl_gsl_enter();
    st = cholesky_plan_alloc(m, dim, n, h, out);
    nl_gsl_leave();
    return st;
}
