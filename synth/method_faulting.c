/* faulting as a method descriptor (synth/method.h over synth/faulting.h).
 * Its nl_method_plan_impl is NULL: the method needs no plan. */
#include "method_internal.h"
#include "../core/nl_error.h"
#include "faulting.h"
#include "../core/field_stats.h"

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

/* The faults the field has; its preview centred on its mean. */
static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    double mean, var, d = nl_method_opt_double(&p->opt, "density");
    (void)m;
    if (!f)
        return nl_method_json(r, "{\"density\": %s}", NL_METHOD_REAL(d));
    nl_field_mean_var(f, &mean, &var);
    r->sd = sqrt(var) > 0 ? sqrt(var) : 1;
    r->offset = mean;
    return nl_method_json(r, "{\"faults\": %zu, \"density\": %s}", nl_synth_faulting_count(seed, d, f),
                          NL_METHOD_REAL(d));
}

const nl_method_type nl_method_faulting = {
    .name = "faulting",
    .summary = "Poisson faulting (Mandelbrot): random steps in 1D, random lines in 2D; no model",
    .noun = "Poisson faulting",
    .help =
        "Poisson faulting (Mandelbrot): random steps in 1D, random lines in 2D;\n"
        "--density D faults per sample (1D) or lines per (nx + ny) (2D); no model:\n"
        "the spectrum is f^-2 (1D), k^-3 radially (2D)",
    .dims = 3,
    .caps = NL_METHOD_NO_MODEL,
    .options = options, .noptions = (int)(sizeof options / sizeof *options),
    .model_conflict = "takes no model (its spectrum is f^-2); got --acf/--spectrum",
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
