/* Kriging weights on the data at many locations, for kriging many value
 * vectors at once (analysis/krige_weights_internal.h). */
#include "krige_weights_internal.h"
#include "krige_local_internal.h"
#include "../core/nl_error.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

size_t nl_krige_weights_width(const nl_krige_local *k)
{
    return k->cap;
}

/* The cap nearest data of x (nl_kl_point's search, gstat's choice at a
 * tie) into w->next, ascending indices. */
static size_t nearest(const nl_krige_local *k, const double *x, nl_kl_work *w)
{
    return nl_kl_neighbours(k, x, SIZE_MAX, w);
}

/* x = L^-T b (L lower, n x n, row-major). */
static void ltsolve(const double *L, size_t n, const double *b, double *x)
{
    for (size_t i = n; i-- > 0;) {
        double s = b[i];
        for (size_t j = i + 1; j < n; j++)
            s -= L[j * n + i] * x[j];
        x[i] = s / L[i * n + i];
    }
}

/* The weights at x into w_out, idx_out (k->cap entries; zero weights on
 * index 0 beyond the neighbourhood) and *c. */
static int point(const nl_krige_local *k, const double *x, nl_kl_work *w, uint32_t *idx_out, double *w_out,
                 double *c)
{
    size_t K = nearest(k, x, w), p = k->p;
    int st;
    if (!(w->valid && K == w->K && memcmp(w->next, w->set, K * sizeof *w->set) == 0)) {
        memcpy(w->set, w->next, K * sizeof *w->set);
        w->K = K, w->valid = 0;
        if ((st = nl_kl_factor(k, w, x)))
            return st;
        w->valid = 1;
    }
    double *c0 = w->c0, *v = w->v, *f = w->f, sum = 0;
    for (size_t i = 0; i < K; i++) {
        double lag[3] = {0, 0, 0};
        for (int a = 0; a < k->dim; a++)
            lag[a] = x[a] - k->pts[w->set[i] * k->dim + a];
        c0[i] = k->shift + nl_model_acf(k->m, k->dim, lag);
    }
    nl_kl_lsolve(w->L, K, c0, v); /* v = L^-1 c0 */
    if (p) {
        nl_kl_drift(k, x, NULL, f);
        for (size_t j = 0; j < p; j++) { /* u = x0 - Q' v */
            double t = f[j];
            for (size_t i = 0; i < K; i++)
                t -= w->Q[j * K + i] * v[i];
            w->u[j] = t;
        }
        nl_kl_lsolve(w->M, p, w->u, w->u2);
        ltsolve(w->M, p, w->u2, w->u); /* (M M')^-1 u */
        for (size_t i = 0; i < K; i++)
            for (size_t j = 0; j < p; j++)
                v[i] += w->Q[j * K + i] * w->u[j];
    }
    ltsolve(w->L, K, v, w->y); /* lambda */
    for (size_t i = 0; i < k->cap; i++) {
        idx_out[i] = i < K ? (uint32_t)w->set[i] : 0;
        w_out[i] = i < K ? w->y[i] : 0;
        sum += i < K ? w->y[i] : 0;
    }
    *c = p ? 0 : k->o.mean * (1 - sum);
    return NL_OK;
}

/* Location t: point t of x, or cell t of the grid g from lo. */
static void location(const nl_krige_local *k, size_t t, const double *x, const double *lo, const nl_field *g,
                     double *xt)
{
    if (x) {
        memcpy(xt, x + t * (size_t)k->dim, (size_t)k->dim * sizeof *xt);
        return;
    }
    size_t ix[3] = {t % g->n[0], t / g->n[0] % g->n[1], t / (g->n[0] * g->n[1])};
    for (int a = 0; a < k->dim; a++)
        xt[a] = lo[a] + ((double)ix[a] + 0.5) * g->h[a];
}

int nl_krige_weights(const nl_krige_local *k, size_t count, const double *x, const double *lo, const nl_field *g,
                     uint32_t *idx, double *w, double *c)
{
    size_t bad = SIZE_MAX, cap = k->cap;
    int nomem = 0, err = NL_OK;
    if (k->o.radius > 0)
        return NL_ERROR(NL_EINVAL, "kriging weights: expected a plan without a radius, got radius %g", k->o.radius);
    if (k->o.ncov)
        return NL_ERROR(NL_EINVAL, "kriging weights: the plan has %zu covariates; expected none", k->o.ncov);
    if (k->n > UINT32_MAX)
        return NL_ERROR(NL_ETOOBIG, "kriging weights: %zu data; expected at most %u", k->n, UINT32_MAX);
#pragma omp parallel if (count > 256 && nl_model_is_reentrant(k->m))
    {
        nl_kl_work wk;
        int ok = nl_kl_work_init(&wk, k->cap, k->p) == NL_OK;
        if (!ok) {
#pragma omp atomic write
            nomem = 1;
        }
#pragma omp for schedule(dynamic, 64) reduction(min : bad)
        for (size_t t = 0; t < count; t++) {
            double xt[3];
            if (!ok)
                continue;
            location(k, t, x, lo, g, xt);
            if (point(k, xt, &wk, idx + t * cap, w + t * cap, c + t))
                bad = t < bad ? t : bad;
        }
        if (ok)
            nl_kl_work_free(&wk);
    }
    if (nomem)
        return NL_ERROR(NL_ENOMEM, "kriging weights: out of memory for the neighbourhoods");
    if (bad != SIZE_MAX) { /* again on this thread, for the message */
        nl_kl_work wk;
        if ((err = nl_kl_work_init(&wk, k->cap, k->p)))
            return err;
        double xt[3];
        location(k, bad, x, lo, g, xt);
        err = point(k, xt, &wk, idx + bad * cap, w + bad * cap, c + bad);
        nl_kl_work_free(&wk);
        if (!err)
            err = NL_ERROR(NL_EFAIL, "kriging weights: location %zu failed", bad + 1);
    }
    return err;
}
