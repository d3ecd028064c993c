/* Ordinary and simple kriging through a Cholesky (or SVD) factorisation. */
#include "krige.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"

#include "../core/field.h"

#include <float.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_cblas.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nl_krige_plan {
    const nl_model *m;  /* the covariance (borrowed) */
    int dim;            /* 1..3 */
    size_t n;           /* points */
    double *pts;        /* n * dim */
    int simple;         /* known mean */
    double r0;          /* R(0) (+ shift) */
    double shift;       /* intrinsic models: the constant added to K = -gamma (0 otherwise) */
    gsl_matrix *L;      /* Cholesky factor of C, or NULL */
    gsl_matrix *pinv;   /* pseudo-inverse of C, or NULL */
    gsl_vector *a;      /* C^-1 (d - b 1) */
    gsl_vector *u;      /* C^-1 1 */
    gsl_vector *w;      /* L^-1 1 (with L), for the blocked variance */
    double s;           /* 1^T C^-1 1 */
    nl_krige_info info;
};

void nl_krige_plan_free(nl_krige_plan *p)
{
    if (!p)
        return;
    gsl_matrix_free(p->L), gsl_matrix_free(p->pinv);
    gsl_vector_free(p->a), gsl_vector_free(p->u), gsl_vector_free(p->w);
    free(p->pts), free(p);
}

static double cov(const nl_krige_plan *p, const double *x, const double *y)
{
    double lag[3] = {0, 0, 0};
    for (int a = 0; a < p->dim; a++)
        lag[a] = x[a] - y[a];
    return p->shift + nl_model_acf(p->m, p->dim, lag);
}

/* y = C^-1 b */
static void solve(const nl_krige_plan *p, const gsl_vector *b, gsl_vector *y)
{
    if (p->L)
        gsl_linalg_cholesky_solve(p->L, b, y);
    else
        gsl_blas_dgemv(CblasNoTrans, 1.0, p->pinv, b, 0.0, y);
}

static int pseudo_inverse(nl_krige_plan *p, const gsl_matrix *C)
{
    size_t n = p->n;
    gsl_matrix *U = gsl_matrix_alloc(n, n), *V = gsl_matrix_alloc(n, n);
    gsl_vector *S = gsl_vector_alloc(n), *w = gsl_vector_alloc(n);
    int st = (!U || !V || !S || !w) ? NL_ERROR(NL_ENOMEM, "out of memory") : NL_OK;
    if (!st) {
        gsl_matrix_memcpy(U, C);
        if (gsl_linalg_SV_decomp(U, V, S, w))
            st = NL_ERROR(NL_EFAIL, "kriging: the SVD failed");
    }
    if (!st) {
        double smax = gsl_vector_get(S, 0);
        p->pinv = gsl_matrix_calloc(n, n);
        p->info.rcond = gsl_vector_get(S, n - 1) / smax;
        /* pinv = V diag(1/s_k) U^T over the kept singular values */
        for (size_t k = 0; k < n; k++) {
            double sk = gsl_vector_get(S, k);
            gsl_vector_view col = gsl_matrix_column(V, k);
            gsl_vector_scale(&col.vector, sk > NL_KRIGE_RCOND_MIN * smax ? 1 / sk : 0);
        }
        gsl_blas_dgemm(CblasNoTrans, CblasTrans, 1.0, V, U, 0.0, p->pinv);
    }
    gsl_matrix_free(U), gsl_matrix_free(V), gsl_vector_free(S), gsl_vector_free(w);
    return st;
}

/* C by Cholesky, or by the pseudo-inverse when it is singular (refused
 * when strict). */
static int factorize(nl_krige_plan *p, const gsl_matrix *C, int strict)
{
    size_t n = p->n;
    int st = NL_OK;
    if (!(p->L = gsl_matrix_alloc(n, n)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu data points", n);
    gsl_matrix_memcpy(p->L, C);
    if (gsl_linalg_cholesky_decomp1(p->L) == 0) {
        gsl_vector *work = gsl_vector_alloc(3 * n);
        if (!work)
            return NL_ERROR(NL_ENOMEM, "out of memory for %zu data points", n);
        gsl_linalg_cholesky_rcond(p->L, &p->info.rcond, work);
        gsl_vector_free(work);
    } else {
        p->info.rcond = 0;
    }
    if (p->info.rcond < NL_KRIGE_RCOND_MIN) {
        gsl_matrix_free(p->L);
        p->L = NULL;
        if (strict)
            st = NL_ERROR(NL_EINVAL, "kriging: the %zu x %zu covariance matrix is singular (reciprocal condition "
                          "%.2g): duplicate data points, or points closer than %s resolves",
                          n, n, p->info.rcond, nl_model_spec(p->m));
        else if (n > NL_KRIGE_PINV_MAX)
            st = NL_ERROR(NL_ETOOBIG, "kriging: the %zu x %zu covariance matrix is singular (reciprocal condition "
                          "%.2g) and its pseudo-inverse (an SVD, about 12 n^3 operations) is refused above %d points: "
                          "remove duplicate points, add a nugget to %s, or krige from neighbourhoods", n, n,
                          p->info.rcond, NL_KRIGE_PINV_MAX, nl_model_spec(p->m));
        else {
            st = pseudo_inverse(p, C);
            p->info.pseudo_inverse = 1;
        }
    }
    return st;
}

/* Coordinates whose differences, and values whose differences, stay finite
 * (distances and the residuals d - b 1 must not overflow). */
static int check_spans(int dim, size_t n, const double *pts, const double *val)
{
    double lo[4] = {INFINITY, INFINITY, INFINITY, INFINITY}, hi[4] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a <= dim; a++) {
            double x = a < dim ? pts[i * dim + a] : val[i];
            if (!isfinite(x))
                return NL_ERROR(NL_EINVAL, "kriging: expected finite coordinates and values, point %zu is not", i);
            lo[a] = fmin(lo[a], x), hi[a] = fmax(hi[a], x);
        }
    for (int a = 0; a <= dim; a++)
        if (!isfinite(4 * (hi[a] - lo[a])))
            return NL_ERROR(NL_EINVAL,
                            "kriging: the data's %s run from %g to %g, whose difference overflows; expected a "
                            "span below %g",
                            a == dim ? "values" : a == 0 ? "x" : a == 1 ? "y" : "z", lo[a], hi[a], DBL_MAX / 4);
    return NL_OK;
}

/* The data's spans, the model's variance and the matrix's memory. */
static int check_inputs(const nl_model *m, int dim, size_t n, const double *pts, const double *val)
{
    double zero[3] = {0, 0, 0}, r0;
    int st = check_spans(dim, n, pts, val);
    if (st)
        return st;
    r0 = nl_model_acf(m, dim, zero);
    if (!(isfinite(r0) && (r0 > 0 || (nl_model_is_intrinsic(m) && r0 == 0))))
        return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a finite positive variance", nl_model_spec(m), r0);
    if (nl_size_check(2, (size_t[]){n, n}, sizeof(double), 4, NULL))
        return NL_ERROR(NL_ETOOBIG, "kriging: the %zu x %zu covariance matrix and its factors (4 copies of %g "
                        "bytes) do not fit in the memory available", n, n, 8.0 * (double)n * (double)n);
    return NL_OK;
}

/* Every covariance of the data finite (a model singular at some lag). */
static int check_matrix(const nl_krige_plan *p, const gsl_matrix *C)
{
    for (size_t i = 0; i < p->n; i++)
        for (size_t j = 0; j < p->n; j++)
            if (!isfinite(gsl_matrix_get(C, i, j))) {
                double lag = 0;
                for (int a = 0; a < p->dim; a++)
                    lag += (p->pts[i * p->dim + a] - p->pts[j * p->dim + a]) *
                           (p->pts[i * p->dim + a] - p->pts[j * p->dim + a]);
                return NL_ERROR(NL_EINVAL, "%s: the covariance of data points %zu and %zu (distance %g) is %g; "
                                "expected a model finite at every lag",
                                nl_model_spec(p->m), i, j, sqrt(lag), gsl_matrix_get(C, i, j));
            }
    return NL_OK;
}

/* The weights and the mean finite (values too large for the model's scale). */
static int check_solution(const nl_krige_plan *p)
{
    int ok = isfinite(p->s) && isfinite(p->info.mean) && isfinite(p->r0);
    for (size_t i = 0; ok && i < p->n; i++)
        ok = isfinite(gsl_vector_get(p->a, i)) && isfinite(gsl_vector_get(p->u, i));
    if (!ok)
        return NL_ERROR(NL_EINVAL, "kriging: the weights or the mean (%g) overflow with %s and these data; "
                        "expected data values and a variance of smaller magnitude", p->info.mean,
                        nl_model_spec(p->m));
    return NL_OK;
}

/* An intrinsic model's K = -gamma gives an indefinite C (one positive
 * eigenvalue of gamma's matrix; Micchelli 1986: nonsingular for distinct
 * points).  Ordinary kriging's weights sum to 1, so a constant A added to
 * every covariance changes neither the weights nor the estimate nor the
 * variance (the bordered system [C + A 1 1^T, 1; 1^T, 0] has the same
 * solution, with the same multiplier); A above 1 / (1^T Gamma^-1 1), which
 * is max over weights summing to 1 of w^T Gamma w, of the order of the
 * largest gamma among the data, makes C + A 1 1^T positive definite, so
 * Cholesky applies.  A = 2 max gamma_ij (1 when all coincide); should it
 * not suffice, the factorisation falls back to the pseudo-inverse as for
 * any singular C, which remains exact. */
static void shift_intrinsic(nl_krige_plan *p, gsl_matrix *C)
{
    double g = 0;
    for (size_t i = 0; i < p->n; i++)
        for (size_t j = 0; j < p->n; j++)
            g = fmax(g, p->r0 - gsl_matrix_get(C, i, j));
    p->shift = g > 0 ? 2 * g : 1;
    p->r0 += p->shift;
    gsl_matrix_add_constant(C, p->shift);
}

static int krige_plan_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val, int simple,
                     double mean, int strict, nl_krige_plan **out)
{
    nl_krige_plan *p;
    gsl_matrix *C;
    gsl_vector *d, *one;
    double zero[3] = {0, 0, 0};
    int st = NL_OK;
    *out = NULL;
    if (n < 1)
        return NL_ERROR(NL_EINVAL, "kriging: expected at least one data point");
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "kriging: expected 1 to 3 coordinates, got %d", dim);
    if ((st = nl_model_check_dim(m, dim)))
        return st;
    if (!nl_model_has_acf(m))
        return NL_ERROR(NL_EINVAL, "%s: kriging needs R(lag)", nl_model_spec(m));
    if (simple && nl_model_is_intrinsic(m))
        return NL_ERROR(NL_EINVAL, "%s: simple kriging (--mean) needs a covariance; %s is intrinsic (no "
                        "covariance, no mean): expected ordinary kriging (no --mean)", nl_model_spec(m),
                        nl_model_family(m)->name);
    if ((st = check_inputs(m, dim, n, pts, val)))
        return st;
    p = calloc(1, sizeof *p);
    if (!p || !(p->pts = malloc(n * (size_t)dim * sizeof *p->pts))) {
        free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    memcpy(p->pts, pts, n * (size_t)dim * sizeof *pts);
    p->m = m, p->dim = dim, p->n = n, p->simple = simple;
    p->r0 = nl_model_acf(m, dim, zero);
    p->info.n = n;
    C = gsl_matrix_alloc(n, n);
    d = gsl_vector_alloc(n), one = gsl_vector_alloc(n);
    p->a = gsl_vector_alloc(n), p->u = gsl_vector_alloc(n);
    if (!C || !d || !one || !p->a || !p->u) {
        gsl_matrix_free(C), gsl_vector_free(d), gsl_vector_free(one), nl_krige_plan_free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu data points", n);
    }
    for (size_t i = 0; i < n; i++) {
        for (size_t j = 0; j < n; j++)
            gsl_matrix_set(C, i, j, cov(p, pts + i * dim, pts + j * dim));
        gsl_vector_set(d, i, val[i]);
        gsl_vector_set(one, i, 1.0);
    }
    st = check_matrix(p, C);
    if (!st && nl_model_is_intrinsic(m))
        shift_intrinsic(p, C);
    if (!st)
        st = factorize(p, C, strict);
    if (!st) {
        double b;
        solve(p, one, p->u);
        gsl_blas_ddot(one, p->u, &p->s);
        if (simple) {
            b = mean;
        } else {
            double ud;
            gsl_blas_ddot(p->u, d, &ud);
            b = ud / p->s;
        }
        p->info.mean = b;
        for (size_t i = 0; i < n; i++)
            gsl_vector_set(d, i, val[i] - b);
        solve(p, d, p->a);
        if (p->L && (p->w = gsl_vector_alloc(n))) {
            gsl_vector_set_all(p->w, 1.0);
            gsl_blas_dtrsv(CblasLower, CblasNoTrans, CblasNonUnit, p->L, p->w);
        } else if (p->L) {
            st = NL_ERROR(NL_ENOMEM, "out of memory");
        }
    }
    gsl_matrix_free(C), gsl_vector_free(d), gsl_vector_free(one);
    if (!st)
        st = check_solution(p);
    if (st) {
        nl_krige_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

void nl_krige_plan_info(const nl_krige_plan *p, nl_krige_info *info) { *info = p->info; }

static int krige_eval(const nl_krige_plan *p, const double *x, double *est, double *var, double *lambda)
{
    size_t n = p->n;
    double e = p->info.mean;
    gsl_vector *c0 = NULL, *y = NULL;
    int need = var || lambda;
    if (need) {
        c0 = gsl_vector_alloc(n), y = gsl_vector_alloc(n);
        if (!c0 || !y) {
            gsl_vector_free(c0), gsl_vector_free(y);
            return NL_ERROR(NL_ENOMEM, "out of memory");
        }
    }
    for (size_t i = 0; i < n; i++) {
        double c = cov(p, x, p->pts + i * p->dim);
        e += c * gsl_vector_get(p->a, i);
        if (need)
            gsl_vector_set(c0, i, c);
    }
    *est = e;
    if (need) {
        double cc, uc, mu;
        solve(p, c0, y);               /* y = C^-1 c0 */
        gsl_blas_ddot(c0, y, &cc);
        gsl_blas_ddot(p->u, c0, &uc);  /* 1^T C^-1 c0 */
        mu = p->simple ? 0 : (uc - 1) / p->s;
        if (var) {
            double v = p->r0 - cc + (p->simple ? 0 : (1 - uc) * (1 - uc) / p->s);
            *var = v > 0 ? v : 0;
        }
        if (lambda)
            for (size_t i = 0; i < n; i++)  /* lambda = C^-1 (c0 - mu 1) */
                lambda[i] = gsl_vector_get(y, i) - mu * gsl_vector_get(p->u, i);
    }
    gsl_vector_free(c0), gsl_vector_free(y);
    return NL_OK;
}

/* cc_b = |z_b|^2 and uc_b = w . z_b over the columns of the n x
 * NL_KRIGE_BLOCK row-major z, row by row (each sum in the order i = 0..n-1). */
static void column_sums(const nl_krige_plan *p, size_t n, const double *z, double *cc, double *uc)
{
    enum { B = NL_KRIGE_BLOCK };
    for (int b = 0; b < B; b++)
        cc[b] = 0, uc[b] = 0;
    for (size_t i = 0; i < n; i++) {
        const double *zi = z + i * B, wi = p->w->data[i * p->w->stride];
        for (int b = 0; b < B; b++)
            cc[b] += zi[b] * zi[b], uc[b] += wi * zi[b];
    }
}

/* The variance of many points at once: with Z = L^-1 K for the n x B
 * cross-covariances K of a block, c0^T C^-1 c0 = |z_b|^2 (column norms) and
 * 1^T C^-1 c0 = (L^-1 1) . z_b, so one level-3 triangular solve (BLAS dtrsm,
 * n^2 B flops at GEMM speed) serves all NL_KRIGE_BLOCK points of a block.
 * A block always has NL_KRIGE_BLOCK columns (a short last block is padded
 * with zeros), so its arithmetic does not depend on the thread that runs it;
 * the threads come from the OpenMP loop over blocks (nl_krige_eval_grid);
 * BLAS itself is OpenBLAS's serial build, and a threaded build put in its
 * place splits only the columns, which gives the same bits
 * (tests/test_blas_threads.c). */
static int krige_eval_block(const nl_krige_plan *p, size_t count, const double *x, double *est, double *var)
{
    size_t n = p->n, B = NL_KRIGE_BLOCK;
    double *z, cc[NL_KRIGE_BLOCK], uc[NL_KRIGE_BLOCK];
    if (!p->L || !var) {
        for (size_t q = 0; q < count; q++) {
            int st = nl_krige_eval(p, x + q * (size_t)p->dim, &est[q], var ? &var[q] : NULL, NULL);
            if (st)
                return st;
        }
        return NL_OK;
    }
    if (!(z = malloc(n * B * sizeof *z)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t q0 = 0; q0 < count; q0 += B) {
        size_t nb = count - q0 < B ? count - q0 : B;
        for (size_t b = 0; b < nb; b++)
            est[q0 + b] = p->info.mean;
        for (size_t i = 0; i < n; i++) {
            double ai = gsl_vector_get(p->a, i);
            for (size_t b = 0; b < nb; b++) {
                double c = cov(p, x + (q0 + b) * (size_t)p->dim, p->pts + i * p->dim);
                z[i * B + b] = c;
                est[q0 + b] += c * ai;
            }
        }
        if (nb < B)  /* a short last block: the unused columns stay 0 */
            for (size_t i = 0; i < n; i++)
                memset(z + i * B + nb, 0, (B - nb) * sizeof *z);
        cblas_dtrsm(CblasRowMajor, CblasLeft, CblasLower, CblasNoTrans, CblasNonUnit, (int)n, (int)B, 1.0,
                    p->L->data, (int)p->L->tda, z, (int)B);
        column_sums(p, n, z, cc, uc);
        for (size_t b = 0; b < nb; b++) {
            double v = p->r0 - cc[b] + (p->simple ? 0 : (1 - uc[b]) * (1 - uc[b]) / p->s);
            var[q0 + b] = v > 0 ? v : 0;
        }
    }
    free(z);
    return NL_OK;
}

int nl_krige_eval_grid(const nl_krige_plan *p, const double *lo, const nl_field *est, nl_field *var)
{
    const nl_field *f = est;
    int dim = p->dim, parallel = nl_model_is_reentrant(p->m), status = NL_OK;
    if (f->dim != dim || (var && (var->dim != dim || var->count != f->count)))
        return NL_ERROR(NL_EINVAL, "kriging grid: expected %dD grids of one size, got %dD", dim, f->dim);
    size_t nblk = (f->count + NL_KRIGE_BLOCK - 1) / NL_KRIGE_BLOCK, g[3] = {f->n[0], f->n[1], f->n[2]};
#pragma omp parallel for schedule(dynamic, 1) if (parallel && f->count > 4096)
    for (size_t blk = 0; blk < nblk; blk++) {
        size_t q0 = blk * NL_KRIGE_BLOCK, nq = f->count - q0 < NL_KRIGE_BLOCK ? f->count - q0 : NL_KRIGE_BLOCK;
        double x[NL_KRIGE_BLOCK * 3];
        for (size_t q = q0; q < q0 + nq; q++) {
            size_t idx[3] = {q % g[0], (q / g[0]) % g[1], q / (g[0] * g[1])};
            for (int a = 0; a < dim; a++)
                x[(q - q0) * (size_t)dim + a] = lo[a] + ((double)idx[a] + 0.5) * f->h[a];
        }
        int st = nl_krige_eval_block(p, nq, x, &f->data[q0], var ? &var->data[q0] : NULL);
        for (size_t q = 0; !st && q < nq; q++)
            if (!isfinite(f->data[q0 + q]) || (var && !isfinite(var->data[q0 + q])))
                st = NL_ERROR(NL_EINVAL, "kriging: the estimate at cell %zu (x %g) is not finite; expected "
                              "cell centres within a finite distance of the data", q0 + q, x[q * (size_t)dim]);
        if (st) {
#pragma omp critical
            status = st;
        }
    }
    return status;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_krige_plan_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val,
                        int simple, double mean, int strict, nl_krige_plan **out)
{
    int st;
    nl_gsl_enter();
    st = krige_plan_alloc(m, dim, n, pts, val, simple, mean, strict, out);
    nl_gsl_leave();
    return st;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_krige_eval(const nl_krige_plan *p, const double *x, double *est, double *var, double *lambda)
{
    int st;
    nl_gsl_enter();
    st = krige_eval(p, x, est, var, lambda);
    nl_gsl_leave();
    return st;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_krige_eval_block(const nl_krige_plan *p, size_t count, const double *x, double *est, double *var)
{
    int st;
    nl_gsl_enter();
    st = krige_eval_block(p, count, x, est, var);
    nl_gsl_leave();
    return st;
}
