/* The unconditional field at data and points between grid samples, drawn
 * from its conditional law given the grid samples around them (Gaussian
 * conditioning; Davis 1987): groups of sites with overlapping
 * neighbourhoods are drawn jointly. */
#include "condsim_internal.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

const double *nl_condsim_coords(const nl_condsim_plan *p, size_t s)
{
    return s < p->n ? p->pts + s * (size_t)p->dim : p->at + (s - p->n) * (size_t)p->dim;
}

/* The first sample per axis of the block of q[a] samples nearest x. */
static void block_start(const nl_condsim_plan *p, const double *x, const size_t *q, long *start)
{
    for (int a = 0; a < p->dim; a++) {
        double u = (x[a] - p->lo[a]) / p->h[a] - 0.5;
        double s = floor(u - 0.5 * (double)(q[a] - 1) + 0.5), top = (double)(p->gn[a] - q[a]);
        start[a] = (long)(s < 0 ? 0 : s > top ? top : s);
    }
    for (int a = p->dim; a < 3; a++)
        start[a] = 0;
}

/* Block side per axis for `hood` samples: at most the grid's size. */
static void block_sides(const nl_condsim_plan *p, size_t hood, size_t *q)
{
    for (int a = 0; a < 3; a++)
        q[a] = a < p->dim ? (hood < p->gn[a] ? hood : p->gn[a]) : 1;
}

/* The grid samples of the block (row-major order: ascending). */
static size_t block_samples(const nl_condsim_plan *p, const long *start, const size_t *q, size_t *out)
{
    size_t k = 0;
    for (size_t l = 0; l < q[2]; l++)
        for (size_t j = 0; j < q[1]; j++)
            for (size_t i = 0; i < q[0]; i++)
                out[k++] = ((size_t)start[2] + l) * p->gn[0] * p->gn[1] + ((size_t)start[1] + j) * p->gn[0] +
                           (size_t)start[0] + i;
    return k;
}

static void sample_coords(const nl_condsim_plan *p, size_t s, double *x)
{
    size_t c[3] = {s % p->gn[0], s / p->gn[0] % p->gn[1], s / (p->gn[0] * p->gn[1])};
    for (int a = 0; a < p->dim; a++)
        x[a] = p->lo[a] + ((double)c[a] + 0.5) * p->h[a];
}

static double cov(const nl_condsim_plan *p, const double *x, const double *y)
{
    double lag[3] = {0, 0, 0};
    for (int a = 0; a < p->dim; a++)
        lag[a] = x[a] - y[a];
    return nl_model_acf(p->m, p->dim, lag);
}

/* In-place Cholesky of the lower triangle of the positive semi-definite A
 * (n x n): a pivot at most tol leaves a zero column (that variable is a
 * combination of the ones before: it adds nothing, its solve gives 0). */
static void cholesky_psd(double *A, size_t n, double tol)
{
    for (size_t j = 0; j < n; j++) {
        double d = A[j * n + j];
        for (size_t k = 0; k < j; k++)
            d -= A[j * n + k] * A[j * n + k];
        int zero = !(d > tol);
        d = zero ? 0 : sqrt(d);
        A[j * n + j] = d;
        for (size_t i = j + 1; i < n; i++) {
            double s = A[i * n + j];
            for (size_t k = 0; k < j; k++)
                s -= A[i * n + k] * A[j * n + k];
            A[i * n + j] = zero ? 0 : s / d;
        }
    }
}

/* x = L^-1 b, then (t) x = L^-T b; zero pivots give zero. */
static void lsolve(const double *L, size_t n, const double *b, double *x)
{
    for (size_t i = 0; i < n; i++) {
        double s = b[i];
        for (size_t j = 0; j < i; j++)
            s -= L[i * n + j] * x[j];
        x[i] = L[i * n + i] > 0 ? s / L[i * n + i] : 0;
    }
}

static void ltsolve(const double *L, size_t n, const double *b, double *x)
{
    for (size_t i = n; i-- > 0;) {
        double s = b[i];
        for (size_t j = i + 1; j < n; j++)
            s -= L[j * n + i] * x[j];
        x[i] = L[i * n + i] > 0 ? s / L[i * n + i] : 0;
    }
}

/* Conditional law of the nt sites `site` given the ng samples `samp`:
 * W (nt x ng) = C_TG C_GG^-1 and S (nt x nt) = chol(C_TT - C_TG C_GG^-1 C_GT).
 * scratch: ng * ng + 2 * ng + nt * ng doubles. */
static void factor_group(const nl_condsim_plan *p, const size_t *site, size_t nt, const size_t *samp, size_t ng,
                         double r0, double *W, double *S, double *scratch)
{
    double *L = scratch, *xs = L + ng * ng, *v = xs + 3 * ng, *A = v + ng, x[3], y[3];
    for (size_t i = 0; i < ng; i++)
        sample_coords(p, samp[i], xs + 3 * i);
    for (size_t i = 0; i < ng; i++)
        for (size_t j = 0; j <= i; j++)
            L[i * ng + j] = cov(p, xs + 3 * i, xs + 3 * j);
    cholesky_psd(L, ng, 1e-12 * r0);
    for (size_t t = 0; t < nt; t++) {
        const double *xt = nl_condsim_coords(p, site[t]);
        for (size_t i = 0; i < ng; i++)
            v[i] = cov(p, xt, xs + 3 * i);
        lsolve(L, ng, v, A + t * ng); /* A_t = L^-1 C_Gt */
        ltsolve(L, ng, A + t * ng, W + t * ng);
    }
    for (size_t t = 0; t < nt; t++) {
        memcpy(x, nl_condsim_coords(p, site[t]), (size_t)p->dim * sizeof *x);
        for (size_t l = 0; l <= t; l++) {
            memcpy(y, nl_condsim_coords(p, site[l]), (size_t)p->dim * sizeof *y);
            double s = cov(p, x, y);
            for (size_t i = 0; i < ng; i++)
                s -= A[t * ng + i] * A[l * ng + i];
            S[t * nt + l] = s;
        }
        for (size_t l = t + 1; l < nt; l++)
            S[t * nt + l] = 0;
    }
    cholesky_psd(S, nt, 1e-12 * r0);
}

/* The conditional variance of site s given the block of `hood` samples
 * per axis around it. */
static double cond_var(const nl_condsim_plan *p, size_t s, size_t hood, double r0, int *nomem)
{
    size_t q[3], ng;
    long st[3];
    block_sides(p, hood, q);
    block_start(p, nl_condsim_coords(p, s), q, st);
    ng = q[0] * q[1] * q[2];
    size_t *samp = malloc(ng * sizeof *samp);
    double *scr = malloc((ng * ng + 6 * ng) * sizeof *scr), S = 0;
    if (samp && scr) {
        block_samples(p, st, q, samp);
        factor_group(p, &s, 1, samp, ng, r0, scr + ng * ng + 5 * ng, &S, scr);
    } else
        *nomem = 1;
    free(samp), free(scr);
    return S * S;
}

/* The screening error (condsim.h) over the first NL_CONDSIM_SCREEN_SITES sites. */
static int screening(nl_condsim_plan *p, double r0)
{
    int nomem = 0;
    size_t done = 0;
    for (size_t s = 0; s < p->n + p->np && done < NL_CONDSIM_SCREEN_SITES && !nomem; s++) {
        if (p->sample[s] != SIZE_MAX)
            continue;
        double a = cond_var(p, s, p->o.hood, r0, &nomem), b = cond_var(p, s, p->o.hood + 2, r0, &nomem);
        double e = sqrt(fmax(a - b, 0) / r0);
        if (e > p->info.screening || !done)
            p->info.screening = e, p->info.worst = s;
        done++;
    }
    return nomem ? NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for the screening check") : NL_OK;
}

/* Union-find with the bound on a group's samples: the sum of its blocks'
 * sizes, or its bounding box's volume, whichever is smaller. */
typedef struct {
    size_t *up, *count; /* parent, sites in a root's group */
    long (*box)[6];     /* a root's box: lo, hi (inclusive) per axis */
} dsu;

static size_t find(dsu *d, size_t i)
{
    while (d->up[i] != i)
        i = d->up[i] = d->up[d->up[i]];
    return i;
}

/* Merge the groups of i and j unless the union would exceed the cap;
 * 1 when refused. */
static int merge(dsu *d, size_t i, size_t j, size_t Q, size_t cap)
{
    size_t a = find(d, i), b = find(d, j);
    if (a == b)
        return 0;
    long box[6];
    size_t vol = 1;
    for (int x = 0; x < 3; x++) {
        box[x] = d->box[a][x] < d->box[b][x] ? d->box[a][x] : d->box[b][x];
        box[3 + x] = d->box[a][3 + x] > d->box[b][3 + x] ? d->box[a][3 + x] : d->box[b][3 + x];
        vol *= (size_t)(box[3 + x] - box[x] + 1);
    }
    size_t sum = (d->count[a] + d->count[b]) * Q;
    if ((vol < sum ? vol : sum) > cap)
        return 1;
    if (b < a) {
        size_t t = a;
        a = b, b = t;
    }
    d->up[b] = a, d->count[a] += d->count[b];
    memcpy(d->box[a], box, sizeof box);
    return 0;
}

static int cmp_size(const void *a, const void *b)
{
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

/* Sites sorted by their block's first sample on axis 0 (then index). */
typedef struct {
    long s0;   /* block start on axis 0 */
    size_t i;  /* site number */
} key_t_;

static int cmp_key(const void *a, const void *b)
{
    const key_t_ *x = a, *y = b;
    return x->s0 != y->s0 ? (x->s0 < y->s0 ? -1 : 1) : (x->i < y->i ? -1 : x->i > y->i);
}

/* Link the sites whose blocks overlap (a sweep along axis 0). */
static void link_sites(nl_condsim_plan *p, dsu *d, long (*st)[3], size_t ns, const size_t *q, key_t_ *key)
{
    size_t Q = q[0] * q[1] * q[2];
    for (size_t i = 0; i < ns; i++)
        key[i].s0 = st[i][0], key[i].i = i;
    qsort(key, ns, sizeof *key, cmp_key);
    for (size_t a = 0; a < ns; a++)
        for (size_t b = a + 1; b < ns && key[b].s0 < key[a].s0 + (long)q[0]; b++) {
            size_t i = key[a].i, j = key[b].i;
            int over = 1;
            for (int x = 1; x < 3; x++)
                over &= labs(st[i][x] - st[j][x]) < (long)q[x];
            if (over)
                p->info.unlinked += (size_t)merge(d, i, j, Q, NL_CONDSIM_JOINT_MAX);
        }
}

/* The groups' sites and samples (ascending) into the plan's arrays. */
static int group_members(nl_condsim_plan *p, dsu *d, long (*st)[3], const size_t *sites, size_t ns, const size_t *q)
{
    size_t Q = q[0] * q[1] * q[2], *gid = malloc(ns * sizeof *gid), *all = malloc(ns * Q * sizeof *all);
    size_t ng = 0, fill = 0;
    if (!gid || !all) {
        free(gid), free(all);
        return NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for %zu sites", ns);
    }
    for (size_t i = 0; i < ns; i++) /* group numbers in site order */
        gid[i] = find(d, i) == i ? ng++ : SIZE_MAX;
    p->ngroups = ng;
    p->site_off = calloc(ng + 1, sizeof(size_t)), p->samp_off = calloc(ng + 1, sizeof(size_t));
    p->site = malloc(ns * sizeof(size_t)), p->samp = malloc(ns * Q * sizeof(size_t));
    if (!p->site_off || !p->samp_off || !p->site || !p->samp) {
        free(gid), free(all);
        return NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for %zu sites", ns);
    }
    for (size_t i = 0; i < ns; i++)
        p->site_off[gid[find(d, i)] + 1]++;
    for (size_t g = 0; g < ng; g++)
        p->site_off[g + 1] += p->site_off[g];
    size_t *pos = gid; /* reuse: group -> next slot, by root */
    for (size_t i = 0; i < ns; i++)
        if (find(d, i) == i)
            pos[i] = p->site_off[gid[i]];
    for (size_t i = 0; i < ns; i++) /* ascending site order within a group */
        p->site[pos[find(d, i)]++] = sites[i];
    for (size_t g = 0; g < ng; g++) {
        size_t k = 0, *buf = all + fill;
        for (size_t t = p->site_off[g]; t < p->site_off[g + 1]; t++) {
            long s[3];
            block_start(p, nl_condsim_coords(p, p->site[t]), q, s);
            k += block_samples(p, s, q, buf + k);
        }
        qsort(buf, k, sizeof *buf, cmp_size);
        size_t u = 0;
        for (size_t i = 0; i < k; i++)
            if (!u || buf[i] != buf[u - 1])
                buf[u++] = buf[i];
        memcpy(p->samp + p->samp_off[g], buf, u * sizeof *buf);
        p->samp_off[g + 1] = p->samp_off[g] + u, fill += u;
        if (u > p->info.largest)
            p->info.largest = u;
    }
    (void)st;
    free(gid), free(all);
    return NL_OK;
}

/* Factor every group (in parallel; each writes its own slices). */
static int factor_groups(nl_condsim_plan *p, double r0)
{
    size_t ng = p->ngroups, big = 0;
    int nomem = 0;
    p->mat_off = calloc(ng + 1, sizeof(size_t)), p->chol_off = calloc(ng + 1, sizeof(size_t));
    if (!p->mat_off || !p->chol_off)
        return NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for %zu groups", ng);
    for (size_t g = 0; g < ng; g++) {
        size_t nt = p->site_off[g + 1] - p->site_off[g], ns = p->samp_off[g + 1] - p->samp_off[g];
        p->mat_off[g + 1] = p->mat_off[g] + nt * ns, p->chol_off[g + 1] = p->chol_off[g] + nt * nt;
        big = ns * ns + 5 * ns + nt * ns > big ? ns * ns + 5 * ns + nt * ns : big;
    }
    p->W = malloc((p->mat_off[ng] + 1) * sizeof(double)), p->S = malloc((p->chol_off[ng] + 1) * sizeof(double));
    if (!p->W || !p->S)
        return NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for the sites' conditional laws");
#pragma omp parallel if (ng > 4 && nl_model_is_reentrant(p->m))
    {
        double *scr = malloc(big * sizeof *scr);
        if (!scr) {
#pragma omp atomic write
            nomem = 1;
        }
#pragma omp for schedule(dynamic, 1)
        for (size_t g = 0; g < ng; g++)
            if (scr)
                factor_group(p, p->site + p->site_off[g], p->site_off[g + 1] - p->site_off[g], p->samp + p->samp_off[g],
                             p->samp_off[g + 1] - p->samp_off[g], r0, p->W + p->mat_off[g], p->S + p->chol_off[g], scr);
        free(scr);
    }
    return nomem ? NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for a group of sites") : NL_OK;
}

int nl_condsim_groups(nl_condsim_plan *p)
{
    size_t q[3], ns = 0, tot = p->n + p->np;
    double zero[3] = {0, 0, 0}, r0 = nl_model_acf(p->m, p->dim, zero);
    int st = NL_OK;
    block_sides(p, p->o.hood, q);
    for (size_t s = 0; s < tot; s++)
        ns += p->sample[s] == SIZE_MAX;
    p->info.sites = ns, p->info.hood = p->o.hood;
    size_t *sites = malloc((ns + 1) * sizeof *sites), *up = malloc((ns + 1) * sizeof *up),
           *count = malloc((ns + 1) * sizeof *count);
    long(*start)[3] = malloc((ns + 1) * sizeof *start), (*box)[6] = malloc((ns + 1) * sizeof *box);
    key_t_ *key = malloc((ns + 1) * sizeof *key);
    if (!sites || !up || !count || !start || !box || !key)
        st = NL_ERROR(NL_ENOMEM, "conditional simulation: out of memory for %zu sites", ns);
    for (size_t s = 0, i = 0; !st && s < tot; s++) {
        if (p->sample[s] != SIZE_MAX)
            continue;
        sites[i] = s, up[i] = i, count[i] = 1;
        block_start(p, nl_condsim_coords(p, s), q, start[i]);
        for (int a = 0; a < 3; a++)
            box[i][a] = start[i][a], box[i][3 + a] = start[i][a] + (long)q[a] - 1;
        i++;
    }
    dsu d = {up, count, box};
    if (!st) {
        link_sites(p, &d, start, ns, q, key);
        st = group_members(p, &d, start, sites, ns, q);
    }
    if (!st)
        st = factor_groups(p, r0);
    p->info.groups = p->ngroups;
    if (!st && ns)
        st = screening(p, r0);
    free(sites), free(up), free(count), free(start), free(box), free(key);
    return st;
}

void nl_condsim_draw(const nl_condsim_plan *p, const nl_field *f, uint64_t seed, double *u)
{
    for (size_t s = 0; s < p->n + p->np; s++)
        if (p->sample[s] != SIZE_MAX)
            u[s] = f->data[p->sample[s]];
#pragma omp parallel for schedule(dynamic, 4) if (p->mat_off[p->ngroups] > 1000000)
    for (size_t g = 0; g < p->ngroups; g++) {
        size_t nt = p->site_off[g + 1] - p->site_off[g], ng = p->samp_off[g + 1] - p->samp_off[g];
        const size_t *site = p->site + p->site_off[g], *samp = p->samp + p->samp_off[g];
        const double *W = p->W + p->mat_off[g], *S = p->S + p->chol_off[g];
        for (size_t t = 0; t < nt; t++) { /* mean, then the correlated noise S e */
            double m = 0, e = 0;
            for (size_t k = 0; k < ng; k++)
                m += W[t * ng + k] * f->data[samp[k]];
            for (size_t l = 0; l <= t; l++)
                e += S[t * nt + l] * nl_rng_gauss(seed, NL_STREAM_CONDSIM, site[l]);
            u[site[t]] = m + e;
        }
    }
}
