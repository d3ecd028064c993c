/* Validation of a model's synthesis: each method's ensemble ACF against the
 * target (analysis/validate.h). */
#include "validate.h"
#include "subdiv_exact.h"
#include "verdict.h"
#include "../core/nl_error.h"
#include "../synth/circulant.h"
#include "../synth/fft.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define L NL_VALIDATE_LAGS

static const char *const names[NL_VALIDATE_METHODS] = {"fft", "circulant", "subdiv", "sparse"};

const char *nl_validate_method_name(int method)
{
    return method >= 0 && method < NL_VALIDATE_METHODS ? names[method] : NULL;
}

void nl_validate_options_default(nl_validate_options *o)
{
    *o = (nl_validate_options){.realizations = 32, .alpha = 1e-3};
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

/* M realizations of one planned method into its ensemble verdict. */
static void run_ensemble(const nl_validate_result *v, int meth, run_fn fn, const void *plan,
                         const nl_validate_options *o, nl_validate_method_result *r)
{
    nl_field *f = nl_field_alloc(v->dim, v->n, NULL, NULL);
    long lags[L][2];
    nl_verdict *vd = NULL;
    int st;
    for (int i = 0; i < L; i++)
        lags[i][0] = i, lags[i][1] = 0;
    st = f ? nl_verdict_alloc(v->dim, v->n, L, (const long (*)[2])lags, &vd) : NL_ENOMEM;
    for (size_t s = 1; s <= v->realizations && !st; s++) {
        if (o->progress)
            o->progress(o->progress_ctx, meth, s - 1, v->realizations);
        if ((st = fn(plan, s, f)) || (st = nl_verdict_add(vd, f)))
            break;
    }
    if (!st)
        st = nl_verdict_stats(vd, r->mean, r->se);
    if (st)
        refuse(r, st);
    else {
        r->ran = 1, r->status = NL_OK, r->why[0] = '\0';
        r->zmax = nl_verdict_zmax(L, r->mean, r->se, v->target, NULL);
        r->pass = r->zmax <= v->threshold;
    }
    nl_verdict_free(vd);
    nl_field_free(f);
}

/* Subdivision's exact expected ACF on grids small enough for its
 * (n_x n_y)^2 covariance. */
static void exact_acf(const nl_subdiv_coeffs *c, const nl_model *m, nl_validate_result *v)
{
    long lags[2 * L];
    if (v->n[0] > (v->dim == 1 ? 2048u : 64u) || v->n[1] > 64)
        return;
    for (int i = 0; i < L; i++)
        lags[2 * i] = i, lags[2 * i + 1] = 0;
    v->have_exact = nl_subdiv_exact_acf(c, m, v->n[0], v->n[1], L, lags, v->exact) == 0;
}

/* A subdivision plan that was refused still shows the exact ACF of its
 * coefficients when they exist and are positive definite (the refusal came
 * from the coarse FFT); levels that are not are reported as such. */
static int refused_subdiv(const nl_model *m, const nl_subdiv_options *so, int st, nl_validate_result *v)
{
    nl_validate_method_result *r = &v->method[NL_VALIDATE_SUBDIV];
    nl_subdiv_coeffs *c;
    refuse(r, st);
    if (nl_subdiv_coeffs_alloc(m, v->dim, so->levels, ldexp(1.0, so->levels), so->N, so->tol, so->nmax, &c))
        return st;
    if (c->flags & NL_SUBDIV_NOT_PD)
        refuse(r, st = NL_ERROR(NL_ENOTPD, "not positive definite at some level"));
    else
        exact_acf(c, m, v);
    nl_subdiv_coeffs_free(c);
    return st;
}

/* Periodic subdivision at unit spacing, N = 2, a coarse grid of at least
 * 16 samples per axis, and its exact ACF. */
static int plan_subdiv(const nl_model *m, nl_validate_result *v, nl_subdiv_plan **p)
{
    nl_subdiv_options so;
    int st;
    nl_subdiv_options_default(&so);
    so.levels = nl_subdiv_default_levels(v->dim, v->n, 16);
    so.N = 2, so.tol = 1e-4, so.nmax = 6;
    if (!so.levels)
        return NL_ERROR(NL_EINVAL, "subdivision: expected sizes divisible by 2 with at least 32 samples");
    if ((st = nl_subdiv_plan_alloc(m, v->dim, v->n, 1.0, &so, p)))
        return refused_subdiv(m, &so, st, v);
    exact_acf(nl_subdiv_plan_coeffs(*p), m, v);
    return NL_OK;
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
    if (meth < 0 || meth >= NL_VALIDATE_METHODS)
        return NL_ERROR(NL_EINVAL, "validate: expected a method 0..%d, got %d", NL_VALIDATE_METHODS - 1, meth);
    if (o->realizations != v->realizations)
        return NL_ERROR(NL_EINVAL, "validate: %zu realizations, but the result was prepared for %zu",
                        o->realizations, v->realizations);
    if (meth == NL_VALIDATE_FFT)
        st = nl_synth_fft_plan_alloc(m, v->dim, v->n, NULL, 0, &pf), plan = pf, fn = run_fft;
    if (meth == NL_VALIDATE_CIRCULANT)
        st = nl_synth_circulant_plan_alloc(m, v->dim, v->n, NULL, 0, 16, &pc), plan = pc, fn = run_circ;
    if (meth == NL_VALIDATE_SUBDIV)
        st = plan_subdiv(m, v, &pd), plan = pd, fn = run_sub;
    if (meth == NL_VALIDATE_SPARSE)
        st = nl_synth_sparse_plan_model(m, v->dim, NULL, 0, 0, 32, &ps), plan = ps, fn = run_sparse;
    if (!v->positive_definite)
        refuse(&v->method[meth], NL_ERROR(NL_ENOTPD, "the model is not positive definite"));
    else if (st)
        refuse(&v->method[meth], st);
    else
        run_ensemble(v, meth, fn, plan, o, &v->method[meth]);
    nl_synth_fft_plan_free(pf), nl_synth_circulant_plan_free(pc), nl_synth_sparse_plan_free(ps);
    nl_subdiv_plan_free(pd);
    return NL_OK;
}

int nl_validate_init(const nl_model *m, int dim, const size_t *n, int positive_definite,
                     const nl_validate_options *o, nl_validate_result *v)
{
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "validate: expected a 1D or 2D grid, got %dD", dim);
    if (n[0] < L || (dim == 2 && n[1] < L))
        return NL_ERROR(NL_EINVAL, "validate: expected at least %d samples per axis", L);
    if (o->realizations < 2)
        return NL_ERROR(NL_EINVAL, "validate: expected at least 2 realizations, got %zu", o->realizations);
    if (!(o->alpha > 0 && o->alpha < 1))
        return NL_ERROR(NL_EINVAL, "validate: expected a false-alarm rate in (0, 1), got %g", o->alpha);
    memset(v, 0, sizeof *v);
    v->dim = dim;
    v->n[0] = n[0], v->n[1] = dim == 2 ? n[1] : 1;
    v->realizations = o->realizations;
    v->positive_definite = positive_definite;
    for (int i = 0; i < L; i++) {
        double lag1[3] = {i * 1.0, 0, 0};
        v->target[i] = nl_model_acf(m, dim, lag1);
    }
    v->threshold = nl_verdict_threshold(o->alpha, L, o->realizations - 1);
    for (int meth = 0; meth < NL_VALIDATE_METHODS; meth++) {
        v->method[meth].name = names[meth];
        snprintf(v->method[meth].why, sizeof v->method[meth].why, "not run");
    }
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
