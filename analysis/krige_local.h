/* Kriging in local neighbourhoods, universal kriging and leave-one-out
 * cross-validation, as gstat's krige(formula, ..., nmax, maxdist) and
 * krige.cv (Pebesma 2004).
 *
 * At each location x0 the data used are the nmax nearest (Euclidean) within
 * the radius (through the k-d tree of core/spindex.h); when the nmax-th and
 * the next are equidistant, the one gstat's quadtree search reaches first
 * (analysis/krige_gstat_order.c), so that neighbourhoods are gstat's.
 * With the covariance matrix C of those K data (C_ij = R(t_i - t_j)), c0 =
 * R(x0 - t_i), the drift matrix X (K x p: 1 for ordinary kriging; 1, x, y,
 * z for linear; 1, the coordinates, their squares and cross products for
 * quadratic; none for simple kriging with a known mean) and the drift at x0,
 * x0, the universal kriging estimate and variance are (generalised least
 * squares; Cressie 1993, eqs. (3.4.60)-(3.4.61)):
 *     beta = (X' C^-1 X)^-1 X' C^-1 z,
 *     est  = x0' beta + c0' C^-1 (z - X beta),
 *     var  = R(0) - c0' C^-1 c0 + u' (X' C^-1 X)^-1 u,  u = x0 - X' C^-1 c0.
 * External drift (gstat's krige(z ~ c1 + c2, ...)): covariates given with
 * the data and with each location add columns c1, c2, ... to X and x0,
 * after the polynomial terms (which hold the constant).
 * Drift columns use coordinates (and covariates) centred on and scaled by
 * the data's range; the estimate does not depend on that choice (same
 * column space).
 * The factorisation of a neighbourhood is reused while consecutive
 * locations have the same neighbour set (always with a global
 * neighbourhood).  Memory: the index, O(n), plus O(K^2) per thread. */
#ifndef NL_KRIGE_LOCAL_H
#define NL_KRIGE_LOCAL_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>
#include <stdint.h>

enum { NL_DRIFT_NONE = -1, NL_DRIFT_CONSTANT = 0, NL_DRIFT_LINEAR = 1, NL_DRIFT_QUADRATIC = 2 };

/* Neighbourhoods of more points than this are refused (O(K^3) each). */
#define NL_KRIGE_LOCAL_MAX 2000

typedef struct {
    size_t nmax;   /* nearest data used; 0 = all (up to NL_KRIGE_LOCAL_MAX) */
    double radius; /* only data within this distance; 0 = no limit */
    int drift;     /* NL_DRIFT_CONSTANT (ordinary), _LINEAR, _QUADRATIC; _NONE: simple kriging */
    double mean;   /* the known mean of simple kriging */
    size_t ncov;        /* external drift: covariates per datum (0: none; not with _NONE) */
    const double *cov;  /* n * ncov covariates of the data, row-major (copied by the plan) */
    int missing;   /* 1: a location with no datum in its neighbourhood, or fewer than the
                    * drift terms, gets NaN estimate and variance (gstat's NA), not an error;
                    * when every location is missing, the first one's error is returned */
} nl_krige_local_options;

typedef struct nl_krige_local nl_krige_local;

/* Plan: index the n data (pts: n * dim, val: n; copied); the plan borrows
 * m, which must outlive it.  *out (NULL on failure) is released by
 * nl_krige_local_free.  Errors: NL_EINVAL for dim outside 1..3, fewer than
 * 2 points, a coordinate or value that is not finite, all points at one
 * place, fewer points (or nmax) than drift terms, nmax = 0 with more than
 * NL_KRIGE_LOCAL_MAX points and no radius, a radius that is negative or not
 * finite, a model that cannot be evaluated in dim dimensions or whose R(0)
 * is not finite and positive; NL_ETOOBIG, NL_ENOMEM. */
int nl_krige_local_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val,
                         const nl_krige_local_options *o, nl_krige_local **out);
void nl_krige_local_free(nl_krige_local *k);

/* Number of drift terms p (0 for simple kriging), covariates included. */
size_t nl_krige_local_terms(const nl_krige_local *k);

/* Estimates (and variances, var may be NULL) at count locations x (count *
 * dim coordinates).  Locations run in parallel (OpenMP) when the model is
 * reentrant; results do not depend on the number of threads.  Errors:
 * NL_EINVAL when a location has fewer neighbours within the radius than
 * drift terms, or no neighbour, or its system is singular (duplicate
 * points: the message names the location); NL_ENOMEM. */
int nl_krige_local_eval(const nl_krige_local *k, size_t count, const double *x, double *est, double *var);

/* nl_krige_local_eval with the covariates of the locations: cov holds
 * count * ncov numbers (row-major, the plan's covariates in its order; NULL
 * when the plan has none).  nl_krige_local_eval and nl_krige_local_grid
 * refuse (NL_EINVAL) a plan with covariates; errors as nl_krige_local_eval,
 * and NL_EINVAL for a covariate that is not finite. */
int nl_krige_local_eval_at(const nl_krige_local *k, size_t count, const double *x, const double *cov, double *est,
                           double *var);

/* On the cell centres of a grid, sample i of axis a at lo[a] + (i + 0.5)
 * est->h[a] (est->dim must be the plan's); var may be NULL or a field of
 * est's size.  Rows are computed in parallel; errors as nl_krige_local_eval. */
int nl_krige_local_grid(const nl_krige_local *k, const double *lo, nl_field *est, nl_field *var);

/* Leave-one-out cross-validation, as gstat's krige.cv: each datum i
 * predicted from its neighbourhood without i.  pred and var (n each)
 * receive the predictions and kriging variances; the summary the mean and
 * variance (divisor n - 1) of the errors z_i - pred_i and of the
 * standardised errors (z_i - pred_i) / sqrt(var_i), and the root mean
 * square error.  Errors as nl_krige_local_eval (a zero variance gives
 * NL_EINVAL); NL_EINVAL, before any work, for values whose max - min
 * exceeds sqrt(DBL_MAX / n) / 16 (the squared errors would overflow), and
 * when a sum of the summary is not finite all the same.  With the option
 * missing, a datum without neighbours gets NaN and is left out of the
 * summary (s->n counts those in it). */
typedef struct {
    double mean_error, var_error; /* of z - pred */
    double mean_z, var_z;         /* of (z - pred) / sqrt(var) */
    double rmse;                  /* sqrt(mean (z - pred)^2) */
    size_t n;                     /* data predicted (not missing) */
} nl_krige_cv_summary;
int nl_krige_local_cv(const nl_krige_local *k, double *pred, double *var, nl_krige_cv_summary *s);

/* k-fold cross-validation, as gstat's krige.cv(..., nfold = K): for each
 * distinct fold id, the data of that fold predicted from the other data
 * alone (a plan of the same options on them: its own neighbourhoods, drift
 * and mean), as gstat.cv's predict(data[-sel, ], newdata = data[sel, ]).
 * fold: n ids (any integers; gstat draws them as sample(K, n, replace =
 * TRUE)).  pred, var and s as nl_krige_local_cv.  Errors: those of
 * nl_krige_local_alloc for the data outside a fold (the message names the
 * fold; e.g. fewer than 2 of them) and of nl_krige_local_cv; NL_EINVAL when
 * there is a single fold (nothing left to predict from). */
int nl_krige_local_cv_folds(const nl_krige_local *k, const long *fold, double *pred, double *var,
                            nl_krige_cv_summary *s);

/* Fold ids 1..K drawn uniformly and independently for n data from seed
 * (core/rng.h, stream 0, datum i at index i): `noiselab krige
 * --cross-validate K --seed S`'s folds.  K >= 1.  Thread-safe. */
void nl_krige_draw_folds(uint64_t seed, size_t n, size_t K, long *fold);

#ifdef __cplusplus
}
#endif

#endif
