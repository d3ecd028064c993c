/* What a synthesised field records of itself: its provenance (the EXR and
 * HDF5 attributes, TSV comments) and synth --json's object. */
#include "synth.h"
#include "../core/version.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

void cli_synth_fill_meta(const cli_synth_job *job, const nl_field *f, const cli_synth_result *res, nl_meta *meta)
{
    memset(meta, 0, sizeof *meta);
    snprintf(meta->model, sizeof meta->model, "%s", job->m ? nl_model_spec(job->m) : "");
    snprintf(meta->method, sizeof meta->method, "%s", res->method);
    snprintf(meta->flags, sizeof meta->flags, "%s", res->flags);
    snprintf(meta->seed, sizeof meta->seed, "%" PRIu64, job->seed);
    snprintf(meta->version, sizeof meta->version, "%s", nl_version());
    for (int a = 0, k = 0, l = 0; a < job->dim; a++) {
        k += snprintf(meta->spacing + k, sizeof meta->spacing - (size_t)k, "%s%.17g", a ? "," : "", f->h[a]);
        l += snprintf(meta->size + l, sizeof meta->size - (size_t)l, "%s%zu", a ? "x" : "", job->n[a]);
    }
    if (job->nonperiodic || (!job->wrap && (job->origin[0] || job->origin[1]))) /* a window: where it starts */
        snprintf(meta->origin, sizeof meta->origin, job->dim == 1 ? "%ld" : "%ld,%ld", job->origin[0],
                 job->origin[1]);
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
