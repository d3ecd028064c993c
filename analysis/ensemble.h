/* Ensemble averages of estimates: the mean of K realizations of an
 * estimate (a periodogram profile, an autocorrelation, a histogram, a
 * moment) and its standard error, so that the scatter of one estimate and
 * the gain of averaging can be read off the numbers.
 *
 * For realizations v_r[i], r = 0..K-1, of an estimate of m values,
 *     mean[i] = (1/K) sum_r v_r[i],
 *     se[i]   = sqrt( sum_r (v_r[i] - mean[i])^2 / ((K - 1) K) ),
 * the standard error of the mean of K independent realizations (the
 * sample standard deviation, divisor K - 1, over sqrt K).  Two passes, so
 * no cancellation.
 * Thread safety: reentrant (but for nl_welford, below); the caller owns
 * every array, and a source's callbacks are called from the calling
 * thread only. */
#ifndef NL_ENSEMBLE_H
#define NL_ENSEMBLE_H

#include "../core/field.h"
#include "hist.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* v: K rows of m values, row r at v + r m.  mean and se: m values each (se
 * may be NULL).  A column holding a non-finite value gives NAN in mean and
 * se.  Returns NL_OK or NL_EINVAL (K < 2 or m = 0: one realization has no
 * standard error). */
int nl_ensemble_mean_se(const double *v, size_t K, size_t m, double *mean, double *se);

/* Ensemble drivers: K fields in, the mean of their estimates and its
 * standard error (nl_ensemble_mean_se) out, each field visited once, in
 * order, and held only while its estimate is made.
 *
 * The fields come from an array or from a callback, so that a caller can
 * read or synthesise field k when it is needed (a file each, or seeds S +
 * k) and K fields need not fit in memory together.  For acf and psd every
 * field must have the first one's dim, size and spacing (NL_EINVAL
 * otherwise: the driver checks); moments and histograms take fields of any
 * size.
 *
 * Failure: the drivers return the status of the first step that fails and,
 * when `bad` is not NULL, the field it concerns: bad = k when field k could
 * not be had or estimated, bad = K when no one field is at fault (the K
 * estimates do not fit in memory: NL_ETOOBIG, checked before any field is
 * asked for, honouring NOISELAB_MEMORY_LIMIT; NL_ENOMEM).  Outputs are then
 * unspecified; nothing is leaked. */

/* Where an ensemble's fields come from. */
typedef struct {
    size_t K;                       /* number of fields */
    const nl_field *const *fields;  /* the K fields; NULL: ask get for each */
    /* Field k into *out, lent to the driver until put (when not NULL) hands
     * it back; the driver never frees it.  Returns NL_OK or a status, which
     * the driver returns (bad = k). */
    int (*get)(void *ctx, size_t k, const nl_field **out);
    void (*put)(void *ctx, size_t k, const nl_field *f);
    void *ctx;                      /* passed to get and put */
} nl_ensemble_source;

/* What nl_ensemble_acf estimates for each field (analysis/acf.h). */
typedef struct {
    double mean;    /* the known mean; NAN: each field's sample mean */
    int unbiased;   /* 1: divide by the pairs per lag; 0: by N */
    int axis;       /* lag direction 0 = x, 1 = y, 2 = z (not radial) */
    int radial;     /* 1: the radial average, bins one spacing wide */
    int direct;     /* 1: the direct sum (nl_acf_direct) along axis */
    size_t nlag;    /* lags 0 .. nlag - 1 (>= 1) */
} nl_ensemble_acf_opts;

/* The autocorrelation of each field (nl_acf_full then nl_acf_axis or
 * nl_acf_radial, or nl_acf_direct), the same numbers acf prints for one:
 * lag (length units; NAN for an empty radial bin), their mean acf and its
 * standard error se, nlag entries each.  K >= 2.  Returns NL_OK, NL_EINVAL
 * (K < 2, nlag 0, bad options, a field unlike the first), NL_ETOOBIG,
 * NL_ENOMEM or the estimators' codes. */
int nl_ensemble_acf(const nl_ensemble_source *src, const nl_ensemble_acf_opts *o, double *lag, double *acf,
                    double *se, size_t *bad);

/* What nl_ensemble_psd estimates for each field (analysis/psd.h, welch.h). */
typedef struct {
    double mean;    /* the known mean; NAN: each field's sample mean */
    size_t welch;   /* 0: the periodogram; else Welch's estimate, segments of this side */
} nl_ensemble_psd_opts;

/* The spectrum of each field: *P (a new field, released by nl_field_free;
 * NULL on failure) the mean of the K estimates on their grid, summed in
 * order then divided by K; and the profile of each estimate
 * (nl_psd_profile: 1D, or the radial average), freq, their mean psd and
 * its standard error se, *nf entries each: the arrays hold at least
 * n[0] + n[1] + n[2] of the fields (spectral.h).  *segments (may be NULL):
 * Welch's segments per field.  K >= 2.  Returns NL_OK, NL_EINVAL,
 * NL_ETOOBIG, NL_ENOMEM or the estimators' codes. */
int nl_ensemble_psd(const nl_ensemble_source *src, const nl_ensemble_psd_opts *o, nl_field **P, double *freq,
                    double *psd, double *se, size_t *nf, size_t *segments, size_t *bad);

/* The moments of each field (nl_moments_compute): in *mean the mean over
 * the fields of mean, variance, skewness and kurtosis, with n the samples
 * of all of them and min, max the overall range; in *se (may be NULL) the
 * standard errors of those four (n 0, min and max NAN).  K = 1 gives the
 * field's moments and NAN standard errors.  A moment undefined in some
 * field (a constant field's skewness) is NAN in both.  Returns NL_OK,
 * NL_EINVAL (K = 0, a field unlike the first) or nl_moments_compute's
 * codes. */
int nl_ensemble_moments(const nl_ensemble_source *src, nl_moments *mean, nl_moments *se, size_t *bad);

/* Histograms on common bins: edges (bins + 1 entries) the equal bins of
 * nl_hist over [lo, hi] (the overall range, nl_ensemble_moments), counts
 * and se (bins entries each) the mean count per field and its standard
 * error (nl_hist_count: a sample outside [lo, hi] counts in the first or
 * last bin).  K >= 2.  Returns
 * NL_OK, NL_EINVAL (K < 2; or, with bad = K, what nl_hist refuses of a
 * field spanning [lo, hi]: bins 0, a bound not finite), NL_ETOOBIG,
 * NL_ENOMEM or nl_hist_count's codes (bad = k). */
int nl_ensemble_hist(const nl_ensemble_source *src, size_t bins, double lo, double hi, double *edges,
                     double *counts, double *se, size_t *bad);

/* Welford's running mean and variance of realizations, sample by sample
 * (Welford 1962): after field k (from 0) is added, mean = the mean of the
 * k + 1 fields and m2 = the sum of their squared deviations from it,
 *     d = x - mean;  mean += d / (k + 1);  m2 += d (x - mean),
 * one pass with no cancellation.  Holds two fields of the realizations'
 * size.  Not thread-safe: one accumulator per thread. */
typedef struct nl_welford nl_welford;

/* An accumulator for fields of dim, n[0..dim-1] and spacing h (NULL: 1).
 * Returns NL_OK, NL_EINVAL, NL_ETOOBIG or NL_ENOMEM (*out NULL). */
int nl_welford_alloc(int dim, const size_t *n, const double *h, nl_welford **out);
void nl_welford_free(nl_welford *w);

/* Add one realization.  NL_EINVAL (nothing added) when its dim or size is
 * not the accumulator's. */
int nl_welford_add(nl_welford *w, const nl_field *f);

/* Realizations added. */
size_t nl_welford_count(const nl_welford *w);

/* The running mean, owned by the accumulator (valid until the next add or
 * free; all zero before the first add). */
const nl_field *nl_welford_mean(const nl_welford *w);

/* The unbiased variance m2 / (count - 1) of each sample into a new field
 * *out (0 everywhere while count < 2).  Returns NL_OK or NL_ENOMEM. */
int nl_welford_variance(const nl_welford *w, nl_field **out);

#ifdef __cplusplus
}
#endif

#endif
