/* Local kriging: the factorisation of a neighbourhood, and the loops over
 * locations (a grid, a list, the data for cross-validation). */
#include "krige_local.h"
#include "krige_local_internal.h"
#include "../core/nl_error.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void nl_kl_work_free(nl_kl_work *w)
{
    free(w->next), free(w->set), free(w->d2), free(w->L), free(w->Q), free(w->M), free(w->beta), free(w->r);
    free(w->c0), free(w->v), free(w->f), free(w->u), free(w->u2), free(w->y);
    free(w->C), free(w->Cp), free(w->prev), free(w->pos);
    memset(w, 0, sizeof *w);
}

int nl_kl_work_init(nl_kl_work *w, size_t cap, size_t p)
{
    size_t c = cap + 1, q = p ? p : 1;
    memset(w, 0, sizeof *w);
    w->cap = cap, w->p = p;
    /* next, d2: one more for the tie check; set: cap more, scratch for gstat's order */
    w->next = malloc((c + 1) * sizeof(size_t)), w->set = malloc((c + cap + 1) * sizeof(size_t));
    w->d2 = malloc((c + 1) * sizeof(double));
    w->L = malloc(c * c * sizeof(double)), w->Q = malloc(q * c * sizeof(double)), w->M = malloc(q * q * sizeof(double));
    w->beta = malloc(q * sizeof(double)), w->r = malloc(c * sizeof(double)), w->c0 = malloc(c * sizeof(double));
    w->v = malloc(c * sizeof(double)), w->f = malloc(q * sizeof(double)), w->u = malloc(q * sizeof(double));
    w->u2 = malloc(q * sizeof(double)), w->y = malloc(c * sizeof(double));
    w->C = malloc(c * c * sizeof(double)), w->Cp = malloc(c * c * sizeof(double));
    w->prev = malloc(c * sizeof(size_t)), w->pos = malloc(c * sizeof(size_t));
    if (!w->next || !w->set || !w->d2 || !w->L || !w->Q || !w->M || !w->beta || !w->r || !w->c0 || !w->v || !w->f ||
        !w->u || !w->u2 || !w->y || !w->C || !w->Cp || !w->prev || !w->pos) {
        nl_kl_work_free(w);
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory for neighbourhoods of %zu points", cap);
    }
    return NL_OK;
}

void nl_kl_lsolve(const double *L, size_t n, const double *b, double *x)
{
    for (size_t i = 0; i < n; i++) {
        double s = b[i];
        for (size_t j = 0; j < i; j++)
            s -= L[i * n + j] * x[j];
        x[i] = s / L[i * n + i];
    }
}

/* x = L^-T b */
static void ltsolve(const double *L, size_t n, const double *b, double *x)
{
    for (size_t i = n; i-- > 0;) {
        double s = b[i];
        for (size_t j = i + 1; j < n; j++)
            s -= L[j * n + i] * x[j];
        x[i] = s / L[i * n + i];
    }
}

/* In-place Cholesky of the lower triangle of A (n x n); -1 when a pivot is
 * not above tol. */
static int cholesky(double *A, size_t n, double tol)
{
    for (size_t j = 0; j < n; j++) {
        double d = A[j * n + j];
        for (size_t k = 0; k < j; k++)
            d -= A[j * n + k] * A[j * n + k];
        if (!(d > tol))
            return -1;
        d = sqrt(d);
        A[j * n + j] = d;
        for (size_t i = j + 1; i < n; i++) {
            double s = A[i * n + j];
            for (size_t k = 0; k < j; k++)
                s -= A[i * n + k] * A[j * n + k];
            A[i * n + j] = s / d;
        }
    }
    return 0;
}

static int singular(const nl_krige_local *k, const double *x, const char *what)
{
    char at[64];
    return NL_ERROR(NL_EINVAL, "kriging: the %s of the neighbourhood of %s is singular (%s); expected "
                    "distinct data points", what, nl_kl_where(k, x, at),
                    what[0] == 'c' ? "duplicate points, or a smooth model with points much closer than its scale"
                                   : "the data lie on a line or plane of the drift");
}

/* C of the set w->set, taking the entries of pairs that were in the
 * previous set from its matrix (neighbourhoods of adjacent locations
 * share most of their points); the same numbers as evaluating them all. */
static void covariances(const nl_krige_local *k, nl_kl_work *w)
{
    size_t K = w->K, Kp = w->Kp, a = 0;
    int dim = k->dim;
    double *t;
    for (size_t i = 0; i < K; i++) {
        while (a < Kp && w->prev[a] < w->set[i])
            a++;
        w->pos[i] = a < Kp && w->prev[a] == w->set[i] ? a : SIZE_MAX;
    }
    for (size_t i = 0; i < K; i++) {
        const double *ti = k->pts + w->set[i] * dim;
        for (size_t j = 0; j <= i; j++) {
            if (w->pos[i] != SIZE_MAX && w->pos[j] != SIZE_MAX) {
                w->Cp[i * K + j] = w->C[w->pos[i] * Kp + w->pos[j]];
                continue;
            }
            double lag[3] = {0, 0, 0};
            for (int b = 0; b < dim; b++)
                lag[b] = ti[b] - k->pts[w->set[j] * dim + b];
            w->Cp[i * K + j] = k->shift + nl_model_acf(k->m, dim, lag);
        }
    }
    t = w->C, w->C = w->Cp, w->Cp = t; /* C: this set's; Cp: scratch */
    memcpy(w->prev, w->set, K * sizeof *w->set);
    w->Kp = K;
}

int nl_kl_factor(const nl_krige_local *k, nl_kl_work *w, const double *x)
{
    size_t K = w->K, p = k->p;
    int dim = k->dim;
    double *L = w->L, *y = w->y;
    covariances(k, w);
    for (size_t i = 0; i < K; i++)
        memcpy(L + i * K, w->C + i * K, (i + 1) * sizeof(double));
    if (cholesky(L, K, 1e-13 * k->r0))
        return singular(k, x, "covariance matrix");
    for (size_t i = 0; i < K; i++) /* X row by row into Q (column-major: Q[j * K + i]), then L^-1 X */
    {
        nl_kl_drift(k, k->pts + w->set[i] * dim, k->cov ? k->cov + w->set[i] * k->o.ncov : NULL, w->f);
        for (size_t j = 0; j < p; j++)
            w->Q[j * K + i] = w->f[j];
    }
    for (size_t j = 0; j < p; j++) {
        memcpy(w->v, w->Q + j * K, K * sizeof(double));
        nl_kl_lsolve(L, K, w->v, w->Q + j * K);
    }
    for (size_t i = 0; i < K; i++)
        w->c0[i] = k->val[w->set[i]] - (p ? 0 : k->o.mean);
    nl_kl_lsolve(L, K, w->c0, y); /* y = L^-1 z */
    if (p) {
        for (size_t a = 0; a < p; a++) {
            double g = 0;
            for (size_t b = 0; b <= a; b++) {
                double s = 0;
                for (size_t i = 0; i < K; i++)
                    s += w->Q[a * K + i] * w->Q[b * K + i];
                w->M[a * p + b] = s;
            }
            for (size_t i = 0; i < K; i++)
                g += w->Q[a * K + i] * y[i];
            w->u[a] = g;
        }
        double tr = 0;
        for (size_t a = 0; a < p; a++)
            tr += w->M[a * p + a];
        if (cholesky(w->M, p, 1e-13 * tr))
            return singular(k, x, "drift matrix");
        nl_kl_lsolve(w->M, p, w->u, w->u2);
        ltsolve(w->M, p, w->u2, w->beta); /* beta = (Q'Q)^-1 Q' y */
        for (size_t i = 0; i < K; i++)
            for (size_t j = 0; j < p; j++)
                y[i] -= w->Q[j * K + i] * w->beta[j];
    }
    ltsolve(L, K, y, w->r); /* r = C^-1 (z - X beta) */
    return NL_OK;
}

/* Run nl_kl_point over count locations in parallel; loc(t, x) gives
 * location t; skip(t) the datum left out (SIZE_MAX: none). */
typedef struct {
    const double *x;    /* count * dim coordinates, or NULL for a grid */
    const double *c;    /* count * ncov covariates of the locations x, or NULL */
    const double *lo;   /* grid origin */
    const nl_field *g;  /* grid, or NULL */
    int cv;             /* cross-validation: location t is datum t, left out */
} locs_t;

static void location(const nl_krige_local *k, const locs_t *L, size_t t, double *x)
{
    int dim = k->dim;
    if (L->cv || L->x) {
        memcpy(x, (L->cv ? k->pts : L->x) + t * dim, dim * sizeof(double));
        return;
    }
    size_t i = t % L->g->n[0], j = t / L->g->n[0] % L->g->n[1], l = t / (L->g->n[0] * L->g->n[1]);
    size_t ix[3] = {i, j, l};
    for (int a = 0; a < dim; a++)
        x[a] = L->lo[a] + ((double)ix[a] + 0.5) * L->g->h[a];
}

/* The covariates of location t (NULL when the plan has none). */
static const double *location_cov(const nl_krige_local *k, const locs_t *L, size_t t)
{
    if (!k->o.ncov)
        return NULL;
    return (L->cv ? k->cov : L->c) + t * k->o.ncov;
}

/* The status of a run: out of memory, or the error of the first location
 * that failed (again on this thread, for the message). */
static int outcome(const nl_krige_local *k, const locs_t *L, int nomem, size_t bad)
{
    if (nomem)
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory for the neighbourhoods");
    if (bad != SIZE_MAX) {
        nl_kl_work w;
        double x[3], e, v;
        int st = nl_kl_work_init(&w, k->cap, k->p);
        if (!st) {
            location(k, L, bad, x);
            st = nl_kl_point(k, x, location_cov(k, L, bad), L->cv ? bad : SIZE_MAX, &w, &e, &v);
            nl_kl_work_free(&w);
        }
        return st ? st : NL_ERROR(NL_EFAIL, "kriging: location %zu failed", bad);
    }
    return NL_OK;
}

/* Every location's neighbourhood is all the data (no radius, nmax 0 or at
 * least n, not cross-validation): one factorisation per thread, then blocks
 * of NL_KRIGE_BLOCK locations solved together (nl_kl_batch, level-3 BLAS).
 * Blocks are fixed, so the bits do not depend on the thread count. */
static int run_global(const nl_krige_local *k, const locs_t *L, size_t count, double *est, double *var)
{
    enum { B = NL_KRIGE_BLOCK };
    size_t bad = SIZE_MAX, nblk = (count + B - 1) / B;
    int nomem = 0;
#pragma omp parallel if (count > 256 && nl_model_is_reentrant(k->m))
    {
        nl_kl_work w;
        double *C0 = malloc(k->n * B * sizeof *C0), *U = malloc((k->p ? k->p : 1) * B * sizeof *U), x[3 * B];
        int init = nl_kl_work_init(&w, k->cap, k->p) == NL_OK, ok = init && C0 && U, factored = 0;
        if (!ok) {
#pragma omp atomic write
            nomem = 1;
        } else {
            for (size_t i = 0; i < k->n; i++)
                w.set[i] = i;
            w.K = k->n;
            location(k, L, 0, x);
            factored = nl_kl_factor(k, &w, x) == NL_OK;
        }
#pragma omp for schedule(dynamic, 1) reduction(min : bad)
        for (size_t blk = 0; blk < nblk; blk++) {
            size_t t0 = blk * B, nb = count - t0 < B ? count - t0 : B;
            if (!ok)
                continue;
            if (!factored) {
                bad = t0 < bad ? t0 : bad;
                continue;
            }
            for (size_t q = 0; q < nb; q++)
                location(k, L, t0 + q, x + q * (size_t)k->dim);
            nl_kl_batch(k, x, location_cov(k, L, t0), nb, &w, C0, U, est + t0, var ? var + t0 : NULL);
        }
        if (init)
            nl_kl_work_free(&w);
        free(C0), free(U);
    }
    return outcome(k, L, nomem, bad);
}

static int run_all(const nl_krige_local *k, const locs_t *L, size_t count, double *est, double *var);

/* As run_all; when every location is missing (o.missing), the error of the
 * first as if missing locations were refused: a map or table of nothing
 * but missing values is a mistake (a radius too small for the data). */
static int run(const nl_krige_local *k, const locs_t *L, size_t count, double *est, double *var)
{
    int st = run_all(k, L, count, est, var);
    size_t i = 0;
    while (!st && k->o.missing && i < count && isnan(est[i]))
        i++;
    if (st || !k->o.missing || i < count || count == 0)
        return st;
    nl_krige_local strict = *k;
    strict.o.missing = 0;
    return outcome(&strict, L, 0, 0);
}

static int run_all(const nl_krige_local *k, const locs_t *L, size_t count, double *est, double *var)
{
    size_t bad = SIZE_MAX;
    int nomem = 0;
    if (!L->cv && k->o.radius == 0 && k->cap >= k->n)
        return run_global(k, L, count, est, var);
#pragma omp parallel if (count > 256 && nl_model_is_reentrant(k->m))
    {
        nl_kl_work w;
        int ok = nl_kl_work_init(&w, k->cap, k->p) == NL_OK;
        if (!ok) {
#pragma omp atomic write
            nomem = 1;
        }
#pragma omp for schedule(dynamic, 64) reduction(min : bad)
        for (size_t t = 0; t < count; t++) {
            double x[3];
            if (!ok)
                continue;
            location(k, L, t, x);
            if (nl_kl_point(k, x, location_cov(k, L, t), L->cv ? t : SIZE_MAX, &w, &est[t], var ? &var[t] : NULL))
                bad = t < bad ? t : bad;
        }
        nl_kl_work_free(&w);
    }
    return outcome(k, L, nomem, bad);
}

static int no_covariates(const nl_krige_local *k)
{
    return NL_ERROR(NL_EINVAL, "kriging: the plan has %zu covariates (an external drift); expected their values at "
                    "the locations (nl_krige_local_eval_at)", k->o.ncov);
}

int nl_krige_local_eval(const nl_krige_local *k, size_t count, const double *x, double *est, double *var)
{
    return nl_krige_local_eval_at(k, count, x, NULL, est, var);
}

int nl_krige_local_eval_at(const nl_krige_local *k, size_t count, const double *x, const double *cov, double *est,
                           double *var)
{
    locs_t L = {.x = x, .c = cov};
    if (k->o.ncov && !cov)
        return no_covariates(k);
    for (size_t i = 0; cov && i < count * k->o.ncov; i++)
        if (!isfinite(cov[i]))
            return NL_ERROR(NL_EINVAL, "kriging: covariate %zu of location %zu is %g; expected a finite number",
                            i % k->o.ncov + 1, i / k->o.ncov + 1, cov[i]);
    return run(k, &L, count, est, var);
}

int nl_krige_local_grid(const nl_krige_local *k, const double *lo, nl_field *est, nl_field *var)
{
    if (k->o.ncov)
        return no_covariates(k);
    if (est->dim != k->dim || (var && var->count != est->count))
        return NL_ERROR(NL_EINVAL, "kriging: expected a %dD grid (and a variance grid of its size), got %dD", k->dim,
                        est->dim);
    locs_t L = {.lo = lo, .g = est};
    return run(k, &L, est->count, est->data, var ? var->data : NULL);
}

/* Values whose cross-validation errors stay representable: an error is a
 * datum minus a weighted mean of others, a few times the values' range at
 * most, and n squared errors are summed: max - min at most
 * sqrt(DBL_MAX / n) / 16. */
static int check_cv_values(const nl_krige_local *k)
{
    double lo = INFINITY, hi = -INFINITY, bound = sqrt(DBL_MAX / (double)k->n) / 16;
    for (size_t i = 0; i < k->n; i++)
        lo = fmin(lo, k->val[i]), hi = fmax(hi, k->val[i]);
    if (!(hi - lo <= bound))
        return NL_ERROR(NL_EINVAL, "kriging: cross-validation: the data's values run from %g to %g: the squared "
                        "errors overflow; expected max - min below %.3g (sqrt(DBL_MAX / n) / 16, n = %zu)", lo, hi,
                        bound, k->n);
    return NL_OK;
}

int nl_krige_local_cv(const nl_krige_local *k, double *pred, double *var, nl_krige_cv_summary *s)
{
    locs_t L = {.cv = 1};
    int st = check_cv_values(k);
    if (st || (st = run(k, &L, k->n, pred, var)))
        return st;
    return nl_kl_cv_summary(k, pred, var, s);
}

int nl_kl_cv_summary(const nl_krige_local *k, const double *pred, const double *var, nl_krige_cv_summary *s)
{
    double se = 0, sz = 0, se2 = 0, sz2 = 0, n = 0;
    int st = check_cv_values(k);
    if (st)
        return st;
    for (size_t i = 0; i < k->n; i++) {
        if (k->o.missing && isnan(pred[i]))
            continue;
        n++;
        if (!(var[i] > 0))
            return NL_ERROR(NL_EINVAL, "kriging: cross-validation: the kriging variance at datum %zu is %g; expected a "
                            "positive variance (duplicate points?)", i + 1, var[i]);
        double e = k->val[i] - pred[i], z = e / sqrt(var[i]);
        se += e, sz += z, se2 += e * e, sz2 += z * z;
    }
    if (n < 2)
        return NL_ERROR(NL_EINVAL, "kriging: cross-validation: %g of the %zu data predicted; expected 2 at least "
                        "(the others have no data in their neighbourhood)", n, k->n);
    s->n = (size_t)n;
    s->mean_error = se / n, s->mean_z = sz / n, s->rmse = sqrt(se2 / n);
    s->var_error = (se2 - se * se / n) / (n - 1), s->var_z = (sz2 - sz * sz / n) / (n - 1);
    if (!(isfinite(s->rmse) && isfinite(s->var_error) && isfinite(sz2) && isfinite(s->var_z)))
        return NL_ERROR(NL_EINVAL, "kriging: cross-validation: the squared errors or standardised errors of the data's "
                        "values overflow with %s (mean error %g); expected values of smaller magnitude or a model "
                        "variance nearer their spread", nl_model_spec(k->m), s->mean_error);
    return NL_OK;
}
