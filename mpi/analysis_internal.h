/* What the distributed estimators of mpi/analysis.h share: slab checks,
 * the global mean and range check, the 1D gather, and the FFTW-MPI grid a
 * slab is spread onto.  Every function is collective over the slab's
 * communicator and agrees on its status (nl_mpi_agree). */
#ifndef NL_MPI_ANALYSIS_INTERNAL_H
#define NL_MPI_ANALYSIS_INTERNAL_H

#include "analysis.h"
#include "../core/field.h"

#include <fftw3-mpi.h>
#include <stddef.h>

/* The slab is a field's (dim 1..3, sizes >= 1, spacings finite and > 0,
 * rows inside the field, data when ns > 0) and the processes' slabs tile
 * the slowest axis in rank order.  NL_OK or NL_EINVAL. */
int nl_mpi_slab_check(const nl_mpi_slab *x);

/* The samples of the slab as a 1D field view (no copy; count ns n0 ...). */
nl_field nl_mpi_slab_view(const nl_mpi_slab *x);

/* *m = mean when it is a number, else the sample mean of the whole field;
 * then nl_estimate_check_range's test over the whole field (spacing: the
 * density's cell too).  NL_OK or NL_EINVAL with its message. */
int nl_mpi_check_range(const nl_mpi_slab *x, double mean, int spacing, double *m);

/* 1D: the whole series on every process, in a new field (*out), with
 * x's spacing.  NL_OK, NL_EINVAL (not 1D, or too long for MPI's counts),
 * NL_ETOOBIG, NL_ENOMEM. */
int nl_mpi_gather_1d(const nl_mpi_slab *x, nl_field **out);

/* An FFTW-MPI real grid of g[0..dim-1] samples (2D or 3D), in place:
 * this process holds rows l0s .. l0s + ln0 - 1 of axis dim - 1, each of
 * `lines` lines (g1 in 3D, 1 in 2D) of pad0 = 2 (g0/2 + 1) doubles; after
 * the forward transform (transposed out), the half spectrum's indices
 * l1s .. l1s + ln1 - 1 of FFTW's second dimension (2D: the x frequency
 * 0..g0/2; 3D: the y frequency) are here, each of g[dim-1] (2D) or
 * g2 (g0/2 + 1) (3D) complex values. */
typedef struct {
    MPI_Comm comm;
    int dim;
    size_t g[3];
    ptrdiff_t ln0, l0s, ln1, l1s;
    size_t pad0, lines;
    double *buf;
    fftw_plan fwd, inv;   /* r2c transposed out; c2r transposed in (when asked) */
} nl_mpi_grid;

/* Plan the grid (inverse: also the c2r).  NL_OK, NL_ETOOBIG (this
 * process's share does not fit: nl_size_check), NL_ENOMEM, NL_EFAIL. */
int nl_mpi_grid_alloc(MPI_Comm comm, int dim, const size_t *g, int inverse, nl_mpi_grid *G);
void nl_mpi_grid_free(nl_mpi_grid *G);

/* Zero the grid and put the slab's samples minus m at the grid's first
 * n[a] indices per axis (zero padding beyond), moving rows between
 * processes by one MPI_Alltoallv.  NL_OK or NL_EFAIL. */
int nl_mpi_grid_fill(const nl_mpi_slab *x, double m, nl_mpi_grid *G);

#endif
