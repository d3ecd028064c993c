/* synth -o OUT.h5 under an MPI launcher: each process synthesises its slab
 * of the field (the methods filtering white noise on the periodic grid or
 * its circulant embedding through FFTW-MPI, mpi/fft.h; the others by their
 * slab executes) and all write one HDF5 file together
 * (mpi/h5.h).  Rank 0 owns the output's temporary name (cli/outputs.c) and
 * renames it when every process has written; every failure is agreed on
 * first, so all processes stop together with rank 0 naming the cause. */
#include "synth.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../mpi/dist.h"
#include "../mpi/fft.h"
#include "../mpi/h5.h"
#include "../synth/circulant_internal.h"
#include "../synth/fft_internal.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* Stop every process together: agreed status, rank 0 tells (h5_main.c
 * silences the others). */
static void check_all(int st) { cli_check(nl_mpi_agree(MPI_COMM_WORLD, st)); }

/* Bytes per process of a method on P processes (for the memory check). */
typedef struct {
    const cli_synth_job *job;   /* the request */
    size_t m[3];                /* the FFT grid: the field's, or its first circulant embedding */
} mem_model;

static size_t bytes_for(int P, const void *arg)
{
    const mem_model *mm = arg;
    const cli_synth_job *job = mm->job;
    size_t rest = 1, b = (job->n[job->dim - 1] + (size_t)P - 1) / (size_t)P;
    for (int a = 0; a + 1 < job->dim; a++)
        rest *= job->n[a];
    if (!job->type->execute_slab)
        return nl_mpi_fft_bytes(job->dim, mm->m, P) + b * rest * sizeof(double);
    /* slab executes: the slab, plus about as much again for the finest
     * level's neighbours and the level below (an estimate) */
    return 2 * b * rest * sizeof(double);
}

/* Exit 2 when P processes would exceed NOISELAB_MEMORY_LIMIT each. */
static void check_memory_on(const cli_synth_job *job, int P)
{
    mem_model mm = {job, {1, 1, 1}};
    size_t lim, need;
    int enough;
    cli_check(nl_mem_limit(&lim));
    for (int a = 0; a < job->dim; a++)
        mm.m[a] = job->type->caps & NL_METHOD_EMBEDDING ? nl_synth_circulant_size(job->n[a]) : job->n[a];
    if (!lim || (need = bytes_for(P, &mm)) <= lim)
        return;
    enough = nl_mpi_processes_needed(bytes_for, &mm, lim, 1 << 20);
    cli_die(2, "NOISELAB_MEMORY_LIMIT: synth %s of %zu%s%.0zu%s%.0zu samples needs about %.0f MiB per process on %d "
            "process%s, above the limit of %.0f MiB; %s%d processes (mpirun -np %d)", job->method, job->n[0],
            job->dim > 1 ? "x" : "", job->dim > 1 ? job->n[1] : 0, job->dim > 2 ? "x" : "",
            job->dim > 2 ? job->n[2] : 0, (double)need / 1048576, P, P == 1 ? "" : "es", (double)lim / 1048576,
            enough ? "it fits on " : "not even on ", enough ? enough : 1 << 20, enough ? enough : 1 << 20);
}

void cli_h5_check_memory(const cli_synth_job *job, cli_synth_run_fn run)
{
    (void)run;
    check_memory_on(job, 1);
}

/* The output's temporary, made by rank 0 and named to every process.  The
 * output must resolve to the same file on every process (a collective
 * create of files that differ never returns), its folder writable on
 * each, so that rank 0 cannot fail alone; then every process must see
 * rank 0's temporary itself (node-local folders of one name do not). */
static const char *begin_output(const char *out, int rank)
{
    static char tmp[PATH_MAX];
    char dir[PATH_MAX];
    const char *slash = strrchr(out, '/');
    int st;
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - out) + 1 : 1, slash ? out : ".");
    if ((st = nl_mpi_same_file(MPI_COMM_WORLD, out, 1)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "-o: %s", nl_errmsg());
    check_all(access(dir, W_OK | X_OK) ? NL_ERROR(NL_EINVAL, "-o: cannot write \"%s\": its folder \"%s\" is not "
                                                   "writable or does not exist", out, dir) : NL_OK);
    memset(tmp, 0, sizeof tmp);
    if (rank == 0)
        snprintf(tmp, sizeof tmp, "%s", cli_out_begin(out));
    MPI_Bcast(tmp, PATH_MAX, MPI_CHAR, 0, MPI_COMM_WORLD);
    if ((st = nl_mpi_same_file(MPI_COMM_WORLD, tmp, 0)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "-o: \"%s\": its temporary %s", out, nl_errmsg());
    if (rank != 0) /* its create can remake the file rank 0's signal handler removed */
        cli_out_share(tmp);
    return tmp;
}

/* The FFTW-MPI methods (NL_METHOD_TORUS, NL_METHOD_EMBEDDING): plan over
 * every process, then execute into f. */
static nl_field *run_fft(cli_synth_job *job, cli_synth_result *res)
{
    unsigned fl = job->clamp ? NL_SYNTH_FFT_CLAMP : 0;
    size_t n[3] = {job->n[0], job->n[1], job->n[2]};
    static nl_method_report mr;
    nl_field *f;
    if (job->type->caps & NL_METHOD_TORUS) {
        nl_mpi_fft_plan *p;
        nl_synth_fft_info info;
        cli_check(nl_mpi_fft_plan_alloc(MPI_COMM_WORLD, job->m, job->dim, job->n, job->h, fl, &p));
        nl_mpi_fft_local(p, &job->s0, &job->ns);
        n[job->dim - 1] = job->ns ? job->ns : 1;
        f = cli_field_alloc(job->dim, n, job->h);
        check_all(nl_mpi_fft_execute(p, job->seed, f->data));
        nl_mpi_fft_plan_info(p, &info);
        nl_mpi_fft_plan_free(p);
        cli_check(nl_synth_fft_report(&info, &mr));
    } else {
        nl_mpi_circulant_plan *p;
        nl_synth_circulant_info info;
        cli_check(nl_mpi_circulant_plan_alloc(MPI_COMM_WORLD, job->m, job->dim, job->n, job->h, fl, 16, &p));
        nl_mpi_circulant_local(p, &job->s0, &job->ns);
        n[job->dim - 1] = job->ns ? job->ns : 1;
        f = cli_field_alloc(job->dim, n, job->h);
        check_all(nl_mpi_circulant_execute(p, job->seed, f->data));
        nl_mpi_circulant_plan_info(p, &info);
        nl_mpi_circulant_plan_free(p);
        cli_check(nl_synth_circulant_report(&info, job->m, job->dim, &mr));
    }
    snprintf(res->method, sizeof res->method, "%.*s", (int)sizeof res->method - 1, mr.method);
    cli_synth_take_report(&mr, res);
    return f;
}

/* --json: what synth prints, and the processes, the slowest process's
 * seconds for synthesis and for writing, and the largest peak RSS. */
static void print_json(const cli_synth_job *job, const nl_meta *meta, const cli_synth_result *res, int P,
                       const double *t)
{
    struct rusage ru;
    double loc[3] = {t[0], t[1], 0}, max[3];
    getrusage(RUSAGE_SELF, &ru);
    loc[2] = (double)ru.ru_maxrss / 1024;
    MPI_Reduce(loc, max, 3, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    json_t *o = cli_synth_json(job, meta, res);
    json_object_set_new(o, "processes", json_integer(P));
    json_object_set_new(o, "seconds", json_pack("{s:f,s:f}", "synthesis", max[0], "write", max[1]));
    json_object_set_new(o, "peak_rss_mib", json_real(max[2]));
    cli_json_print(o);
}

/* NL_OK when every sample of this process's slab is finite (and, f32,
 * within float32), else NL_EINVAL naming the first bad one by its index and
 * coordinates in the whole field, as the one-process synth does. */
static int check_samples(const cli_synth_job *job, const nl_field *f, int f32, const char *out)
{
    size_t k, g = job->s0, n0 = job->n[0], n1 = job->dim > 1 ? job->n[1] : 1;
    const char *sp = job->m ? " " : "", *spec = job->m ? nl_model_spec(job->m) : "";
    double v;
    if (!job->ns || !nl_field_check_finite(f, f32 ? FLT_MAX : INFINITY, &k))
        return NL_OK;
    for (int a = 0; a + 1 < job->dim; a++)
        g *= job->n[a];
    g += k, v = f->data[k];
    if (!isfinite(v))
        return NL_ERROR(NL_EINVAL, "synth %s%s%s: sample %zu (x %zu, y %zu, z %zu) is %g, expected a finite number; "
                        "%s not written", job->method, sp, spec, g, g % n0, g / n0 % n1, g / (n0 * n1), v, out);
    return NL_ERROR(NL_EINVAL, "synth %s%s%s: sample %zu (x %zu, y %zu, z %zu) is %g, beyond the largest magnitude "
                    "%g of float32 (lower the variance); %s not written", job->method, sp, spec, g, g % n0,
                    g / n0 % n1, g / (n0 * n1), v, (double)FLT_MAX, out);
}

/* Has the method an option that stands in for a model (a kernel)? */
static int takes_other_kernel(const nl_method_type *t)
{
    for (int k = 0; k < t->noptions; k++)
        if (t->options[k].flags & NL_METHOD_REPLACES_MODEL)
            return 1;
    return 0;
}

int cli_h5_synth(cli_synth_job *job, const char *out, cli_synth_run_fn run, int json)
{
    double t[3];
    int P, rank, f32 = !cli_h5_double;
    cli_synth_result res;
    nl_meta meta;
    nl_field *f;
    const char *tmp;
    MPI_Comm_size(MPI_COMM_WORLD, &P);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (!(job->type->caps & NL_METHOD_DISTRIBUTED)) {
        char list[256];
        nl_method_names(NL_METHOD_DISTRIBUTED | NL_METHOD_EXACT_FIRST, NULL, ", ", ", ", list, sizeof list);
        cli_die(2, "synth %s: runs on one process; distributed: %s (or run it without mpirun)", job->method, list);
    }
    if (!job->m && !takes_other_kernel(job->type))
        cli_die(2, "synth %s: expected --acf or --spectrum", job->method);
    check_memory_on(job, P);
    tmp = begin_output(out, rank);
    memset(&res, 0, sizeof res);
    MPI_Barrier(MPI_COMM_WORLD);
    t[0] = MPI_Wtime();
    job->slab = 1;
    if (!job->type->execute_slab) { /* through FFTW-MPI */
        f = run_fft(job, &res);
    } else {
        size_t n[3] = {job->n[0], job->n[1], job->n[2]};
        nl_mpi_block(job->n[job->dim - 1], P, rank, &job->s0, &job->ns);
        n[job->dim - 1] = job->ns ? job->ns : 1;
        f = cli_field_alloc(job->dim, n, job->h);
        run(job, f, &res);
    }
    t[1] = MPI_Wtime();
    /* nothing is written unless every sample is finite (and fits float32):
     * the lowest rank's first bad sample is the field's first */
    check_all(check_samples(job, f, f32, out));
    /* the attributes are written collectively: rank 0's, on every process */
    cli_synth_fill_meta(job, f, &res, &meta);
    MPI_Bcast(&meta, sizeof meta, MPI_BYTE, 0, MPI_COMM_WORLD);
    cli_check(nl_mpi_h5_write(tmp, MPI_COMM_WORLD, job->dim, job->n, job->s0, job->ns, job->ns ? f->data : NULL,
                              &meta, cli_h5_double, P));
    t[2] = MPI_Wtime();
    if (rank == 0) {
        cli_out_commit(out);
        cli_write_xdmf(out, job->dim, job->n, job->h, &meta);
    }
    if (json) {
        double d[2] = {t[1] - t[0], t[2] - t[1]};
        print_json(job, &meta, &res, P, d);
    }
    json_decref(res.report);
    nl_field_free(f);
    nl_model_free(job->m);
    return 0;
}
