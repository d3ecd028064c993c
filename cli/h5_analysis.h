/* The distributed analysis hooks of noiselab-mpi (cli/h5_analysis.c). */
#ifndef NL_CLI_H5_ANALYSIS_H
#define NL_CLI_H5_ANALYSIS_H

#include "cli.h"

/* Set read_slab, slab_free, acf, psd and hist of h (over MPI_COMM_WORLD). */
void cli_h5_analysis_hooks(cli_h5_hooks *h);

#endif
