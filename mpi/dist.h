/* Distributed fields: slabs, agreement on errors, the process grid.
 *
 * A distributed field of n[0..dim-1] samples (x fastest, as core/field.h)
 * is cut along its slowest axis, dim - 1 (rows in 2D, slices in 3D): process
 * r of P holds the samples whose index along that axis is s0 .. s0 + ns - 1,
 * every other axis whole, row-major in a buffer of its own.  The default cut
 * is FFTW-MPI's block distribution (nl_mpi_block): block = ceil(N / P) rows
 * per process, so the last processes may hold fewer rows or none.
 *
 * Every function of the module takes the communicator it works on; the
 * collective ones say so and must be called by every process of it, in the
 * same order.  Without MPI_Init (a program started without a launcher) the
 * module's serial paths take comm = MPI_COMM_NULL (the HDF5 functions); the
 * collective ones need MPI initialised.
 *
 * Errors follow core/nl_error.h: a function returns NL_OK or an NL_E* code
 * with a one-line message for nl_errmsg() (per thread).  A collective
 * function agrees on its result before it returns (nl_mpi_agree): every
 * process returns the same status and the same message, so a caller can
 * stop on every process together without a hang. */
#ifndef NL_MPI_DIST_H
#define NL_MPI_DIST_H

#include <mpi.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Process r's block of N rows over P processes: *s0 = min(r b, N), *ns =
 * min(b, N - *s0) with b = ceil(N / P) (FFTW-MPI's default block).  Pure. */
void nl_mpi_block(size_t N, int P, int r, size_t *s0, size_t *ns);

/* Collective: the worst status of the processes (the largest NL_E* code,
 * NL_OK when all are NL_OK) on every process, with the message of the
 * lowest-ranked process that had it (so rank 0 can print the one line).
 * Returns NL_EFAIL when the communication itself fails. */
int nl_mpi_agree(MPI_Comm comm, int status);

/* Collective: does `path` name the same file on every process of comm?
 * Each process resolves it (realpath; with `create`, of its folder, plus
 * the name, for a file about to be made) and compares with process 0: the
 * resolved path; the device and inode of the file (create: the folder)
 * with the first process of its own node (device numbers are per machine);
 * without `create`, the size and modification time with process 0.  A
 * collective MPI-IO open of a path that differs never returns, so call this
 * first.  NL_OK when every process sees the same (or every process fails
 * to resolve it alike: the open then says why); NL_EINPUT, the same on
 * every process, naming the path, the process that differs and what
 * differs; NL_EFAIL, NL_ENOMEM. */
int nl_mpi_same_file(MPI_Comm comm, const char *path, int create);

/* Collective: the smallest number of processes P >= 1 for which
 * bytes(P, arg) <= limit, looking up to pmax (0 when none fits).  bytes
 * is the peak memory of the busiest process of P (the caller's model of
 * its method); used to name the process count a refused request needs.
 * Pure (not collective). */
int nl_mpi_processes_needed(size_t (*bytes)(int P, const void *arg), const void *arg, size_t limit, int pmax);

#ifdef __cplusplus
}
#endif

#endif
