/* Local-neighbourhood and universal kriging: the neighbour search, the
 * factorisation of a neighbourhood (cached while the set repeats) and the
 * estimate at one location (Cressie 1993, eqs. (3.4.60)-(3.4.61)). */
#include "krige_local.h"
#include "krige_local_internal.h"
#include "../core/nl_error.h"

#include <gsl/gsl_cblas.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void nl_krige_local_free(nl_krige_local *k)
{
    if (!k)
        return;
    nl_spindex_free(k->index);
    nl_gq_free(k->gq);
    free(k->pts), free(k->val), free(k->cov), free(k->cc), free(k->cs), free(k);
}

size_t nl_krige_local_terms(const nl_krige_local *k) { return k->p; }

static size_t terms(int drift, int dim)
{
    return drift == NL_DRIFT_NONE ? 0 : drift == NL_DRIFT_CONSTANT ? 1 : drift == NL_DRIFT_LINEAR ? (size_t)dim + 1
                                                                     : (size_t)(1 + dim + dim * (dim + 1) / 2);
}

static int check_data(int dim, size_t n, const double *pts, const double *val, double *lo, double *hi)
{
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "kriging: expected 1 to 3 coordinates per point, got %d", dim);
    if (n < 2)
        return NL_ERROR(NL_EINVAL, "kriging: expected at least 2 data points, got %zu", n);
    for (int a = 0; a < dim; a++)
        lo[a] = INFINITY, hi[a] = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(val[i]))
            return NL_ERROR(NL_EINVAL, "kriging: the value of point %zu is %g; expected a finite number", i + 1, val[i]);
        for (int a = 0; a < dim; a++) {
            double v = pts[i * dim + a];
            if (!isfinite(v))
                return NL_ERROR(NL_EINVAL, "kriging: coordinate %d of point %zu is %g; expected a finite number", a + 1,
                                i + 1, v);
            lo[a] = fmin(lo[a], v), hi[a] = fmax(hi[a], v);
        }
    }
    int same = 1;
    for (int a = 0; a < dim; a++)
        same &= hi[a] == lo[a];
    if (same)
        return NL_ERROR(NL_EINVAL, "kriging: all %zu points are at one place; expected points at two places at least", n);
    return NL_OK;
}

static int check_options(const nl_krige_local_options *o, size_t n, size_t p, int dim)
{
    if (!(o->radius >= 0) || !isfinite(o->radius))
        return NL_ERROR(NL_EINVAL, "kriging: radius: expected a finite distance >= 0 (0: no limit), got %g", o->radius);
    if (o->drift < NL_DRIFT_NONE || o->drift > NL_DRIFT_QUADRATIC)
        return NL_ERROR(NL_EINVAL, "kriging: drift: expected none, constant, linear or quadratic, got %d", o->drift);
    if (o->drift == NL_DRIFT_NONE && !isfinite(o->mean))
        return NL_ERROR(NL_EINVAL, "kriging: mean: expected a finite number, got %g", o->mean);
    if (o->ncov && (o->drift == NL_DRIFT_NONE || !o->cov))
        return NL_ERROR(NL_EINVAL, "kriging: %zu covariates: expected %s", o->ncov,
                        o->cov ? "ordinary or universal kriging (an external drift has no known mean)"
                               : "their values for the data");
    size_t k = o->nmax && o->nmax < n ? o->nmax : n;
    if (k < p || k < 1)
        return NL_ERROR(NL_EINVAL, "kriging: a %s drift in %dD with %zu covariates has %zu terms; expected at least "
                        "as many points in a neighbourhood, got %zu",
                        o->drift == NL_DRIFT_QUADRATIC ? "quadratic" : o->drift == NL_DRIFT_LINEAR ? "linear"
                                                                                                     : "constant",
                        dim, o->ncov, p, k);
    if (o->nmax > NL_KRIGE_LOCAL_MAX || (!o->nmax && !o->radius && n > NL_KRIGE_LOCAL_MAX))
        return NL_ERROR(NL_EINVAL, "kriging: neighbourhoods of %zu points; expected at most %d (set nmax)",
                        o->nmax ? o->nmax : n, NL_KRIGE_LOCAL_MAX);
    return NL_OK;
}

/* Copy the data's covariates; their centres and scales for the drift. */
static int covariates(nl_krige_local *k, const nl_krige_local_options *o)
{
    size_t q = o->ncov;
    k->cov = malloc(k->n * q * sizeof(double)), k->cc = malloc(q * sizeof(double)), k->cs = malloc(q * sizeof(double));
    if (!k->cov || !k->cc || !k->cs)
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory for %zu covariates", q);
    memcpy(k->cov, o->cov, k->n * q * sizeof(double));
    for (size_t j = 0; j < q; j++) {
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < k->n; i++) {
            double v = k->cov[i * q + j];
            if (!isfinite(v))
                return NL_ERROR(NL_EINVAL, "kriging: covariate %zu of point %zu is %g; expected a finite number", j + 1,
                                i + 1, v);
            lo = fmin(lo, v), hi = fmax(hi, v);
        }
        k->cc[j] = 0.5 * (lo + hi), k->cs[j] = hi > lo ? 0.5 * (hi - lo) : 1;
    }
    k->o.cov = NULL; /* the caller's array is not kept */
    return NL_OK;
}

int nl_krige_local_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val,
                         const nl_krige_local_options *o, nl_krige_local **out)
{
    double lo[3], hi[3], zero[3] = {0, 0, 0};
    int st;
    *out = NULL;
    if ((st = check_data(dim, n, pts, val, lo, hi)) || (st = check_options(o, n, terms(o->drift, dim) + o->ncov, dim)))
        return st;
    if ((st = nl_model_check_dim(m, dim)))
        return st;
    double r0 = nl_model_acf(m, dim, zero), shift = 0;
    if (nl_model_is_intrinsic(m)) {
        /* as analysis/krige.c: a constant added to K = -gamma, here twice
         * gamma across the data's bounding box, bounding every pair's */
        double lag[3] = {0, 0, 0};
        if (o->drift == NL_DRIFT_NONE)
            return NL_ERROR(NL_EINVAL, "%s: simple kriging (--mean) needs a covariance; %s is intrinsic (no "
                            "covariance, no mean): expected ordinary or universal kriging", nl_model_spec(m),
                            nl_model_family(m)->name);
        for (int a = 0; a < dim; a++)
            lag[a] = hi[a] - lo[a];
        shift = 2 * nl_model_variogram(m, dim, lag);
        if (!(shift > 0) || !isfinite(shift))
            shift = 1;
        r0 += shift;
    }
    if (!(r0 > 0) || !isfinite(r0))
        return NL_ERROR(NL_EINVAL, "kriging: the model's R(0) is %g; expected a finite positive variance", r0);
    nl_krige_local *k = calloc(1, sizeof *k);
    if (!k)
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory");
    k->m = m, k->dim = dim, k->n = n, k->o = *o, k->p = terms(o->drift, dim) + o->ncov, k->r0 = r0;
    k->shift = shift;
    k->cap = o->nmax && o->nmax < n ? o->nmax : n < NL_KRIGE_LOCAL_MAX ? n : NL_KRIGE_LOCAL_MAX;
    for (int a = 0; a < dim; a++)
        k->centre[a] = 0.5 * (lo[a] + hi[a]), k->scale[a] = hi[a] > lo[a] ? 0.5 * (hi[a] - lo[a]) : 1;
    k->pts = malloc(n * dim * sizeof(double)), k->val = malloc(n * sizeof(double));
    if (!k->pts || !k->val) {
        nl_krige_local_free(k);
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory for %zu points", n);
    }
    memcpy(k->pts, pts, n * dim * sizeof(double)), memcpy(k->val, val, n * sizeof(double));
    if (o->ncov && (st = covariates(k, o))) {
        nl_krige_local_free(k);
        return st;
    }
    if ((st = nl_spindex_alloc(dim, n, pts, &k->index))) {
        nl_krige_local_free(k);
        return st;
    }
    if (o->nmax && o->nmax < n && !(k->gq = nl_gq_build(k, SIZE_MAX))) {
        nl_krige_local_free(k);
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory for the search tree of %zu points", n);
    }
    *out = k;
    return NL_OK;
}

/* The drift terms at x (p values). */
void nl_kl_drift(const nl_krige_local *k, const double *x, const double *c, double *f)
{
    double u[3];
    size_t t = 0;
    if (k->p == 0)
        return;
    f[t++] = 1;
    if (k->o.drift != NL_DRIFT_CONSTANT)
        for (int a = 0; a < k->dim; a++)
            u[a] = (x[a] - k->centre[a]) / k->scale[a], f[t++] = u[a];
    if (k->o.drift == NL_DRIFT_QUADRATIC)
        for (int a = 0; a < k->dim; a++)
            for (int b = a; b < k->dim; b++)
                f[t++] = u[a] * u[b];
    for (size_t j = 0; j < k->o.ncov; j++)
        f[t++] = (c[j] - k->cc[j]) / k->cs[j];
}

static int cmp_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

/* The nearest k->cap neighbours are a tie (the cap-th and the next are
 * equidistant): take gstat's choice (analysis/krige_gstat_order.c) into
 * w->next, keeping the k-d tree's when memory runs out. */
static size_t gstat_tie(const nl_krige_local *k, const double *x, size_t skip, nl_kl_work *w, size_t m)
{
    nl_gq_node *t = skip == (size_t)-1 ? k->gq : nl_gq_build(k, skip);
    size_t got = t ? nl_gq_select(k, t, x, k->cap, w->set + k->cap + 1) : 0;
    if (t && t != k->gq)
        nl_gq_free(t);
    if (got != k->cap)
        return m < k->cap ? m : k->cap;
    memcpy(w->next, w->set + k->cap + 1, got * sizeof *w->next);
    return got;
}

/* The neighbours of x (without datum `skip`, SIZE_MAX for none) into
 * w->next (ascending indices); returns their number.  When nmax binds, one
 * more is looked at, for ties. */
static size_t neighbours(const nl_krige_local *k, const double *x, size_t skip, nl_kl_work *w)
{
    size_t want = k->cap + (skip != (size_t)-1) + (k->gq != NULL), got;
    if (want > k->n)
        want = k->n;
    if (k->o.radius > 0) {
        got = nl_spindex_within(k->index, x, k->o.radius, want, w->next, w->d2);
        w->overflow = !k->o.nmax && got > want;
        if (got > want)
            got = want;
    } else
        got = nl_spindex_knn(k->index, x, want, w->next, w->d2), w->overflow = 0;
    size_t m = 0;
    for (size_t i = 0; i < got; i++)
        if (w->next[i] != skip)
            w->next[m++] = w->next[i];
    if (k->gq && m > k->cap &&
        nl_gq_d2(k->dim, x, k->pts + w->next[k->cap - 1] * k->dim) == nl_gq_d2(k->dim, x, k->pts + w->next[k->cap] * k->dim))
        m = gstat_tie(k, x, skip, w, m);
    if (m > k->cap)
        m = k->cap;
    qsort(w->next, m, sizeof *w->next, cmp_size);
    return m;
}

static double cov(const nl_krige_local *k, const double *x, const double *y)
{
    double lag[3] = {0, 0, 0};
    for (int a = 0; a < k->dim; a++)
        lag[a] = x[a] - y[a];
    return k->shift + nl_model_acf(k->m, k->dim, lag);
}

const char *nl_kl_where(const nl_krige_local *k, const double *x, char *buf)
{
    if (k->dim == 1)
        snprintf(buf, 64, "(%g)", x[0]);
    else if (k->dim == 2)
        snprintf(buf, 64, "(%g, %g)", x[0], x[1]);
    else
        snprintf(buf, 64, "(%g, %g, %g)", x[0], x[1], x[2]);
    return buf;
}

/* What the neighbourhood of a location is, for messages: the data within
 * the radius, the nmax nearest or all of them, less a datum left out. */
static const char *hood(const nl_krige_local *k, size_t skip, char *buf)
{
    const char *less = skip != (size_t)-1 ? ", less the point left out" : "";
    if (k->o.radius > 0 && k->o.nmax)
        snprintf(buf, 96, "the nearest %zu within the radius %g%s", k->o.nmax, k->o.radius, less);
    else if (k->o.radius > 0)
        snprintf(buf, 96, "the data within the radius %g%s", k->o.radius, less);
    else if (k->o.nmax)
        snprintf(buf, 96, "the nearest %zu, no radius%s", k->o.nmax, less);
    else
        snprintf(buf, 96, "all the data, no radius%s", less);
    return buf;
}

/* Location x: estimate and variance from the neighbourhood of x (without
 * datum skip). */
int nl_kl_point(const nl_krige_local *k, const double *x, const double *c, size_t skip, nl_kl_work *w, double *est,
                double *var)
{
    size_t K = neighbours(k, x, skip, w), p = k->p;
    int st;
    char at[64], desc[96];
    if (w->overflow)
        return NL_ERROR(NL_EINVAL, "kriging: more than %zu data within the radius %g of %s; expected fewer (set nmax)",
                        k->cap, k->o.radius, nl_kl_where(k, x, at));
    if ((K < p || K == 0) && k->o.missing) {
        *est = NAN;
        if (var)
            *var = NAN;
        return NL_OK;
    }
    if (K < p || K == 0)
        return NL_ERROR(NL_EINVAL, "kriging: %zu data in the neighbourhood of %s (%s); expected at least %zu", K,
                        nl_kl_where(k, x, at), hood(k, skip, desc), p ? p : 1);
    if (!(w->valid && K == w->K && memcmp(w->next, w->set, K * sizeof *w->set) == 0)) {
        memcpy(w->set, w->next, K * sizeof *w->set);
        w->K = K, w->valid = 0;
        if ((st = nl_kl_factor(k, w, x)))
            return st;
        w->valid = 1;
    }
    double *c0 = w->c0, *v = w->v, *f = w->f, s = 0, e = 0;
    for (size_t i = 0; i < K; i++)
        c0[i] = cov(k, x, k->pts + w->set[i] * k->dim);
    nl_kl_lsolve(w->L, K, c0, v); /* v = L^-1 c0 */
    for (size_t i = 0; i < K; i++)
        e += c0[i] * w->r[i], s += v[i] * v[i];
    nl_kl_drift(k, x, c, f);
    if (p == 0)
        e += k->o.mean;
    for (size_t j = 0; j < p; j++) { /* u = x0 - Q' v, then M^-1 u */
        double t = f[j];
        for (size_t i = 0; i < K; i++)
            t -= w->Q[j * K + i] * v[i];
        w->u[j] = t, e += f[j] * w->beta[j];
    }
    nl_kl_lsolve(w->M, p, w->u, w->u2);
    for (size_t j = 0; j < p; j++)
        s -= w->u2[j] * w->u2[j];
    *est = e;
    if (var)
        *var = fmax(k->r0 - s, 0);
    return NL_OK;
}

/* nb (<= NL_KRIGE_BLOCK) locations x whose neighbourhood is the factored
 * set of w (the global one): the same estimator as nl_kl_point, with the
 * K x nb covariances C0 solved at once, V = L^-1 C0 (level-3 BLAS dtrsm),
 * and the drift residuals U = F - Q V by dgemm.  C0 is K x NL_KRIGE_BLOCK
 * scratch (row-major), U p x NL_KRIGE_BLOCK; unused columns are zero, so a
 * block's arithmetic does not depend on nb's neighbours or on the thread. */
void nl_kl_batch(const nl_krige_local *k, const double *x, const double *c, size_t nb, nl_kl_work *w, double *C0,
                 double *U, double *est, double *var)
{
    enum { B = NL_KRIGE_BLOCK };
    size_t K = w->K, p = k->p;
    int dim = k->dim;
    memset(C0, 0, K * B * sizeof *C0);
    for (size_t b = 0; b < nb; b++) {
        double e = p == 0 ? k->o.mean : 0;
        for (size_t i = 0; i < K; i++) {
            double c = cov(k, x + b * dim, k->pts + w->set[i] * dim);
            C0[i * B + b] = c;
            e += c * w->r[i];
        }
        nl_kl_drift(k, x + b * dim, c ? c + b * k->o.ncov : NULL, w->f);
        for (size_t j = 0; j < p; j++)
            e += w->f[j] * w->beta[j];
        est[b] = e;
        for (size_t j = 0; j < p; j++)
            U[j * B + b] = w->f[j];
    }
    for (size_t j = 0; j < p; j++)
        memset(U + j * B + nb, 0, (B - nb) * sizeof *U);
    cblas_dtrsm(CblasRowMajor, CblasLeft, CblasLower, CblasNoTrans, CblasNonUnit, (int)K, B, 1.0, w->L, (int)K, C0,
                B);
    if (p)
        cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, (int)p, B, (int)K, -1.0, w->Q, (int)K, C0, B, 1.0, U,
                    B);
    if (!var)
        return;
    for (size_t b = 0; b < nb; b++) {
        double s = 0;
        for (size_t i = 0; i < K; i++)
            s += C0[i * B + b] * C0[i * B + b];
        for (size_t j = 0; j < p; j++)
            w->u[j] = U[j * B + b];
        nl_kl_lsolve(w->M, p, w->u, w->u2);
        for (size_t j = 0; j < p; j++)
            s -= w->u2[j] * w->u2[j];
        var[b] = fmax(k->r0 - s, 0);
    }
}

size_t nl_kl_neighbours(const nl_krige_local *k, const double *x, size_t skip, nl_kl_work *w)
{
    return neighbours(k, x, skip, w);
}
