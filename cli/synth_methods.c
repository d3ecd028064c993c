/* The methods of `noiselab synth`: planned, synthesised and described
 * through their descriptors (synth/method.h), then reported: flags, the
 * preview's range and the --json object of the methods that report more
 * than their method string. */
#include "synth.h"
#include "../core/autocorr.h"
#include "../core/field_stats.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/wk.h"
#include "../synth/cholesky.h"
#include "../synth/circulant.h"
#include "../synth/faulting.h"
#include "../synth/fft.h"
#include "../synth/lattice.h"
#include "../synth/midpoint.h"
#include "../synth/method.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void cli_synth_fft_describe(const nl_synth_fft_info *i, cli_synth_result *r)
{
    const nl_synth_fft_info info = *i;
    snprintf(r->method, sizeof r->method, "fft");
    if (info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        snprintf(r->flags, sizeof r->flags, "clamped");
    r->sd = sqrt(info.variance);
    r->report = json_pack("{s:f,s:f,s:f,s:I,s:f}", "variance", info.variance, "min_spectrum", info.min_lambda,
                          "max_spectrum", info.max_lambda, "clamped", (json_int_t)info.negatives, "clamp_error",
                          info.clamp_error);
}

void cli_synth_circulant_describe(const cli_synth_job *job, const nl_synth_circulant_info *i, cli_synth_result *r)
{
    const nl_synth_circulant_info info = *i;
    snprintf(r->method, sizeof r->method, "circulant:embedding=%zux%zux%zu", info.m[0], info.m[1], info.m[2]);
    int clamped = info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL, lost = fabs(info.variance_loss) > NL_SYNTH_CIRCULANT_LOSS_TOL;
    snprintf(r->flags, sizeof r->flags, "%s%s%s", clamped ? "clamped" : "", clamped && lost ? "," : "",
             lost ? "variance-changed" : "");
    double zero[3] = {0, 0, 0};
    r->sd = sqrt(nl_model_acf(job->m, job->dim, zero));
    if (!(r->sd > 0))
        r->sd = 1;
    r->report = json_pack("{s:[I,I,I],s:f,s:f,s:f,s:i}", "embedding", (json_int_t)info.m[0], (json_int_t)info.m[1],
                          (json_int_t)info.m[2], "min_eigenvalue", info.min_eigenvalue, "max_eigenvalue",
                          info.max_eigenvalue, "clamp_error", info.clamp_error, "doublings", info.doublings);
    /* the spectral models' loss to the embedding's frequency sampling (synth/circulant.h) */
    if (lost)
        json_object_set_new(r->report, "variance_loss", json_real(info.variance_loss));
}

static json_t *levels_report(const nl_subdiv_coeffs *c)
{
    json_t *a = json_array();
    for (int k = 0; k < c->levels; k++) {
        const nl_subdiv_level *l = &c->level[k];
        unsigned fl = 0;
        double v = 0;
        char buf[128];
        for (int j = 0; j < l->nclass; j++)
            fl |= l->cls[j].flags, v = fmax(v, l->cls[j].variance);
        cli_subdiv_flags(fl, buf, sizeof buf);
        json_t *o = json_pack("{s:i,s:f,s:i,s:f,s:s}", "level", k, "spacing", l->spacing, "N", l->N,
                              "max_variance", v, "flags", buf);
        if (l->filt) {
            json_object_set_new(o, "taps", json_integer(l->taps));
            json_object_set_new(o, "filter_error", json_real(l->filt_error));
        }
        json_array_append_new(a, o);
    }
    return a;
}

/* A method's report of its plan (impl: nl_method_plan_impl) and field. */
typedef void report_fn(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r);

static void fft_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    nl_synth_fft_info info;
    (void)job, (void)f;
    nl_synth_fft_plan_info(impl, &info);
    cli_synth_fft_describe(&info, r);
}

static void circulant_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    nl_synth_circulant_info info;
    (void)f;
    nl_synth_circulant_plan_info(impl, &info);
    cli_synth_circulant_describe(job, &info, r);
}

static void cholesky_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    double zero[3] = {0, 0, 0};
    (void)impl, (void)f;
    r->sd = sqrt(nl_model_acf(job->m, job->dim, zero));
}

static void subdiv_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    const nl_subdiv_coeffs *c = nl_subdiv_plan_coeffs(impl);
    nl_subdiv_info info;
    (void)f;
    nl_subdiv_plan_info(impl, &info);
    cli_subdiv_flags(c->flags, r->flags, sizeof r->flags);
    r->sd = sqrt(c->r0);
    r->report = json_pack("{s:f,s:f,s:o}", "spacing0", info.spacing0, "variance", c->r0, "levels",
                          levels_report(c));
    if (job->nonperiodic)
        json_object_set_new(r->report, "coarse_correlation", json_real(info.coarse_correlation));
}

static void midpoint_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    const nl_midpoint_method_plan *mp = impl;
    nl_subdiv_info info;
    (void)job;
    if (mp->miller) {
        r->sd = nl_field_rms(f) > 0 ? nl_field_rms(f) : 1;
        r->report = json_pack("{s:f,s:i,s:f,s:s}", "H", mp->H, "levels", mp->levels, "variance_scale", mp->vscale,
                              "interpolant", "miller");
        return;
    }
    nl_subdiv_plan_info(mp->plan, &info);
    r->sd = sqrt(info.variance);
    r->report = json_pack("{s:f,s:i,s:f}", "H", mp->H, "levels", info.levels, "variance_scale", mp->vscale);
}

static void faulting_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    const nl_method_value *d = nl_method_options_get(&job->opts, "density");
    double mean, var;
    (void)impl;
    nl_field_mean_var(f, &mean, &var);
    r->sd = sqrt(var) > 0 ? sqrt(var) : 1;
    /* the preview is centred on 0: shift the range by the mean */
    r->offset = mean;
    r->report = json_pack("{s:I,s:f}", "faults", (json_int_t)nl_synth_faulting_count(job->seed, d->d, f),
                          "density", d->d);
}

/* Flags: a clamped spectrum, and a kernel that loses more than
 * CLI_SPARSE_TRUNC_FLAG of its energy at the radius (the variance is then
 * R(0) less that fraction; the report gives it as truncated_energy). */
#define CLI_SPARSE_TRUNC_FLAG 1e-3

static void sparse_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    nl_synth_sparse_info info;
    int k = 0;
    (void)job, (void)f;
    nl_synth_sparse_plan_info(impl, &info);
    if (info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        k = snprintf(r->flags, sizeof r->flags, "clamped");
    if (info.truncated > CLI_SPARSE_TRUNC_FLAG)
        snprintf(r->flags + k, sizeof r->flags - (size_t)k, "%struncated=%.2g", k ? "," : "", info.truncated);
    r->sd = sqrt(info.variance);
    r->offset = info.mean;
    r->report = json_pack("{s:i,s:i,s:f,s:f,s:f,s:f}", "radius", info.radius, "cell", info.cell, "density",
                          info.density, "variance", info.variance, "excess_kurtosis", info.kurtosis, "truncated_energy",
                          info.truncated);
    if (info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        json_object_set_new(r->report, "clamp_error", json_real(info.clamp_error));
}

static void lattice_report(const cli_synth_job *job, void *impl, const nl_field *f, cli_synth_result *r)
{
    const nl_lattice_method_plan *lp = impl;
    const nl_synth_lattice_plan *p = &lp->perlin;
    (void)job;
    if (lp->wiener) {
        nl_synth_lattice_wiener_info info;
        nl_synth_lattice_wiener_plan_info(lp->plan, &info);
        if (info.negatives)
            snprintf(r->flags, sizeof r->flags, "clamped");
        r->sd = sqrt(info.variance);
        r->report = json_pack("{s:i,s:[I,I],s:f,s:f,s:f,s:i}", "cell", info.cell, "nodes", (json_int_t)info.nodes[0],
                              (json_int_t)info.nodes[1], "variance", info.variance, "mean_error_variance",
                              info.mean_error, "max_error_variance", info.max_error, "rank", info.rank);
        return;
    }
    json_t *oct = json_array();
    if (lp->grid_clamp_error > 0 || p->negatives)
        snprintf(r->flags, sizeof r->flags, "clamped");
    for (int o = 0; o < p->octaves; o++)
        json_array_append_new(oct, json_pack("{s:f,s:f,s:f,s:f}", "cell", p->cell[o], "weight", p->weight[o], "peak",
                                             p->peak[o], "leakage", p->leakage[o]));
    r->sd = nl_field_rms(f) > 0 ? nl_field_rms(f) : 1;
    r->report = json_pack("{s:o}", "octaves", oct);
    if (p->negatives)
        json_object_set_new(r->report, "clamp_error", json_real(p->clamp_error));
}

/* The reports beyond the method string, by method; a method without one is
 * previewed over its field's own range. */
static report_fn *find_report(const char *name)
{
    static const struct {
        const char *name;
        report_fn *fn;
    } reports[] = {{"fft", fft_report},           {"circulant", circulant_report}, {"cholesky", cholesky_report},
                   {"subdiv", subdiv_report},     {"midpoint", midpoint_report},   {"faulting", faulting_report},
                   {"sparse", sparse_report},     {"lattice", lattice_report}};
    for (size_t i = 0; i < sizeof reports / sizeof *reports; i++)
        if (!strcmp(reports[i].name, name))
            return reports[i].fn;
    return NULL;
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
    report_fn *report = find_report(job->method);
    /* files in HDF5 are read by the CLI's reader (cli/h5_main.c) */
    for (int k = 0; k < job->type->noptions; k++)
        if ((job->type->options[k].flags & NL_METHOD_FILE) && o.v[k].set && cli_is_h5(o.v[k].s))
            o.v[k].field = files[k] = cli_read_field(o.v[k].s, NULL);
    cli_check(nl_method_plan_alloc(job->type, job->m, &g, &o, &p));
    cli_check(execute(job, p, f));
    cli_check(nl_method_describe(p, r->method, sizeof r->method));
    if (report)
        report(job, nl_method_plan_impl(p), f, r);
    else
        r->sd = nl_field_rms(f) > 0 ? nl_field_rms(f) : 1;
    nl_method_plan_free(p);
    for (int k = 0; k < NL_METHOD_MAX_OPTIONS; k++)
        nl_field_free(files[k]);
}
