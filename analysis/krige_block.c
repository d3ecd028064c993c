/* Block kriging (Journel and Huijbregts 1978, section V.A.2) and the
 * location loop the kriging flavours share: the discretisation of a block
 * as gstat's src/block.c, point-to-block and block-to-block covariances as
 * gstat's src/vario_io.c (sem_cov_blocks). */
#include "krige_flavours.h"
#include "krige_flavours_internal.h"
#include "../core/nl_error.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* gstat's src/block.c: Gauss-Legendre on [-1/2, 1/2] (Carr and Palmer 1993) */
static const double gauss_x[4] = {-0.4305681558, -0.1699905218, 0.1699905218, 0.4305681558};
static const double gauss_w[4] = {0.1739274226, 0.3260725774, 0.3260725774, 0.1739274226};

/* gstat's gl_zero: lags shorter than this between a block's points count as this long */
#define ZERO_LAG (DBL_EPSILON * 10.0)

int nl_krige_block_discretise(const nl_krige_block *b, int dim, size_t *nd, double *d, double *w)
{
    int N = b->points ? b->points : 4;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "block kriging: expected 1 to 3 dimensions, got %d", dim);
    for (int a = 0; a < dim; a++)
        if (!(b->size[a] > 0) || !isfinite(b->size[a]))
            return NL_ERROR(NL_EINVAL, "block kriging: block edge %d is %g; expected a finite positive size", a + 1,
                            b->size[a]);
    if (b->points < 0 || b->points == 1 || b->points > NL_KRIGE_BLOCK_AXIS_MAX)
        return NL_ERROR(NL_EINVAL, "block kriging: %d points per axis; expected 0 (Gauss-Legendre) or 2 to %d",
                        b->points, NL_KRIGE_BLOCK_AXIS_MAX);
    size_t total = 1;
    for (int a = 0; a < dim; a++)
        total *= (size_t)N;
    if (total > NL_KRIGE_BLOCK_POINTS_MAX)
        return NL_ERROR(NL_EINVAL, "block kriging: %d points per axis in %dD make %zu points; expected at most %d",
                        N, dim, total, NL_KRIGE_BLOCK_POINTS_MAX);
    /* gstat's order: the first axis slowest */
    for (size_t j = 0; j < total; j++) {
        size_t r = j;
        w[j] = 1;
        for (int a = dim - 1; a >= 0; a--) {
            size_t i = r % (size_t)N;
            r /= (size_t)N;
            double u = b->points ? -0.5 + ((double)i + 0.5) / N : gauss_x[i];
            d[j * dim + a] = b->size[a] * u;
            w[j] *= b->points ? 1.0 / N : gauss_w[i];
        }
    }
    *nd = total;
    return NL_OK;
}

/* C(lag) of the plan, a lag under ZERO_LAG taken as ZERO_LAG when zero_effect. */
static double cov_at(const nl_krige_local *k, double *lag, int zero_effect)
{
    if (zero_effect) {
        double h2 = 0;
        for (int a = 0; a < k->dim; a++)
            h2 += lag[a] * lag[a];
        if (h2 < ZERO_LAG * ZERO_LAG)
            lag[0] = ZERO_LAG, lag[1] = lag[2] = 0;
    }
    return k->shift + nl_model_acf(k->m, k->dim, lag);
}

int nl_kf_support_init(const nl_krige_local *k, const nl_krige_block *b, nl_kf_support *s)
{
    int dim = k->dim, st;
    memset(s, 0, sizeof *s);
    if (k->o.ncov)
        return NL_ERROR(NL_EINVAL, "block kriging: the plan has %zu covariates (an external drift); expected none",
                        k->o.ncov);
    size_t cap = b ? NL_KRIGE_BLOCK_POINTS_MAX : 1;
    s->d = calloc(cap * (size_t)dim, sizeof *s->d), s->w = malloc(cap * sizeof *s->w);
    if (!s->d || !s->w) {
        nl_kf_support_free(s);
        return NL_ERROR(NL_ENOMEM, "block kriging: out of memory for the discretisation");
    }
    if (!b) {
        s->nd = 1, s->w[0] = 1, s->cbb = k->r0;
        return NL_OK;
    }
    if ((st = nl_krige_block_discretise(b, dim, &s->nd, s->d, s->w))) {
        nl_kf_support_free(s);
        return st;
    }
    double cbb = 0; /* Journel and Huijbregts 1978, eq. (V.19): the double average */
    for (size_t i = 0; i < s->nd; i++) {
        double row = 0;
        for (size_t j = 0; j < s->nd; j++) {
            double lag[3] = {0, 0, 0};
            for (int a = 0; a < dim; a++)
                lag[a] = s->d[i * dim + a] - s->d[j * dim + a];
            row += s->w[j] * cov_at(k, lag, 1);
        }
        cbb += s->w[i] * row;
    }
    s->cbb = cbb;
    if (!isfinite(cbb)) {
        nl_kf_support_free(s);
        return NL_ERROR(NL_EINVAL, "block kriging: the block-to-block covariance of %s is %g; expected a finite number",
                        nl_model_spec(k->m), cbb);
    }
    return NL_OK;
}

void nl_kf_support_free(nl_kf_support *s)
{
    free(s->d), free(s->w);
    memset(s, 0, sizeof *s);
}

/* The neighbourhood of x, factored (reused while the set repeats). */
static int neighbourhood(const nl_krige_local *k, const double *x, size_t skip, nl_kl_work *w)
{
    size_t K = nl_kl_neighbours(k, x, skip, w), p = k->p;
    char at[64];
    int st;
    if (w->overflow)
        return NL_ERROR(NL_EINVAL, "kriging: more than %zu data within the radius %g of %s; expected fewer (set nmax)",
                        k->cap, k->o.radius, nl_kl_where(k, x, at));
    if (K < p || K == 0)
        return NL_ERROR(NL_EINVAL, "kriging: %zu data in the neighbourhood of %s%s; expected at least %zu", K,
                        nl_kl_where(k, x, at), skip != SIZE_MAX ? " less the point left out" : "", p ? p : 1);
    if (!(w->valid && K == w->K && memcmp(w->next, w->set, K * sizeof *w->set) == 0)) {
        memcpy(w->set, w->next, K * sizeof *w->set);
        w->K = K, w->valid = 0;
        if ((st = nl_kl_factor(k, w, x)))
            return st;
        w->valid = 1;
    }
    return NL_OK;
}

/* One location: the estimator of nl_kl_point (Cressie 1993, eqs.
 * (3.4.60)-(3.4.61)) with c0, the drift at x0 and R(0) averaged over the
 * support. */
static int locate(const nl_krige_local *k, const nl_kf_support *s, const double *x, size_t skip, nl_kl_work *w,
                  nl_kf_out *o)
{
    int st, dim = k->dim, block = s->nd > 1; /* a point: nd 1 */
    if ((st = neighbourhood(k, x, skip, w)))
        return st;
    size_t K = w->K, p = k->p;
    double *c0 = w->c0, *v = w->v, f[16] = {0}, g[16], e = p ? 0 : k->o.mean, ss = 0;
    for (size_t i = 0; i < K; i++) {
        const double *t = k->pts + w->set[i] * dim;
        double c = 0;
        for (size_t j = 0; j < s->nd; j++) {
            double lag[3] = {0, 0, 0};
            for (int a = 0; a < dim; a++)
                lag[a] = x[a] + s->d[j * dim + a] - t[a];
            c += s->w[j] * cov_at(k, lag, block);
        }
        c0[i] = c;
    }
    for (size_t j = 0; j < s->nd && p; j++) {
        double y[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++)
            y[a] = x[a] + s->d[j * dim + a];
        nl_kl_drift(k, y, NULL, g);
        for (size_t q = 0; q < p; q++)
            f[q] += s->w[j] * g[q];
    }
    nl_kl_lsolve(w->L, K, c0, v); /* v = L^-1 c0 */
    for (size_t i = 0; i < K; i++)
        e += c0[i] * w->r[i], ss += v[i] * v[i];
    for (size_t q = 0; q < p; q++) { /* u = x0 - Q' v */
        double t = f[q];
        for (size_t i = 0; i < K; i++)
            t -= w->Q[q * K + i] * v[i];
        w->u[q] = t, e += f[q] * w->beta[q];
    }
    o->mu = o->lag = NAN;
    if (p == 1 && k->o.drift == NL_DRIFT_CONSTANT) /* M = chol(1' C^-1 1) */
        o->mu = w->beta[0], o->lag = w->u[0] / (w->M[0] * w->M[0]);
    nl_kl_lsolve(w->M, p, w->u, w->u2);
    for (size_t q = 0; q < p; q++)
        ss -= w->u2[q] * w->u2[q];
    o->est = e, o->var = fmax(s->cbb - ss, 0);
    return NL_OK;
}

int nl_kf_run(const nl_krige_local *k, const nl_kf_support *s, size_t count, const double *x, int cv, nl_kf_out *out)
{
    size_t bad = SIZE_MAX;
    int nomem = 0, dim = k->dim;
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
            if (!ok)
                continue;
            if (locate(k, s, (cv ? k->pts : x) + t * dim, cv ? t : SIZE_MAX, &w, &out[t]))
                bad = t < bad ? t : bad;
        }
        if (ok)
            nl_kl_work_free(&w);
    }
    if (nomem)
        return NL_ERROR(NL_ENOMEM, "kriging: out of memory for the neighbourhoods");
    if (bad == SIZE_MAX)
        return NL_OK;
    nl_kl_work w; /* again on this thread, for the message */
    int st = nl_kl_work_init(&w, k->cap, k->p);
    if (!st) {
        st = locate(k, s, (cv ? k->pts : x) + bad * dim, cv ? bad : SIZE_MAX, &w, &out[bad]);
        nl_kl_work_free(&w);
    }
    return st ? st : NL_ERROR(NL_EFAIL, "kriging: location %zu failed", bad + 1);
}

int nl_krige_block_eval(const nl_krige_local *k, const nl_krige_block *b, size_t count, const double *x, double *est,
                        double *var)
{
    nl_kf_support s;
    int st = nl_kf_support_init(k, b, &s);
    if (st)
        return st;
    nl_kf_out *o = malloc((count ? count : 1) * sizeof *o);
    if (!o) {
        nl_kf_support_free(&s);
        return NL_ERROR(NL_ENOMEM, "block kriging: out of memory for %zu locations", count);
    }
    if (!(st = nl_kf_run(k, &s, count, x, 0, o)))
        for (size_t t = 0; t < count; t++) {
            est[t] = o[t].est;
            if (var)
                var[t] = o[t].var;
        }
    free(o);
    nl_kf_support_free(&s);
    return st;
}
