/* Flavours of kriging on a local or global neighbourhood plan
 * (analysis/krige_local.h), as gstat's krige(..., block = ), krigeTg and
 * indicator kriging (Pebesma 2004).
 *
 * Block kriging (Journel and Huijbregts 1978, section V.A.2; gstat's manual,
 * "block kriging"): the estimate of the mean of the field over a block B
 * (an axis-aligned box of edges size[a], centred at the location).  B is
 * discretised by points d_j with weights w_j (sum 1):
 *   - points = 0: gstat's default, 4-point Gauss-Legendre quadrature on each
 *     axis (nodes +-0.4305681558, +-0.1699905218 and weights 0.1739274226,
 *     0.3260725774 times the edge; gstat's src/block.c, after Carr and
 *     Palmer 1993), 4^dim points;
 *   - points = N >= 2: N regular points per axis at the centres of N equal
 *     intervals, equal weights (gstat's set = list(nblockdiscr = N)).
 * The point-to-block covariance is the average C(t_i, B) = sum_j w_j
 * C(t_i - x - d_j), the block-to-block variance the double average
 * sum_jk w_j w_k C(d_j - d_k), and the drift at the block the average of the
 * drift terms over the d_j (equal to the drift at the centre for constant
 * and linear drifts).  As gstat, a lag shorter than 10 DBL_EPSILON between
 * two discretisation points or a datum and a discretisation point is taken
 * as that length (the "zero effect"): the nugget never enters a block
 * covariance.  The neighbourhood is that of the block's centre.
 *
 * Trans-Gaussian kriging (Cressie 1993, section 3.2.2; gstat's R/krigeTg.R):
 * the data are transformed by Box-Cox, Y = phi^-1(Z) = (Z^lambda - 1) /
 * lambda (log Z for lambda = 0; Z > 0), kriged (ordinary), and back-
 * transformed with the bias correction of Cressie (3.2.40):
 *   est = phi(Y_OK) + phi''(mu) (sigma2_OK / 2 - m),
 *   var = phi'(mu)^2 sigma2_OK,
 * where mu is the generalised-least-squares mean of the neighbourhood
 * (gstat's BLUE), sigma2_OK the ordinary kriging variance and m the
 * Lagrange multiplier, (1 - 1' C^-1 c0) / (1' C^-1 1) (krigeTg's
 * (OK var - SK var) / (1 - sum of SK weights)); phi(y) = (lambda y +
 * 1)^(1/lambda) (exp y), phi' = (lambda y + 1)^(1/lambda - 1), phi'' =
 * (1 - lambda)(lambda y + 1)^(1/lambda - 2) (both exp for lambda = 0).
 * These are krigeTg's var1TG.pred and var1TG.var.
 *
 * Indicator kriging (Journel 1983; Deutsch and Journel 1998, section
 * IV.1.9, program ik3d): for thresholds t_1 < ... < t_K, the indicators
 * I_k = 1 if z <= t_k else 0 are kriged (each with its own model, or one
 * model for all), giving estimates of P(Z <= t_k).  The order relations
 * are then corrected as GSLIB's ordrel: clip to [0, 1], an upward pass
 * (running maximum from t_1), a downward pass (running minimum from t_K),
 * and their average; the result is non-decreasing in k and in [0, 1].
 *
 * Units: estimates in the data's units (block: the mean over the block),
 * variances in their square; probabilities without units.
 * Threads: the evaluations run locations in parallel (OpenMP) when the
 * model is reentrant; results do not depend on the thread count.  Plans are
 * borrowed read-only and may be shared.
 * Errors: NL_EINVAL with a message naming the value or location; NL_ENOMEM. */
#ifndef NL_KRIGE_FLAVOURS_H
#define NL_KRIGE_FLAVOURS_H

#ifdef __cplusplus
extern "C" {
#endif

#include "krige_local.h"

#include <stddef.h>

/* Discretisation points per axis at most, and in a block at most. */
#define NL_KRIGE_BLOCK_AXIS_MAX 64
#define NL_KRIGE_BLOCK_POINTS_MAX 4096

/* A block: edges in coordinate units, one per axis of the data (each > 0);
 * points per axis as above (0: gstat's Gauss-Legendre default). */
typedef struct {
    double size[3]; /* block edges (the first dim are used) */
    int points;     /* 0: 4-point Gauss-Legendre; N >= 2: N regular points per axis */
} nl_krige_block;

/* The discretisation of block b in dim dimensions: *nd points, offsets d
 * (nd * dim, from the centre) and weights w (nd) into arrays of at least
 * NL_KRIGE_BLOCK_POINTS_MAX (* dim) entries.  Errors: NL_EINVAL for an edge
 * that is not finite and positive, points of 1, below 0 or above
 * NL_KRIGE_BLOCK_AXIS_MAX, or more than NL_KRIGE_BLOCK_POINTS_MAX points. */
int nl_krige_block_discretise(const nl_krige_block *b, int dim, size_t *nd, double *d, double *w);

/* Block kriging: estimates and variances (var may be NULL) of the block
 * means centred at count locations x (count * dim coordinates) with plan k
 * (any drift; simple kriging adds the known mean).  The variance is
 * C(B, B) - 2 sum_i lambda_i C(t_i, B) + sum_ij lambda_i lambda_j C_ij.
 * Errors: as nl_krige_block_discretise and nl_krige_local_eval. */
int nl_krige_block_eval(const nl_krige_local *k, const nl_krige_block *b, size_t count, const double *x, double *est,
                        double *var);

/* Y = phi^-1(z) for n values (out may be val).  Errors: NL_EINVAL for a
 * lambda that is not finite or outside [-5, 5], a value that is not
 * finite and positive (the message names it), or a transformed value that
 * is not finite. */
int nl_krige_tg_transform(double lambda, size_t n, const double *val, double *out);

/* Trans-Gaussian kriging with plan k, made on transformed data (ordinary:
 * NL_DRIFT_CONSTANT, else NL_EINVAL as krigeTg) at count locations x,
 * of points (b NULL) or blocks: est and var (var may be NULL) in the units
 * of the untransformed data.  Errors: those of nl_krige_block_eval, and
 * NL_EINVAL when lambda y + 1 <= 0 for an estimate y (the back-transform is
 * undefined: the message names the location). */
int nl_krige_tg_eval(const nl_krige_local *k, const nl_krige_block *b, double lambda, size_t count, const double *x,
                     double *est, double *var);

/* Leave-one-out cross-validation of trans-Gaussian point kriging: pred
 * and var (n each) at the data, each from the others, in the units of the
 * untransformed data; the summary of nl_krige_local_cv on z = the
 * untransformed data (orig, n values).  Errors as nl_krige_tg_eval and
 * nl_krige_local_cv. */
int nl_krige_tg_cv(const nl_krige_local *k, double lambda, const double *orig, double *pred, double *var,
                   nl_krige_cv_summary *s);

/* Indicator kriging.  thr: nk thresholds, finite and strictly increasing;
 * m: nk models, one per threshold (the same pointer may repeat; borrowed);
 * o: the neighbourhood and drift of every threshold's plan; b: blocks, or
 * NULL for points.  At count locations x (x NULL: leave-one-out at the n
 * data, count must be n), raw (count * nk, row-major by location, may be
 * NULL) receives the kriged indicators before correction and cdf (count *
 * nk) the corrected probabilities P(Z <= t_k); *ncorrected (may be NULL)
 * the number of locations where the correction changed a value by more
 * than 1e-12.  Errors: NL_EINVAL for nk = 0 or above 256, thresholds not
 * increasing, simple kriging (o->drift NL_DRIFT_NONE: each indicator has
 * its own mean), and those of nl_krige_local_alloc and nl_krige_block_eval;
 * NL_ENOMEM. */
int nl_krige_indicator(const nl_model *const *m, size_t nk, const double *thr, int dim, size_t n, const double *pts,
                       const double *val, const nl_krige_local_options *o, const nl_krige_block *b, size_t count,
                       const double *x, double *raw, double *cdf, size_t *ncorrected);

/* GSLIB's order-relation correction of count rows of nk probabilities
 * (in place): clip to [0, 1], average of the upward and downward
 * corrections.  Returns the number of rows changed by more than 1e-12
 * (nk = 0 or above 256: nothing is done, 0). */
size_t nl_krige_order_relations(size_t count, size_t nk, double *p);

#ifdef __cplusplus
}
#endif

#endif
