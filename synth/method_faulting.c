/* faulting as a method descriptor (synth/method.h over synth/faulting.h).
 * Its nl_method_plan_impl is NULL: the method needs no plan. */
#include "method_internal.h"
#include "../core/nl_error.h"
#include "faulting.h"

#include <math.h>
#include <stdlib.h>

static const nl_method_option options[] = {
    {"density", NL_METHOD_DOUBLE, NL_METHOD_OPEN, 0, HUGE_VAL, NULL, "a positive number", "1",
     "faults per sample (1D) or lines per (nx + ny) (2D)"},
};

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    (void)m;
    *out = nl_method_plan_head(sizeof **out, g, o);
    return *out ? NL_OK : NL_ENOMEM;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f)
{
    size_t K;
    return nl_synth_faulting(seed, nl_method_opt_double(&p->opt, "density"), f, &K);
}

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    size_t len = 0;
    return nl_method_append(buf, size, &len, "faulting:density=%.17g", nl_method_opt_double(&p->opt, "density"));
}

static void plan_free(nl_method_plan *p) { free(p); }

const nl_method_type nl_method_faulting = {
    .name = "faulting",
    .summary = "Poisson faulting (Mandelbrot): random steps in 1D, random lines in 2D; no model",
    .help =
        "Poisson faulting (Mandelbrot): random steps in 1D, random lines in 2D;\n"
        "--density D faults per sample (1D) or lines per (nx + ny) (2D); no model:\n"
        "the spectrum is f^-2 (1D), k^-3 radially (2D)",
    .dims = 3,
    .caps = NL_METHOD_NO_MODEL,
    .options = options, .noptions = (int)(sizeof options / sizeof *options),
    .model_conflict = "takes no model (its spectrum is f^-2); got --acf/--spectrum",
    .plan = plan, .execute = execute, .describe = describe, .free = plan_free,
};
