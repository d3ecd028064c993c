/* Distributed moments and histogram: per-process sums, counts and
 * extremes, reduced over the processes (analysis/hist.h's definitions). */
#include "analysis_internal.h"
#include "dist.h"
#include "../analysis/hist.h"
#include "../core/nl_error.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

/* Count, sum (long double, as GSL's running sums), min and max of every sample. */
static int first_pass(const nl_mpi_slab *x, unsigned long long *n, long double *sum, double *lo, double *hi)
{
    nl_field v = nl_mpi_slab_view(x);
    *n = v.count, *sum = 0, *lo = INFINITY, *hi = -INFINITY;
    for (size_t i = 0; i < v.count; i++) {
        *sum += v.data[i];
        *lo = fmin(*lo, v.data[i]), *hi = fmax(*hi, v.data[i]);
    }
    if (MPI_Allreduce(MPI_IN_PLACE, n, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, x->comm) != MPI_SUCCESS ||
        MPI_Allreduce(MPI_IN_PLACE, sum, 1, MPI_LONG_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS ||
        MPI_Allreduce(MPI_IN_PLACE, lo, 1, MPI_DOUBLE, MPI_MIN, x->comm) != MPI_SUCCESS ||
        MPI_Allreduce(MPI_IN_PLACE, hi, 1, MPI_DOUBLE, MPI_MAX, x->comm) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: reducing the samples' sums failed");
    return NL_OK;
}

/* Sums of powers 1..3 of (x - mean) / sd (sd = 1 for the variance pass:
 * s[0] = sum d^2), reduced over every process.  pass 2: d^2; pass 3: the
 * standardised cubes and fourth powers (as GSL forms them, so that the
 * powers do not overflow where the variance does not). */
static int power_sums(const nl_mpi_slab *x, double mean, double sd, int pass, long double *s)
{
    nl_field v = nl_mpi_slab_view(x);
    s[0] = s[1] = 0;
    for (size_t i = 0; i < v.count; i++) {
        long double d = (v.data[i] - mean) / sd;
        if (pass == 2)
            s[0] += d * d;
        else
            s[0] += d * d * d, s[1] += d * d * d * d;
    }
    if (MPI_Allreduce(MPI_IN_PLACE, s, 2, MPI_LONG_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS)
        return NL_ERROR(NL_EFAIL, "MPI: reducing the moments failed");
    return NL_OK;
}

int nl_mpi_moments(const nl_mpi_slab *x, nl_moments *m)
{
    unsigned long long n;
    long double sum, s[2];
    int st = nl_mpi_slab_check(x);
    if (st || (st = nl_mpi_agree(x->comm, first_pass(x, &n, &sum, &m->min, &m->max))))
        return st;
    if (n < 2)
        return NL_ERROR(NL_EINVAL, "moments: expected at least 2 samples, got %llu", n);
    m->n = (size_t)n, m->mean = (double)(sum / (long double)n);
    if (!isfinite(m->mean))
        return NL_ERROR(NL_EINVAL, "moments: the samples run from %g to %g: the mean and variance overflow; expected "
                        "max - min below %g", m->min, m->max, DBL_MAX);
    if ((st = nl_mpi_agree(x->comm, power_sums(x, m->mean, 1, 2, s))))
        return st;
    m->variance = (double)(s[0] / (long double)n) * ((double)n / (double)(n - 1));
    if (!isfinite(m->variance))
        return NL_ERROR(NL_EINVAL, "moments: the samples deviate from their mean %g by up to %g: the variance "
                        "overflows; expected deviations below %.3g (sqrt(DBL_MAX / 2))", m->mean,
                        fmax(m->max - m->mean, m->mean - m->min), sqrt(DBL_MAX / 2));
    if (m->variance == 0) {
        m->skewness = m->kurtosis = NAN;
        return NL_OK;
    }
    if ((st = nl_mpi_agree(x->comm, power_sums(x, m->mean, sqrt(m->variance), 3, s))))
        return st;
    m->skewness = (double)(s[0] / (long double)n);
    m->kurtosis = (double)(s[1] / (long double)n) - 3.0;
    return NL_OK;
}

int nl_mpi_hist(const nl_mpi_slab *x, size_t bins, double *edges, double *counts)
{
    unsigned long long n;
    long double sum;
    size_t two = 2;
    double lo, hi;
    nl_field *span = NULL, v = nl_mpi_slab_view(x);
    int st = nl_mpi_slab_check(x);
    if (st)
        return st;
    if (bins < 1 || bins > (size_t)1 << 30)
        st = NL_ERROR(NL_EINVAL, "bins: expected 1 to 2^30, got %zu", bins);
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    /* the edges depend on the range alone: those of the two-sample field
     * (min, max) are the whole field's (nl_hist) */
    if (!(st = first_pass(x, &n, &sum, &lo, &hi)) && (span = nl_field_alloc(1, &two, NULL, &st))) {
        span->data[0] = lo, span->data[1] = hi;
        st = nl_hist(span, bins, edges, counts);
    }
    nl_field_free(span);
    if ((st = nl_mpi_agree(x->comm, st)))
        return st;
    /* the same bins as nl_hist's GSL search: edges[b] <= v < edges[b + 1] */
    nl_hist_count(&v, edges, bins, counts);
    if (MPI_Allreduce(MPI_IN_PLACE, counts, (int)bins, MPI_DOUBLE, MPI_SUM, x->comm) != MPI_SUCCESS)
        st = NL_ERROR(NL_EFAIL, "MPI: summing the counts failed");
    return nl_mpi_agree(x->comm, st);
}
