/* The methods of `noiselab synth`: plan, synthesise, report. */
#include "synth.h"
#include "../core/autocorr.h"
#include "../core/nl_error.h"
#include "../synth/cholesky.h"
#include "../synth/circulant.h"
#include "../synth/faulting.h"
#include "../synth/fft.h"
#include "../synth/lattice.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void cli_synth_fft_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_fft_plan *p;
    nl_synth_fft_info info;
    int st;
    if ((st = nl_synth_fft_plan_alloc(job->m, job->dim, job->n, job->h, job->clamp ? NL_SYNTH_FFT_CLAMP : 0, &p)))
        cli_die_status(st);
    nl_synth_fft_plan_info(p, &info);
    if ((st = nl_synth_fft_execute(p, job->seed, f)))
        cli_die_status(st);
    nl_synth_fft_plan_free(p);
    snprintf(r->method, sizeof r->method, "fft");
    if (info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        snprintf(r->flags, sizeof r->flags, "clamped");
    r->sd = sqrt(info.variance);
    r->report = json_pack("{s:f,s:f,s:f,s:I,s:f}", "variance", info.variance, "min_spectrum", info.min_lambda,
                          "max_spectrum", info.max_lambda, "clamped", (json_int_t)info.negatives, "clamp_error",
                          info.clamp_error);
}

/* Largest L with every size divisible by 2^L and at least `min` coarse samples. */
static int default_levels(const cli_synth_job *job, long min)
{
    int L = 0;
    for (;;) {
        int ok = 1;
        for (int a = 0; a < job->dim; a++)
            if ((long)job->n[a] % (2L << L) != 0 || (long)job->n[a] / (2L << L) < min)
                ok = 0;
        if (!ok || L >= 30)
            return L;
        L++;
    }
}

static void flags_string(unsigned f, char *buf, size_t len)
{
    size_t k = 0;
    buf[0] = 0;
    for (unsigned b = 0; b < 6; b++)
        if (f & (1u << b))
            k += (size_t)snprintf(buf + k, len - k, "%s%s", k ? "," : "", nl_subdiv_flag_name(b));
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
        flags_string(fl, buf, sizeof buf);
        json_array_append_new(a, json_pack("{s:i,s:f,s:i,s:f,s:s}", "level", k, "spacing", l->spacing, "N", l->N,
                                           "max_variance", v, "flags", buf));
    }
    return a;
}

static nl_field *seed_image(const cli_synth_job *job, double *mean)
{
    nl_field *img;
    int st = nl_field_read(job->seed_image, &img, NULL);
    if (st)
        cli_die_status(st);
    if (img->dim != job->dim)
        cli_die(2, "--seed-image: %s is %dD, expected %dD like --size", job->seed_image, img->dim, job->dim);
    *mean = nl_field_mean(img);
    return img;
}

void cli_synth_subdiv_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_subdiv_coeffs *c;
    nl_field *img = NULL;
    double mean = 0, s0, zero[2] = {0, 0}, coarse_corr = NAN;
    int L = job->levels, N = job->N < 0 ? 2 : job->N, st;
    if (job->dim > 2)
        cli_die(2, "synth subdiv: expected a 1D or 2D --size, got %dD", job->dim);
    for (int a = 1; a < job->dim; a++)
        if (job->h[a] != job->h[0])
            cli_die(2, "--spacing: subdivision needs the same spacing on every axis");
    if (job->seed_image) {
        int Li = 0;
        img = seed_image(job, &mean);
        while ((img->n[0] << Li) < job->n[0])
            Li++;
        if ((img->n[0] << Li) != job->n[0] || (job->dim == 2 && (img->n[1] << Li) != job->n[1]))
            cli_die(2, "--seed-image: a %zu%s%.0zu image refines to a power-of-two multiple of its size, not to "
                    "--size %zu%s%.0zu", img->n[0], job->dim == 2 ? "x" : "", job->dim == 2 ? img->n[1] : (size_t)0,
                    job->n[0], job->dim == 2 ? "x" : "", job->dim == 2 ? job->n[1] : (size_t)0);
        if (L && L != Li)
            cli_die(2, "--levels: the seed image fixes %d levels, got %d", Li, L);
        L = Li;
        if (L < 1)
            cli_die(2, "--seed-image: the image is already as large as --size");
    }
    if (!L)
        L = job->nonperiodic ? 6 : default_levels(job, 8);
    if (L < 1)
        cli_die(2, "--size: expected a size divisible by 2 with at least 16 samples for subdivision, got %zu",
                job->n[0]);
    s0 = ldexp(job->h[0], L);
    if ((st = nl_subdiv_coeffs_alloc(job->m, job->dim, L, s0, N, job->tol, job->dim == 1 ? 16 : 6, &c)))
        cli_die_status(st);
    if (job->random_nb) {
        if (job->dim != 2)
            cli_die(2, "--random-neighborhoods: expected a 2D --size");
        if ((st = nl_subdiv_coeffs_randomize(c, job->m, job->random_nb, 1)))
            cli_die_status(st);
    }
    if (job->nonperiodic) {
        double lag[2] = {s0, 0};
        coarse_corr = nl_model_acf(job->m, job->dim, lag) / nl_model_acf(job->m, job->dim, zero);
        st = nl_subdiv_synth_window(c, job->seed, job->origin, f);
    } else if (img) {
        size_t step = (size_t)1 << L;
        nl_field *work = nl_field_alloc(img->dim, img->n, img->h, &st);
        if (!work)
            cli_die_status(st);
        for (size_t i = 0; i < img->count; i++)
            work->data[i] = img->data[i] - mean;
        st = nl_subdiv_refine_periodic(c, work, job->seed, job->clamp, f);
        nl_field_free(work);
        for (size_t i = 0; !st && i < f->count; i++)
            f->data[i] += mean;
        /* the seed samples are the data, bit for bit (not (v - mean) + mean) */
        for (size_t j = 0; !st && j < img->n[1]; j++)
            for (size_t i = 0; i < img->n[0]; i++)
                f->data[(job->dim == 2 ? j * step * f->n[0] : 0) + i * step] = img->data[j * img->n[0] + i];
    } else {
        st = nl_subdiv_synth_periodic(c, job->m, job->seed, job->clamp, f);
    }
    if (st)
        cli_die_status(st);
    char nb[16] = "auto";
    if (N)
        snprintf(nb, sizeof nb, "%d", N);
    snprintf(r->method, sizeof r->method, "subdiv:levels=%d,neighborhood=%s,tol=%g%s%s", L, nb, job->tol,
             job->nonperiodic ? ",nonperiodic" : ",periodic", img ? ",seed-image" : "");
    if (job->random_nb)
        snprintf(r->method + strlen(r->method), sizeof r->method - strlen(r->method), ",random-neighborhoods=%d",
                 job->random_nb);
    if (job->nonperiodic)
        snprintf(r->method + strlen(r->method), sizeof r->method - strlen(r->method), ",origin=%ld:%ld",
                 job->origin[0], job->origin[1]);
    if (img)
        snprintf(r->method + strlen(r->method), sizeof r->method - strlen(r->method), "|seed-image=%s",
                 job->seed_image);
    flags_string(c->flags, r->flags, sizeof r->flags);
    r->sd = sqrt(c->r0);
    r->report = json_pack("{s:f,s:f,s:o}", "spacing0", s0, "variance", c->r0, "levels", levels_report(c));
    if (job->nonperiodic)
        json_object_set_new(r->report, "coarse_correlation", json_real(coarse_corr));
    nl_field_free(img);
    nl_subdiv_coeffs_free(c);
}

void cli_synth_midpoint_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_subdiv_coeffs *c;
    double H = job->H;
    int L = job->levels, st;
    if (job->dim > 2)
        cli_die(2, "synth midpoint: expected a 1D or 2D --size, got %dD", job->dim);
    if (isnan(H)) {
        /* f^-d with d = 2H + E (E = 1 or 2) */
        if (nl_model_get_kind(job->m) != NL_MODEL_POWER)
            cli_die(2, "synth midpoint: expected --H or a power:d=D model, got \"%s\"", nl_model_spec(job->m));
        double d = NAN;
        sscanf(strstr(nl_model_spec(job->m), "d=") + 2, "%lf", &d);
        H = (d - job->dim) / 2;
        if (!(H > 0 && H < 1))
            cli_die(2, "synth midpoint: power:d=%g gives H = %g in %dD; expected %d < d < %d", d, H, job->dim,
                    job->dim, job->dim + 2);
    }
    if (!L)
        L = default_levels(job, 2);
    if ((st = nl_subdiv_coeffs_midpoint(job->dim, L, ldexp(job->h[0], L), H, 1.0, job->vscale, &c)))
        cli_die_status(st);
    if ((st = nl_subdiv_synth_periodic(c, NULL, job->seed, 0, f)))
        cli_die_status(st);
    snprintf(r->method, sizeof r->method, "midpoint:H=%.17g,levels=%d,variance-scale=%.17g", H, L, job->vscale);
    r->sd = sqrt(c->r0);
    r->report = json_pack("{s:f,s:i,s:f}", "H", H, "levels", L, "variance_scale", job->vscale);
    nl_subdiv_coeffs_free(c);
}

void cli_synth_circulant_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_circulant_plan *p;
    nl_synth_circulant_info info;
    int st;
    if ((st = nl_synth_circulant_plan_alloc(job->m, job->dim, job->n, job->h, job->clamp ? NL_SYNTH_FFT_CLAMP : 0, 16,
                                         &p)))
        cli_die_status(st);
    nl_synth_circulant_plan_info(p, &info);
    if ((st = nl_synth_circulant_execute(p, job->seed, f)))
        cli_die_status(st);
    nl_synth_circulant_plan_free(p);
    snprintf(r->method, sizeof r->method, "circulant:embedding=%zux%zux%zu", info.m[0], info.m[1], info.m[2]);
    if (info.clamp_error > NL_SYNTH_FFT_CLAMP_TOL)
        snprintf(r->flags, sizeof r->flags, "clamped");
    double zero[3] = {0, 0, 0};
    r->sd = sqrt(nl_model_acf(job->m, job->dim, zero));
    if (!(r->sd > 0))
        r->sd = 1;
    r->report = json_pack("{s:[I,I,I],s:f,s:f,s:f,s:i}", "embedding", (json_int_t)info.m[0], (json_int_t)info.m[1],
                          (json_int_t)info.m[2], "min_eigenvalue", info.min_eigenvalue, "max_eigenvalue",
                          info.max_eigenvalue, "clamp_error", info.clamp_error, "doublings", info.doublings);
}

void cli_synth_cholesky_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_cholesky_plan *p;
    int st;
    double zero[3] = {0, 0, 0};
    if ((st = nl_synth_cholesky_plan_alloc(job->m, job->dim, job->n, job->h, &p)))
        cli_die_status(st);
    if ((st = nl_synth_cholesky_execute(p, job->seed, f)))
        cli_die_status(st);
    nl_synth_cholesky_plan_free(p);
    snprintf(r->method, sizeof r->method, "cholesky");
    r->sd = sqrt(nl_model_acf(job->m, job->dim, zero));
}

void cli_synth_faulting_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    size_t K;
    int st;
    if (job->dim > 2)
        cli_die(2, "synth faulting: expected a 1D or 2D --size, got %dD", job->dim);
    if ((st = nl_synth_faulting(job->seed, job->density, f, &K)))
        cli_die_status(st);
    snprintf(r->method, sizeof r->method, "faulting:density=%.17g", job->density);
    double mean = 0, var = 0;
    for (size_t i = 0; i < f->count; i++)
        mean += f->data[i] / (double)f->count;
    for (size_t i = 0; i < f->count; i++)
        var += (f->data[i] - mean) * (f->data[i] - mean) / (double)f->count;
    r->sd = sqrt(var) > 0 ? sqrt(var) : 1;
    /* the preview is centred on 0: shift the range by the mean */
    r->offset = mean;
    r->report = json_pack("{s:I,s:f}", "faults", (json_int_t)K, "density", job->density);
}

void cli_synth_sparse_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_sparse_plan *p;
    nl_synth_sparse_info info;
    double mean = 0;
    int st, given = (job->m != NULL) + (job->kernel != NULL) + (job->exemplar != NULL);
    if (job->dim > 2)
        cli_die(2, "synth sparse: expected a 1D or 2D --size, got %dD", job->dim);
    if (given != 1)
        cli_die(2, "synth sparse: expected exactly one kernel: --acf/--spectrum SPEC, --kernel EXPR or --exemplar FILE");
    if (job->m)
        st = nl_synth_sparse_plan_model(job->m, job->dim, job->h, job->radius, job->cell, job->density, &p);
    else if (job->kernel)
        st = nl_synth_sparse_plan_expr(job->kernel, job->dim, job->radius ? job->radius : 16, job->cell, job->density,
                                    &p);
    else {
        nl_field *img = cli_read_field(job->exemplar, NULL);
        if (job->dim != 2 || img->dim != 2)
            cli_die(2, "--exemplar: expected a 2D image and a 2D --size");
        if (job->radius) {
            /* the central 2R x 2R window of the exemplar */
            size_t w = 2 * (size_t)job->radius, crop[2] = {w, w};
            if (w > img->n[0] || w > img->n[1])
                cli_die(2, "--radius: %d needs a %zux%zu window, larger than the %zux%zu exemplar", job->radius, w, w,
                        img->n[0], img->n[1]);
            nl_field *c = nl_field_alloc(2, crop, NULL, &st);
            if (!c)
                cli_die_status(st);
            for (size_t j = 0; j < w; j++)
                for (size_t i = 0; i < w; i++)
                    c->data[j * w + i] = img->data[(j + (img->n[1] - w) / 2) * img->n[0] + i + (img->n[0] - w) / 2];
            nl_field_free(img);
            img = c;
        }
        mean = nl_field_mean(img);
        st = nl_synth_sparse_plan_image(img, job->cell, job->density, &p);
        nl_field_free(img);
    }
    if (st)
        cli_die_status(st);
    if (job->angle && (st = nl_synth_sparse_set_angle(p, job->angle)))
        cli_die_status(st);
    nl_synth_sparse_plan_info(p, &info);
    if (job->wrap && job->nonperiodic)
        cli_die(2, "synth sparse: --wrap and --origin exclude each other");
    if ((st = nl_synth_sparse_execute(p, job->seed, job->wrap, job->wrap ? NULL : job->origin, f)))
        cli_die_status(st);
    for (size_t i = 0; mean != 0 && i < f->count; i++)
        f->data[i] += mean;
    nl_synth_sparse_plan_free(p);
    /* expression-valued keys follow '|', as they may hold commas */
    char org[64] = "";
    if (!job->wrap && (job->origin[0] || job->origin[1]))
        snprintf(org, sizeof org, ",origin=%ld:%ld", job->origin[0], job->origin[1]);
    snprintf(r->method, sizeof r->method, "sparse:radius=%d,cell=%d,density=%.17g%s%s%s%s%s%s%s", info.radius,
             info.cell, info.density, job->wrap ? ",wrap" : org, job->kernel ? "|kernel=" : "",
             job->kernel ? job->kernel : "", job->exemplar ? "|exemplar=" : "", job->exemplar ? job->exemplar : "",
             job->angle ? "|angle=" : "", job->angle ? job->angle : "");
    r->sd = sqrt(info.variance);
    r->offset = mean;
    r->report = json_pack("{s:i,s:i,s:f,s:f,s:f,s:f}", "radius", info.radius, "cell", info.cell, "density",
                          info.density, "variance", info.variance, "excess_kurtosis", info.kurtosis, "truncated_energy",
                          info.truncated);
}

void cli_synth_lattice_run(const cli_synth_job *job, nl_field *f, cli_synth_result *r)
{
    nl_synth_lattice_plan p;
    double c0 = job->cell ? job->cell : (double)f->n[0] / 4;
    int O = job->octaves, st;
    json_t *oct = json_array();
    if (job->dim > 2)
        cli_die(2, "synth lattice: expected a 1D or 2D --size, got %dD", job->dim);
    if (!O)
        for (O = 1; c0 / pow(2, O) >= 2 && O < NL_LATTICE_MAX_OCTAVES; O++)
            ;
    if ((st = nl_synth_lattice_plan_alloc(job->m, job->dim, c0, O, &p)) || (st = nl_synth_lattice_execute(&p, job->seed, f)))
        cli_die_status(st);
    double var = 0;
    for (int o = 0; o < p.octaves; o++) {
        json_array_append_new(oct, json_pack("{s:f,s:f,s:f,s:f}", "cell", p.cell[o], "weight", p.weight[o], "peak",
                                             p.peak[o], "leakage", p.leakage[o]));
        var += p.weight[o] * p.weight[o];
    }
    snprintf(r->method, sizeof r->method, "lattice:cell=%.17g,octaves=%d", c0, O);
    for (size_t i = 0; i < f->count; i++)
        r->sd += f->data[i] * f->data[i] / (double)f->count;
    r->sd = sqrt(r->sd) > 0 ? sqrt(r->sd) : 1;
    r->report = json_pack("{s:o}", "octaves", oct);
}
