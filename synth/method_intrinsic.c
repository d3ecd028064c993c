/* intrinsic as a method descriptor (synth/method.h over synth/intrinsic.h).
 * Its nl_method_plan_impl is the nl_synth_intrinsic_plan. */
#include "method_internal.h"
#include "../core/nl_error.h"
#include "intrinsic.h"

#include <math.h>
#include <stdlib.h>

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    nl_method_plan *p = nl_method_plan_head(sizeof *p, g, o);
    int st = p ? nl_synth_intrinsic_plan_alloc(m, g->dim, g->n, g->h, (nl_synth_intrinsic_plan **)&p->impl)
               : NL_ENOMEM;
    if (st)
        nl_method_plan_free(p), p = NULL;
    *out = p;
    return st;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    return nl_synth_intrinsic_execute(p->impl, seed, f);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    nl_synth_intrinsic_info info;
    size_t len = 0;
    nl_synth_intrinsic_plan_info(p->impl, &info);
    return nl_method_append(buf, size, &len, "intrinsic:embedding=%zux%zu", info.m[0], info.m[1]);
}

static void plan_free(nl_method_plan *p)
{
    nl_synth_intrinsic_plan_free(p->impl);
    free(p);
}

/* The preview's scale: sqrt(gamma) at the grid's largest lag (the field
 * is 0 at the origin and has no variance of its own). */
static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    nl_synth_intrinsic_info i;
    double lag[3] = {0, 0, 0};
    (void)seed;
    nl_synth_intrinsic_plan_info(p->impl, &i);
    for (int a = 0; a < p->grid.dim; a++)
        lag[a] = (double)(p->grid.n[a] - 1) * p->grid.h[a];
    r->sd = sqrt(nl_model_variogram(m, p->grid.dim, lag));
    if (!(r->sd > 0) || !isfinite(r->sd))
        r->sd = 1;
    if (f) {
        double s = 0;
        for (size_t k = 0; k < f->count; k++)
            s += f->data[k];
        r->offset = s / (double)f->count;
    }
    return nl_method_json(r, "{\"embedding\": [%zu, %zu], \"min_eigenvalue\": %s, \"max_eigenvalue\": %s, "
                          "\"cutoff\": %s, \"c2\": %s, \"diameter\": %s}", i.m[0], i.m[1],
                          NL_METHOD_REAL(i.min_eigenvalue), NL_METHOD_REAL(i.max_eigenvalue),
                          NL_METHOD_REAL(i.cutoff), NL_METHOD_REAL(i.c2), NL_METHOD_REAL(i.diameter));
}

const nl_method_type nl_method_intrinsic = {
    .name = "intrinsic",
    .summary = "exact intrinsic field (power variogram, fractional Brownian) by cut-off embedding",
    .noun = "intrinsic embedding",
    .help =
        "exact field of an intrinsic model (powvar: gamma = c |h|^alpha, fractional\n"
        "Brownian field with H = alpha/2) on a 1D or 2D grid: 1D by circulant\n"
        "embedding of its increments (Davies-Harte) summed, 2D by Stein's (2002)\n"
        "cut-off embedding plus a random plane; the field is 0 at the origin.\n"
        "Only intrinsic models; isotropic in 2D",
    .dims = 3,
    /* it represents a nugget too, but NL_METHOD_NUGGET lists the methods a
     * stationary model with a nugget is sent to, which this one refuses */
    .caps = NL_METHOD_MODEL | NL_METHOD_EXACT | NL_METHOD_INTRINSIC,
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
