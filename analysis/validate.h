/* Validation of a model's synthesis: does each method reproduce the target,
 * and by how much does it miss?
 *
 * For each method the registry marks NL_METHOD_VALIDATED (synth/method.h),
 * exact methods first (nl_method_ranked), and for each other choice of its
 * CHOICE options (a variant, "METHOD-CHOICE": subdivision with correlated
 * displacements) the model is planned once and M
 * realizations (seeds S..S+M-1, S = 1 by default) are synthesised on a grid of unit spacing (lags
 * in samples, frequencies in cycles per sample).  Each realization gives
 * the unbiased ACF with known mean 0 (analysis/acf.h, E r(l) = C(l)) and the
 * periodogram with known mean 0 (analysis/psd.h); the ensemble gives their
 * means and standard errors se = sd / sqrt(M) (analysis/verdict.h).
 *
 * Lags tested: along each direction (x; x, y and the diagonal (1, 1) in 2D;
 * x, y, z and the diagonal (1, 1, 1) in 3D) from 0 to the last lag at which
 * |R| > 5% of R(0), plus one, but at most a quarter of the shortest axis
 * the direction crosses (at least 4 lags); and the lag map: every lag of
 * the half box 0 <= |l_a| <= W (l and -l estimate the same sum, so one of
 * each pair), W = the longest direction's last lag, at most
 * NL_VALIDATE_MAP_2D (2D) or NL_VALIDATE_MAP_3D (3D).  T lags in all.
 *
 * Per method, with d(l) = mean(l) - R(l) and everything divided by R(0):
 *   - z(l) = |d(l)| / se(l); max |z| against the Bonferroni threshold of
 *     Student's t(M - 1) at family-wise rate alpha over the T lags
 *     (nl_verdict_threshold): `detected` says whether any error was found.
 *   - effect size e = max_l |d(l)| / R(0) over a set of lags, with a
 *     conservative 95% interval from simultaneous intervals
 *     d(l) +- c se(l), c = nl_verdict_threshold(0.05, T, M - 1):
 *         lo = max_l max(0, |d(l)| - c se(l)),  hi = max_l (|d(l)| + c se(l))
 *     (each over R(0)); whenever every d(l) lies in its interval, which has
 *     probability >= 95%, the true largest error lies in [lo, hi].
 *   - detectable error: (t_thr + t_0.8) max_l se(l) / R(0), t_thr the
 *     verdict's threshold and t_0.8 the 80% quantile of t(M - 1): an error
 *     of this size at any tested lag is detected with about 80% power.
 *   - variance ratio mean r(0) / R(0) +- t_0.975 se(0) / R(0).
 *   - spectrum: the periodogram averaged over octave bands of radial
 *     frequency |f|, band b holding 0.5 2^-(b+1) < |f| <= 0.5 2^-b (band 0
 *     also the corners above 0.5), against the band mean of its expectation
 *     for the method's covariance: the model's spectrum sampled on the
 *     periodic grid (nl_wk_sample_spectrum) for the periodic methods (fft,
 *     subdiv, sparse wrapped), the Fejer-smoothed one (the transform of R
 *     times the Bartlett window) for circulant embedding.  Relative error
 *     per band with a 95% interval simultaneous over the bands (Bonferroni),
 *     from a Gamma law of the band mean: shape M (sum S)^2 / (2 sum S^2)
 *     over the band's expected spectrum (independent exponential ordinates),
 *     or (mean / se)^2 from the ensemble when smaller (ordinates correlated
 *     by leakage); and the largest over the bands; bands whose expectation is below 1e-6 of the
 *     largest band are not compared (NAN).  Reported, not part of the verdict.
 *   - verdict against the tolerance E on the effect size over all T lags:
 *     NL_VALIDATE_WITHIN when hi <= E (shown to be within E), NL_VALIDATE_OFF
 *     when lo > E (shown to exceed E), NL_VALIDATE_UNRESOLVED otherwise (the
 *     interval straddles E: more realizations or a larger grid resolve it).
 *
 * The plans, through the registry (nl_method_plan_alloc) at unit spacing,
 * without clamping, each method's defaults but for these options of
 * nl_validate_options, given to every method that has an option of that
 * name: levels (0: a coarse grid of at least 16 samples per axis),
 * neighborhood (0: auto, growing up to max-neighborhood 6), tol,
 * random-neighborhoods, radius and cell (0: the defaults), density; a flag
 * making the field a periodic tile (sparse's wrap) is set.  Subdivision
 * (synth/subdiv.h) is then periodic; circulant embedding grows up to 16 n
 * per axis.  A method without the grid's dimension is refused.
 *
 * Subdivision (Lewis 1987) estimates new points from earlier levels only, so
 * its covariance differs from R except for Markovian models in 1D.  Its
 * verdict is against the target R like every method's; on grids small
 * enough for its exact expected ACF (analysis/subdiv_exact.h: 1D up to 2048
 * samples, 2D up to 64 x 64, at most 4 neighbours per side, no random
 * neighbourhoods) the result also holds that ACF at every tested lag and the
 * method's effect size against it (vs_exact): a correct implementation
 * matches its own exact ACF, and the difference between the two is the
 * method's error by construction.
 *
 * A method that cannot run (its plan fails, a realization fails, or the
 * caller says the model is not positive definite) is "refused": a result
 * (status and message in its nl_validate_method_result), not an error.
 *
 * Thread safety: none of these functions is thread-safe (they plan FFTW and
 * evaluate the model, which is not thread-safe for expression models). */
#ifndef NL_VALIDATE_H
#define NL_VALIDATE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/model.h"
#include "../synth/method.h"

#include <stddef.h>
#include <stdint.h>

/* Lags 0..NL_VALIDATE_MAXLAG along a direction at most. */
#define NL_VALIDATE_MAXLAG 512
/* Largest half-width of the lag map in 2D and 3D, and its largest size. */
#define NL_VALIDATE_MAP_2D 32
#define NL_VALIDATE_MAP_3D 10
#define NL_VALIDATE_MAPLAGS 4700
/* Octave bands of the spectrum. */
#define NL_VALIDATE_BANDS 16

/* The methods and variants validate runs, numbered 0 .. NL_VALIDATE_METHODS
 * - 1 in the order nl_validate_model runs them (the registry's, module
 * comment; nl_validate_method_count() of them, which tests check equal). */
#define NL_VALIDATE_METHODS 5

/* The directions: lag l stands for (l, 0, 0), (0, l, 0), (0, 0, l) and
 * (l, l, 0) in 2D or (l, l, l) in 3D. */
enum { NL_VALIDATE_X, NL_VALIDATE_Y, NL_VALIDATE_Z, NL_VALIDATE_DIAG, NL_VALIDATE_DIRS };

/* Verdicts against the tolerance. */
enum { NL_VALIDATE_WITHIN, NL_VALIDATE_OFF, NL_VALIDATE_UNRESOLVED };

/* What a method claims (nl_validate_claim): the model's covariance (an
 * exact method, NL_METHOD_EXACT), its own exact expected ACF (subdivision
 * where vs_exact is set: it misses R by construction, by the error it
 * reports, exact_effect), or nothing measurable here (an approximate
 * method without its exact ACF at this size: its verdict against R is
 * reported, not judged). */
enum { NL_VALIDATE_CLAIM_MODEL, NL_VALIDATE_CLAIM_OWN, NL_VALIDATE_CLAIM_NONE };

/* How many methods and variants the registry gives validate (at most
 * NL_VALIDATE_METHODS). */
int nl_validate_method_count(void);

/* Method `method`'s name: the registry's ("fft"), or a variant's
 * ("subdiv-correlated"); NULL outside 0..nl_validate_method_count() - 1. */
const char *nl_validate_method_name(int method);

/* The registry's method that method `method` runs (a variant: the method
 * whose option it sets); NULL outside 0..nl_validate_method_count() - 1. */
const nl_method_type *nl_validate_method_type(int method);

/* 1 when method `method`'s field is periodic (its expected spectrum the
 * model's sampled on the periodic grid), 0 when not (the Fejer-smoothed
 * one: circulant embedding) or out of range. */
int nl_validate_method_periodic(int method);

/* "x", "y", "z", "diagonal"; NULL outside 0..NL_VALIDATE_DIRS - 1. */
const char *nl_validate_dir_name(int dir);

/* "within", "off", "unresolved"; NULL otherwise. */
const char *nl_validate_verdict_name(int verdict);

typedef struct {
    size_t realizations;  /* M >= 2 */
    uint64_t seed;        /* S: seeds S..S+M-1 (wrapping modulo 2^64) */
    double alpha;         /* family-wise false-alarm rate of the z test, in (0, 1) */
    double tolerance;     /* E > 0: largest |mean ACF - R| / R(0) accepted */
    int subdiv_levels;    /* 0: a coarse grid of at least 16 samples per axis */
    int subdiv_N;         /* neighbourhood half-width >= 1, or 0: grow until eq. (7) improves by < subdiv_tol */
    double subdiv_tol;    /* > 0 */
    int subdiv_random;    /* 2D: random neighbourhoods per point class, 0: the standard block */
    int sparse_radius;    /* 0: the model kernel's default */
    int sparse_cell;      /* 0: the radius */
    double sparse_density;/* impulses per cell, > 0 */
    /* NULL, or called before each realization: `done` of `total` realizations
     * of `method` are finished */
    void (*progress)(void *ctx, int method, size_t done, size_t total);
    void *progress_ctx;   /* passed to progress */
} nl_validate_options;

/* The defaults: 32 realizations from seed 1, alpha = 1e-3, tolerance 0.1, subdivision
 * with N = 2, tol 1e-4 and default levels, sparse convolution at density 32
 * with the default radius and cell, no progress. */
void nl_validate_options_default(nl_validate_options *o);

/* An estimate with its 95% confidence interval (lo <= est <= hi). */
typedef struct {
    double est, lo, hi;
} nl_validate_interval;

/* An effect size over a set of lags (module comment). */
typedef struct {
    nl_validate_interval effect; /* max |d| / R(0), conservative 95% interval */
    double zmax;                 /* max |z| */
    double detectable;           /* error detected with ~80% power */
    long worst[3];               /* the lag of the largest |d| */
} nl_validate_effect;

/* One method's ensemble against the target. */
typedef struct {
    const char *name;               /* nl_validate_method_name (static storage) */
    int ran;                        /* 1: the ensemble ran and the numbers below are set; 0: refused */
    int status;                     /* the NL_E* code of a refusal; NL_OK when ran or not run yet */
    char why[256];                  /* the refusal's one-line message ("" when ran, "not run" before) */
    double seconds;                 /* wall time of planning and the ensemble */
    /* ensemble mean ACF and its standard error by direction and lag
     * (variance units of the model); lags 0..nlag[dir] - 1 of the result */
    double mean[NL_VALIDATE_DIRS][NL_VALIDATE_MAXLAG + 1];
    double se[NL_VALIDATE_DIRS][NL_VALIDATE_MAXLAG + 1];
    double map_mean[NL_VALIDATE_MAPLAGS], map_se[NL_VALIDATE_MAPLAGS]; /* the same at the map's lags */
    nl_validate_effect dir[NL_VALIDATE_DIRS]; /* against R, per direction */
    nl_validate_effect map;         /* against R over the lag map */
    nl_validate_effect all;         /* against R over every tested lag: the verdict's */
    int have_exact;                 /* vs_exact is set (subdiv only) */
    nl_validate_effect vs_exact;    /* against the exact expected ACF, every tested lag */
    nl_validate_interval variance;  /* mean r(0) / R(0) */
    double band_mean[NL_VALIDATE_BANDS], band_se[NL_VALIDATE_BANDS]; /* periodogram band means */
    nl_validate_interval band_error[NL_VALIDATE_BANDS]; /* (mean - expected) / expected; NAN: not compared */
    nl_validate_interval spectrum_error; /* max |band_error| over the bands */
    int pass;                       /* max |z| over all lags <= threshold: no error detected */
    int verdict;                    /* NL_VALIDATE_WITHIN, _OFF or _UNRESOLVED */
} nl_validate_method_result;

/* Everything validation found; caller-owned, nothing to free (large:
 * about 550 kB; keep it static or on the heap). */
typedef struct {
    int dim;                        /* 1..3 */
    size_t n[3];                    /* grid (1 beyond dim) */
    size_t realizations;            /* M */
    uint64_t seed;                  /* S */
    double alpha, tolerance;        /* as given */
    int positive_definite;          /* as given to nl_validate_init */
    size_t nlag[NL_VALIDATE_DIRS];  /* lags 0..nlag - 1 per direction; 0: direction not tested */
    double target[NL_VALIDATE_DIRS][NL_VALIDATE_MAXLAG + 1]; /* R along each direction */
    size_t nmap;                    /* lags in the map */
    long map[NL_VALIDATE_MAPLAGS][3];   /* the map's lags */
    double map_target[NL_VALIDATE_MAPLAGS]; /* R there */
    size_t ntests;                  /* T: every tested lag */
    double threshold;               /* Bonferroni threshold of t(M - 1) at alpha over T lags */
    double ci_factor;               /* c: simultaneous 95% over T lags */
    size_t nbands;                  /* bands compared, 0..nbands - 1 */
    double band_lo[NL_VALIDATE_BANDS], band_hi[NL_VALIDATE_BANDS]; /* band edges, cycles per sample */
    double band_periodic[NL_VALIDATE_BANDS], band_fejer[NL_VALIDATE_BANDS]; /* expected band means */
    double band_shape_periodic[NL_VALIDATE_BANDS], band_shape_fejer[NL_VALIDATE_BANDS]; /* their Gamma shapes */
    int have_exact;                 /* exact[] and exact_map[] are set */
    double exact[NL_VALIDATE_DIRS][NL_VALIDATE_MAXLAG + 1]; /* subdivision's exact expected ACF */
    double exact_map[NL_VALIDATE_MAPLAGS];
    double exact_effect;            /* max |exact - R| / R(0) over the tested lags: subdivision's error by construction */
    long exact_worst[3];            /* where */
    nl_validate_method_result method[NL_VALIDATE_METHODS]; /* by NL_VALIDATE_* */
} nl_validate_result;

/* Does method `method` of res deliver what it claims?  Returns the claim
 * (NL_VALIDATE_CLAIM_*) and, for CLAIM_MODEL and CLAIM_OWN, the verdict
 * against it in *verdict (CLAIM_MODEL: the method's verdict; CLAIM_OWN:
 * vs_exact's interval against the tolerance, as the verdict's rule);
 * *verdict is -1 for CLAIM_NONE and for a method that did not run.
 * Thread-safe. */
int nl_validate_claim(const nl_validate_result *res, int method, int *verdict);

/* Prepare *out for model m in dim (1..3) on an n[0..dim-1] grid, each
 * n[a] >= 16: the lags, the target, the thresholds, the spectrum's
 * expectations, every method not yet run.  positive_definite is the
 * caller's verdict on the model (nl_check_model, analysis/check.h): 0
 * refuses every method (NL_ENOTPD).  m is read, not kept.  Returns NL_OK;
 * NL_EINVAL (dim, a size, realizations, alpha or tolerance out of range;
 * R(0) not positive and finite; R or the spectrum not finite at a tested
 * lag or grid frequency); or the codes of nl_wk_sample_spectrum and
 * nl_wk_sample_acf (NL_ETOOBIG, NL_ENOMEM).  *out is then unspecified. */
int nl_validate_init(const nl_model *m, int dim, const size_t *n, int positive_definite,
                     const nl_validate_options *o, nl_validate_result *out);

/* Plan `method` for m (the model given to nl_validate_init), synthesise the
 * ensemble and fill out->method[method] (subdivision also sets have_exact,
 * exact and exact_map when it can).  The effect sizes are against
 * out->target and out->map_target, which the caller may replace after
 * nl_validate_init (e.g. to judge against another model).  o must give the
 * realizations and seed given to nl_validate_init; its method options are read here,
 * its alpha and tolerance are not (out's are).  The time it took is in
 * out->method[method].seconds.  Returns
 * NL_OK (ran or refused: see ran and status), or NL_EINVAL (method out of
 * range, options differing from out's; out untouched). */
int nl_validate_method(const nl_model *m, int method, const nl_validate_options *o, nl_validate_result *out);

/* nl_validate_init, then nl_validate_method for every method in order.
 * Returns what nl_validate_init returns. */
int nl_validate_model(const nl_model *m, int dim, const size_t *n, int positive_definite,
                      const nl_validate_options *o, nl_validate_result *out);

/* The effect size of mean +- se against target over L lags (se > 0 where
 * the ensemble varies), with the interval factor c and the detectability
 * factor k = t_thr + t_0.8: e = max |mean - target| / r0, interval and
 * detectable error as in the module comment, zmax = max |z|; *worst = the
 * index of the largest |mean - target|.  Reentrant. */
void nl_validate_effect_of(size_t L, const double *mean, const double *se, const double *target, double r0,
                           double c, double k, nl_validate_effect *e, size_t *worst);

#ifdef __cplusplus
}
#endif

#endif
