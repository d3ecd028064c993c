/* noiselab-mpi: the command line with HDF5 files and MPI runs.  Under a
 * launcher every process runs the same command (checked first) on its
 * share of the field, with paths that name the same files (mpi/path.c);
 * only rank 0 prints (the others' standard output and error go to
 * /dev/null), and errors are agreed on first, so every process stops
 * together with rank 0 telling why. */
#include "cli.h"
#include "synth.h"
#include "h5_analysis.h"
#include "../mpi/dist.h"
#include "../mpi/h5.h"
#include "../core/fftw_plan.h"
#include "../core/nl_error.h"

#include <fftw3-mpi.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <unistd.h>

static cli_h5_hooks hooks;

int cli_h5_synth(cli_synth_job *job, const char *out, cli_synth_run_fn run, int json);
void cli_h5_check_memory(const cli_synth_job *job, cli_synth_run_fn run);

/* --from FILE.h5 under a launcher: every process reads the provenance
 * itself, so the file must be the same one everywhere (else each would
 * make another field, and their collective calls would not match). */
static int read_meta(const char *path, nl_meta *meta)
{
    int st = hooks.size > 1 ? nl_mpi_same_file(MPI_COMM_WORLD, path, 0) : NL_OK;
    if (st) {
        char msg[512]; /* the message is rewritten from itself */
        snprintf(msg, sizeof msg, "%s", nl_errmsg());
        memset(meta, 0, sizeof *meta);
        return NL_ERROR(st, "--from: %s", msg);
    }
    return nl_mpi_h5_read_meta(path, meta);
}

static int agree(int status) { return hooks.launched ? nl_mpi_agree(MPI_COMM_WORLD, status) : status; }

static int failed_alone; /* rank 0 is leaving on an error: no MPI_Finalize */

static void finish(void)
{
    if (failed_alone)
        return;
    fftw_mpi_cleanup();
    MPI_Finalize();
}

/* An error exit of rank 0 (cli_die: its message is printed) skips
 * MPI_Finalize, which would wait for the other processes, perhaps stuck in
 * a collective call rank 0 left; mpirun then stops them (their signal
 * handlers remove what they made) and exits with rank 0's status.  The
 * other ranks finalize: their errors are agreed ones (rank 0 tells), and
 * leaving first could end rank 0 before its message is out. */
static void on_exit_code(int code)
{
    if (hooks.launched && hooks.rank == 0 && code) {
        fflush(NULL);
        failed_alone = 1;
    }
}

/* Under a launcher every process must run one command: a size or seed
 * that differs makes slabs of other fields, or collective calls that do
 * not match (a hang).  argv[1..] of each against process 0's. */
static void check_same_command(int argc, char **argv)
{
    unsigned long long len = 0;
    char *zero, *p;
    int k = 1, st = NL_OK;
    for (int i = 1; i < argc; i++)
        len += strlen(argv[i]) + 1;
    MPI_Bcast(&len, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    if (!(zero = calloc(len + 1, 1)))
        cli_die(1, "out of memory comparing the command with process 0's");
    for (int i = 1, off = 0; hooks.rank == 0 && i < argc; off += (int)strlen(argv[i++]) + 1)
        memcpy(zero + off, argv[i], strlen(argv[i]) + 1);
    MPI_Bcast(zero, (int)len, MPI_CHAR, 0, MPI_COMM_WORLD);
    for (p = zero; k < argc && p < zero + len && !strcmp(p, argv[k]); p += strlen(p) + 1)
        k++;
    if (k < argc && p < zero + len)
        st = NL_ERROR(NL_EINVAL, "the processes were given different commands: argument %d is \"%s\" on process 0 "
                      "but \"%s\" on process %d; expected the same command on every process", k, p, argv[k],
                      hooks.rank);
    else if (k < argc || p < zero + len)
        st = NL_ERROR(NL_EINVAL, "the processes were given different commands: %s arguments on process %d than on "
                      "process 0; expected the same command on every process", k < argc ? "more" : "fewer",
                      hooks.rank);
    free(zero);
    if ((st = nl_mpi_agree(MPI_COMM_WORLD, st)))
        cli_die(2, "%s", nl_errmsg());
}

int main(int argc, char **argv)
{
    int provided;
    hooks.size = 1;
    hooks.read = nl_mpi_h5_read;
    hooks.write = nl_mpi_h5_write_field;
    hooks.meta = read_meta;
    hooks.agree = agree;
    hooks.synth = cli_h5_synth;
    hooks.check_memory = cli_h5_check_memory;
    cli_h5_analysis_hooks(&hooks);
    if (cli_mpi_launched()) {
        /* A launcher ended outright (SIGKILL, a crash) cannot stop its
         * processes: they would go on, or be ended by Open MPI without
         * removing their temporaries.  The kernel tells them instead
         * (SIGTERM, whose handler, cli/outputs.c, removes them). */
        pid_t parent = getppid();
        if (prctl(PR_SET_PDEATHSIG, SIGTERM) == 0 && getppid() != parent)
            raise(SIGTERM);
        if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
            fprintf(stderr, "noiselab: MPI could not start\n");
            return 1;
        }
        nl_fftw_flags(0); /* FFTW's threads first, then its MPI part */
        fftw_mpi_init();
        hooks.launched = 1;
        cli_out_guard();
        MPI_Comm_size(MPI_COMM_WORLD, &hooks.size);
        MPI_Comm_rank(MPI_COMM_WORLD, &hooks.rank);
        atexit(finish);
        cli_exit_hook = on_exit_code;
        if (hooks.rank != 0 && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)))
            return 1;
    }
    cli_h5 = &hooks;
    if (hooks.size > 1)
        check_same_command(argc, argv);
    if (hooks.size > 1 && argc > 1 && strcmp(argv[1], "synth") && strcmp(argv[1], "acf") && strcmp(argv[1], "psd") &&
        strcmp(argv[1], "hist") && strcmp(argv[1], "--help") && strcmp(argv[1], "--version"))
        cli_die(2, "%s runs on one process; under mpirun with %d processes: synth, acf, psd, hist", argv[1],
                hooks.size);
    return cli_main(argc, argv);
}
