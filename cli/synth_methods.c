/* The methods of `noiselab synth`: planned, synthesised, described and
 * reported through their descriptors (synth/method.h): flags, the
 * preview's range and the --json object of the method's report. */
#include "synth.h"
#include "../core/nl_error.h"
#include "../synth/method.h"

#include <string.h>

void cli_synth_take_report(const nl_method_report *mr, cli_synth_result *r)
{
    snprintf(r->flags, sizeof r->flags, "%s", mr->flags);
    r->sd = mr->sd;
    r->offset = mr->offset;
    r->report = mr->json[0] ? json_loads(mr->json, 0, NULL) : NULL;
}

/* Distributed: this process's rows s0 .. s0 + ns - 1 (none when ns = 0),
 * the same bits as the whole field's; the status agreed by every process. */
static int execute(const cli_synth_job *job, nl_method_plan *p, nl_field *f)
{
    if (!job->slab)
        return nl_method_execute(p, job->seed, f);
    return cli_h5->agree(job->ns ? nl_method_execute_slab(p, job->seed, job->s0, f) : NL_OK);
}

void cli_synth_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_method_grid g = {job->dim, {job->n[0], job->n[1], job->n[2]}, {job->h[0], job->h[1], job->h[2]},
                        {job->origin[0], job->origin[1]}};
    nl_method_options o = job->opts;
    nl_field *files[NL_METHOD_MAX_OPTIONS] = {0};
    nl_method_plan *p;
    static nl_method_report mr;
    /* files in HDF5 are read by the CLI's reader (cli/h5_main.c) */
    for (int k = 0; k < job->type->noptions; k++)
        if ((job->type->options[k].flags & NL_METHOD_FILE) && o.v[k].set && cli_is_h5(o.v[k].s))
            o.v[k].field = files[k] = cli_read_field(o.v[k].s, NULL);
    cli_check(nl_method_plan_alloc(job->type, job->m, &g, &o, &p));
    cli_check(execute(job, p, f));
    cli_check(nl_method_describe(p, r->method, sizeof r->method));
    cli_check(nl_method_report_of(p, job->m, job->seed, f, &mr));
    cli_synth_take_report(&mr, r);
    nl_method_plan_free(p);
    for (int k = 0; k < NL_METHOD_MAX_OPTIONS; k++)
        nl_field_free(files[k]);
}
