/* Distributed analysis: the autocorrelation, periodogram, moments and
 * histogram of a field cut in slabs over the processes of a communicator
 * (mpi/dist.h), giving what the one-process estimators of analysis/acf.h,
 * psd.h, spectral.h and hist.h give for the whole field, to rounding.
 *
 * Input: a field of n[0..dim-1] samples with spacing h (x fastest), cut
 * along its slowest axis dim - 1: this process holds rows s0 .. s0 + ns - 1
 * (ns may be 0), every other axis whole, row-major.  The slabs of the
 * processes, in rank order, must tile 0 .. n[dim-1] - 1 (nl_mpi_block's
 * cut does; any other contiguous cut in rank order does too).
 *
 * Method.  2D and 3D: the autocorrelation and periodogram are FFTW-MPI
 * transforms (fftw_mpi_plan_dft_r2c / c2r, in place) on FFTW's own slab
 * distribution, reached by one all-to-all of the input rows; the forward
 * transform leaves its output transposed (FFTW_MPI_TRANSPOSED_OUT) and the
 * autocorrelation's inverse takes it so (FFTW_MPI_TRANSPOSED_IN), which
 * saves two global transposes.  The averages over lags or frequencies are
 * partial sums per process, then MPI_Allreduce.  1D fields are small: every
 * process gathers the series and runs the one-process estimator (the same
 * bits).  The moments and the histogram are reductions of per-process
 * sums, counts and extremes.  No process holds more than its share of the
 * (padded) grid plus O(lags + bins).
 *
 * Agreement with the one-process results: the transforms and the sums run
 * in another order, so values agree to rounding, not bitwise (measured by
 * tests/mpi/analysis.c: within 1e-12 of the largest |value| of each
 * estimate, 6.3e-14 at worst for P = 1..4); counts, bins and edges are
 * exact.
 *
 * Every function is collective over comm (every process calls it with the
 * same dim, n, h and options and its own slab) and agrees on its status
 * (nl_mpi_agree): every process returns the same code and message.  The
 * results are on every process.  Needs MPI initialised and, for 2D and 3D
 * estimates, fftw_mpi_init() called.  Not thread-safe (FFTW's planner). */
#ifndef NL_MPI_ANALYSIS_H
#define NL_MPI_ANALYSIS_H

#include "../analysis/hist.h"
#include "../analysis/slope.h"

#include <mpi.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One process's part of a distributed field. */
typedef struct {
    MPI_Comm comm;       /* the processes holding the field */
    int dim;             /* 1, 2 or 3 */
    size_t n[3];         /* samples per axis of the whole field (1 beyond dim) */
    double h[3];         /* spacing per axis (1 beyond dim) */
    size_t s0, ns;       /* this process's rows along axis dim - 1 */
    const double *data;  /* ns n[0] ... n[dim-2] samples, row-major (NULL when ns = 0) */
} nl_mpi_slab;

/* The autocorrelation estimate of analysis/acf.h (biased or unbiased,
 * about `mean`, NAN for the sample mean) along `axis` for lags 0..maxlag
 * (samples): lag[i] = i h_axis, val[i] as nl_acf_full then nl_acf_axis.
 * Returns NL_OK, NL_EINVAL (a bad slab, axis or maxlag >= n_axis, or
 * samples whose sums overflow: nl_estimate_check_range), NL_ETOOBIG (the
 * padded share does not fit this process: nl_size_check, honouring
 * NOISELAB_MEMORY_LIMIT), NL_ENOMEM, NL_EFAIL (FFTW-MPI or MPI failed). */
int nl_mpi_acf_axis(const nl_mpi_slab *x, double mean, int unbiased, int axis, size_t maxlag, double *lag,
                    double *val);

/* The radial average of the full estimate in nbins bins one spacing (the
 * smallest h_a) wide, as nl_acf_full then nl_acf_radial: lag, val (NAN
 * when empty) and cnt hold nbins entries.  Codes as nl_mpi_acf_axis. */
int nl_mpi_acf_radial(const nl_mpi_slab *x, double mean, int unbiased, size_t nbins, double *lag, double *val,
                      size_t *cnt);

/* What nl_mpi_psd may add to the profile (NULL: nothing). */
typedef struct {
    /* 2D: the nsec angular sectors of nl_psd_sectors over flo <= |f| <= fhi
     * cycles per sample into sector[0..nsec-1] and their max/min into
     * aniso, when sector is not NULL */
    size_t nsec;
    double flo, fhi, *sector, aniso;
    /* when slope is set: the fit of log P on log |f| over fmin <= |f| <=
     * fmax into sl, as nl_psd_slope on the 1D half spectrum (E = 1) or
     * nl_psd_slope_grid on a 2D/3D periodogram (every ordinate, each
     * Hermitian pair once) */
    int slope;
    double fmin, fmax;
    nl_slope sl;
} nl_mpi_psd_more;

/* The periodogram of analysis/psd.h (about mean, NAN: the sample mean) as
 * the profile of nl_psd_profile (1D: the half spectrum; 2D/3D: the radial
 * average): freq, val and cnt hold nl_mpi_psd_profile_size entries, *nf
 * receives their number; and what `more` asks for.  Codes as
 * nl_mpi_acf_axis; NL_EINVAL also for sectors of a field not 2D and for a
 * slope band holding fewer than 3 ordinates (as nl_psd_slope). */
int nl_mpi_psd(const nl_mpi_slab *x, double mean, double *freq, double *val, size_t *cnt, size_t *nf,
               nl_mpi_psd_more *more);

/* nl_psd_profile_size for a field of dim, n[0..dim-1], h.  Pure. */
size_t nl_mpi_psd_profile_size(int dim, const size_t *n, const double *h);

/* The moments of nl_moments_compute over the whole field (n, mean,
 * unbiased variance, skewness, excess kurtosis, min, max).  Returns NL_OK
 * or NL_EINVAL (a bad slab, fewer than 2 samples, or overflowing moments,
 * as nl_moments_compute). */
int nl_mpi_moments(const nl_mpi_slab *x, nl_moments *m);

/* The histogram of nl_hist over the whole field: the same edges[0..bins]
 * and the same counts[0..bins-1] (exact).  Returns NL_OK or the codes of
 * nl_hist (NL_EINVAL, NL_ENOMEM). */
int nl_mpi_hist(const nl_mpi_slab *x, size_t bins, double *edges, double *counts);

#ifdef __cplusplus
}
#endif

#endif
