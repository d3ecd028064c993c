/* Goodness of fit of a correlated field's marginal law: a parametric
 * bootstrap under the Gaussian-copula null, every sample kept.
 *
 * H0: the field's marginal law is F (the nl_dist d).  Under H0 the normal
 * scores y = Phi^-1(F(x)) (F(x) clipped to [1/(2n), 1 - 1/(2n)], n the
 * field's samples) are standard normal at every sample; the null model takes
 * them jointly Gaussian (a Gaussian copula) with the correlation the field
 * itself shows:
 *   1. rho: the sample autocorrelation of y (analysis/acf.h, FFT, sample mean
 *      removed, divided by the overlap: NL_ACF_UNBIASED, since the biased
 *      divisor would shrink the estimate by up to 44% at the window's edge,
 *      and the positive definiteness it buys is restored by step 4 anyway),
 *      normalised to 1 at lag 0;
 *   2. the first-order bias of removing the sample mean mended: every lag's
 *      estimate is low by about Var(ybar) = (1/N) sum_l rho(l); with W lags
 *      in the window below and S their estimated sum, rho <- (rho + V) /
 *      (1 + V) with V = S / (N - W) (the window holds the correlation);
 *   3. a flat-top lag window (Politis and Romano 1995, trapezoid with
 *      c = 1/2): weight 1 up to radius M / 2, falling linearly to 0 at M =
 *      2 r0 (Politis 2003's rule), r0 the first whole radius (in samples)
 *      at which the radial mean of rho is <= 0; M at most a quarter of the
 *      shortest axis (a window that tapers from lag 0, Bartlett's or
 *      Parzen's, would cut the integral of a Markov correlation by a
 *      third);
 *   4. the windowed rho placed on the field's own periodic grid (wrapped
 *      lags, core/wk.h: M <= n/4 never wraps onto itself), turned into a
 *      spectrum (nl_wk_acf_to_spectrum), negative ordinates set to 0, and
 *      scaled to unit variance.
 * A null field g_b is that spectrum's FFT synthesis (synth/fft.h) with the
 * white noise of seed s_b (Random123); u = Phi(g_b) then has exactly the
 * uniform marginal and the field's own dependence, and x_b = F^-1(u) (the
 * exact map nl_dist_transform) is a null realization of the field.  An
 * ensemble of K independent fields draws one null field per input, each
 * from that input's own spectrum, and every statistic pools all samples.
 *
 * Statistics T, on the data (u = F(x)) and on each of the B draws:
 *   ks        D = sup |F_n(u) - u| of the pooled u (that of x against F);
 *   chi2      X^2 on `bins` equal-probability bins of u;
 *   mean, variance (divisor n - 1), skewness, kurtosis (excess; GSL's
 *             definitions, as analysis/hist.h): of x, each only when the law
 *             has it and the moment its normal law needs (nl_dist_mean ..
 *             nl_dist_kurtosis finite: the variance for the mean, the
 *             kurtosis for the other three).
 * p-values, each statistic against its own bootstrap null (so that values
 * far below 1/B can be reported, the null is summarised by a law):
 *   moments   two-sided Student t, t = (g(T) - m_b) / s_b with m_b and s_b
 *             the draws' mean and sd of g(T_b), g the log for the variance
 *             and log(kurtosis + 3) for the kurtosis (their nulls are
 *             skewed like a chi-square's; the logs are nearly symmetric),
 *             the identity for the mean and skewness: sample moments of a
 *             short-range dependent field are asymptotically normal (a
 *             central limit theorem for mixing fields, e.g. Bolthausen
 *             1982), and s_b rests on a spectrum estimated from the field
 *             itself, with the equivalent degrees of freedom nu = 2 N /
 *             sum_l w(l)^2 of its lag window w (Priestley 1981, eq.
 *             (6.2.124); summed over an ensemble's fields): a normal law
 *             would ignore the noise of that estimate and reject too often;
 *   chi2      a chi2_nu law scaled by a, matched to the draws' mean m and
 *             variance v (Satterthwaite 1946): a = v / (2m), nu = 2m^2 / v,
 *             p = Q_chi2(X^2 / a; nu);
 *   ks        the Kolmogorov law moved and scaled, Q_KS(sqrt(n_eff) (D - c)),
 *             c and n_eff such that the draws' median and 95% quantile of D
 *             are the law's, 0.8275735551899077 and 1.3580986393225505:
 *             the D of a correlated field has a longer tail than the
 *             Kolmogorov law with n_eff matched at the median alone (its
 *             supremum follows a few slow modes), which rejected 17% of
 *             null fields at 5% (experiments/gof_boot_rates.c);
 * and the rank p-value (1 + #{T_b >= T}) / (B + 1) of each (moments:
 * |g(T_b) - m_b| >= |g(T) - m_b|).  The verdict is Bonferroni's: the smallest
 * approximate p times the number of statistics tested, at most 1.
 *
 * Power at the 5% level (80% power):
 *   variance  a field scaled about its mean so that its variance is r times
 *             the law's has a variance statistic r times the null's: its
 *             log moves by log r and keeps its sd s (the draws' sd of the
 *             log variance); the test (t law, nu degrees of freedom)
 *             rejects it 80% of the time when |log r| = (t_0.975 + t_0.8) s
 *             (t_q: quantiles of t_nu), r = exp(+-(t_0.975 + t_0.8) s);
 *   ks        a law at KS distance delta from F, attained at some u*, gives
 *             D >= |F_n(u*) - F_alt(u*)| ~ delta + e with e of sd at most
 *             sigma_1/2 (the draws' sd of F_n(1/2) - 1/2: the median
 *             indicator is the one of largest variance); D exceeds the
 *             draws' 95% quantile q_95 at least 80% of the time when
 *             delta = q_95 + z_0.8 sigma_1/2 (z_0.8 = 0.841621).
 *
 * Thread safety: plans FFTW (analysis/acf.h, synth/fft.h): not thread-safe;
 * x and d are only read.  Memory: about six times the samples in doubles,
 * besides the input. */
#ifndef NL_GOF_BOOT_H
#define NL_GOF_BOOT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/dist.h"
#include "../core/field.h"

#include <stddef.h>
#include <stdint.h>

/* Default number of null draws and seed (noiselab hist --draws, --draw-seed). */
#define NL_GOF_BOOT_DRAWS 199
#define NL_GOF_BOOT_SEED 1

/* The statistics, in the order of nl_gof_boot.stat. */
enum { NL_GOF_KS, NL_GOF_CHI2, NL_GOF_MEAN, NL_GOF_VARIANCE, NL_GOF_SKEWNESS, NL_GOF_KURTOSIS, NL_GOF_NSTATS };

/* One statistic and its bootstrap null. */
typedef struct {
    int tested;        /* 1: computed; 0: the law lacks this moment (the rest is NAN) */
    double value;      /* on the data (all fields pooled) */
    double expected;   /* the law's value (moments; NAN for ks and chi2) */
    double null_mean;  /* mean over the draws */
    double null_sd;    /* standard deviation over the draws */
    double p;          /* approximate p-value (see above) */
    double p_rank;     /* rank p-value, >= 1 / (B + 1) */
} nl_gof_boot_stat;

/* The test's outcome. */
typedef struct {
    size_t n;                          /* samples in all */
    size_t fields;                     /* K */
    size_t draws;                      /* B */
    size_t bins;                       /* chi-square bins */
    size_t tests;                      /* statistics tested (2 to 6) */
    nl_gof_boot_stat stat[NL_GOF_NSTATS]; /* indexed by NL_GOF_KS .. */
    double ks_n_eff, ks_shift;         /* n_eff and c of the KS p-value */
    double moment_dof;                 /* nu of the moments' t law */
    double chi2_scale, chi2_dof;       /* a and nu of the chi-square p-value */
    double p;                          /* verdict: min p times tests, at most 1 */
    int p_from;                        /* the statistic of the smallest p */
    double var_ratio_lo, var_ratio_hi; /* variance ratios detected 80% of the time at 5% (NAN: no variance test) */
    double ks_q95;                     /* the draws' 95% quantile of D */
    double ks_detectable;              /* KS distance detected 80% of the time at 5% */
    double radius_min, radius_max;     /* M over the fields (samples; 0: no correlation found) */
} nl_gof_boot;

/* The test of the K >= 1 fields x[0..K-1] (1 to 3D, each of at least 2
 * samples; independent of each other) against d, with B = draws >= 2 null
 * draws from seed and chi-square on 2 <= bins <= n equal-probability bins.
 * Draw b of field k uses seed s_bk = a 64-bit mix of (seed, b, k).
 * Returns NL_OK, NL_EINVAL (K = 0, draws < 2, bins out of range, a field of
 * fewer than 2 samples or not finite, d an expr: without a CDF), NL_ETOOBIG
 * / NL_ENOMEM, NL_EFAIL (FFTW); *out is untouched on failure. */
int nl_gof_boot_test(const nl_field *const *x, size_t K, const nl_dist *d, size_t draws, uint64_t seed, size_t bins,
                     nl_gof_boot *out);

/* The null spectrum of one field (steps 1 to 4 above): *S (released by
 * nl_field_free) on x's grid with unit spacing, wrapped order, two-sided,
 * mean 1 over the grid (unit variance); *radius = M (0 when the normal
 * scores are constant: S = 1, white), *dof = nu of the window (2 N when
 * white).  Returns NL_OK, NL_EINVAL (fewer than
 * 2 samples, an expr: law), NL_ETOOBIG / NL_ENOMEM, NL_EFAIL; *S is NULL on
 * failure. */
int nl_gof_boot_spectrum(const nl_field *x, const nl_dist *d, nl_field **S, double *radius, double *dof);

/* "ks", "chi2", "mean", "variance", "skewness", "kurtosis" (a static
 * string; NULL for another index). */
const char *nl_gof_boot_name(int stat);

#ifdef __cplusplus
}
#endif

#endif
