/* Distributed autocorrelation estimates: the lag sums of eq. (15) (Lewis
 * 1987) by FFTW-MPI on the zero-padded grid of core/autocorr.h, then the
 * divisors of analysis/acf.h, then the axis or radial extraction. */
#include "analysis_internal.h"
#include "dist.h"
#include "../analysis/acf.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdlib.h>

/* The full estimate on the padded grid G (2 n_a per axis), this process's
 * rows, as nl_acf_plan_execute makes it: lag sums over the padded count,
 * then over N (biased) or the pairs at each lag (unbiased). */
static int full_estimate(const nl_mpi_slab *x, double mean, int unbiased, nl_mpi_grid *G)
{
    size_t g[3], N = x->n[0] * x->n[1] * x->n[2], count, half;
    double m;
    int st = nl_mpi_check_range(x, mean, 0, &m);
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    for (int a = 0; a < 3; a++)
        g[a] = a < x->dim ? 2 * x->n[a] : 1;
    count = g[0] * g[1] * g[2];
    if ((st = nl_mpi_grid_alloc(x->comm, x->dim, g, 1, G)))
        return st;
    if ((st = nl_mpi_grid_fill(x, m, G))) {
        nl_mpi_grid_free(G);
        return st;
    }
    fftw_execute(G->fwd);
    /* |F|^2, in the transposed layout: ln1 x g[dim-1] x (g2 (g0/2 + 1) in 3D) */
    half = (size_t)G->ln1 * g[x->dim - 1] * (x->dim == 3 ? G->pad0 / 2 : 1);
    for (size_t i = 0; i < half; i++) {
        double re = G->buf[2 * i], im = G->buf[2 * i + 1];
        G->buf[2 * i] = re * re + im * im, G->buf[2 * i + 1] = 0;
    }
    fftw_execute(G->inv);
    for (size_t r = 0; r < (size_t)G->ln0; r++)
        for (size_t j = 0; j < G->lines; j++)
            for (size_t i = 0; i < g[0]; i++) {
                size_t idx[3] = {i, x->dim == 3 ? j : (size_t)G->l0s + r, (size_t)G->l0s + r};
                double w = unbiased ? 1.0 : (double)N, *c = G->buf + (r * G->lines + j) * G->pad0 + i;
                for (int a = 0; unbiased && a < x->dim; a++)
                    w *= (double)x->n[a] - fabs((double)nl_wrap(idx[a], g[a]));
                *c = *c / (double)count;
                *c /= w > 0 ? w : 1.0;
            }
    return NL_OK;
}

/* The 1D estimate on every process (the series is small). */
static int full_1d(const nl_mpi_slab *x, double mean, int unbiased, nl_field **full)
{
    nl_field *f;
    int st = nl_mpi_gather_1d(x, &f);
    if (st)
        return st;
    st = nl_acf_full(f, mean, unbiased, full);
    nl_field_free(f);
    return nl_mpi_agree(x->comm, st);
}

int nl_mpi_acf_axis(const nl_mpi_slab *x, double mean, int unbiased, int axis, size_t maxlag, double *lag,
                    double *val)
{
    nl_mpi_grid G;
    nl_field *full;
    int st = nl_mpi_slab_check(x);
    if (st)
        return st;
    if (axis < 0 || axis >= x->dim)
        st = NL_ERROR(NL_EINVAL, "axis: expected an axis of the %d-D field, got %d", x->dim, axis);
    else if (maxlag >= x->n[axis])
        st = NL_ERROR(NL_EINVAL, "max-lag: expected at most %zu samples, got %zu", x->n[axis] - 1, maxlag);
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    if (x->dim == 1) {
        if (!(st = full_1d(x, mean, unbiased, &full)))
            st = nl_acf_axis(full, axis, maxlag, lag, val);
        nl_field_free(full);
        return nl_mpi_agree(x->comm, st);
    }
    if ((st = full_estimate(x, mean, unbiased, &G)))
        return st;
    /* lag l along axis is the point l e_axis: on the process holding its row */
    for (size_t l = 0; l <= maxlag; l++) {
        size_t idx[3] = {0, 0, 0}, r;
        idx[axis] = l;
        r = idx[x->dim - 1];
        lag[l] = (double)l * x->h[axis], val[l] = 0;
        if (r >= (size_t)G.l0s && r < (size_t)(G.l0s + G.ln0))
            val[l] = G.buf[((r - (size_t)G.l0s) * G.lines + (x->dim == 3 ? idx[1] : 0)) * G.pad0 + idx[0]];
    }
    nl_mpi_grid_free(&G);
    if (MPI_Allreduce(MPI_IN_PLACE, val, (int)(maxlag + 1), MPI_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: collecting the lags failed");
    return nl_mpi_agree(x->comm, st);
}

/* Bin sums of the radial average (analysis/radial.h, lag grid) over this
 * process's rows, then over every process. */
static int radial_sums(const nl_mpi_slab *x, const nl_mpi_grid *G, double step, size_t nbins, double *r, double *v,
                       size_t *cnt)
{
    unsigned long long *c = calloc(nbins ? nbins : 1, sizeof *c);
    int st = NL_OK;
    if ((st = nl_mpi_agree(x->comm, c ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for %zu bins", nbins))))
        return free(c), st;
    for (size_t b = 0; b < nbins; b++)
        r[b] = v[b] = 0;
    for (size_t row = 0; row < (size_t)G->ln0; row++)
        for (size_t j = 0; j < G->lines; j++)
            for (size_t i = 0; i < G->g[0]; i++) {
                size_t idx[3] = {i, x->dim == 3 ? j : (size_t)G->l0s + row, (size_t)G->l0s + row};
                double d2 = 0, d, q;
                for (int a = 0; a < x->dim; a++) {
                    double e = nl_wrap(idx[a], G->g[a]) * x->h[a];
                    d2 += e * e;
                }
                d = sqrt(d2), q = floor(d / step + 0.5);
                if (!(q < (double)nbins))
                    continue;
                r[(size_t)q] += d, v[(size_t)q] += G->buf[(row * G->lines + j) * G->pad0 + i], c[(size_t)q]++;
            }
    if (MPI_Allreduce(MPI_IN_PLACE, r, (int)nbins, MPI_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS ||
        MPI_Allreduce(MPI_IN_PLACE, v, (int)nbins, MPI_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS ||
        MPI_Allreduce(MPI_IN_PLACE, c, (int)nbins, MPI_UNSIGNED_LONG_LONG, MPI_SUM, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: summing the radial bins failed");
    for (size_t b = 0; b < nbins; b++) {
        cnt[b] = (size_t)c[b];
        r[b] = cnt[b] ? r[b] / (double)cnt[b] : NAN;
        v[b] = cnt[b] ? v[b] / (double)cnt[b] : NAN;
    }
    free(c);
    return nl_mpi_agree(x->comm, st);
}

int nl_mpi_acf_radial(const nl_mpi_slab *x, double mean, int unbiased, size_t nbins, double *lag, double *val,
                      size_t *cnt)
{
    nl_mpi_grid G;
    nl_field *full;
    double step = x->h[0];
    int st = nl_mpi_slab_check(x);
    if (st)
        return st;
    if (nbins > (size_t)1 << 30)
        st = NL_ERROR(NL_EINVAL, "radial average: expected at most 2^30 bins, got %zu", nbins);
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    if (x->dim == 1) {
        if (!(st = full_1d(x, mean, unbiased, &full)))
            st = nl_acf_radial(full, nbins, lag, val, cnt);
        nl_field_free(full);
        return nl_mpi_agree(x->comm, st);
    }
    for (int a = 1; a < x->dim; a++)
        step = fmin(step, x->h[a]);
    if ((st = full_estimate(x, mean, unbiased, &G)))
        return st;
    st = radial_sums(x, &G, step, nbins, lag, val, cnt);
    nl_mpi_grid_free(&G);
    return st;
}
