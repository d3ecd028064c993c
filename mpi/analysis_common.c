/* Shared parts of the distributed estimators: slabs, the global mean and
 * range, the 1D gather, and the FFTW-MPI grid. */
#include "analysis_internal.h"
#include "dist.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Samples per row (along axis dim - 1) of a field of n[0..dim-1]. */
static size_t row_len(int dim, const size_t *n) { return dim == 3 ? n[0] * n[1] : dim == 2 ? n[0] : 1; }

static int slab_local(const nl_mpi_slab *x)
{
    if (x->dim < 1 || x->dim > 3)
        return NL_ERROR(NL_EINVAL, "distributed field: expected 1 to 3 dimensions, got %d", x->dim);
    for (int a = 0; a < 3; a++) {
        if (a < x->dim && x->n[a] < 1)
            return NL_ERROR(NL_EINVAL, "distributed field: axis %d: expected at least 1 sample, got 0", a);
        if (!(x->h[a] > 0) || !isfinite(x->h[a]))
            return NL_ERROR(NL_EINVAL, "distributed field: axis %d: expected a positive spacing, got %g", a, x->h[a]);
    }
    if (x->n[x->dim - 1] > INT_MAX || row_len(x->dim, x->n) > INT_MAX)
        return NL_ERROR(NL_EINVAL, "distributed field: expected at most %d rows of at most %d samples", INT_MAX, INT_MAX);
    if (x->s0 > x->n[x->dim - 1] || x->ns > x->n[x->dim - 1] - x->s0)
        return NL_ERROR(NL_EINVAL, "distributed field: rows %zu..%zu are outside the %zu of axis %d", x->s0,
                        x->s0 + x->ns, x->n[x->dim - 1], x->dim - 1);
    if (x->ns && !x->data)
        return NL_ERROR(NL_EINVAL, "distributed field: %zu rows and no samples", x->ns);
    return NL_OK;
}

int nl_mpi_slab_check(const nl_mpi_slab *x)
{
    int st = slab_local(x), P, rank;
    unsigned long long mine[2] = {x->s0, x->ns}, *all;
    if (MPI_Comm_size(x->comm, &P) != MPI_SUCCESS || MPI_Comm_rank(x->comm, &rank) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: the communicator cannot be queried");
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    if (!(all = malloc(2 * (size_t)P * sizeof *all)))
        st = NL_ERROR(NL_ENOMEM, "out of memory for %d slabs", P);
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    if (MPI_Allgather(mine, 2, MPI_UNSIGNED_LONG_LONG, all, 2, MPI_UNSIGNED_LONG_LONG, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: gathering the slabs failed");
    for (int q = 0, next = 0; !st && q < P; q++) {
        if (all[2 * q + 1] && all[2 * q] != (unsigned long long)next)
            st = NL_ERROR(NL_EINVAL, "distributed field: process %d holds rows from %llu, expected %d (the slabs "
                          "must tile axis %d in rank order)", q, all[2 * q], next, x->dim - 1);
        next += (int)all[2 * q + 1];
        if (!st && q == P - 1 && (size_t)next != x->n[x->dim - 1])
            st = NL_ERROR(NL_EINVAL, "distributed field: the slabs hold %d rows, expected %zu", next, x->n[x->dim - 1]);
    }
    free(all);
    return nl_mpi_agree(x->comm, st);
}

nl_field nl_mpi_slab_view(const nl_mpi_slab *x)
{
    nl_field v = {.dim = 1, .n = {x->ns * row_len(x->dim, x->n), 1, 1}, .h = {1, 1, 1}};
    v.count = v.n[0], v.data = (double *)x->data;
    return v;
}

/* The deviation bound of nl_estimate_check_range (analysis/acf.h), over the
 * whole field: max |x - m| from every process. */
int nl_mpi_check_range(const nl_mpi_slab *x, double mean, int spacing, double *m)
{
    size_t cnt = x->ns * row_len(x->dim, x->n), N = row_len(x->dim, x->n) * x->n[x->dim - 1];
    double s = 0, d = 0, cell = x->h[0] * x->h[1] * x->h[2], bound = sqrt(DBL_MAX / 16.0) / (double)N;
    for (size_t i = 0; isnan(mean) && i < cnt; i++)
        s += x->data[i];
    if (isnan(mean) && MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS)
        return nl_mpi_agree(x->comm, NL_ERROR(NL_EFAIL, "MPI: summing the samples failed"));
    *m = isnan(mean) ? s / (double)N : mean;
    for (size_t i = 0; i < cnt; i++)
        d = fmax(d, fabs(x->data[i] - *m));
    if (MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MAX, x->comm) != MPI_SUCCESS)
        return nl_mpi_agree(x->comm, NL_ERROR(NL_EFAIL, "MPI: the largest deviation could not be found"));
    if (!isfinite(*m) || !(d <= bound))
        return NL_ERROR(NL_EINVAL,
                        "the samples deviate from their mean %g by up to %g: the sums of squares of the estimate "
                        "overflow; expected deviations below %.3g (sqrt(DBL_MAX / 16) / %zu samples)",
                        *m, d, bound, N);
    if (spacing && !isfinite(d * d * (double)N * (double)N * cell))
        return NL_ERROR(NL_EINVAL,
                        "the samples deviate from their mean %g by up to %g: the spectral density overflows at the "
                        "cell %g; expected deviations below %.3g (sqrt(DBL_MAX / cell) / %zu samples)",
                        *m, d, cell, sqrt(DBL_MAX / cell) / (double)N, N);
    return NL_OK;
}

int nl_mpi_gather_1d(const nl_mpi_slab *x, nl_field **out)
{
    int P, st = NL_OK, *cnt = NULL, *disp = NULL, mine = (int)x->ns;
    nl_field *f = NULL;
    *out = NULL;
    MPI_Comm_size(x->comm, &P);
    if (x->dim != 1)
        st = NL_ERROR(NL_EINVAL, "gather: expected a 1D field, got %dD", x->dim);
    else if (!(f = nl_field_alloc(1, x->n, x->h, &st)))
        ;
    else if (!(cnt = malloc(2 * (size_t)P * sizeof *cnt)))
        st = NL_ERROR(NL_ENOMEM, "out of memory for %d counts", P);
    if ((st = nl_mpi_agree(x->comm, st))) {
        nl_field_free(f), free(cnt);
        return st;
    }
    disp = cnt + P;
    if (MPI_Allgather(&mine, 1, MPI_INT, cnt, 1, MPI_INT, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: gathering the slab sizes failed");
    for (int q = 0, at = 0; q < P; q++)
        disp[q] = at, at += cnt[q];
    if (!st && MPI_Allgatherv(x->ns ? x->data : f->data, mine, MPI_DOUBLE, f->data, cnt, disp, MPI_DOUBLE, x->comm) !=
                   MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: gathering the series failed");
    free(cnt);
    if ((st = nl_mpi_agree(x->comm, st))) {
        nl_field_free(f);
        return st;
    }
    *out = f;
    return NL_OK;
}

void nl_mpi_grid_free(nl_mpi_grid *G)
{
    if (G->fwd)
        fftw_destroy_plan(G->fwd);
    if (G->inv)
        fftw_destroy_plan(G->inv);
    fftw_free(G->buf);
    G->fwd = G->inv = NULL, G->buf = NULL;
}

int nl_mpi_grid_alloc(MPI_Comm comm, int dim, const size_t *g, int inverse, nl_mpi_grid *G)
{
    ptrdiff_t D[3], Dc[3], alloc;
    size_t two;
    int st = NL_OK;
    memset(G, 0, sizeof *G);
    G->comm = comm, G->dim = dim;
    for (int a = 0; a < 3; a++)
        G->g[a] = a < dim ? g[a] : 1;
    for (int a = 0; a < dim; a++) /* FFTW's order: slowest axis first */
        D[a] = Dc[a] = (ptrdiff_t)G->g[dim - 1 - a];
    Dc[dim - 1] = D[dim - 1] / 2 + 1;
    G->pad0 = 2 * (G->g[0] / 2 + 1), G->lines = dim == 3 ? G->g[1] : 1;
    alloc = fftw_mpi_local_size_transposed(dim, Dc, comm, &G->ln0, &G->l0s, &G->ln1, &G->l1s);
    two = 2 * (size_t)(alloc > 0 ? alloc : 1);
    if ((st = nl_size_check(1, &two, sizeof(double), 1, NULL))) {
        char why[256];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        st = NL_ERROR(st, "this process's share of the %zu x %zu x %zu transform does not fit: %s; expected more "
                      "processes", G->g[0], G->g[1], G->g[2], why);
    } else if (!(G->buf = fftw_alloc_real(two)))
        st = NL_ERROR(NL_ENOMEM, "out of memory for this process's %zu doubles of the transform", two);
    if ((st = nl_mpi_agree(comm, st))) {
        nl_mpi_grid_free(G);
        return st;
    }
    /* planned before the grid is filled (FFTW_MEASURE would overwrite it) */
    G->fwd = fftw_mpi_plan_dft_r2c(dim, D, G->buf, (fftw_complex *)G->buf, comm,
                                   FFTW_ESTIMATE | FFTW_MPI_TRANSPOSED_OUT);
    if (inverse)
        G->inv = fftw_mpi_plan_dft_c2r(dim, D, (fftw_complex *)G->buf, G->buf, comm,
                                       FFTW_ESTIMATE | FFTW_MPI_TRANSPOSED_IN);
    if (!G->fwd || (inverse && !G->inv))
        st = NL_ERROR(NL_EFAIL, "FFTW-MPI could not plan a %d-D transform of %zu x %zu x %zu", dim, G->g[0], G->g[1],
                      G->g[2]);
    if ((st = nl_mpi_agree(comm, st)))
        nl_mpi_grid_free(G);
    return st;
}

/* The overlap of rows [a0, a0 + na) and [b0, b0 + nb): its start, its length. */
static void overlap(size_t a0, size_t na, size_t b0, size_t nb, size_t *o0, size_t *no)
{
    size_t lo = a0 > b0 ? a0 : b0, hi = a0 + na < b0 + nb ? a0 + na : b0 + nb;
    *o0 = lo, *no = hi > lo ? hi - lo : 0;
}

/* Counts and displacements, in rows, of what this process sends to and
 * receives from each process q: its slab against q's grid rows, and q's
 * slab against its own grid rows (mine: s0, ns, r0, nr; all: P of each). */
static void plan_moves(const unsigned long long *all, int P, const unsigned long long *mine, int *sc, int *sd,
                       int *rc, int *rd)
{
    for (int q = 0; q < P; q++) {
        const unsigned long long *o = all + 4 * q;
        size_t o0, no;
        overlap(mine[0], mine[1], o[2], o[3], &o0, &no);
        sc[q] = (int)no, sd[q] = no ? (int)(o0 - mine[0]) : 0;
        overlap(o[0], o[1], mine[2], mine[3], &o0, &no);
        rc[q] = (int)no, rd[q] = no ? (int)(o0 - mine[2]) : 0;
    }
}

/* The row types: a slab row is contiguous; a grid row is `lines` lines of
 * n0 samples pad0 apart, one grid row (lines pad0 doubles) long. */
static int row_types(const nl_mpi_slab *x, const nl_mpi_grid *G, MPI_Datatype *send, MPI_Datatype *recv)
{
    MPI_Datatype v;
    size_t lines = x->dim == 3 ? x->n[1] : 1;
    if (MPI_Type_contiguous((int)row_len(x->dim, x->n), MPI_DOUBLE, send) != MPI_SUCCESS)
        return 0;
    if (MPI_Type_vector((int)lines, (int)x->n[0], (int)G->pad0, MPI_DOUBLE, &v) != MPI_SUCCESS)
        return MPI_Type_free(send), 0;
    int ok = MPI_Type_create_resized(v, 0, (MPI_Aint)(G->lines * G->pad0 * sizeof(double)), recv) == MPI_SUCCESS;
    MPI_Type_free(&v);
    if (ok && MPI_Type_commit(send) == MPI_SUCCESS && MPI_Type_commit(recv) == MPI_SUCCESS)
        return 1;
    MPI_Type_free(send);
    if (ok)
        MPI_Type_free(recv);
    return 0;
}

int nl_mpi_grid_fill(const nl_mpi_slab *x, double m, nl_mpi_grid *G)
{
    int P, st = NL_OK, *cnt;
    unsigned long long mine[4] = {x->s0, x->ns, (unsigned long long)G->l0s, (unsigned long long)G->ln0}, *all;
    MPI_Datatype send, recv;
    size_t rows = x->n[x->dim - 1], lines = x->dim == 3 ? x->n[1] : 1;
    MPI_Comm_size(x->comm, &P);
    memset(G->buf, 0, (size_t)G->ln0 * G->lines * G->pad0 * sizeof(double));
    cnt = malloc(4 * (size_t)P * sizeof *cnt);
    all = malloc(4 * (size_t)P * sizeof *all);
    if (!cnt || !all)
        st = NL_ERROR(NL_ENOMEM, "out of memory for the moves of %d processes", P);
    if ((st = nl_mpi_agree(x->comm, st)))
        return free(cnt), free(all), st;
    if (MPI_Allgather(mine, 4, MPI_UNSIGNED_LONG_LONG, all, 4, MPI_UNSIGNED_LONG_LONG, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: gathering the slabs failed");
    else if (!row_types(x, G, &send, &recv))
        st = NL_ERROR(NL_EFAIL, "MPI: the row types could not be made");
    if ((st = nl_mpi_agree(x->comm, st)))
        return free(cnt), free(all), st;
    plan_moves(all, P, mine, cnt, cnt + P, cnt + 2 * P, cnt + 3 * P);
    if (MPI_Alltoallv(x->ns ? x->data : (const double *)G->buf, cnt, cnt + P, send, G->buf, cnt + 2 * P, cnt + 3 * P,
                      recv, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: moving the rows onto the transform's slabs failed");
    MPI_Type_free(&send), MPI_Type_free(&recv);
    free(cnt), free(all);
    /* the samples less the mean; the padding stays zero */
    for (size_t r = 0; r < (size_t)G->ln0 && (size_t)G->l0s + r < rows; r++)
        for (size_t j = 0; j < lines; j++) {
            double *line = G->buf + (r * G->lines + j) * G->pad0;
            for (size_t i = 0; i < x->n[0]; i++)
                line[i] -= m;
        }
    return nl_mpi_agree(x->comm, st);
}
