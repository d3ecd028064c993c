/* circulant as a method descriptor (synth/method.h over synth/circulant.h).
 * Its nl_method_plan_impl is the nl_synth_circulant_plan. */
#include "method_internal.h"
#include "../core/nl_error.h"
#include "circulant_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The embedding doubles at most this many times (up to 16x the size). */
#define MAX_GROWTH 16

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    nl_method_plan *p = nl_method_plan_head(sizeof *p, g, o);
    unsigned fl = o->flags & NL_METHOD_OPT_CLAMP ? NL_SYNTH_FFT_CLAMP : 0;
    int st = p ? nl_synth_circulant_plan_alloc(m, g->dim, g->n, g->h, fl, MAX_GROWTH,
                                               (nl_synth_circulant_plan **)&p->impl)
               : NL_ENOMEM;
    if (st)
        nl_method_plan_free(p), p = NULL;
    *out = p;
    return st;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    return nl_synth_circulant_execute(p->impl, seed, f);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    nl_synth_circulant_info info;
    size_t len = 0;
    nl_synth_circulant_plan_info(p->impl, &info);
    return nl_method_append(buf, size, &len, "circulant:embedding=%zux%zux%zu", info.m[0], info.m[1], info.m[2]);
}

static void plan_free(nl_method_plan *p)
{
    nl_synth_circulant_plan_free(p->impl);
    free(p);
}

int nl_synth_circulant_report(const nl_synth_circulant_info *i, const nl_model *m, int dim, nl_method_report *r)
{
    const double zero[3] = {0, 0, 0};
    int clamped = i->clamp_error > NL_SYNTH_FFT_CLAMP_TOL, lost = fabs(i->variance_loss) > NL_SYNTH_CIRCULANT_LOSS_TOL;
    int st;
    snprintf(r->method, sizeof r->method, "circulant:embedding=%zux%zux%zu", i->m[0], i->m[1], i->m[2]);
    snprintf(r->flags, sizeof r->flags, "%s%s%s", clamped ? "clamped" : "", clamped && lost ? "," : "",
             lost ? "variance-changed" : "");
    r->sd = sqrt(nl_model_acf(m, dim, zero));
    if (!(r->sd > 0))
        r->sd = 1;
    r->json[0] = '\0';
    st = nl_method_json(r, "{\"embedding\": [%zu, %zu, %zu], \"min_eigenvalue\": %s, \"max_eigenvalue\": %s, "
                        "\"clamp_error\": %s, \"doublings\": %d", i->m[0], i->m[1], i->m[2],
                        NL_METHOD_REAL(i->min_eigenvalue), NL_METHOD_REAL(i->max_eigenvalue),
                        NL_METHOD_REAL(i->clamp_error), i->doublings);
    /* the spectral models' loss to the embedding's frequency sampling (synth/circulant.h) */
    if (!st && lost)
        st = nl_method_json(r, ", \"variance_loss\": %s", NL_METHOD_REAL(i->variance_loss));
    return st ? st : nl_method_json(r, "}");
}

static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    nl_synth_circulant_info info;
    (void)seed, (void)f;
    nl_synth_circulant_plan_info(p->impl, &info);
    return nl_synth_circulant_report(&info, m, p->grid.dim, r);
}

const nl_method_type nl_method_circulant = {
    .name = "circulant",
    .summary = "exact stationary field on a non-periodic grid by circulant embedding",
    .noun = "circulant embedding",
    .help =
        "exact stationary field on a NON-periodic grid by circulant embedding\n"
        "(Dietrich-Newsam, Wood-Chan): the embedding doubles until its eigenvalues\n"
        "are non-negative, up to 16x the size; the report gives the embedding and\n"
        "the smallest eigenvalue",
    .dims = 7,
    .caps = NL_METHOD_MODEL | NL_METHOD_DISTRIBUTED | NL_METHOD_CONDITIONABLE | NL_METHOD_EXACT | NL_METHOD_CLAMP |
            NL_METHOD_EMBEDDING | NL_METHOD_VALIDATED | NL_METHOD_NUGGET,
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
