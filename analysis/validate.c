/* Validation of a model's synthesis: each method's ensemble against the
 * target (analysis/validate.h). */
#include "validate_internal.h"
#include "psd.h"
#include "subdiv_exact.h"
#include "verdict.h"
#include "../core/nl_error.h"
#include "../synth/method.h"
#include "../synth/subdiv.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* What validate runs: each NL_METHOD_VALIDATED method of the registry, in
 * nl_method_ranked's order (exact methods first), with its defaults and
 * then once per other choice of each of its CHOICE options (a variant,
 * named METHOD-CHOICE). */
typedef struct {
    const nl_method_type *type; /* the method */
    int row, choice;            /* the variant: option row `row` set to choice `choice`; row -1: none */
    int periodic;               /* its field is periodic (band_periodic), else band_fejer */
    char name[48];              /* "subdiv", "subdiv-correlated", ... */
} slot;

static slot slots[NL_VALIDATE_METHODS];
static int nslots;
static pthread_once_t slots_once = PTHREAD_ONCE_INIT;

static void add_slot(const nl_method_type *t, int row, int choice, const char *word, size_t len)
{
    slot *s = &slots[nslots];
    if (nslots >= NL_VALIDATE_METHODS)
        return;
    s->type = t, s->row = row, s->choice = choice;
    s->periodic = (t->caps & NL_METHOD_PERIODIC) != 0;
    for (int k = 0; k < t->noptions; k++)
        s->periodic |= (t->options[k].flags & NL_METHOD_NO_WINDOW) != 0; /* set by validate: wrapped */
    snprintf(s->name, sizeof s->name, "%s%s%.*s", t->name, word ? "-" : "", (int)len, word ? word : "");
    nslots++;
}

static void build_slots(void)
{
    const nl_method_type *t;
    for (int i = 0; (t = nl_method_ranked(i)); i++) {
        if (!(t->caps & NL_METHOD_VALIDATED))
            continue;
        add_slot(t, -1, 0, NULL, 0);
        for (int k = 0; k < t->noptions; k++) {
            const char *w = t->options[k].type == NL_METHOD_CHOICE ? t->options[k].words : NULL;
            for (int c = 0; w && *w; c++) {
                size_t len = strcspn(w, "|");
                if (c > 0)
                    add_slot(t, k, c, w, len);
                w += len + (w[len] == '|');
            }
        }
    }
}

static const slot *slot_at(int meth)
{
    pthread_once(&slots_once, build_slots);
    return meth >= 0 && meth < nslots ? &slots[meth] : NULL;
}

int nl_validate_method_count(void)
{
    pthread_once(&slots_once, build_slots);
    return nslots;
}

int nl_validate_claim(const nl_validate_result *res, int method, int *verdict)
{
    const slot *sl = slot_at(method);
    const nl_validate_method_result *r = sl ? &res->method[method] : NULL;
    *verdict = -1;
    if (sl && (sl->type->caps & NL_METHOD_EXACT)) {
        if (r->ran)
            *verdict = r->verdict;
        return NL_VALIDATE_CLAIM_MODEL;
    }
    if (!r || !r->ran || !r->have_exact)
        return NL_VALIDATE_CLAIM_NONE;
    *verdict = r->vs_exact.effect.hi <= res->tolerance  ? NL_VALIDATE_WITHIN
               : r->vs_exact.effect.lo > res->tolerance ? NL_VALIDATE_OFF
                                                        : NL_VALIDATE_UNRESOLVED;
    return NL_VALIDATE_CLAIM_OWN;
}

const char *nl_validate_method_name(int method)
{
    const slot *s = slot_at(method);
    return s ? s->name : NULL;
}

const nl_method_type *nl_validate_method_type(int method)
{
    const slot *s = slot_at(method);
    return s ? s->type : NULL;
}

int nl_validate_method_periodic(int method)
{
    const slot *s = slot_at(method);
    return s && s->periodic;
}

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
static int run_ensemble(const nl_validate_result *v, int meth, nl_method_plan *plan, const nl_validate_options *o,
                        ensemble *e, double *mean, double *se)
{
    int st = ensemble_alloc(v, e);
    for (size_t s = 1; s <= v->realizations && !st; s++) {
        if (o->progress)
            o->progress(o->progress_ctx, meth, s - 1, v->realizations);
        if (!(st = nl_method_execute(plan, v->seed + (s - 1), e->f)) && !(st = nl_verdict_add(e->vd, e->f)))
            st = add_bands(v, e);
    }
    return st ? st : nl_verdict_stats(e->vd, mean, se);
}

/* Synthesise, summarise, time. */
static void run_method(nl_validate_result *v, int meth, nl_method_plan *plan, const nl_validate_options *o)
{
    const slot *sl = slot_at(meth);
    nl_validate_method_result *r = &v->method[meth];
    double *mean = malloc(v->ntests * sizeof *mean), *se = malloc(v->ntests * sizeof *se), *exact = NULL;
    ensemble e;
    int st = mean && se ? run_ensemble(v, meth, plan, o, &e, mean, se) : NL_ERROR(NL_ENOMEM, "out of memory");
    if (!st && (sl->type->caps & NL_METHOD_SUBDIVISION) && sl->row < 0 && v->have_exact &&
        (exact = malloc(v->ntests * sizeof *exact)))
        nl_validate_flatten(v, v->exact, v->exact_map, exact);
    if (st)
        refuse(r, st);
    else {
        r->ran = 1, r->status = NL_OK, r->why[0] = '\0';
        nl_validate_summarise(v, mean, se, e.b1, e.b2, sl->periodic ? v->band_periodic : v->band_fejer, exact, r);
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
static int refused_subdiv(const nl_model *m, const slot *sl, const nl_method_options *mo, int st,
                          nl_validate_result *v)
{
    nl_validate_method_result *r = &v->method[sl - slots];
    int levels = (int)nl_method_options_get(mo, "levels")->i;
    nl_subdiv_coeffs *c;
    refuse(r, st);
    if (v->dim > 2 || sl->row >= 0 ||
        nl_subdiv_coeffs_alloc(m, v->dim, levels, ldexp(1.0, levels), (int)nl_method_options_get(mo, "neighborhood")->i,
                               nl_method_options_get(mo, "tol")->d,
                               (int)nl_method_options_get(mo, "max-neighborhood")->i, &c))
        return st;
    if (c->flags & NL_SUBDIV_NOT_PD)
        refuse(r, st = NL_ERROR(NL_ENOTPD, "not positive definite at some level"));
    else
        exact_acf(c, m, v);
    nl_subdiv_coeffs_free(c);
    return st;
}

/* Option `name` of mo given as i (and d), when the method has it. */
static void put(nl_method_options *mo, const char *name, long i, double d)
{
    int k = nl_method_option_index(mo->type, name);
    if (k >= 0)
        mo->v[k] = (nl_method_value){.set = 2, .i = i, .d = d};
}

/* The method's options from validate's: subdivision with the options'
 * neighbourhood (auto: up to 6), tol, random neighbourhoods and levels (0:
 * a coarse grid of at least 16 samples per axis); sparse convolution at
 * the options' radius and cell (0: the defaults) and density; periodic
 * wherever an option makes it so (a wrapped tile).  Refused: a variant with
 * random neighbourhoods, a grid of a dimension the method lacks. */
static int method_options(const slot *sl, const nl_validate_options *o, const nl_validate_result *v,
                          nl_method_options *mo)
{
    const nl_method_type *t = sl->type;
    long levels = o->subdiv_levels ? o->subdiv_levels : nl_subdiv_default_levels(v->dim, v->n, 16);
    if (sl->row >= 0 && o->subdiv_random && nl_method_option_index(t, "random-neighborhoods") >= 0)
        return NL_ERROR(NL_EINVAL, "%s %s: not with random neighbourhoods", nl_validate_method_name((int)(sl - slots)) +
                        strlen(t->name) + 1, t->options[sl->row].name);
    if (!(t->dims & (1u << (v->dim - 1))))
        return NL_ERROR(NL_EINVAL, "%s: expected a %s grid, got %dD", t->noun, t->dims == 3 ? "1D or 2D" : "1D", v->dim);
    if (nl_method_option_index(t, "levels") >= 0 && !levels)
        return NL_ERROR(NL_EINVAL, "%s: expected sizes divisible by 2 with at least 32 samples", t->noun);
    nl_method_options_default(t, mo);
    put(mo, "levels", levels, 0);
    put(mo, "neighborhood", o->subdiv_N, 0);
    put(mo, "max-neighborhood", 6, 0);
    put(mo, "tol", -1, o->subdiv_tol);
    if (o->subdiv_random)
        put(mo, "random-neighborhoods", o->subdiv_random, 0);
    if (o->sparse_radius)
        put(mo, "radius", o->sparse_radius, 0);
    if (o->sparse_cell)
        put(mo, "cell", o->sparse_cell, 0);
    put(mo, "density", 0, o->sparse_density);
    for (int k = 0; k < t->noptions; k++)
        if (t->options[k].flags & NL_METHOD_NO_WINDOW)
            mo->v[k] = (nl_method_value){.set = 2, .i = 1};
    if (sl->row >= 0)
        mo->v[sl->row] = (nl_method_value){.set = 2, .i = sl->choice};
    return NL_OK;
}

/* The slot's plan on the unit-spacing grid; subdivision with its
 * defaults: its exact ACF too. */
static int plan_slot(const nl_model *m, const slot *sl, const nl_validate_options *o, nl_validate_result *v,
                     nl_method_plan **p)
{
    nl_method_grid g = {v->dim, {v->n[0], v->n[1], v->n[2]}, {1, 1, 1}, {0, 0}};
    nl_method_options mo;
    int st, subdiv = (sl->type->caps & NL_METHOD_SUBDIVISION) != 0;
    *p = NULL;
    if ((st = method_options(sl, o, v, &mo)))
        return st;
    if ((st = nl_method_plan_alloc(sl->type, m, &g, &mo, p)))
        return subdiv ? refused_subdiv(m, sl, &mo, st, v) : st;
    if (subdiv && sl->row < 0)
        exact_acf(nl_subdiv_plan_coeffs(nl_method_plan_impl(*p)), m, v);
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
    const slot *sl = slot_at(meth);
    nl_method_plan *p = NULL;
    int st = NL_OK;
    double t0 = now();
    if (!sl)
        return NL_ERROR(NL_EINVAL, "validate: expected a method 0..%d, got %d", nl_validate_method_count() - 1, meth);
    if (o->realizations != v->realizations || o->seed != v->seed)
        return NL_ERROR(NL_EINVAL, "validate: %zu realizations from seed %llu, but the result was prepared for %zu from %llu",
                        o->realizations, (unsigned long long)o->seed, v->realizations, (unsigned long long)v->seed);
    if (!v->positive_definite)
        st = NL_ERROR(NL_ENOTPD, "the model is not positive definite");
    else
        st = plan_slot(m, sl, o, v, &p);
    if (st)
        refuse(&v->method[meth], st);
    else
        run_method(v, meth, p, o);
    nl_method_plan_free(p);
    v->method[meth].seconds = now() - t0;
    return NL_OK;
}

int nl_validate_model(const nl_model *m, int dim, const size_t *n, int positive_definite,
                      const nl_validate_options *o, nl_validate_result *v)
{
    int st = nl_validate_init(m, dim, n, positive_definite, o, v);
    for (int meth = 0; meth < nl_validate_method_count() && !st; meth++)
        st = nl_validate_method(m, meth, o, v);
    return st;
}
