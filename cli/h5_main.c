/* noiselab-mpi: the command line with HDF5 files and MPI runs.  Under a
 * launcher every process runs the same command on its share of the field;
 * only rank 0 prints (the others' standard output and error go to
 * /dev/null), and errors are agreed on first, so every process stops
 * together with rank 0 telling why. */
#include "cli.h"
#include "h5_analysis.h"
#include "../mpi/dist.h"
#include "../mpi/h5.h"

#include <fftw3-mpi.h>
#include <stdio.h>
#include <stdlib.h>

static cli_h5_hooks hooks;

static int h5_write(const char *path, const nl_field *f, const nl_meta *meta, int dbl)
{
    return nl_mpi_h5_write(path, MPI_COMM_NULL, f->dim, f->n, 0, f->n[f->dim - 1], f->data, meta, dbl, 1);
}

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
    hooks.write = h5_write;
    hooks.meta = nl_mpi_h5_read_meta;
    hooks.agree = agree;
    cli_h5_analysis_hooks(&hooks);
    if (cli_mpi_launched()) {
        if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
            fprintf(stderr, "noiselab: MPI could not start\n");
            return 1;
        }
        fftw_mpi_init();
        hooks.launched = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &hooks.size);
        MPI_Comm_rank(MPI_COMM_WORLD, &hooks.rank);
        atexit(finish);
        if (hooks.rank != 0 && (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)))
            return 1;
    }
    cli_h5 = &hooks;
    return cli_main(argc, argv);
}
