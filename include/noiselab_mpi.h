/* noiselab's distributed module: fields cut in slabs over the processes of
 * an MPI communicator, FFTW-MPI synthesis, HDF5 fields (one process or
 * collective).  Include after <noiselab.h>; link with
 *
 *     cc app.c $(pkg-config --cflags --libs noiselab hdf5-openmpi mpi) -lnoiselab_mpi -lfftw3_mpi
 *
 * (or mpicc).  Kept out of <noiselab.h> and libnoiselab, so that programs
 * without MPI need neither its headers nor its libraries.  Each header
 * states its contract; docs/scale-out.md explains the decomposition. */
#ifndef NOISELAB_MPI_H
#define NOISELAB_MPI_H

#include <mpi.h>

#ifdef __cplusplus
extern "C" {
#endif

#include "noiselab/mpi/dist.h"
#include "noiselab/mpi/h5.h"
#include "noiselab/mpi/fft.h"
#include "noiselab/mpi/analysis.h"

#ifdef __cplusplus
}
#endif

#endif
