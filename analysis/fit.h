/* Fitting a covariance model to data: weighted least squares on an
 * empirical semivariogram, and (restricted) maximum likelihood on the data.
 *
 * Models.  The named families of core/model.h with an R in closed form:
 * markov, gauss, markaussian, oscillatory, gauss-osc, matern, spherical.
 * Their parameters, by spec name: var and scale always; nugget when asked
 * for (nugget = 1) or fixed; alpha (markaussian), omega (oscillatory,
 * gauss-osc), nu (matern).  Each is fitted unless fixed (nl_fit_options.fix).
 * Positive parameters are optimised as logarithms, alpha as the logistic
 * 2 / (1 + exp(-u)) (0 < alpha < 2); standard errors are carried back to
 * the spec's parameters by the delta method (se(p) = |dp/du| se(u)).
 *
 * Semivariogram of a model: gamma(h) = var + nugget - R(h) for h > 0 (R(h)
 * excludes the nugget there), the convention of gstat and GSTools (nugget:
 * the jump at the origin; sill = var + nugget).
 *
 * WLS (nl_fit_variogram).  Minimises sum_j w_j (gamma_j - g(h_j))^2 over the
 * bins with pairs > 0, g the model's semivariogram, by GSL's nonlinear
 * least squares (gsl_multifit_nlinear, trust region with Levenberg-Marquardt
 * steps, finite-difference Jacobian).  Weights:
 *   NL_FIT_CRESSIE  w_j = N_j / g(h_j)^2, as gstat's fit.method = 2
 *                   (Cressie 1985), with g the model's value re-evaluated at
 *                   every step: the residual is sqrt(N_j) (gamma_j / g(h_j)
 *                   - 1), Cressie's criterion itself (gstat instead fixes the
 *                   weights within each of its iterations and converges to a
 *                   point close to this one);
 *   NL_FIT_PAIRS    w_j = N_j (gstat's fit.method = 1).
 * Standard errors: the covariance s^2 (J^T J)^-1 of the last step's Jacobian,
 * s^2 = objective / (bins - free parameters): the usual nonlinear
 * least-squares errors, which treat the bins as independent.  They are not
 * (bins share points), so they understate the spread (experiments/
 * fit_coverage.c measures by how much).  AIC = m ln(objective / m) + 2 p,
 * m bins, p free parameters (the least-squares form; not a likelihood, so
 * only comparable between fits of one variogram with one weighting).
 *
 * ML and REML (nl_fit_ml).  The data z_i at points x_i, an unknown constant
 * mean beta (generalised least squares, profiled out), covariance C_ij =
 * R(x_i - x_j) (the nugget on the diagonal):
 *   -2 l_ML   = n ln 2 pi + ln|C| + r' C^-1 r,  r = z - beta 1,
 *   -2 l_REML = (n-1) ln 2 pi + ln|C| + ln(1' C^-1 1) + r' C^-1 r
 * (Patterson and Thompson 1971; gstat has no likelihood fit, GSTools none;
 * RandomFields' RFfit and geoR's likfit use these).  Minimised over the
 * transformed parameters by GSL's Nelder-Mead simplex (gsl_multimin,
 * nmsimplex2, simplex size below 1e-5 in log units or 2000 steps), the
 * Cholesky factor of C by GSL.  Standard errors from the observed
 * information: the inverse of the Hessian of -l, by central differences
 * (step 2e-3 in the transformed parameters).  AIC = -2 l + 2 p, p the free
 * covariance parameters plus the mean.  O(n^3) per step: n up to a few
 * thousand (NL_FIT_ML_MAX).
 *
 * Statuses: NL_OK; NL_EINVAL (a family that cannot be fitted, a fixed
 * parameter the family does not have or out of its range, fewer bins with
 * pairs than free parameters + 1, fewer data than free parameters + 2, a
 * non-finite coordinate or value, all points identical, dim not 1..3);
 * NL_ETOOBIG (n above NL_FIT_ML_MAX or its n x n matrix beyond the memory
 * limit); NL_ENOMEM; NL_EFAIL (the optimiser found no finite objective).
 * A fit that stops at the iteration limit is NL_OK with converged = 0.
 * Thread safety: fits parse and evaluate models of named families only,
 * which is reentrant; each call owns its workspaces, so concurrent calls
 * are safe. */
#ifndef NL_FIT_H
#define NL_FIT_H

#include <stddef.h>

#define NL_FIT_MAX_PARAMS 5     /* var, scale, nugget and one shape parameter */
#define NL_FIT_MAX_FIX 8
#define NL_FIT_ML_MAX 10000     /* most data for a likelihood fit */

typedef enum { NL_FIT_CRESSIE = 0, NL_FIT_PAIRS = 1 } nl_fit_weights;
typedef enum { NL_FIT_ML = 0, NL_FIT_REML = 1 } nl_fit_likelihood;

typedef struct {
    const char *family;                  /* markov, gauss, matern, spherical, ... */
    int nugget;                          /* fit a nugget (else 0 unless fixed) */
    size_t nfix;                         /* entries in fix_name / fix_value */
    const char *fix_name[NL_FIT_MAX_FIX];/* parameters held at fix_value */
    double fix_value[NL_FIT_MAX_FIX];    /* their values */
    nl_fit_weights weights;              /* WLS weighting */
    nl_fit_likelihood likelihood;        /* ML or REML */
    const double *start;                 /* NULL, or a start value per parameter (the order of
                                            nl_fit_result.name; NaN: automatic) */
} nl_fit_options;

typedef struct {
    char spec[512];                       /* the fitted model, ready for --acf */
    size_t np;                            /* parameters (free and fixed) */
    char name[NL_FIT_MAX_PARAMS][8];      /* their spec names: var, scale, nugget, nu, ... */
    double value[NL_FIT_MAX_PARAMS];      /* fitted (or fixed) values */
    double se[NL_FIT_MAX_PARAMS];         /* standard errors (0 when fixed; NaN when the
                                             information matrix is singular) */
    int fixed[NL_FIT_MAX_PARAMS];         /* held at the given value */
    size_t nfree;                         /* free parameters */
    double objective;                     /* WLS: weighted sum of squares; ML: -2 l at the optimum */
    double aic;                           /* see above */
    double mean;                          /* ML: the GLS mean; WLS: NaN */
    size_t nobs;                          /* bins used (WLS) or data (ML) */
    int iterations;                       /* optimiser steps */
    int converged;                        /* the optimiser's test was met */
} nl_fit_result;

/* WLS fit to an empirical semivariogram of nbins bins: mean pair distance
 * distance[j] (> 0; the model is isotropic in those units), semivariance
 * gamma[j], pair count pairs[j] (bins with 0 pairs are skipped).  dim (1..3)
 * is the data's dimension (for the spherical model's validity and the spec's
 * evaluation).  Fills *res. */
int nl_fit_variogram(const double *distance, const double *gamma, const double *pairs, size_t nbins, int dim,
                     const nl_fit_options *o, nl_fit_result *res);

/* ML or REML fit to n data: coords[i * dim + a] the a-th coordinate of point
 * i, values[i] its value.  Allocates an n x n matrix (checked against the
 * memory limit) and frees it before returning. */
int nl_fit_ml(const double *coords, const double *values, size_t n, int dim, const nl_fit_options *o,
              nl_fit_result *res);

#endif
