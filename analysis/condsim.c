/* Conditional simulation by kriging the residual of an unconditional
 * field (Journel 1974): Z = U + K[d - U(t)], the plan and a realization. */
#include "condsim_internal.h"
#include "krige.h"
#include "krige_local.h"
#include "krige_weights_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void nl_condsim_plan_free(nl_condsim_plan *p)
{
    if (!p)
        return;
    free(p->pts), free(p->val), free(p->at), free(p->sample);
    free(p->site_off), free(p->site), free(p->samp_off), free(p->samp), free(p->mat_off), free(p->chol_off);
    free(p->W), free(p->S), free(p->widx), free(p->w), free(p->c), free(p);
}

void nl_condsim_plan_info(const nl_condsim_plan *p, nl_condsim_info *info)
{
    *info = p->info;
}

/* Datum or point s: in the extent, and on a sample (p->sample[s]) or not
 * (SIZE_MAX); the data's largest distance to their nearest sample. */
static int place(nl_condsim_plan *p, size_t s)
{
    const double *t = nl_condsim_coords(p, s);
    const char *what = s < p->n ? "datum" : "point";
    size_t row = s < p->n ? s + 1 : s - p->n + 1, lin = 0, stride = 1;
    double d2 = 0;
    int on = 1;
    for (int a = 0; a < p->dim; a++) {
        double top = p->lo[a] + (double)p->gn[a] * p->h[a];
        if (!isfinite(t[a]))
            return NL_ERROR(NL_EINVAL, "%s %zu: expected finite coordinates, got a non-finite one on axis %d", what,
                            row, a + 1);
        if (!(t[a] >= p->lo[a] && t[a] <= top))
            return NL_ERROR(NL_EINVAL, "%s %zu lies at %.10g on axis %d, outside the grid's extent %.10g:%.10g", what,
                            row, t[a], a + 1, p->lo[a], top);
        double u = (t[a] - p->lo[a]) / p->h[a] - 0.5, near = floor(u + 0.5), top1 = (double)(p->gn[a] - 1);
        double c = near < 0 ? 0 : near > top1 ? top1 : near;
        if (fabs(u - c) >= NL_CONDSIM_ON_SAMPLE) /* else on a sample but for the rounding of its coordinate */
            on = 0, d2 += (u - c) * (u - c) * p->h[a] * p->h[a];
        lin += (size_t)c * stride, stride *= p->gn[a];
    }
    p->sample[s] = on ? lin : SIZE_MAX;
    if (s < p->n) {
        p->info.on_samples += (size_t)on;
        p->info.max_move = fmax(p->info.max_move, sqrt(d2));
    }
    return NL_OK;
}

/* Refuse, once, what kriging refuses in the model and the data. */
static int check_kriging(const nl_model *m, int dim, size_t n, const double *pts, const double *val,
                         const nl_condsim_options *o)
{
    int st;
    if (o->nmax) {
        nl_krige_local *kl;
        nl_krige_local_options ko = {.nmax = o->nmax, .drift = o->simple ? NL_DRIFT_NONE : NL_DRIFT_CONSTANT, .mean = o->mean};
        if (!(st = nl_krige_local_alloc(m, dim, n, pts, val, &ko, &kl)))
            nl_krige_local_free(kl);
        return st;
    }
    nl_krige_plan *kp;
    if (!(st = nl_krige_plan_alloc(m, dim, n, pts, val, o->simple, o->mean, 0, &kp)))
        nl_krige_plan_free(kp);
    return st;
}

/* The kriging weights of every cell and point, when they fit and the
 * system allows (else p->width stays 0: each realization kriges anew). */
static int weights(nl_condsim_plan *p, const nl_field *given)
{
    nl_field g = {.dim = p->dim, .n = {p->gn[0], p->gn[1], p->gn[2]}, .h = {p->h[0], p->h[1], p->h[2]},
                  .count = p->gn[0] * p->gn[1] * p->gn[2]}, *grid = &g; /* given->count may be unset */
    size_t rows = grid->count + p->np, width = p->o.nmax && p->o.nmax < p->n ? p->o.nmax : p->n;
    nl_krige_local *kl;
    nl_krige_local_options ko = {.nmax = p->o.nmax, .drift = p->o.simple ? NL_DRIFT_NONE : NL_DRIFT_CONSTANT,
                                 .mean = p->o.mean};
    if (p->o.rekrige || p->n < 2 || (!p->o.nmax && p->n > NL_KRIGE_LOCAL_MAX) ||
        rows > NL_CONDSIM_WEIGHTS_MAX / 12 / width)
        return NL_OK;
    int st = nl_krige_local_alloc(p->m, p->dim, p->n, p->pts, p->val, &ko, &kl);
    if (st) /* local kriging was checked to accept the data: out of memory; global: nl_krige_plan's cases */
        return p->o.nmax ? st : NL_OK;
    p->widx = malloc(rows * width * sizeof *p->widx), p->w = malloc(rows * width * sizeof *p->w);
    p->c = malloc(rows * sizeof *p->c);
    st = p->widx && p->w && p->c ? NL_OK : NL_ENOMEM;
    (void)given;
    if (!st && (st = nl_krige_weights(kl, grid->count, NULL, p->lo, grid, p->widx, p->w, p->c)) == NL_OK && p->np)
        st = nl_krige_weights(kl, p->np, p->at, NULL, NULL, p->widx + grid->count * width, p->w + grid->count * width,
                              p->c + grid->count);
    nl_krige_local_free(kl);
    if (st && (st == NL_ENOMEM || p->o.nmax)) /* local kriging was checked to work: only memory can fail */
        return st == NL_ENOMEM ? NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for the kriging weights")
                               : st;
    if (st) { /* a singular global system: nl_krige_plan's pseudo-inverse, realization by realization */
        free(p->widx), free(p->w), free(p->c);
        p->widx = NULL, p->w = p->c = NULL;
        return NL_OK;
    }
    p->width = width, p->info.reuse = 1;
    p->info.weight_bytes = rows * (width * (sizeof *p->widx + sizeof *p->w) + sizeof *p->c);
    return NL_OK;
}

static int build(nl_condsim_plan *p, const double *pts, const double *val, const double *at, const nl_field *grid)
{
    size_t n = p->n, d = (size_t)p->dim, tot = n + p->np;
    int st;
    p->pts = malloc(n * d * sizeof *p->pts), p->val = malloc(n * sizeof *p->val);
    p->at = malloc((p->np ? p->np : 1) * d * sizeof *p->at), p->sample = malloc(tot * sizeof *p->sample);
    if (!p->pts || !p->val || !p->at || !p->sample)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu data and points", tot);
    memcpy(p->pts, pts, n * d * sizeof *p->pts);
    memcpy(p->val, val, n * sizeof *p->val);
    if (p->np)
        memcpy(p->at, at, p->np * d * sizeof *p->at);
    for (size_t s = 0; s < tot; s++)
        if ((st = place(p, s)))
            return st;
    if ((st = nl_condsim_groups(p)))
        return st;
    return weights(p, grid);
}

int nl_condsim_plan_alloc(const nl_model *m, size_t n, const double *pts, const double *val, const double *lo,
                          const nl_field *grid, const nl_condsim_options *o, size_t np, const double *at,
                          nl_condsim_plan **out)
{
    nl_condsim_options opt = o ? *o : (nl_condsim_options){0};
    nl_condsim_plan *p;
    int st;
    *out = NULL;
    if ((st = nl_model_check_stationary(m, "conditional simulation")))
        return st;
    if (!n)
        return NL_ERROR(NL_EINVAL, "conditional simulation: expected at least one datum, got none");
    if (opt.hood > 16)
        return NL_ERROR(NL_EINVAL, "conditional simulation: hood: expected 1 to 16 samples per axis (0: %d), got %zu",
                        NL_CONDSIM_HOOD, opt.hood);
    if (np && !at)
        return NL_ERROR(NL_EINVAL, "conditional simulation: expected the coordinates of %zu points, got none", np);
    opt.hood = opt.hood ? opt.hood : NL_CONDSIM_HOOD;
    for (int a = 0; a < grid->dim; a++)
        if (!isfinite(lo[a]) || !isfinite(lo[a] + (double)grid->n[a] * grid->h[a]))
            return NL_ERROR(NL_EINVAL, "the grid's extent on axis %d: expected finite bounds", a + 1);
    if ((st = check_kriging(m, grid->dim, n, pts, val, &opt)))
        return st;
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->m = m, p->dim = grid->dim, p->n = n, p->np = np, p->o = opt;
    p->info.n = n;
    for (int a = 0; a < 3; a++)
        p->gn[a] = grid->n[a], p->h[a] = grid->h[a], p->lo[a] = a < grid->dim ? lo[a] : 0;
    if ((st = build(p, pts, val, at, grid))) {
        nl_condsim_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

/* K[r] on the grid into k and at the points into kat, kriging anew:
 * global (krige.h) or from the nmax nearest (krige_local.h). */
static int krige_anew(const nl_condsim_plan *p, const double *r, nl_field *k, double *kat)
{
    int st;
    if (p->o.nmax) {
        nl_krige_local *kl;
        nl_krige_local_options o = {.nmax = p->o.nmax, .drift = p->o.simple ? NL_DRIFT_NONE : NL_DRIFT_CONSTANT,
                                    .mean = p->o.mean};
        if ((st = nl_krige_local_alloc(p->m, p->dim, p->n, p->pts, r, &o, &kl)))
            return st;
        st = nl_krige_local_grid(kl, p->lo, k, NULL);
        if (!st && p->np)
            st = nl_krige_local_eval(kl, p->np, p->at, kat, NULL);
        nl_krige_local_free(kl);
        return st;
    }
    nl_krige_plan *kp;
    if ((st = nl_krige_plan_alloc(p->m, p->dim, p->n, p->pts, r, p->o.simple, p->o.mean, 0, &kp)))
        return st;
    st = nl_krige_eval_grid(kp, p->lo, k, NULL);
    if (!st && p->np)
        st = nl_krige_eval_block(kp, p->np, p->at, kat, NULL);
    nl_krige_plan_free(kp);
    return st;
}

/* Z = U + K[r] with the kept weights: the grid's cells in parallel (each
 * cell's sum in a fixed order), then the points from U at them. */
static void apply_weights(const nl_condsim_plan *p, const double *r, nl_field *f, const double *u, double *z_at)
{
    size_t W = p->width, count = f->count;
#pragma omp parallel for schedule(static) if (count * W > ((size_t)1 << 22)) /* milliseconds of work */
    for (size_t x = 0; x < count; x++) {
        const uint32_t *ix = p->widx + x * W;
        const double *w = p->w + x * W;
        double s = p->c[x];
        for (size_t k = 0; k < W; k++)
            s += w[k] * r[ix[k]];
        f->data[x] += s;
    }
    for (size_t j = 0; z_at && j < p->np; j++) {
        const uint32_t *ix = p->widx + (count + j) * W;
        const double *w = p->w + (count + j) * W;
        double s = p->c[count + j];
        for (size_t k = 0; k < W; k++)
            s += w[k] * r[ix[k]];
        z_at[j] = u[p->n + j] + s;
    }
}

int nl_condsim_execute(const nl_condsim_plan *p, nl_field *f, uint64_t seed, double *z_at)
{
    int st = NL_OK;
    if (f->dim != p->dim || f->n[0] != p->gn[0] || f->n[1] != p->gn[1] || f->n[2] != p->gn[2])
        return NL_ERROR(NL_EINVAL, "conditional simulation: expected the plan's grid of %zux%zux%zu samples, got "
                        "%zux%zux%zu", p->gn[0], p->gn[1], p->gn[2], f->n[0], f->n[1], f->n[2]);
    double *u = malloc((p->n + p->np) * sizeof *u), *r = malloc(p->n * sizeof *r);
    if (!u || !r) {
        free(u), free(r);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu data", p->n);
    }
    nl_condsim_draw(p, f, seed, u);
    for (size_t i = 0; i < p->n; i++) /* the residual d - U(t) */
        if (!isfinite(r[i] = p->val[i] - u[i])) {
            free(u), free(r);
            return NL_ERROR(NL_EINVAL, "conditional simulation: the unconditional field is not finite near datum %zu",
                            i + 1);
        }
    if (p->width)
        apply_weights(p, r, f, u, z_at);
    else {
        double *kat = malloc((p->np ? p->np : 1) * sizeof *kat);
        nl_field *k = kat ? nl_field_alloc(p->dim, p->gn, p->h, &st) : NULL;
        if (!kat)
            st = NL_ERROR(NL_ENOMEM, "out of memory for %zu points", p->np);
        if (k)
            st = krige_anew(p, r, k, kat);
        for (size_t i = 0; !st && i < f->count; i++)
            f->data[i] += k->data[i];
        for (size_t j = 0; !st && z_at && j < p->np; j++)
            z_at[j] = u[p->n + j] + kat[j];
        nl_field_free(k);
        free(kat);
    }
    free(u), free(r);
    return st;
}
