/* midpoint as a method descriptor (synth/method.h over synth/subdiv.h's
 * midpoint plans and synth/midpoint.h's Miller interpolant).  Its
 * nl_method_plan_impl is an nl_midpoint_method_plan. */
#include "method_internal.h"
#include "midpoint.h"
#include "subdiv.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

typedef struct {
    nl_method_plan head;         /* impl: &mp */
    nl_midpoint_method_plan mp;  /* H, levels, interpolant, the plan */
} midpoint_plan;

static const nl_method_option options[] = {
    {"H", NL_METHOD_DOUBLE, NL_METHOD_OPEN | NL_METHOD_REPLACES_MODEL, 0, 1, NULL,
     "a Hurst exponent between 0 and 1", NULL, "the Hurst exponent (instead of a power:d=D model)"},
    {"levels", NL_METHOD_INT, 0, 1, 30, NULL, NULL, NULL, "levels of refinement"},
    {"variance-scale", NL_METHOD_DOUBLE, NL_METHOD_OPEN, 0, HUGE_VAL, NULL, "a positive factor", "1",
     "an extra factor on the variance of each level"},
    {"interpolant", NL_METHOD_CHOICE, 0, 0, 0, "fournier|miller", "fournier or miller for midpoint", "fournier",
     "nearest-neighbour midpoints (fournier) or Miller's square-square subdivision"},
};

static void plan_free(nl_method_plan *p)
{
    nl_subdiv_plan_free(((midpoint_plan *)p)->mp.plan);
    free(p);
}

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    midpoint_plan *p;
    nl_midpoint_method_plan mp = {0};
    nl_subdiv_info info;
    int st;
    *out = NULL;
    mp.H = nl_method_opt_set(o, "H") ? nl_method_opt_double(o, "H") : NAN;
    mp.levels = (int)nl_method_opt_int(o, "levels");
    mp.vscale = nl_method_opt_double(o, "variance-scale");
    mp.miller = nl_method_opt_int(o, "interpolant") == 1;
    if (isnan(mp.H) && !m)
        return NL_ERROR(NL_EINVAL, "synth midpoint: expected --H or a power:d=D model");
    if (isnan(mp.H) && (st = nl_subdiv_midpoint_hurst(m, g->dim, &mp.H)))
        return st;
    if (mp.miller && !mp.levels)
        mp.levels = nl_synth_midpoint_miller_default_levels(g->dim, g->n);
    if (!mp.miller) {
        if ((st = nl_subdiv_plan_alloc_midpoint(g->dim, g->n, g->h[0], mp.levels, mp.H, 1.0, mp.vscale, &mp.plan)))
            return st;
        nl_subdiv_plan_info(mp.plan, &info);
        mp.levels = info.levels;
    }
    if (!(p = (midpoint_plan *)nl_method_plan_head(sizeof *p, g, o))) {
        nl_subdiv_plan_free(mp.plan);
        return NL_ENOMEM;
    }
    p->mp = mp;
    p->head.impl = &p->mp;
    *out = &p->head;
    return NL_OK;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    const nl_midpoint_method_plan *mp = p->impl;
    if (mp->miller)
        return nl_synth_midpoint_miller(mp->levels, mp->H, 1.0, mp->vscale, seed, f);
    return nl_subdiv_plan_execute(mp->plan, seed, f);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    const nl_midpoint_method_plan *mp = p->impl;
    size_t len = 0;
    return nl_method_append(buf, size, &len, "midpoint:H=%.17g,levels=%d,variance-scale=%.17g%s", mp->H,
                            mp->levels, mp->vscale, mp->miller ? ",interpolant=miller" : "");
}

static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    const nl_midpoint_method_plan *mp = p->impl;
    nl_subdiv_info info;
    (void)m, (void)seed, (void)f;
    if (mp->miller)
        return nl_method_json(r, "{\"H\": %s, \"levels\": %d, \"variance_scale\": %s, \"interpolant\": \"miller\"}",
                              NL_METHOD_REAL(mp->H), mp->levels, NL_METHOD_REAL(mp->vscale));
    nl_subdiv_plan_info(mp->plan, &info);
    r->sd = sqrt(info.variance);
    return nl_method_json(r, "{\"H\": %s, \"levels\": %d, \"variance_scale\": %s}", NL_METHOD_REAL(mp->H),
                          info.levels, NL_METHOD_REAL(mp->vscale));
}

const nl_method_type nl_method_midpoint = {
    .name = "midpoint",
    .summary = "midpoint displacement (Fournier, Fussell and Carpenter), nearest neighbours only",
    .noun = "midpoint displacement",
    .help =
        "midpoint displacement (Fournier, Fussell and Carpenter), nearest neighbours\n"
        "only; --H h (Hurst exponent) or --acf/--spectrum power:d=D with d = 2H + 1\n"
        "(1D), --levels L, --variance-scale Q multiplies the variance of each level\n"
        "by an extra Q (Haruyama-Barsky-style altered variances); --interpolant\n"
        "miller: Miller's square-square subdivision (each level a new grid of\n"
        "half the spacing, weights 9/16 3/16 3/16 1/16 of the parent square;\n"
        "1D 3/4 1/4) instead of the nearest-neighbour midpoint (fournier)",
    .dims = 3,
    .caps = NL_METHOD_MODEL,
    .options = options, .noptions = (int)(sizeof options / sizeof *options),
    .model_conflict = "give either --H or a power-law model, not both",
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
