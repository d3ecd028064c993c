/* An HDF5 field's origin survives a distributed read, under mpirun -np
 * 1..4 (tests/mpi/run.sh): process 0 writes a 2D field whose grid starts at
 * a recorded origin (nl_meta_set_origin: a map's first cell centre, not a
 * whole number of samples), every process reads its slab collectively
 * (nl_mpi_h5_read_slab), and each finds the same origin and spacing
 * (nl_meta_origin, to 4 ulps: stored in samples with 17 digits) and, at its
 * slab's rows, the values of a known function of the coordinates. */
#include "../../mpi/h5.h"
#include "../../core/mem.h"
#include "../../core/nl_error.h"
#include "../../core/provenance.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* The field's value at (x, y): float32-exact (a multiple of 2^-8 under 2^8). */
static double value(double x, double y) { return round(256 * (3 * x - 2 * y)) / 256; }

int main(int argc, char **argv)
{
    int rank, P, fails = 0, dim, st;
    size_t n[3] = {9, 7, 1}, s0, ns;
    double h[3] = {0.25, 0.75, 1}, o[3] = {-3.125, 10.375, 0}, got[3];
    char path[256];
    double *slab = NULL;
    nl_meta m = {0};
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &P);
    snprintf(path, sizeof path, "/tmp/nl-origin-%ld.h5", (long)getpid());
    MPI_Bcast(path, sizeof path, MPI_CHAR, 0, MPI_COMM_WORLD);
    if (rank == 0) {
        nl_field *f = nl_field_alloc(2, n, h, NULL);
        for (size_t j = 0; j < n[1]; j++)
            for (size_t i = 0; i < n[0]; i++)
                f->data[j * n[0] + i] = value(o[0] + (double)i * h[0], o[1] + (double)j * h[1]);
        if (nl_meta_set_origin(&m, 2, h, o) || nl_mpi_h5_write_field(path, f, &m, 0)) {
            fprintf(stderr, "origin: cannot write %s: %s\n", path, nl_errmsg());
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        nl_field_free(f);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    size_t rn[3];
    double rh[3];
    nl_meta rm;
    st = nl_mpi_h5_read_slab(path, MPI_COMM_WORLD, &dim, rn, rh, &rm, &s0, &ns, &slab);
    if (st || dim != 2 || rn[0] != n[0] || rn[1] != n[1]) {
        fprintf(stderr, "FAIL origin: rank %d: read %d (%s), %dD %zu x %zu\n", rank, st, nl_errmsg(), dim, rn[0], rn[1]);
        fails++;
    } else if (nl_meta_origin(&rm, 2, rn, rh, got)) {
        fprintf(stderr, "FAIL origin: rank %d: %s\n", rank, nl_errmsg());
        fails++;
    } else {
        for (int a = 0; a < 2; a++)
            if (fabs(got[a] - o[a]) > 4 * 0x1p-52 * fabs(o[a]) || rh[a] != h[a]) {
                fprintf(stderr, "FAIL origin: rank %d of %d: axis %d: origin %.17g spacing %g, expected %.17g %g\n",
                        rank, P, a, got[a], rh[a], o[a], h[a]);
                fails++;
            }
        for (size_t j = 0; j < ns; j++) /* the slab's rows at their own coordinates */
            for (size_t i = 0; i < rn[0]; i++) {
                double want = value(got[0] + (double)i * rh[0], got[1] + (double)(s0 + j) * rh[1]);
                if (slab[j * rn[0] + i] != want && fails++ < 5)
                    fprintf(stderr, "FAIL origin: rank %d: sample (%zu, %zu) %g, expected %g\n", rank, i, s0 + j,
                            slab[j * rn[0] + i], want);
            }
    }
    nl_free(slab);
    MPI_Allreduce(MPI_IN_PLACE, &fails, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank == 0)
        remove(path);
    MPI_Finalize();
    return fails != 0;
}
