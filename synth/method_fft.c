/* fft as a method descriptor (synth/method.h over synth/fft.h).  Its
 * nl_method_plan_impl is the nl_synth_fft_plan. */
#include "method_internal.h"
#include "../core/nl_error.h"
#include "fft_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int plan(const nl_model *m, const nl_method_grid *g, const nl_method_options *o, nl_method_plan **out)
{
    nl_method_plan *p = nl_method_plan_head(sizeof *p, g, o);
    unsigned fl = o->flags & NL_METHOD_OPT_CLAMP ? NL_SYNTH_FFT_CLAMP : 0;
    int st = p ? nl_synth_fft_plan_alloc(m, g->dim, g->n, g->h, fl, (nl_synth_fft_plan **)&p->impl) : NL_ENOMEM;
    if (st)
        nl_method_plan_free(p), p = NULL;
    *out = p;
    return st;
}

static int execute(nl_method_plan *p, uint64_t seed, nl_field *f) { return nl_synth_fft_execute(p->impl, seed, f); }

static int describe(const nl_method_plan *p, char *buf, size_t size)
{
    size_t len = 0;
    (void)p;
    return nl_method_append(buf, size, &len, "fft");
}

int nl_synth_fft_report(const nl_synth_fft_info *i, nl_method_report *r)
{
    snprintf(r->method, sizeof r->method, "fft");
    if (i->clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        snprintf(r->flags, sizeof r->flags, "clamped");
    r->sd = sqrt(i->variance);
    r->json[0] = '\0';
    return nl_method_json(r, "{\"variance\": %s, \"min_spectrum\": %s, \"max_spectrum\": %s, \"clamped\": %zu, "
                          "\"clamp_error\": %s}", NL_METHOD_REAL(i->variance), NL_METHOD_REAL(i->min_lambda),
                          NL_METHOD_REAL(i->max_lambda), i->negatives, NL_METHOD_REAL(i->clamp_error));
}

static int report(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f, nl_method_report *r)
{
    nl_synth_fft_info info;
    (void)m, (void)seed, (void)f;
    nl_synth_fft_plan_info(p->impl, &info);
    return nl_synth_fft_report(&info, r);
}

static void plan_free(nl_method_plan *p)
{
    nl_synth_fft_plan_free(p->impl);
    free(p);
}

const nl_method_type nl_method_fft = {
    .name = "fft",
    .summary = "periodic Fourier synthesis: white noise filtered by the square root of the model's spectrum",
    .noun = "Fourier synthesis",
    .help =
        "periodic Fourier synthesis: white noise filtered by the square root of\n"
        "the model's spectrum on the periodic grid; Gaussian, zero ensemble mean,\n"
        "variance R(0), covariance exactly the model's R sampled on the torus.\n"
        "The same seed and size give the same white noise for every model.",
    .dims = 7,
    .caps = NL_METHOD_MODEL | NL_METHOD_PERIODIC | NL_METHOD_DISTRIBUTED | NL_METHOD_CONDITIONABLE |
            NL_METHOD_EXACT | NL_METHOD_CLAMP | NL_METHOD_TORUS | NL_METHOD_VALIDATED | NL_METHOD_NUGGET,
    .plan = plan, .execute = execute, .describe = describe, .report = report, .free = plan_free,
};
