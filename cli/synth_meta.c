/* What a synthesised field records of itself: its provenance (the EXR and
 * HDF5 attributes, TSV comments) and synth --json's object. */
#include "synth.h"
#include "../core/provenance.h"
#include "../core/version.h"

#include <stdio.h>
#include <string.h>

void cli_synth_fill_meta(const cli_synth_job *job, const nl_field *f, const cli_synth_result *res, nl_meta *meta)
{
    nl_provenance p;
    nl_provenance_init(&p);
    snprintf(p.model, sizeof p.model, "%s", job->m ? nl_model_spec(job->m) : "");
    snprintf(p.method, sizeof p.method, "%s", res->method);
    snprintf(p.flags, sizeof p.flags, "%s", res->flags);
    snprintf(p.version, sizeof p.version, "%s", nl_version());
    p.seed = job->seed, p.has_seed = 1;
    p.dim = p.nspacing = job->dim;
    for (int a = 0; a < job->dim; a++)
        p.n[a] = job->n[a], p.h[a] = f->h[a];
    if (job->nonperiodic || (!job->wrap && (job->origin[0] || job->origin[1]))) /* a window: where it starts */
        p.norigin = job->dim == 1 ? 1 : 2, p.origin[0] = job->origin[0], p.origin[1] = job->origin[1];
    cli_check(nl_provenance_format(&p, meta));
}

json_t *cli_synth_json(const cli_synth_job *job, const nl_meta *meta, const cli_synth_result *res)
{
    json_t *o = json_pack("{s:s,s:s,s:I,s:s,s:s}", "model", meta->model, "method", meta->method, "seed",
                          (json_int_t)job->seed, "size", meta->size, "spacing", meta->spacing);
    /* JSON integers here are signed 64-bit: a larger seed is given as its decimal string */
    if (job->seed > (uint64_t)INT64_MAX)
        json_object_set_new(o, "seed", json_string(meta->seed));
    json_t *fl = json_array();
    const char *p = res->flags;
    while (*p) {
        size_t l = strcspn(p, ",");
        json_array_append_new(fl, json_stringn(p, l));
        p += l + (p[l] == ',');
    }
    json_object_set_new(o, "flags", fl);
    if (res->report)
        json_object_update(o, res->report);
    return o;
}
