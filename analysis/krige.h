/* Kriging (Stam and Fiume 1991, section 5, eqs. (19)-(22)): the minimum-
 * variance unbiased linear estimator L(t) = sum_i lambda_i d_i of a random
 * field from data d_i at t_i, for a covariance R of the model layer (e.g.
 * the ellipsoidal Gaussian of the paper: gauss:scale=..,angle=..,ratio=..).
 *
 * Ordinary kriging (unknown mean; unbiasedness by a Lagrange multiplier nu):
 *     [C 1; 1^T 0] [lambda; nu] = [c_0; 1],  C_ij = R(t_i - t_j), c_0i = R(t - t_i),
 * solved through C alone: with the generalised-least-squares mean
 * b = 1^T C^-1 d / 1^T C^-1 1, the estimate is b + c_0^T C^-1 (d - b 1) and
 * the kriging variance R(0) - c_0^T C^-1 c_0 + (1 - 1^T C^-1 c_0)^2 / 1^T C^-1 1.
 * Simple kriging (known mean m): m + c_0^T C^-1 (d - m 1), variance
 * R(0) - c_0^T C^-1 c_0.
 * Plan/execute: C is factorised once (Cholesky; GSL), the dual weights
 * a = C^-1 (d - b 1) stored, and each estimate costs O(n) (the variance
 * O(n^2), a triangular solve).  A singular C (duplicate points, a Gaussian
 * model with points closer than its scale resolves in double precision:
 * Cholesky fails or its reciprocal condition number is below NL_KRIGE_RCOND_MIN)
 * is solved by the SVD pseudo-inverse (singular values below
 * NL_KRIGE_RCOND_MIN of the largest dropped) and flagged, or refused when the
 * caller asks for strictness.  The SVD costs about 12 n^3 operations without
 * blocking (a second at 600 points, minutes at 2000): a singular system of
 * more than NL_KRIGE_PINV_MAX points is refused. */
#ifndef NL_KRIGE_H
#define NL_KRIGE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>

#define NL_KRIGE_RCOND_MIN 1e-12
#define NL_KRIGE_PINV_MAX 1000

typedef struct nl_krige_plan nl_krige_plan;

typedef struct {
    size_t n;           /* data points */
    double rcond;       /* reciprocal condition number of C (1-norm estimate) */
    int pseudo_inverse; /* C was singular: solved by the pseudo-inverse */
    double mean;        /* b (ordinary) or m (simple) */
} nl_krige_info;

/* Ownership and threads: nl_krige_plan_alloc copies pts and val; the
 * plan borrows m, which must outlive it; nl_krige_plan_free releases the
 * plan (NULL is a no-op).  A plan is read-only after it is made: the
 * evaluations may run concurrently on one plan for models that are
 * thread-safe (every kind but expr:). */

/* pts: n points of dim coordinates (row-major, n * dim), val: n values;
 * simple: use `mean` as the known mean.  strict: refuse a singular system
 * (NL_EINVAL naming it) instead of the pseudo-inverse.  *out is NULL on
 * failure.
 * Errors: NL_EINVAL for n = 0, dim outside 1..3, a model that cannot be
 * evaluated in dim dimensions or has no R(lag) (spectrum:), whose R(0) is
 * not finite and positive or whose covariance of two data points is not
 * finite, a coordinate or value that is not finite, data whose coordinate
 * or value spans overflow (the message names them), weights that
 * overflow, or a singular system with strict; NL_ETOOBIG for a singular
 * system of more than NL_KRIGE_PINV_MAX points (its pseudo-inverse would
 * take minutes), or when the n x n matrix and its factors (4 copies)
 * exceed the memory available
 * (core/field.h); NL_ENOMEM.  (A singular system whose SVD failed to
 * converge would give NL_EFAIL; GSL's SVD of a finite symmetric matrix
 * does not fail.) */
int nl_krige_plan_alloc(const nl_model *m, int dim, size_t n, const double *pts, const double *val, int simple,
                     double mean, int strict, nl_krige_plan **out);

/* Estimate at x (dim coordinates); *var (may be NULL) receives the kriging
 * variance (in the units of R, >= 0).  The weights lambda (n doubles, may
 * be NULL) are filled when asked (O(n^2)).  Errors: NL_ENOMEM. */
int nl_krige_eval(const nl_krige_plan *p, const double *x, double *est, double *var, double *lambda);

/* nl_krige_eval for `count` points x (count * dim coordinates) at once: the
 * same estimates and variances (to rounding), with the variances of
 * NL_KRIGE_BLOCK points computed together by one level-3 BLAS triangular
 * solve (n^2 NL_KRIGE_BLOCK flops).  var may be NULL.  Errors: NL_ENOMEM.
 * Blocks may run in parallel; the bits do not depend on the thread count. */
#define NL_KRIGE_BLOCK 256
int nl_krige_eval_block(const nl_krige_plan *p, size_t count, const double *x, double *est, double *var);

/* Evaluate on the cell centres of a grid: sample i of axis a sits at
 * lo[a] + (i + 0.5) est->h[a] (est's n and h set the grid; its dim must be
 * the plan's); est->data receives the estimates, var->data (var may be
 * NULL, else a field of the same size) the variances.  Blocks of
 * NL_KRIGE_BLOCK samples run in parallel (OpenMP) above 4096 samples
 * unless the model is expr:.  Errors: NL_EINVAL for grids of another
 * dimension or size; NL_ENOMEM. */
int nl_krige_eval_grid(const nl_krige_plan *p, const double *lo, const nl_field *est, nl_field *var);

/* Copy the plan's figures into *info. */
void nl_krige_plan_info(const nl_krige_plan *p, nl_krige_info *info);
void nl_krige_plan_free(nl_krige_plan *p);

#ifdef __cplusplus
}
#endif

#endif
