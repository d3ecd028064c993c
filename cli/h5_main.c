/* noiselab-mpi: the command line with HDF5 files and MPI runs.  Under a
 * launcher every process runs the same command on its share of the field;
 * only rank 0 prints (the others' standard output and error go to
 * /dev/null), and errors are agreed on first, so every process stops
 * together with rank 0 telling why. */
#include "cli.h"
#include "synth.h"
#include "h5_analysis.h"
#include "../mpi/dist.h"
#include "../mpi/h5.h"
#include "../core/fftw_plan.h"

#include <fftw3-mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static cli_h5_hooks hooks;

int cli_h5_synth(cli_synth_job *job, const char *out, cli_synth_run_fn run, int json);
void cli_h5_check_memory(const cli_synth_job *job, cli_synth_run_fn run);

static int agree(int status) { return hooks.launched ? nl_mpi_agree(MPI_COMM_WORLD, status) : status; }

static void finish(void)
{
    fftw_mpi_cleanup();
    MPI_Finalize();
}

int main(int argc, char **argv)
{
    int provided;
    hooks.size = 1;
    hooks.read = nl_mpi_h5_read;
    hooks.write = nl_mpi_h5_write_field;
    hooks.meta = nl_mpi_h5_read_meta;
    hooks.agree = agree;
    hooks.synth = cli_h5_synth;
    hooks.check_memory = cli_h5_check_memory;
    cli_h5_analysis_hooks(&hooks);
    if (cli_mpi_launched()) {
        if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
            fprintf(stderr, "noiselab: MPI could not start\n");
            return 1;
        }
        nl_fftw_flags(0); /* FFTW's threads first, then its MPI part */
        fftw_mpi_init();
        hooks.launched = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &hooks.size);
        MPI_Comm_rank(MPI_COMM_WORLD, &hooks.rank);
        atexit(finish);
        if (hooks.rank != 0 && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)))
            return 1;
    }
    cli_h5 = &hooks;
    if (hooks.size > 1 && argc > 1 && strcmp(argv[1], "synth") && strcmp(argv[1], "acf") && strcmp(argv[1], "psd") &&
        strcmp(argv[1], "hist") && strcmp(argv[1], "--help") && strcmp(argv[1], "--version"))
        cli_die(2, "%s runs on one process; under mpirun with %d processes: synth, acf, psd, hist", argv[1],
                hooks.size);
    return cli_main(argc, argv);
}
