/* The methods of `noiselab synth`: plan, synthesise, report. */
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
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void cli_synth_fft_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_fft_plan *p;
    nl_synth_fft_info info;
    cli_check(nl_synth_fft_plan_alloc(job->m, job->dim, job->n, job->h, job->clamp ? NL_SYNTH_FFT_CLAMP : 0, &p));
    nl_synth_fft_plan_info(p, &info);
    cli_check(nl_synth_fft_execute(p, job->seed, f));
    nl_synth_fft_plan_free(p);
    cli_synth_fft_describe(&info, r);
}

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

static nl_field *seed_image(const cli_synth_job *job)
{
    nl_field *img;
    int st = nl_field_read(job->seed_image, &img, NULL);
    cli_check(st);
    if (img->dim != job->dim)
        cli_die(2, "--seed-image: %s is %dD, expected %dD like --size", job->seed_image, img->dim, job->dim);
    return img;
}

/* The plan for the job's options; the seed image, if any, in *img. */
static nl_subdiv_plan *subdiv_plan(const cli_synth_job *job, nl_field **img)
{
    nl_subdiv_options o;
    nl_subdiv_plan *p;
    nl_subdiv_options_default(&o);
    o.levels = job->levels;
    o.N = job->N < 0 ? 2 : job->N;
    o.tol = job->tol;
    o.stop = job->stop;
    o.nonperiodic = job->nonperiodic;
    o.allow_not_pd = job->clamp;
    o.random_nb = job->random_nb;
    o.displacements = job->displacements;
    o.taps = job->taps;
    *img = NULL;
    if (job->dim > 2)
        cli_die(2, "synth subdiv: expected a 1D or 2D --size, got %dD", job->dim);
    for (int a = 1; a < job->dim; a++)
        if (job->h[a] != job->h[0])
            cli_die(2, "--spacing: subdivision needs the same spacing on every axis, got %g and %g", job->h[0],
                    job->h[a]);
    if (job->seed_image) {
        *img = seed_image(job);
        cli_check(nl_subdiv_image_levels(job->dim, (*img)->n, job->n, job->levels, &o.levels));
        o.image = !job->nonperiodic;
    }
    cli_check(nl_subdiv_plan_alloc(job->m, job->dim, job->n, job->h[0], &o, &p));
    return p;
}

static void subdiv_describe(const cli_synth_job *job, const nl_subdiv_plan *p, cli_synth_result *r)
{
    const nl_subdiv_coeffs *c = nl_subdiv_plan_coeffs(p);
    nl_subdiv_info info;
    char nb[16] = "auto";
    int N = job->N < 0 ? 2 : job->N;
    size_t k;
    nl_subdiv_plan_info(p, &info);
    if (N)
        snprintf(nb, sizeof nb, "%d", N);
    k = (size_t)snprintf(r->method, sizeof r->method, "subdiv:levels=%d,neighborhood=%s,tol=%s%g%s%s",
                         info.levels, nb, job->stop == NL_SUBDIV_STOP_VARIANCE ? "variance:" : "", job->tol,
                         job->nonperiodic ? ",nonperiodic" : ",periodic", job->seed_image ? ",seed-image" : "");
    if (job->random_nb)
        k += (size_t)snprintf(r->method + k, sizeof r->method - k, ",random-neighborhoods=%d", job->random_nb);
    if (c->level[0].filt)
        k += (size_t)snprintf(r->method + k, sizeof r->method - k, ",displacements=correlated,taps=%d",
                              c->level[0].taps);
    if (job->nonperiodic)
        k += (size_t)snprintf(r->method + k, sizeof r->method - k, ",origin=%ld:%ld", job->origin[0],
                              job->origin[1]);
    if (job->seed_image)
        snprintf(r->method + k, sizeof r->method - k, "|seed-image=%s", job->seed_image);
    cli_subdiv_flags(c->flags, r->flags, sizeof r->flags);
    r->sd = sqrt(c->r0);
    r->report = json_pack("{s:f,s:f,s:o}", "spacing0", info.spacing0, "variance", c->r0, "levels",
                          levels_report(c));
    if (job->nonperiodic)
        json_object_set_new(r->report, "coarse_correlation", json_real(info.coarse_correlation));
}

/* The window origin of a slab: the job's origin moved s0 along the slowest axis. */
static void slab_origin(const cli_synth_job *job, long *o)
{
    o[0] = job->origin[0], o[1] = job->origin[1];
    o[job->dim - 1] += (long)job->s0;
}

/* Distributed: this process's rows s0 .. s0 + ns - 1 (none when ns = 0),
 * the same bits as the whole field's; the status agreed by every process. */
static int subdiv_slab(const cli_synth_job *job, const nl_subdiv_plan *p, const nl_field *img, nl_field *f)
{
    long o[2];
    int st = NL_OK;
    slab_origin(job, o);
    if (!job->ns)
        st = NL_OK;
    else if (job->nonperiodic)
        st = nl_subdiv_synth_window(nl_subdiv_plan_coeffs(p), job->seed, o, f);
    else if (img)
        st = nl_subdiv_plan_execute_image_slab(p, img, job->seed, job->s0, f);
    else
        st = nl_subdiv_plan_execute_slab(p, job->seed, job->s0, f);
    return cli_h5->agree(st);
}

void cli_synth_subdiv_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_field *img;
    nl_subdiv_plan *p = subdiv_plan(job, &img);
    int st;
    if (job->slab)
        st = subdiv_slab(job, p, img, f);
    else if (job->nonperiodic)
        st = nl_subdiv_plan_execute_window(p, job->seed, job->origin, f);
    else if (img)
        st = nl_subdiv_plan_execute_image(p, img, job->seed, f);
    else
        st = nl_subdiv_plan_execute(p, job->seed, f);
    cli_check(st);
    subdiv_describe(job, p, r);
    nl_field_free(img);
    nl_subdiv_plan_free(p);
}

void cli_synth_midpoint_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_subdiv_plan *p;
    nl_subdiv_info info;
    double H = job->H;
    int st;
    if (job->dim > 2)
        cli_die(2, "synth midpoint: expected a 1D or 2D --size, got %dD", job->dim);
    if (isnan(H) && (st = nl_subdiv_midpoint_hurst(job->m, job->dim, &H)))
        cli_die_status(st);
    if (job->interpolant && strcmp(job->interpolant, "fournier")) {
        if (strcmp(job->interpolant, "miller"))
            cli_die(2, "--interpolant: expected fournier or miller for midpoint, got \"%s\"", job->interpolant);
        int L = job->levels ? job->levels : nl_midpoint_miller_default_levels(job->dim, job->n);
        cli_check(nl_midpoint_miller(L, H, 1.0, job->vscale, job->seed, f));
        snprintf(r->method, sizeof r->method, "midpoint:H=%.17g,levels=%d,variance-scale=%.17g,interpolant=miller",
                 H, L, job->vscale);
        r->sd = nl_field_rms(f) > 0 ? nl_field_rms(f) : 1;
        r->report = json_pack("{s:f,s:i,s:f,s:s}", "H", H, "levels", L, "variance_scale", job->vscale,
                              "interpolant", "miller");
        return;
    }
    cli_check(nl_subdiv_plan_alloc_midpoint(job->dim, job->n, job->h[0], job->levels, H, 1.0, job->vscale, &p));
    cli_check(nl_subdiv_plan_execute(p, job->seed, f));
    nl_subdiv_plan_info(p, &info);
    snprintf(r->method, sizeof r->method, "midpoint:H=%.17g,levels=%d,variance-scale=%.17g", H, info.levels,
             job->vscale);
    r->sd = sqrt(info.variance);
    r->report = json_pack("{s:f,s:i,s:f}", "H", H, "levels", info.levels, "variance_scale", job->vscale);
    nl_subdiv_plan_free(p);
}

void cli_synth_circulant_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_circulant_plan *p;
    nl_synth_circulant_info info;
    cli_check(nl_synth_circulant_plan_alloc(job->m, job->dim, job->n, job->h, job->clamp ? NL_SYNTH_FFT_CLAMP : 0, 16,
                               &p));
    nl_synth_circulant_plan_info(p, &info);
    cli_check(nl_synth_circulant_execute(p, job->seed, f));
    nl_synth_circulant_plan_free(p);
    cli_synth_circulant_describe(job, &info, r);
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

void cli_synth_cholesky_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_cholesky_plan *p;
    double zero[3] = {0, 0, 0};
    cli_check(nl_synth_cholesky_plan_alloc(job->m, job->dim, job->n, job->h, &p));
    cli_check(nl_synth_cholesky_execute(p, job->seed, f));
    nl_synth_cholesky_plan_free(p);
    snprintf(r->method, sizeof r->method, "cholesky");
    r->sd = sqrt(nl_model_acf(job->m, job->dim, zero));
}

void cli_synth_faulting_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    size_t K;
    if (job->dim > 2)
        cli_die(2, "synth faulting: expected a 1D or 2D --size, got %dD", job->dim);
    cli_check(nl_synth_faulting(job->seed, job->density, f, &K));
    snprintf(r->method, sizeof r->method, "faulting:density=%.17g", job->density);
    double mean, var;
    nl_field_mean_var(f, &mean, &var);
    r->sd = sqrt(var) > 0 ? sqrt(var) : 1;
    /* the preview is centred on 0: shift the range by the mean */
    r->offset = mean;
    r->report = json_pack("{s:I,s:f}", "faults", (json_int_t)K, "density", job->density);
}

/* Flags: a clamped spectrum, and a kernel that loses more than
 * CLI_SPARSE_TRUNC_FLAG of its energy at the radius (the variance is then
 * R(0) less that fraction; the report gives it as truncated_energy). */
#define CLI_SPARSE_TRUNC_FLAG 1e-3

static void sparse_flags(const nl_synth_sparse_info *info, char *flags, size_t size)
{
    int k = 0;
    if (info->clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        k = snprintf(flags, size, "clamped");
    if (info->truncated > CLI_SPARSE_TRUNC_FLAG)
        snprintf(flags + k, size - (size_t)k, "%struncated=%.2g", k ? "," : "", info->truncated);
}

/* A model kernel.  The kernel's FFT grid depends on whether the radius was
 * automatic, and a field records the radius it used: regenerating (--from),
 * the automatic radius is tried first and kept when it is the recorded
 * one, so that the field comes back bit for bit. */
static int sparse_model_plan(const cli_synth_job *job, nl_synth_sparse_plan **p)
{
    unsigned fl = job->clamp ? NL_SYNTH_FFT_CLAMP : 0;
    if (job->from && job->radius) {
        nl_synth_sparse_info info;
        if (!nl_synth_sparse_plan_model_flags(job->m, job->dim, job->h, 0, job->cell, job->density, fl, p)) {
            nl_synth_sparse_plan_info(*p, &info);
            if (info.radius == job->radius)
                return NL_OK;
            nl_synth_sparse_plan_free(*p);
        }
    }
    return nl_synth_sparse_plan_model_flags(job->m, job->dim, job->h, job->radius, job->cell, job->density, fl, p);
}

void cli_synth_sparse_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_sparse_plan *p;
    nl_synth_sparse_info info;
    int st, given = (job->m != NULL) + (job->kernel != NULL) + (job->exemplar != NULL);
    if (job->dim > 2)
        cli_die(2, "synth sparse: expected a 1D or 2D --size, got %dD", job->dim);
    if (given != 1)
        cli_die(2, "synth sparse: expected exactly one kernel: --acf/--spectrum SPEC, --kernel EXPR or --exemplar FILE");
    /* an explicit radius: the work is known before the kernel is made */
    if (job->radius || job->kernel)
        cli_check(nl_synth_sparse_check_work(job->dim, job->n, job->radius ? job->radius : 16, job->cell,
                                             job->density, job->angle != NULL));
    if (job->m)
        st = sparse_model_plan(job, &p);
    else if (job->kernel)
        st = nl_synth_sparse_plan_expr(job->kernel, job->dim, job->radius ? job->radius : 16, job->cell, job->density,
                                    &p);
    else {
        nl_field *img = cli_read_field(job->exemplar, NULL);
        if (job->dim != 2)
            cli_die(2, "--exemplar: expected a 2D image and a 2D --size, got %dD %s and a %dD --size", img->dim,
                    job->exemplar, job->dim);
        st = nl_synth_sparse_plan_exemplar(img, job->radius, job->cell, job->density, &p);
        nl_field_free(img);
    }
    cli_check(st);
    if (job->angle && (st = nl_synth_sparse_set_angle(p, job->angle)))
        cli_die_status(st);
    nl_synth_sparse_plan_info(p, &info);
    if (job->slab) {
        long o[2];
        slab_origin(job, o);
        st = !job->ns ? NL_OK
             : job->wrap ? nl_synth_sparse_execute_slab(p, job->seed, 1, job->n, job->s0, f)
                         : nl_synth_sparse_execute(p, job->seed, 0, o, f);
        cli_check(cli_h5->agree(st));
    } else {
        cli_check(nl_synth_sparse_execute(p, job->seed, job->wrap, job->wrap ? NULL : job->origin, f));
    }
    nl_synth_sparse_plan_free(p);
    /* expression-valued keys follow '|', as they may hold commas */
    char org[64] = "";
    if (!job->wrap && (job->origin[0] || job->origin[1]))
        snprintf(org, sizeof org, ",origin=%ld:%ld", job->origin[0], job->origin[1]);
    snprintf(r->method, sizeof r->method, "sparse:radius=%d,cell=%d,density=%.17g%s%s%s%s%s%s%s", info.radius,
             info.cell, info.density, job->wrap ? ",wrap" : org, job->kernel ? "|kernel=" : "",
             job->kernel ? job->kernel : "", job->exemplar ? "|exemplar=" : "", job->exemplar ? job->exemplar : "",
             job->angle ? "|angle=" : "", job->angle ? job->angle : "");
    sparse_flags(&info, r->flags, sizeof r->flags);
    r->sd = sqrt(info.variance);
    r->offset = info.mean;
    r->report = json_pack("{s:i,s:i,s:f,s:f,s:f,s:f}", "radius", info.radius, "cell", info.cell, "density",
                          info.density, "variance", info.variance, "excess_kurtosis", info.kurtosis, "truncated_energy",
                          info.truncated);
    if (info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        json_object_set_new(r->report, "clamp_error", json_real(info.clamp_error));
}

static void lattice_check_pd(const cli_synth_job *job, cli_synth_result *r)
{
    double err;
    cli_check(nl_synth_lattice_check_grid(job->m, job->dim, job->n, job->clamp, &err));
    if (err > 0)
        snprintf(r->flags, sizeof r->flags, "clamped");
}

/* --interpolant wiener: one lattice of the target's covariance, kriged. */
static void lattice_wiener_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_lattice_wiener_plan *p;
    nl_synth_lattice_wiener_info info;
    int cell = job->cell ? job->cell : 4;
    if (job->octaves)
        cli_die(2, "--octaves: the Wiener lattice has one lattice (no octaves), got --octaves %d", job->octaves);
    cli_check(nl_synth_lattice_wiener_plan_alloc(job->m, job->dim, job->n, cell,
                                                 job->clamp ? NL_SYNTH_LATTICE_CLAMP : 0, &p));
    nl_synth_lattice_wiener_plan_info(p, &info);
    cli_check(nl_synth_lattice_wiener_execute(p, job->seed, f, NULL));
    nl_synth_lattice_wiener_plan_free(p);
    snprintf(r->method, sizeof r->method, "lattice:cell=%d,interpolant=wiener", cell);
    if (info.negatives)
        snprintf(r->flags, sizeof r->flags, "clamped");
    r->sd = sqrt(info.variance);
    r->report = json_pack("{s:i,s:[I,I],s:f,s:f,s:f,s:i}", "cell", cell, "nodes", (json_int_t)info.nodes[0],
                          (json_int_t)info.nodes[1], "variance", info.variance, "mean_error_variance",
                          info.mean_error, "max_error_variance", info.max_error, "rank", info.rank);
}

void cli_synth_lattice_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    if (job->interpolant && strcmp(job->interpolant, "perlin")) {
        if (strcmp(job->interpolant, "wiener"))
            cli_die(2, "--interpolant: expected perlin or wiener for lattice, got \"%s\"", job->interpolant);
        if (job->dim > 2)
            cli_die(2, "synth lattice: expected a 1D or 2D --size, got %dD", job->dim);
        lattice_wiener_run(job, f, r);
        return;
    }
    nl_synth_lattice_plan p;
    double c0 = job->cell ? job->cell : nl_synth_lattice_default_cell(f->n);
    int O = job->octaves, st;
    json_t *oct = json_array();
    if (job->dim > 2)
        cli_die(2, "synth lattice: expected a 1D or 2D --size, got %dD", job->dim);
    if (!O)
        O = nl_synth_lattice_default_octaves(c0);
    lattice_check_pd(job, r);
    if ((st = nl_synth_lattice_plan_init_flags(job->m, job->dim, c0, O, job->clamp ? NL_SYNTH_LATTICE_CLAMP : 0, &p)) ||
        (st = nl_synth_lattice_execute(&p, job->seed, f)))
        cli_die_status(st);
    if (p.negatives)
        snprintf(r->flags, sizeof r->flags, "clamped");
    for (int o = 0; o < p.octaves; o++)
        json_array_append_new(oct, json_pack("{s:f,s:f,s:f,s:f}", "cell", p.cell[o], "weight", p.weight[o], "peak",
                                             p.peak[o], "leakage", p.leakage[o]));
    snprintf(r->method, sizeof r->method, "lattice:cell=%.17g,octaves=%d", c0, O);
    r->sd = nl_field_rms(f) > 0 ? nl_field_rms(f) : 1;
    r->report = json_pack("{s:o}", "octaves", oct);
    if (p.negatives)
        json_object_set_new(r->report, "clamp_error", json_real(p.clamp_error));
}
