/* Conditional simulation by kriging the residual of an unconditional
 * field (Journel 1974): Z = U + K[d - U(t)]. */
#include "condsim.h"
#include "krige.h"
#include "krige_local.h"
#include "../core/field_sample.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct nl_condsim_plan {
    const nl_model *m;   /* borrowed */
    int dim;             /* grid dimension */
    size_t gn[3];        /* grid samples per axis */
    double h[3], lo[3];  /* grid spacing, lower corner of the extent */
    size_t n;            /* data */
    double *pts, *val;   /* n * dim coordinates, n values (copies) */
    size_t *idx;         /* n * NL_STENCIL_MAX grid indices of each datum's stencil */
    double *w;           /* n * NL_STENCIL_MAX weights (0 beyond the stencil) */
    int simple;          /* simple kriging with `mean`, else ordinary */
    double mean;         /* the known mean (simple) */
    size_t nmax;         /* local kriging from the nmax nearest data; 0: global */
    nl_condsim_info info;/* the figures */
};

void nl_condsim_plan_free(nl_condsim_plan *p)
{
    if (!p)
        return;
    free(p->pts), free(p->val), free(p->idx), free(p->w), free(p);
}

void nl_condsim_plan_info(const nl_condsim_plan *p, nl_condsim_info *info)
{
    *info = p->info;
}

/* s_i / sqrt(R(0)) for datum i's stencil (see condsim.h). */
static double stencil_error(const nl_condsim_plan *p, size_t i, size_t k, double r0)
{
    const size_t *idx = p->idx + i * NL_STENCIL_MAX;
    const double *w = p->w + i * NL_STENCIL_MAX, *t = p->pts + i * (size_t)p->dim;
    double x[NL_STENCIL_MAX][3], s = r0;
    for (size_t j = 0; j < k; j++) {
        size_t q = idx[j], c[3];
        c[0] = q % p->gn[0], c[1] = q / p->gn[0] % p->gn[1], c[2] = q / (p->gn[0] * p->gn[1]);
        for (int a = 0; a < p->dim; a++)
            x[j][a] = p->lo[a] + ((double)c[a] + 0.5) * p->h[a];
    }
    for (size_t j = 0; j < k; j++) {
        double lag[3];
        for (int a = 0; a < p->dim; a++)
            lag[a] = t[a] - x[j][a];
        s -= 2 * w[j] * nl_model_acf(p->m, p->dim, lag);
        for (size_t l = 0; l < k; l++) {
            for (int a = 0; a < p->dim; a++)
                lag[a] = x[j][a] - x[l][a];
            s += w[j] * w[l] * nl_model_acf(p->m, p->dim, lag);
        }
    }
    return s > 0 ? sqrt(s / r0) : 0;
}

/* Each datum's stencil, its interpolation error and its distance to the nearest sample. */
static int stencils(nl_condsim_plan *p, const nl_field *grid, int interp)
{
    double zero[3] = {0, 0, 0}, r0 = nl_model_acf(p->m, p->dim, zero);
    for (size_t i = 0; i < p->n; i++) {
        const double *t = p->pts + i * (size_t)p->dim;
        double u[3], d2 = 0;
        for (int a = 0; a < p->dim; a++) {
            double top = p->lo[a] + (double)p->gn[a] * p->h[a];
            if (!isfinite(t[a]))
                return NL_ERROR(NL_EINVAL, "datum %zu: expected finite coordinates, got a non-finite one on axis %d",
                                i + 1, a + 1);
            if (!(t[a] >= p->lo[a] && t[a] <= top))
                return NL_ERROR(NL_EINVAL, "datum %zu lies at %.10g on axis %d, outside the grid's extent %.10g:%.10g",
                                i + 1, t[a], a + 1, p->lo[a], top);
            u[a] = (t[a] - p->lo[a]) / p->h[a] - 0.5;
            double near = floor(u[a] + 0.5), top1 = (double)(p->gn[a] - 1);
            double c = near < 0 ? 0 : near > top1 ? top1 : near;
            if (fabs(u[a] - c) < NL_CONDSIM_ON_SAMPLE) /* on a sample but for the rounding of its coordinate */
                u[a] = c;
            d2 += (u[a] - c) * (u[a] - c) * p->h[a] * p->h[a];
        }
        size_t k = nl_field_stencil(grid, u, interp, p->idx + i * NL_STENCIL_MAX, p->w + i * NL_STENCIL_MAX);
        p->info.max_move = fmax(p->info.max_move, sqrt(d2));
        if (k == 1 && d2 == 0) {
            p->info.on_samples++;
            continue;
        }
        double e = isfinite(r0) && r0 > 0 ? stencil_error(p, i, k, r0) : 0;
        if (e > p->info.max_error)
            p->info.max_error = e, p->info.worst = i;
    }
    return NL_OK;
}

/* The plan's arrays, copied data and stencils. */
static int build(nl_condsim_plan *p, const double *pts, const double *val, const nl_field *grid, int interp)
{
    size_t n = p->n, d = (size_t)p->dim;
    p->pts = malloc(n * d * sizeof *p->pts);
    p->val = malloc(n * sizeof *p->val);
    p->idx = calloc(n * NL_STENCIL_MAX, sizeof *p->idx);
    p->w = calloc(n * NL_STENCIL_MAX, sizeof *p->w);
    if (!p->pts || !p->val || !p->idx || !p->w)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu data", n);
    memcpy(p->pts, pts, n * d * sizeof *p->pts);
    memcpy(p->val, val, n * sizeof *p->val);
    return stencils(p, grid, interp);
}

int nl_condsim_plan_alloc(const nl_model *m, size_t n, const double *pts, const double *val, const double *lo,
                          const nl_field *grid, int interp, int simple, double mean, size_t nmax,
                          nl_condsim_plan **out)
{
    nl_condsim_plan *p;
    nl_krige_plan *kp;
    int st;
    *out = NULL;
    if ((st = nl_model_check_stationary(m, "conditional simulation")))
        return st;
    if (!n)
        return NL_ERROR(NL_EINVAL, "conditional simulation: expected at least one datum, got none");
    if (interp != NL_INTERP_NEAREST && interp != NL_INTERP_LINEAR)
        return NL_ERROR(NL_EINVAL, "interpolation %d: expected nearest (%d) or linear (%d)", interp,
                        NL_INTERP_NEAREST, NL_INTERP_LINEAR);
    for (int a = 0; a < grid->dim; a++)
        if (!isfinite(lo[a]) || !isfinite(lo[a] + (double)grid->n[a] * grid->h[a]))
            return NL_ERROR(NL_EINVAL, "the grid's extent on axis %d: expected finite bounds", a + 1);
    /* what kriging refuses in the model and the data, refused now, once */
    if (nmax) {
        nl_krige_local *kl;
        nl_krige_local_options o = {.nmax = nmax, .drift = simple ? NL_DRIFT_NONE : NL_DRIFT_CONSTANT, .mean = mean};
        if ((st = nl_krige_local_alloc(m, grid->dim, n, pts, val, &o, &kl)))
            return st;
        nl_krige_local_free(kl);
    } else if ((st = nl_krige_plan_alloc(m, grid->dim, n, pts, val, simple, mean, 0, &kp)))
        return st;
    else
        nl_krige_plan_free(kp);
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->m = m, p->dim = grid->dim, p->n = n, p->simple = simple, p->mean = mean, p->nmax = nmax;
    p->info.n = n;
    for (int a = 0; a < 3; a++)
        p->gn[a] = grid->n[a], p->h[a] = grid->h[a], p->lo[a] = a < grid->dim ? lo[a] : 0;
    if ((st = build(p, pts, val, grid, interp))) {
        nl_condsim_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

/* K[r] on the grid into k: global (krige.h) or from the nmax nearest (krige_local.h). */
static int krige_residual(const nl_condsim_plan *p, const double *r, nl_field *k)
{
    int st;
    if (p->nmax) {
        nl_krige_local *kl;
        nl_krige_local_options o = {.nmax = p->nmax, .drift = p->simple ? NL_DRIFT_NONE : NL_DRIFT_CONSTANT, .mean = p->mean};
        if ((st = nl_krige_local_alloc(p->m, p->dim, p->n, p->pts, r, &o, &kl)))
            return st;
        st = nl_krige_local_grid(kl, p->lo, k, NULL);
        nl_krige_local_free(kl);
        return st;
    }
    nl_krige_plan *kp;
    if ((st = nl_krige_plan_alloc(p->m, p->dim, p->n, p->pts, r, p->simple, p->mean, 0, &kp)))
        return st;
    st = nl_krige_eval_grid(kp, p->lo, k, NULL);
    nl_krige_plan_free(kp);
    return st;
}

int nl_condsim_execute(const nl_condsim_plan *p, nl_field *f)
{
    int st;
    if (f->dim != p->dim || f->n[0] != p->gn[0] || f->n[1] != p->gn[1] || f->n[2] != p->gn[2])
        return NL_ERROR(NL_EINVAL, "conditional simulation: expected the plan's grid of %zux%zux%zu samples, got "
                        "%zux%zux%zu", p->gn[0], p->gn[1], p->gn[2], f->n[0], f->n[1], f->n[2]);
    double *r = malloc(p->n * sizeof *r);
    if (!r)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu data", p->n);
    for (size_t i = 0; i < p->n; i++) { /* the residual d - U(t) */
        double u = 0;
        for (size_t j = 0; j < NL_STENCIL_MAX; j++)
            u += p->w[i * NL_STENCIL_MAX + j] * f->data[p->idx[i * NL_STENCIL_MAX + j]];
        r[i] = p->val[i] - u;
        if (!isfinite(r[i])) {
            free(r);
            return NL_ERROR(NL_EINVAL, "conditional simulation: the unconditional field is not finite at datum %zu",
                            i + 1);
        }
    }
    nl_field *k = nl_field_alloc(p->dim, p->gn, p->h, &st);
    if (k)
        st = krige_residual(p, r, k);
    free(r);
    for (size_t i = 0; !st && i < f->count; i++)
        f->data[i] += k->data[i];
    nl_field_free(k);
    return st;
}
