/* Validation of a model's synthesis: each method's ensemble against the
 * target (analysis/validate.h). */
#include "validate_internal.h"
#include "psd.h"
#include "subdiv_exact.h"
#include "verdict.h"
#include "../core/nl_error.h"
#include "../synth/circulant.h"
#include "../synth/fft.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char *const names[NL_VALIDATE_METHODS] = {"fft", "circulant", "subdiv", "subdiv-correlated", "sparse"};

const char *nl_validate_method_name(int method)
{
    return method >= 0 && method < NL_VALIDATE_METHODS ? names[method] : NULL;
}

/* One realization of a planned method. */
typedef int (*run_fn)(const void *plan, uint64_t seed, nl_field *f);
static int run_fft(const void *p, uint64_t s, nl_field *f) { return nl_synth_fft_execute(p, s, f); }
static int run_circ(const void *p, uint64_t s, nl_field *f) { return nl_synth_circulant_execute(p, s, f); }
static int run_sub(const void *p, uint64_t s, nl_field *f) { return nl_subdiv_plan_execute(p, s, f); }
static int run_sparse(const void *p, uint64_t s, nl_field *f) { return nl_synth_sparse_execute(p, s, 1, NULL, f); }

/* A method that cannot run: its status and the message of the last error. */
static void refuse(nl_validate_method_result *r, int st)
{
    r->ran = 0;
    r->status = st;
    snprintf(r->why, sizeof r->why, "%s", nl_errmsg());
}

/* What an ensemble accumulates besides the ACF: the periodogram's bands. */
typedef struct {
    nl_verdict *vd;    /* ACF at every tested lag */
    nl_psd_plan *pp;   /* periodogram */
    nl_field *f, *P;   /* a realization and its periodogram */
    int *band;         /* band of each frequency */
    double b1[NL_VALIDATE_BANDS], b2[NL_VALIDATE_BANDS]; /* sums of band means and of their squares */
} ensemble;

static void ensemble_free(ensemble *e)
{
    nl_verdict_free(e->vd);
    nl_psd_plan_free(e->pp);
    nl_field_free(e->f), nl_field_free(e->P);
    free(e->band);
}

static int ensemble_alloc(const nl_validate_result *v, ensemble *e)
{
    long (*lags)[3] = NULL;
    int st = NL_OK;
    memset(e, 0, sizeof *e);
    if ((e->f = nl_field_alloc(v->dim, v->n, NULL, &st)) && (e->P = nl_field_alloc(v->dim, v->n, NULL, &st)) &&
        !(st = nl_psd_plan_alloc(v->dim, v->n, &e->pp)) && !(st = nl_validate_lags_alloc(v, &lags)))
        st = nl_verdict_alloc3(v->dim, v->n, v->ntests, (const long (*)[3])lags, &e->vd);
    free(lags);
    if (!st && !(st = nl_size_check(v->dim, v->n, sizeof *e->band, 1, NULL)) &&
        !(e->band = malloc(e->f->count * sizeof *e->band)))
        st = NL_ERROR(NL_ENOMEM, "out of memory for %zu frequencies", e->f->count);
    if (!st)
        nl_validate_bands_of(v, e->band);
    return st;
}

/* The periodogram of e->f into the band sums. */
static int add_bands(const nl_validate_result *v, ensemble *e)
{
    double s[NL_VALIDATE_BANDS] = {0}, c[NL_VALIDATE_BANDS] = {0};
    int st = nl_psd_plan_execute(e->pp, e->f, 0.0, e->P);
    for (size_t j = 0; j < e->P->count && !st; j++)
        if (e->band[j] >= 0)
            s[e->band[j]] += e->P->data[j], c[e->band[j]]++;
    for (size_t b = 0; b < v->nbands && !st; b++) {
        double x = c[b] > 0 ? s[b] / c[b] : 0;
        e->b1[b] += x, e->b2[b] += x * x;
    }
    return st;
}

/* M realizations of one planned method: their mean and se at every tested
 * lag (mean, se: v->ntests each) and band sums in e. */
static int run_ensemble(const nl_validate_result *v, int meth, run_fn fn, const void *plan,
                        const nl_validate_options *o, ensemble *e, double *mean, double *se)
{
    int st = ensemble_alloc(v, e);
    for (size_t s = 1; s <= v->realizations && !st; s++) {
        if (o->progress)
            o->progress(o->progress_ctx, meth, s - 1, v->realizations);
        if (!(st = fn(plan, v->seed + (s - 1), e->f)) && !(st = nl_verdict_add(e->vd, e->f)))
            st = add_bands(v, e);
    }
    return st ? st : nl_verdict_stats(e->vd, mean, se);
}

/* Synthesise, summarise, time. */
static void run_method(nl_validate_result *v, int meth, run_fn fn, const void *plan, const nl_validate_options *o)
{
    nl_validate_method_result *r = &v->method[meth];
    double *mean = malloc(v->ntests * sizeof *mean), *se = malloc(v->ntests * sizeof *se), *exact = NULL;
    ensemble e;
    int st = mean && se ? run_ensemble(v, meth, fn, plan, o, &e, mean, se) : NL_ERROR(NL_ENOMEM, "out of memory");
    if (!st && meth == NL_VALIDATE_SUBDIV && v->have_exact && (exact = malloc(v->ntests * sizeof *exact)))
        nl_validate_flatten(v, v->exact, v->exact_map, exact);
    if (st)
        refuse(r, st);
    else {
        r->ran = 1, r->status = NL_OK, r->why[0] = '\0';
        nl_validate_summarise(v, mean, se, e.b1, e.b2,
                              meth == NL_VALIDATE_CIRCULANT ? v->band_fejer : v->band_periodic, exact, r);
    }
    if (mean && se)
        ensemble_free(&e);
    free(mean), free(se), free(exact);
}

/* Subdivision's exact expected ACF at every tested lag, on grids small
 * enough for its (n_x n_y)^2 covariance. */
static void exact_acf(const nl_subdiv_coeffs *c, const nl_model *m, nl_validate_result *v)
{
    long (*l3)[3] = NULL, *l2 = NULL;
    double *flat = NULL;
    if (v->dim > 2 || v->n[0] > (v->dim == 1 ? 2048u : 64u) || v->n[1] > 64)
        return;
    if (!nl_validate_lags_alloc(v, &l3) && (l2 = malloc(2 * v->ntests * sizeof *l2)) &&
        (flat = malloc(v->ntests * sizeof *flat))) {
        for (size_t i = 0; i < v->ntests; i++)
            l2[2 * i] = l3[i][0], l2[2 * i + 1] = l3[i][1];
        v->have_exact = nl_subdiv_exact_acf(c, m, v->n[0], v->n[1], v->ntests, l2, flat) == 0;
    }
    for (size_t i = 0, k = 0; v->have_exact && i < NL_VALIDATE_DIRS; i++)
        for (size_t l = 0; l < v->nlag[i]; l++)
            v->exact[i][l] = flat[k++];
    for (size_t i = 0, k = v->ntests - v->nmap; v->have_exact && i < v->nmap; i++)
        v->exact_map[i] = flat[k + i];
    if (v->have_exact)
        nl_validate_exact_effect(v, flat);
    free(l3), free(l2), free(flat);
}

/* A subdivision plan that was refused still shows the exact ACF of its
 * coefficients when they exist and are positive definite (the refusal came
 * from the coarse FFT); levels that are not are reported as such. */
static int refused_subdiv(const nl_model *m, const nl_subdiv_options *so, int st, nl_validate_result *v)
{
    nl_validate_method_result *r = &v->method[so->displacements ? NL_VALIDATE_SUBDIV_CORR : NL_VALIDATE_SUBDIV];
    nl_subdiv_coeffs *c;
    refuse(r, st);
    if (v->dim > 2 || so->displacements ||
        nl_subdiv_coeffs_alloc(m, v->dim, so->levels, ldexp(1.0, so->levels), so->N, so->tol, so->nmax, &c))
        return st;
    if (c->flags & NL_SUBDIV_NOT_PD)
        refuse(r, st = NL_ERROR(NL_ENOTPD, "not positive definite at some level"));
    else
        exact_acf(c, m, v);
    nl_subdiv_coeffs_free(c);
    return st;
}

/* Periodic subdivision at unit spacing with the options' neighbourhood
 * and levels, and (independent displacements) its exact ACF; correlated:
 * displacements with the filter's default taps, compared with the target
 * only. */
static int plan_subdiv(const nl_model *m, const nl_validate_options *o, int correlated, nl_validate_result *v,
                       nl_subdiv_plan **p)
{
    nl_subdiv_options so;
    int st;
    nl_subdiv_options_default(&so);
    so.levels = o->subdiv_levels ? o->subdiv_levels : nl_subdiv_default_levels(v->dim, v->n, 16);
    so.N = o->subdiv_N, so.tol = o->subdiv_tol, so.nmax = 6, so.random_nb = o->subdiv_random;
    so.displacements = correlated ? NL_SUBDIV_DISP_ERROR : NL_SUBDIV_DISP_INDEPENDENT;
    if (correlated && so.random_nb)
        return NL_ERROR(NL_EINVAL, "correlated displacements: not with random neighbourhoods");
    if (v->dim > 2)
        return NL_ERROR(NL_EINVAL, "subdivision: expected a 1D or 2D grid, got %dD", v->dim);
    if (!so.levels)
        return NL_ERROR(NL_EINVAL, "subdivision: expected sizes divisible by 2 with at least 32 samples");
    if ((st = nl_subdiv_plan_alloc(m, v->dim, v->n, 1.0, &so, p)))
        return refused_subdiv(m, &so, st, v);
    if (!correlated)
        exact_acf(nl_subdiv_plan_coeffs(*p), m, v);
    return NL_OK;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int nl_validate_method(const nl_model *m, int meth, const nl_validate_options *o, nl_validate_result *v)
{
    nl_synth_fft_plan *pf = NULL;
    nl_synth_circulant_plan *pc = NULL;
    nl_synth_sparse_plan *ps = NULL;
    nl_subdiv_plan *pd = NULL;
    const void *plan = NULL;
    run_fn fn = NULL;
    int st = NL_OK;
    double t0 = now();
    if (meth < 0 || meth >= NL_VALIDATE_METHODS)
        return NL_ERROR(NL_EINVAL, "validate: expected a method 0..%d, got %d", NL_VALIDATE_METHODS - 1, meth);
    if (o->realizations != v->realizations || o->seed != v->seed)
        return NL_ERROR(NL_EINVAL, "validate: %zu realizations from seed %llu, but the result was prepared for %zu from %llu",
                        o->realizations, (unsigned long long)o->seed, v->realizations, (unsigned long long)v->seed);
    if (!v->positive_definite)
        st = NL_ERROR(NL_ENOTPD, "the model is not positive definite");
    else if (meth == NL_VALIDATE_FFT)
        st = nl_synth_fft_plan_alloc(m, v->dim, v->n, NULL, 0, &pf), plan = pf, fn = run_fft;
    else if (meth == NL_VALIDATE_CIRCULANT)
        st = nl_synth_circulant_plan_alloc(m, v->dim, v->n, NULL, 0, 16, &pc), plan = pc, fn = run_circ;
    else if (meth == NL_VALIDATE_SUBDIV || meth == NL_VALIDATE_SUBDIV_CORR)
        st = plan_subdiv(m, o, meth == NL_VALIDATE_SUBDIV_CORR, v, &pd), plan = pd, fn = run_sub;
    else if (v->dim > 2)
        st = NL_ERROR(NL_EINVAL, "sparse convolution: expected a 1D or 2D grid, got %dD", v->dim);
    else
        st = nl_synth_sparse_plan_model(m, v->dim, NULL, o->sparse_radius, o->sparse_cell, o->sparse_density, &ps),
        plan = ps, fn = run_sparse;
    if (st)
        refuse(&v->method[meth], st);
    else
        run_method(v, meth, fn, plan, o);
    nl_synth_fft_plan_free(pf), nl_synth_circulant_plan_free(pc), nl_synth_sparse_plan_free(ps);
    nl_subdiv_plan_free(pd);
    v->method[meth].seconds = now() - t0;
    return NL_OK;
}

int nl_validate_model(const nl_model *m, int dim, const size_t *n, int positive_definite,
                      const nl_validate_options *o, nl_validate_result *v)
{
    int st = nl_validate_init(m, dim, n, positive_definite, o, v);
    for (int meth = 0; meth < NL_VALIDATE_METHODS && !st; meth++)
        st = nl_validate_method(m, meth, o, v);
    return st;
}
