/* Fields in HDF5 files, written and read by one process or collectively.
 *
 * Layout: one dataset "/field" of the field's samples, row-major with the
 * slowest axis first in HDF5's dimension order: (n0) in 1D, (n1, n0) in 2D,
 * (n2, n1, n0) in 3D (h5py's f["field"][z, y, x] is sample (x, y, z), as the
 * EXR's rows); IEEE float32 little-endian by default (each double rounded
 * to nearest, the same values as the EXR writer stores), float64 with
 * `dbl`.  Provenance: variable-length UTF-8 string attributes of /field named as the nl_meta
 * fields (model, method, seed, spacing, size, version, flags, origin; empty
 * ones are not written) and an integer attribute "processes", the number of
 * processes that wrote it.  Spacing is read back from "spacing" (unit when
 * absent).
 *
 * With comm = MPI_COMM_NULL the file is written or read by the calling
 * process alone (HDF5's default POSIX driver: no MPI_Init needed); with a
 * communicator, through MPI-IO, collectively: every process of comm calls
 * with the same path, sizes and provenance, and its own slab (mpi/dist.h),
 * possibly empty.  Collective calls first check that path names the same
 * file on every process (nl_mpi_same_file: NL_EINPUT, not a hang, when it
 * does not) and agree on their status (nl_mpi_agree).
 *
 * Reading checks what the file declares before reading it: /field holds
 * numbers (floating point or integer; not compound, string, enum, array,
 * ...), each provenance attribute present is one string (a scalar, fixed
 * or variable length) of at most its nl_meta capacity less one bytes, one
 * string with no NUL or control character inside, ASCII or UTF-8 as its
 * encoding says, and "processes" is one integer >= 1; anything else is
 * NL_EINPUT naming the file and the attribute.
 *
 * Returns NL_OK, NL_EIO (the file cannot be created or written), NL_EINPUT
 * (not an HDF5 file, no /field, a rank, size, sample type or attribute
 * that is not a field's),
 * NL_ETOOBIG (the size does not fit this process: nl_size_check, honouring
 * NOISELAB_MEMORY_LIMIT), NL_ENOMEM.  HDF5's own error printing is turned
 * off by these functions (process-wide: the library never prints).
 * Thread safety: Debian's parallel HDF5 is not thread-safe; one thread at a
 * time. */
#ifndef NL_MPI_H5_H
#define NL_MPI_H5_H

#include "../core/field.h"
#include "../core/io.h"

#include <mpi.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Write the slab s0 .. s0 + ns - 1 (along axis dim - 1) of a field of
 * n[0..dim-1] samples at spacing h (NULL: from meta only) from `slab`
 * (ns n[0] ... n[dim-2] doubles, row-major; NULL when ns = 0).  Writes
 * exactly `path` (atomic appearance is the caller's job, as core/io.h).
 * `processes` is recorded as the "processes" attribute. */
int nl_mpi_h5_write(const char *path, MPI_Comm comm, int dim, const size_t *n, size_t s0, size_t ns,
                    const double *slab, const nl_meta *meta, int dbl, int processes);

/* One process, no MPI: nl_mpi_h5_write of the whole field f (processes 1),
 * with f's own sizes and spacing. */
int nl_mpi_h5_write_field(const char *path, const nl_field *f, const nl_meta *meta, int dbl);

/* One process: the whole field into a new *out (spacing from the
 * "spacing" attribute) and, when meta is not NULL, its provenance.
 * Samples must be finite (NL_EINPUT names the first that is not). */
int nl_mpi_h5_read(const char *path, nl_field **out, nl_meta *meta);

/* One process: the provenance of path's /field alone (meta zeroed first). */
int nl_mpi_h5_read_meta(const char *path, nl_meta *meta);

/* Collective: the field's rank and size (*dim, n[0..2], unused axes 1),
 * spacing h[0..2] and provenance, on every process, then this process's
 * block (nl_mpi_block over comm's size) into a new *slab (NULL when
 * empty), *s0 and *ns.  Samples must be finite (NL_EINPUT). */
int nl_mpi_h5_read_slab(const char *path, MPI_Comm comm, int *dim, size_t *n, double *h, nl_meta *meta,
                        size_t *s0, size_t *ns, double **slab);

/* Is the file at path HDF5 (its signature at offset 0)?  1 yes, 0 no or
 * unreadable.  Serial. */
int nl_mpi_h5_is_hdf5(const char *path);

#ifdef __cplusplus
}
#endif

#endif
