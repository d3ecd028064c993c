/* cholesky as a method descriptor (synth/method.h over synth/cholesky.h).
 * Its nl_method_plan_impl is the nl_synth_cholesky_plan, which holds its
 * workspace: one execute at a time per plan. */
#include "method_internal.h"
#include "../core/nl_error.h"
#include "cholesky.h"

#include <math.h>
#include <stdlib.h>

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    nl_method_plan *p = nl_method_plan_head(sizeof *p, g, o);
    int st = p ? nl_synth_cholesky_plan_alloc(m, g->dim, g->n, g->h, (nl_synth_cholesky_plan **)&p->impl)
               : NL_ENOMEM;
    if (st)
        nl_method_plan_free(p), p = NULL;
    *out = p;
    return st;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    return nl_synth_cholesky_execute(p->impl, seed, f);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    size_t len = 0;
    (void)p;
    return nl_method_append(buf, size, &len, "cholesky");
}

static void plan_free(nl_method_plan *p)
{
    nl_synth_cholesky_plan_free(p->impl);
    free(p);
}

static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    const double zero[3] = {0, 0, 0};
    (void)seed, (void)f;
    r->sd = sqrt(nl_model_acf(m, p->grid.dim, zero));
    return NL_OK;
}

const nl_method_type nl_method_cholesky = {
    .name = "cholesky",
    .summary = "direct simulation by the Cholesky factor of the covariance matrix (exact, small grids)",
    .noun = "Cholesky factorization",
    .help =
        "direct simulation by the Cholesky factor of the covariance matrix; exact,\n"
        "O(N^3), at most 8192 samples: the ground truth for small grids",
    .dims = 7,
    .caps = NL_METHOD_MODEL | NL_METHOD_EXACT | NL_METHOD_SERIAL | NL_METHOD_NUGGET,
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
