/* Validation: the lags tested, their target, the thresholds
 * (analysis/validate.h). */
#include "validate_internal.h"
#include "verdict.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const dir_names[NL_VALIDATE_DIRS] = {"x", "y", "z", "diagonal"};
static const char *const verdict_names[] = {"within", "off", "unresolved"};

const char *nl_validate_dir_name(int dir) { return dir >= 0 && dir < NL_VALIDATE_DIRS ? dir_names[dir] : NULL; }

const char *nl_validate_verdict_name(int v) { return v >= 0 && v <= NL_VALIDATE_UNRESOLVED ? verdict_names[v] : NULL; }

void nl_validate_dir_lag(int dim, int dir, long l, long *lag)
{
    lag[0] = lag[1] = lag[2] = 0;
    if (dir == NL_VALIDATE_DIAG)
        for (int a = 0; a < dim; a++)
            lag[a] = l;
    else
        lag[dir] = l;
}

/* R at a lag: the model's, or read from G, R sampled on a grid longer
 * than the field (spectrum: models, whose R has no closed form). */
static double acf_at(const nl_model *m, int dim, const long *lag, const nl_field *G)
{
    double t[3] = {(double)lag[0], (double)lag[1], (double)lag[2]};
    size_t at = 0;
    if (!G)
        return nl_model_acf(m, dim, t);
    for (int a = dim - 1; a >= 0; a--)
        at = at * G->n[a] + (size_t)((lag[a] + (long)G->n[a]) % (long)G->n[a]);
    return G->data[at];
}

/* spectrum: models: R on a grid of 8 n (1D), 4 n (2D) or 2 n (3D) per
 * axis from the sampled spectrum (core/wk.h), so that lags up to a quarter
 * of the field are far from the grid's period; NULL in *G for other
 * models. */
static int spectral_acf(const nl_model *m, int dim, const size_t *n, nl_field **G)
{
    size_t g[3] = {1, 1, 1};
    int st = NL_OK;
    *G = NULL;
    if (nl_model_has_acf(m))
        return NL_OK;
    for (int a = 0; a < dim; a++)
        g[a] = n[a] * (dim == 1 ? 8 : dim == 2 ? 4 : 2);
    if ((*G = nl_field_alloc(dim, g, NULL, &st)) && (st = nl_wk_sample_acf(m, *G))) {
        nl_field_free(*G);
        *G = NULL;
    }
    return st;
}

/* Lags along dir: up to one past the last |R| > 5% R(0), within a quarter
 * of the shortest axis crossed, at least 4; R finite at each. */
static int dir_lags(const nl_model *m, const nl_field *G, nl_validate_result *v, int dir)
{
    size_t q = SIZE_MAX, last = 0;
    double r0 = v->target[NL_VALIDATE_X][0];
    for (int a = 0; a < v->dim; a++)
        if (dir == NL_VALIDATE_DIAG || dir == a)
            q = v->n[a] / 4 < q ? v->n[a] / 4 : q;
    if (q > NL_VALIDATE_MAXLAG)
        q = NL_VALIDATE_MAXLAG;
    for (size_t l = 0; l <= q; l++) {
        long lag[3];
        nl_validate_dir_lag(v->dim, dir, (long)l, lag);
        v->target[dir][l] = acf_at(m, v->dim, lag, G);
        if (!isfinite(v->target[dir][l]))
            return NL_ERROR(NL_EINVAL, "validate: the model is not finite at lag (%ld, %ld, %ld)", lag[0], lag[1],
                            lag[2]);
        if (fabs(v->target[dir][l]) > 0.05 * r0)
            last = l;
    }
    last = last + 1 < q ? last + 1 : q;
    v->nlag[dir] = (last < 4 ? (q < 4 ? q : 4) : last) + 1;
    return NL_OK;
}

/* The half box of half-width W: l and -l estimate the same sum. */
static int map_lags(const nl_model *m, const nl_field *G, nl_validate_result *v)
{
    long W = 0, w[3] = {0, 0, 0};
    for (int d = 0; d < NL_VALIDATE_DIRS; d++)
        W = v->nlag[d] && (long)v->nlag[d] - 1 > W ? (long)v->nlag[d] - 1 : W;
    if (W > (v->dim == 2 ? NL_VALIDATE_MAP_2D : NL_VALIDATE_MAP_3D))
        W = v->dim == 2 ? NL_VALIDATE_MAP_2D : NL_VALIDATE_MAP_3D;
    for (int a = 0; a < v->dim; a++)
        w[a] = W < (long)v->n[a] / 4 ? W : (long)v->n[a] / 4;
    v->nmap = 0;
    for (long z = -w[2]; z <= w[2]; z++)
        for (long y = -w[1]; y <= w[1]; y++)
            for (long x = 0; x <= w[0]; x++) {
                long *l = v->map[v->nmap];
                if (x == 0 && (y < 0 || (y == 0 && z < 0)))
                    continue;  /* the mirror of a lag already in */
                if (v->nmap == NL_VALIDATE_MAPLAGS)
                    return NL_ERROR(NL_EINVAL, "validate: more than %d lags in the map", NL_VALIDATE_MAPLAGS);
                l[0] = x, l[1] = y, l[2] = z;
                v->map_target[v->nmap] = acf_at(m, v->dim, l, G);
                if (!isfinite(v->map_target[v->nmap]))
                    return NL_ERROR(NL_EINVAL, "validate: the model is not finite at lag (%ld, %ld, %ld)", x, y, z);
                v->nmap++;
            }
    return NL_OK;
}

void nl_validate_options_default(nl_validate_options *o)
{
    *o = (nl_validate_options){.realizations = 32, .seed = 1, .alpha = 1e-3, .tolerance = 0.1, .subdiv_N = 2,
                               .subdiv_tol = 1e-4, .sparse_density = 32};
}

static int check_options(int dim, const size_t *n, const nl_validate_options *o)
{
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "validate: expected a 1D, 2D or 3D grid, got %dD", dim);
    for (int a = 0; a < dim; a++)
        if (n[a] < 16)
            return NL_ERROR(NL_EINVAL, "validate: expected at least 16 samples per axis, got %zu", n[a]);
    if (o->realizations < 2)
        return NL_ERROR(NL_EINVAL, "validate: expected at least 2 realizations, got %zu", o->realizations);
    if (!(o->alpha > 0 && o->alpha < 1))
        return NL_ERROR(NL_EINVAL, "validate: expected a false-alarm rate in (0, 1), got %g", o->alpha);
    if (!(o->tolerance > 0 && isfinite(o->tolerance)))
        return NL_ERROR(NL_EINVAL, "validate: expected a positive tolerance, got %g", o->tolerance);
    return NL_OK;
}

/* Octave bands down to a lowest one holding every frequency below it. */
static void set_bands(nl_validate_result *v)
{
    size_t nmin = v->n[0];
    for (int a = 1; a < v->dim; a++)
        nmin = v->n[a] < nmin ? v->n[a] : nmin;
    v->nbands = 0;
    while (((size_t)4 << v->nbands) <= nmin && v->nbands < NL_VALIDATE_BANDS)
        v->nbands++;
    for (size_t b = 0; b < v->nbands; b++)
        v->band_hi[b] = ldexp(0.5, -(int)b), v->band_lo[b] = b + 1 < v->nbands ? ldexp(0.5, -(int)b - 1) : 0;
}

int nl_validate_init(const nl_model *m, int dim, const size_t *n, int positive_definite,
                     const nl_validate_options *o, nl_validate_result *v)
{
    int st = check_options(dim, n, o);
    nl_field *G;
    double r0;
    if (st)
        return st;
    memset(v, 0, sizeof *v);
    v->dim = dim;
    for (int a = 0; a < 3; a++)
        v->n[a] = a < dim ? n[a] : 1;
    v->realizations = o->realizations, v->seed = o->seed, v->alpha = o->alpha, v->tolerance = o->tolerance;
    v->positive_definite = positive_definite;
    if ((st = spectral_acf(m, dim, v->n, &G)))
        return st;
    r0 = v->target[NL_VALIDATE_X][0] = acf_at(m, dim, (long[3]){0, 0, 0}, G);
    if (!(r0 > 0 && isfinite(r0)))
        st = NL_ERROR(NL_EINVAL, "validate: expected R(0) positive and finite, got %g", r0);
    for (int d = 0; d < NL_VALIDATE_DIRS && !st; d++)
        if (d < dim || (d == NL_VALIDATE_DIAG && dim > 1))
            st = dir_lags(m, G, v, d);
    if (!st && dim > 1)
        st = map_lags(m, G, v);
    nl_field_free(G);
    if (st)
        return st;
    for (int d = 0; d < NL_VALIDATE_DIRS; d++)
        v->ntests += v->nlag[d];
    v->ntests += v->nmap;
    v->threshold = nl_verdict_threshold(o->alpha, v->ntests, o->realizations - 1);
    v->ci_factor = nl_verdict_threshold(0.05, v->ntests, o->realizations - 1);
    set_bands(v);
    if ((st = nl_validate_spectrum_targets(m, v)))
        return st;
    for (int meth = 0; meth < NL_VALIDATE_METHODS; meth++) {
        v->method[meth].name = nl_validate_method_name(meth);
        snprintf(v->method[meth].why, sizeof v->method[meth].why, "not run");
    }
    return NL_OK;
}

int nl_validate_lags_alloc(const nl_validate_result *v, long (**out)[3])
{
    size_t k = 0;
    if (!(*out = malloc(v->ntests * sizeof **out)))
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu lags", v->ntests);
    for (int d = 0; d < NL_VALIDATE_DIRS; d++)
        for (size_t l = 0; l < v->nlag[d]; l++)
            nl_validate_dir_lag(v->dim, d, (long)l, (*out)[k++]);
    for (size_t i = 0; i < v->nmap; i++, k++)
        memcpy((*out)[k], v->map[i], sizeof v->map[i]);
    return NL_OK;
}

void nl_validate_flatten(const nl_validate_result *v, const double (*a)[NL_VALIDATE_MAXLAG + 1], const double *map,
                         double *flat)
{
    size_t k = 0;
    for (int d = 0; d < NL_VALIDATE_DIRS; d++)
        for (size_t l = 0; l < v->nlag[d]; l++)
            flat[k++] = a[d][l];
    for (size_t i = 0; i < v->nmap; i++)
        flat[k++] = map[i];
}
