/* lattice as a method descriptor (synth/method.h over synth/lattice.h).
 * Its nl_method_plan_impl is an nl_lattice_method_plan. */
#include "method_internal.h"
#include "lattice.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    nl_method_plan head;      /* impl: &lp */
    nl_lattice_method_plan lp;/* Perlin or Wiener */
} lattice_plan;

/* The Wiener lattice's default node spacing. */
#define WIENER_CELL 4

static const nl_method_option options[] = {
    {"cell", NL_METHOD_INT, 0, 1, 2147483647, NULL, NULL, NULL,
     "largest lattice cell (Perlin, default size/4) or node spacing (Wiener, default 4)"},
    {"octaves", NL_METHOD_INT, 0, 1, 16, NULL, NULL, NULL, "octaves (default: down to cell 2)"},
    {"interpolant", NL_METHOD_CHOICE, 0, 0, 0, "perlin|wiener", "perlin or wiener for lattice", "perlin",
     "Perlin gradient noise over octaves, or one Wiener-interpolated lattice"},
};

static int plan_wiener(const nl_model *m, const nl_method_grid *g, const nl_method_options *o,
                       nl_lattice_method_plan *lp)
{
    unsigned fl = o->flags & NL_METHOD_OPT_CLAMP ? NL_SYNTH_LATTICE_CLAMP : 0;
    int cell = nl_method_opt_set(o, "cell") ? (int)nl_method_opt_int(o, "cell") : WIENER_CELL;
    if (nl_method_opt_set(o, "octaves"))
        return NL_ERROR(NL_EINVAL, "--octaves: the Wiener lattice has one lattice (no octaves), got --octaves %ld",
                        nl_method_opt_int(o, "octaves"));
    lp->wiener = 1;
    lp->cell0 = cell;
    return nl_synth_lattice_wiener_plan_alloc(m, g->dim, g->n, cell, fl, &lp->plan);
}

static int plan_perlin(const nl_model *m, const nl_method_grid *g, const nl_method_options *o,
                       nl_lattice_method_plan *lp)
{
    unsigned fl = o->flags & NL_METHOD_OPT_CLAMP ? NL_SYNTH_LATTICE_CLAMP : 0;
    int st;
    lp->cell0 = nl_method_opt_set(o, "cell") ? (double)nl_method_opt_int(o, "cell")
                                             : nl_synth_lattice_default_cell(g->n);
    lp->octaves = nl_method_opt_set(o, "octaves") ? (int)nl_method_opt_int(o, "octaves")
                                                   : nl_synth_lattice_default_octaves(lp->cell0);
    if ((st = nl_synth_lattice_check_grid(m, g->dim, g->n, fl, &lp->grid_clamp_error)))
        return st;
    return nl_synth_lattice_plan_init(m, g->dim, lp->cell0, lp->octaves, fl, &lp->perlin);
}

static void plan_free(nl_method_plan *p)
{
    nl_synth_lattice_wiener_plan_free(((lattice_plan *)p)->lp.plan);
    free(p);
}

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    lattice_plan *p = (lattice_plan *)nl_method_plan_head(sizeof *p, g, o);
    int st;
    *out = NULL;
    if (!p)
        return NL_ENOMEM;
    p->head.impl = &p->lp;
    st = nl_method_opt_int(o, "interpolant") == 1 ? plan_wiener(m, g, o, &p->lp) : plan_perlin(m, g, o, &p->lp);
    if (st)
        plan_free(&p->head);
    else
        *out = &p->head;
    return st;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    const nl_lattice_method_plan *lp = p->impl;
    if (lp->wiener)
        return nl_synth_lattice_wiener_execute(lp->plan, seed, f, NULL);
    return nl_synth_lattice_execute(&lp->perlin, seed, f);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    const nl_lattice_method_plan *lp = p->impl;
    size_t len = 0;
    if (lp->wiener)
        return nl_method_append(buf, size, &len, "lattice:cell=%d,interpolant=wiener", (int)lp->cell0);
    return nl_method_append(buf, size, &len, "lattice:cell=%.17g,octaves=%d", lp->cell0, lp->octaves);
}

static int report_wiener(const nl_lattice_method_plan *lp, nl_method_report *r)
{
    nl_synth_lattice_wiener_info i;
    nl_synth_lattice_wiener_plan_info(lp->plan, &i);
    if (i.negatives)
        snprintf(r->flags, sizeof r->flags, "clamped");
    r->sd = sqrt(i.variance);
    return nl_method_json(r, "{\"cell\": %d, \"nodes\": [%zu, %zu], \"variance\": %s, \"mean_error_variance\": %s, "
                          "\"max_error_variance\": %s, \"rank\": %d}", i.cell, i.nodes[0], i.nodes[1],
                          NL_METHOD_REAL(i.variance), NL_METHOD_REAL(i.mean_error), NL_METHOD_REAL(i.max_error),
                          i.rank);
}

/* Perlin: each octave's weight and leakage; the preview over the field's own range. */
static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    const nl_lattice_method_plan *lp = p->impl;
    const nl_synth_lattice_plan *pp = &lp->perlin;
    int st;
    (void)m, (void)seed, (void)f;
    if (lp->wiener)
        return report_wiener(lp, r);
    if (lp->grid_clamp_error > 0 || pp->negatives)
        snprintf(r->flags, sizeof r->flags, "clamped");
    st = nl_method_json(r, "{\"octaves\": [");
    for (int o = 0; o < pp->octaves && !st; o++)
        st = nl_method_json(r, "%s{\"cell\": %s, \"weight\": %s, \"peak\": %s, \"leakage\": %s}", o ? ", " : "",
                            NL_METHOD_REAL(pp->cell[o]), NL_METHOD_REAL(pp->weight[o]), NL_METHOD_REAL(pp->peak[o]),
                            NL_METHOD_REAL(pp->leakage[o]));
    if (!st)
        st = nl_method_json(r, "]");
    if (!st && pp->negatives)
        st = nl_method_json(r, ", \"clamp_error\": %s", NL_METHOD_REAL(pp->clamp_error));
    return st ? st : nl_method_json(r, "}");
}

const nl_method_type nl_method_lattice = {
    .name = "lattice",
    .summary = "interpolated noise lattice (Perlin gradient noise) summed over octaves",
    .noun = "lattice noise",
    .help =
        "interpolated noise lattice (Perlin gradient noise) summed over octaves,\n"
        "weighted to the target spectrum's power in each octave's band; --cell C\n"
        "largest lattice cell (default size/4), --octaves O (default: down to cell\n"
        "2); the report gives each octave's weight and its low-frequency leakage;\n"
        "--interpolant wiener: one lattice of the target's own covariance (FFT on\n"
        "the lattice), every sample its simple-kriging (Wiener) estimate from the\n"
        "4 (1D) or 4x4 nearest nodes; --cell C the node spacing (default 4)",
    .dims = 3,
    .caps = NL_METHOD_MODEL | NL_METHOD_CLAMP,
    .options = options, .noptions = (int)(sizeof options / sizeof *options),
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
