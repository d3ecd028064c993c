/* Fitting a covariance model to data: weighted least squares on an
 * empirical semivariogram, and (restricted) maximum likelihood on the data.
 *
 * Models.  The families of the registry flagged NL_FAMILY_FIT (core/
 * family.h: an R in closed form of named parameters; `noiselab models`
 * and docs/models.md say which).  Their parameters, by spec name: var and
 * scale always; nugget when asked for (nugget = 1) or fixed; every shape
 * parameter of the family (alpha, omega, nu, beta, ...).  Each is fitted
 * unless fixed (nl_fit_options.fix).  Positive parameters are optimised as
 * logarithms, one with an upper end hi (markaussian's alpha, 0 < alpha <=
 * 2) as the logistic hi / (1 + exp(-u)); standard errors are carried back
 * to the spec's parameters by the delta method (se(p) = |dp/du| se(u)).
 * Starts: the family's descriptor gives each shape parameter's start and
 * the factor on the automatic scale start (2 for the spherical range).
 *
 * Nested models.  nl_fit_options.family may instead be a model spec
 * (core/model.h): one structure with values, or a sum or product of up to
 * 8 structures of those families ("spherical:var=0.5,scale=12,nugget=0.1
 * + markov:var=0.6,scale=40", "spherical + markov"), without anisotropy
 * keys; a structure of the nugget family (white noise) is fitted by its
 * var.  Each structure's var, scale, nugget (when its spec gives one, when
 * fixed, or with nugget = 1 for the first structure that takes one, unless
 * a nugget structure is there) and shape parameters are
 * fitted unless fixed; in a sum or product they are named NAME.I, I the
 * structure from 1 (var.2, scale.1, nugget.1: fix takes these names), in
 * the order structure by structure, each as above.  The values the spec
 * gives are the starts (gstat's fit.variogram starts from its vgm); the
 * others' automatic starts split the sill equally among the structures and
 * spread their scales by factors of 2.  The WLS fits equal gstat's
 * fit.variogram with the same structures and weights
 * (tests/test_fit_gstat.c: Meuse, and a nested Sph + Exp + Nug to 2e-7);
 * the likelihood fits take nested models the same way.
 *
 * Bounds.  A shape parameter with a fit range in its descriptor
 * (nl_family_param.fit_lo, fit_hi) is held to it, starts included: matern's
 * nu to 0.2..30 (GSTools' bounds for Matern; at 30 R is gauss's within 1%),
 * markaussian's and gencauchy's alpha to 0.05..2, gencauchy's beta to
 * 0.05..50; gauss-osc's and oscillatory's omega (a frequency in the data's
 * units) have none.  A fit that ends within 1e-4 (relative) of an end is
 * flagged NL_FIT_PARAM_AT_BOUND, as is a nugget below NL_FIT_RCOND_MIN var
 * (0 to the precision the information matrix keeps): no standard error (the curvature across a
 * bound is not information); the profile interval stops at the end.
 *
 * Identifiability.  The information matrix of the free transformed
 * parameters (ML: the Hessian of -l; WLS: J^T J / s^2) is tested by its
 * eigenvalues: a direction of curvature below NL_FIT_RCOND_MIN =
 * sqrt(DBL_EPSILON) = 1.5e-8 times the largest (a second difference keeps
 * about half of the objective's digits; the transformed parameters are
 * unit-free, so the ratio is meaningful), or not positive, or one where a
 * Hessian step leaves the positive definite covariances, is singular, and
 * the parameters carrying over a tenth of its weight are flagged
 * NL_FIT_PARAM_SINGULAR ("not identifiable"): se, lower and upper NaN.  The
 * others' standard errors then come from the pseudo-inverse over the
 * regular directions: conditional on the flagged parameters, as for fixed
 * ones (smaller than a marginal error would be where they correlate).  A profile interval narrower than its solver's
 * tolerance (2e-3 transformed units) is flagged the same way, never
 * reported with width 0.  rcond is the matrix's reciprocal condition
 * number.
 *
 * Semivariogram of a model: gamma(h) = var + nugget - R(h) for h > 0 (R(h)
 * excludes the nugget there), the convention of gstat and GSTools (nugget:
 * the jump at the origin; sill = var + nugget).  Scales against theirs:
 * markov's scale is gstat's Exp range and GSTools' Exponential len_scale;
 * gauss's is gstat's Gau range (GSTools' Gaussian has exp(-pi/4 (r/l)^2):
 * l = scale sqrt(pi) / 2); spherical's is the range in both; matern's u =
 * sqrt(2 nu) r / scale is GSTools' with len_scale = scale / sqrt(2) (GSTools
 * uses sqrt(nu) r / l), gstat's Ste kappa = nu.
 *
 * WLS (nl_fit_variogram).  Minimises sum_j w_j (gamma_j - g(h_j))^2 over the
 * bins with pairs > 0, g the model's semivariogram, by GSL's nonlinear
 * least squares (gsl_multifit_nlinear, trust region with Levenberg-Marquardt
 * steps, finite-difference Jacobian).  Weights:
 *   NL_FIT_CRESSIE  w_j = N_j / g(h_j)^2 (Cressie 1985), with g the
 *                   model's value re-evaluated at every step: the residual
 *                   is sqrt(N_j) (gamma_j / g(h_j) - 1), Cressie's criterion
 *                   itself (gstat's fit.method = 2 has these weights but
 *                   iterates to another point: NL_FIT_REWEIGHTED);
 *   NL_FIT_REWEIGHTED  w_j = N_j / g(h_j)^2 with g held at the previous
 *                   solve's model, solved again until no transformed
 *                   parameter moves by 1e-10 (at most 200 solves): the fixed
 *                   point sum_j w_j (gamma_j - g_j) dg_j = 0 that gstat's
 *                   fit.method = 2 iterates to.  It is not Cressie's
 *                   minimum (whose gradient has the weights' derivative too):
 *                   on the markov data of tests/test_fit_gstat.c the two
 *                   differ by 0.4% in the scale, 0.9% in var, 2.7% in the
 *                   nugget.  Equal to gstat's fit.method = 2 repeated to its
 *                   fixed point within 2e-8 (one call of gstat stops up to
 *                   0.5% short of it);
 *   NL_FIT_PAIRS    w_j = N_j (gstat's fit.method = 1);
 *   NL_FIT_DISTANCE w_j = N_j / h_j^2 (gstat's fit.method = 7, its default;
 *                   the default of noiselab fit and of the Python package);
 *   NL_FIT_OLS      w_j = 1, ordinary least squares (gstat's fit.method = 6).
 * Each equals gstat's fit.variogram with that fit.method on Meuse to 1e-5
 * (tests/test_fit_gstat.c).  The zero value of nl_fit_options.weights is
 * NL_FIT_CRESSIE.
 * Standard errors: the covariance s^2 (J^T J)^-1 of the last step's Jacobian,
 * s^2 = objective / (bins - free parameters): the usual nonlinear
 * least-squares errors, which treat the bins as independent.  They are not
 * (bins share points), so they understate the spread (experiments/
 * fit_coverage.c measures by how much).  AIC = m ln(objective / m) + 2 p,
 * m bins, p free parameters (the least-squares form; not a likelihood, so
 * only comparable between fits of one variogram with one weighting).
 *
 * ML and REML (nl_fit_ml, nl_fit_ml_design).  The data z_i at points x_i,
 * a mean X beta with unknown coefficients beta (generalised least squares,
 * profiled out), covariance C_ij = R(x_i - x_j) (the nugget on the
 * diagonal):
 *   -2 l_ML   = n ln 2 pi + ln|C| + r' C^-1 r,  r = z - X beta,
 *   -2 l_REML = (n-q) ln 2 pi + ln|C| + ln|X' C^-1 X| + r' C^-1 r,
 * beta = (X' C^-1 X)^-1 X' C^-1 z, q the columns of X (Harville 1974,
 * eq. (2), without its constant -ln|X' X|: REML values of two designs of
 * one column space differ by a constant; Patterson and Thompson 1971 for
 * X = 1; gstat has no likelihood fit, GSTools none; RandomFields' RFfit
 * and geoR's likfit use these).  The Cholesky factor of C by GSL.  Standard
 * errors from the observed information: the inverse of the Hessian of -l,
 * by central differences (step 2e-3 in the transformed parameters).
 * AIC = -2 l + 2 (p + q), p the free covariance parameters.  Two data at
 * one place share the continuous part of the covariance but not the
 * nugget's white noise; they are refused without a nugget (C would be
 * singular).  Data without variation are refused by both fits (WLS: a
 * variogram 0 in every bin).
 *
 * Drift (nl_fit_options.drift, nl_fit_ml_design).  X's columns: 1 for
 * NL_DRIFT_CONSTANT (the default: the GLS mean, nl_fit_result.mean);
 * 1, u_a for _LINEAR; 1, u_a, u_a u_b (a <= b) for _QUADRATIC; none for
 * _NONE (a known mean 0), u_a = (x_a - c_a) / s_a the coordinates centred
 * on the bounding box's centre c and divided by its half-widths s (as
 * analysis/krige_local.h: the same columns as `noiselab krige --drift`),
 * then nl_fit_ml_design's covariate columns.  nl_fit_result.drift gives
 * beta in that order, drift_se the square roots of the diagonal of
 * (X' C^-1 X)^-1 at the optimum (the GLS errors, the covariance parameters
 * taken as known).  The design is refused when its columns are linearly
 * dependent (X' X, columns scaled to norm 1, with a condition number above
 * about 1e12) or with more than n - p - 1 columns.
 *
 * Search.  The free parameters are held to a box: each scale from a tenth
 * of the smallest to NL_FIT_SCALE_REACH = 10 times the largest distance
 * between two data, each variance and nugget up to NL_FIT_VAR_REACH = 1e6
 * times the sample variance, each nugget above 1e-10 of it (0, below).  A
 * likelihood can have several minima in the scale (the spherical range:
 * Meuse's log(zinc), REML, has them at ranges 1203 and 3031, -2 l 196.60
 * and 194.92), so nl_fit_ml does not stop at the first: with
 * search = NL_FIT_SEARCH_GLOBAL (the default), a rough simplex from the
 * start (simplex size 1e-2), then the profile of -2 l over the first free
 * scale on a grid of 17 scales from max(hmin, hmax / 1000) to 3 hmax,
 * evenly in log (hmin, hmax: the smallest and largest distance), each
 * point optimised in the other parameters (their common variance factor in
 * closed form when every variance and nugget is free and the model a sum,
 * Mardia and Marshall 1984), then 6 more points around each of its three
 * lowest local minima (a quarter of the spacing apart: the spherical
 * model's valleys can be a tenth of the range wide); then up to two of
 * the lowest points in distinct valleys, within 2 of the lowest and 0.5 of
 * the best refined, are each optimised locally.  A local optimisation
 * (alone with NL_FIT_SEARCH_LOCAL) is GSL's Nelder-Mead simplex
 * (gsl_multimin nmsimplex2; simplex size below 1e-5 in the transformed
 * units or 2000 steps; the box as a quadratic penalty outside it),
 * restarted from its end (at least twice, at most four times) until the
 * projected gradient of -2 l in the transformed parameters (central
 * differences, step 1e-4; a component pointing out of the box at its edge
 * dropped) is below 1e-4 n in every component: converged.  A scale or
 * variance at the upper end of its box (or a scale at the lower) means the
 * likelihood still improves beyond it, with no optimum inside: that
 * parameter is flagged NL_FIT_PARAM_AT_BOUND and the fit not converged
 * (Meuse, markov with a nugget, REML: -2 l falls towards the linear
 * variogram's 195.53 as the scale grows).  nl_fit_result.starts counts the
 * local optimisations, gradient the projected gradient's largest
 * component at the optimum.  When a profile interval (below) meets a point
 * more than 1e-2 below the optimum, the fit restarts there (a local
 * optimisation, then the covariance and the intervals again; at most three
 * times): nl_fit_result.restarts counts them.
 *
 * Cost (nl_fit_ml_work).  O(n^3) per likelihood evaluation: the estimate
 * is E (n^3 / 3 + 50 n^2) operations (the Cholesky factor and the model at
 * n^2 / 2 pairs) with E = 450 k + 2 k^2 + 1 + 20 m (1 + 40 (k - 1))
 * evaluations for k free parameters and m profile intervals (the search,
 * the Hessian, about 10 profile points per end).  A fit above the budget
 * (max_work, or NL_FIT_ML_WORK_MAX = 2e12: about 3 minutes at the 1e10
 * operations per second of a 2020s core; markov with a nugget and every
 * interval: up to about 1000 data; without intervals about 1600) is
 * refused with NL_ETOOBIG, as is n above NL_FIT_ML_MAX.
 *
 * Intervals (ML and REML, nl_fit_options.intervals): the 95% profile-
 * likelihood interval of each chosen free parameter, the parameter values
 * theta_j whose profile -2 l_p(theta_j) = min over the other free
 * parameters of -2 l stays within chi^2_1(0.95) = 3.841459 of the minimum
 * (the likelihood-ratio interval, Cox and Hinkley 1974, 9.3; invariant
 * under the log and logistic transforms).  Each end is bracketed from the
 * optimum outwards (first step 1.96 standard errors of the transformed
 * parameter, or 0.5 where that is not finite, doubled until -2 l_p exceeds
 * the cutoff or the end lies 12 units away) and found by GSL's Brent
 * solver (gsl_root_fsolver_brent) to 1e-3 in the transformed coordinate
 * (0.1% of a positive parameter); the other parameters are re-optimised by
 * Nelder-Mead (simplex size 1e-3, or a gain of -2 l under 1e-4 in 10 steps)
 * from the last profile point inside the interval.  An end where another
 * parameter sits at the upper edge of its search box is tried again with
 * that edge 10 times further: when the profile falls there by more than
 * 0.5, the box and not the data bounded it, and the end is unbounded
 * (Meuse, markov, REML: var's upper end while the scale runs away).  An end
 * not reached within 12 units is the edge of the parameter's domain (0, or
 * +infinity for var, scale, nugget, nu, omega; 0 or 2 for alpha): the
 * data do not bound the parameter on that side.  Costs about 7 profile
 * optimisations per end, each of some 10-60 likelihood evaluations.  These
 * intervals are the ones to quote for the spherical range: its likelihood
 * is not smooth in the range, and the Hessian's standard error understates
 * the spread of the range by about 2x (experiments/fit_coverage.c, 100 data
 * sets of 500 points: the profile interval holds the spherical range 0.92
 * and var 0.93 of the time, the Wald interval 0.85 and 0.88; markov with a
 * nugget: scale 0.93, var 0.98, nugget 0.96).  WLS fits report no intervals (lower, upper NaN).
 *
 * Statuses: NL_OK; NL_EINVAL (an unknown weighting, drift or search, a drift's
 * design that is not finite or has dependent columns, a family that cannot be fitted, a fixed
 * parameter the family does not have or out of its range, fewer bins with
 * pairs than free parameters + 1, fewer data than free parameters + 2, a
 * non-finite coordinate or value, coordinates spanning no finite extent,
 * all points identical, no variation, values spreading over less than
 * 1e-150 or more than 1e150, a variogram that overflows, two data at one
 * place without a nugget, dim not 1..3);
 * NL_ETOOBIG (n above NL_FIT_ML_MAX, work above the budget, or its n x n
 * matrix beyond the memory limit); NL_ENOMEM; NL_EFAIL (the optimiser found no finite objective, or
 * the reweighted fit met a model semivariogram of 0).
 * A fit that stops at the iteration limit, with a projected gradient above
 * its test, or at the edge of its search box is NL_OK with converged = 0.
 * Thread safety: fits parse and evaluate models of named families only,
 * which is reentrant; each call owns its workspaces, so concurrent calls
 * are safe. */
#ifndef NL_FIT_H
#define NL_FIT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "krige_local.h" /* NL_DRIFT_* */

#include <stddef.h>

#define NL_FIT_MAX_FIX 8
#define NL_FIT_ML_MAX 10000     /* most data for a likelihood fit */
/* The work budget of a likelihood fit (nl_fit_options.max_work 0), in
 * floating-point operations: see "Cost" above. */
#define NL_FIT_ML_WORK_MAX 2e12
/* The search box of a likelihood fit (see Search): scales up to
 * NL_FIT_SCALE_REACH times the largest distance between data, variances
 * and nuggets up to NL_FIT_VAR_REACH times the sample variance. */
#define NL_FIT_SCALE_REACH 10.0
#define NL_FIT_VAR_REACH 1e6
/* The least reciprocal condition number of an information matrix whose
 * inverse is reported: sqrt(DBL_EPSILON), see "Identifiability" above. */
#define NL_FIT_RCOND_MIN 1.4901161193847656e-08

/* nl_fit_param.flags */
enum {
    NL_FIT_PARAM_SINGULAR = 1,  /* not identifiable: the information matrix is singular in its
                                   direction (se, lower, upper NaN) */
    NL_FIT_PARAM_AT_BOUND = 2   /* ended at an end of its family's fit range, or a nugget at 0
                                   (se NaN; the interval reaches that end) */
};

/* WLS weightings (see WLS above); gstat's fit.method numbers: PAIRS 1,
 * REWEIGHTED 2, OLS 6, DISTANCE 7 (gstat's default). */
typedef enum {
    NL_FIT_CRESSIE = 0, NL_FIT_PAIRS = 1, NL_FIT_REWEIGHTED = 2, NL_FIT_DISTANCE = 3, NL_FIT_OLS = 4
} nl_fit_weights;
typedef enum { NL_FIT_ML = 0, NL_FIT_REML = 1 } nl_fit_likelihood;
/* How a likelihood fit looks for its optimum (see Search). */
typedef enum { NL_FIT_SEARCH_GLOBAL = 0, NL_FIT_SEARCH_LOCAL = 1 } nl_fit_search;
/* Which profile-likelihood intervals an ML or REML fit computes. */
typedef enum { NL_FIT_INTERVALS_NONE = 0, NL_FIT_INTERVALS_ALL = 1, NL_FIT_INTERVALS_SCALE = 2 } nl_fit_intervals;

typedef struct {
    const char *family;                  /* markov, gauss, matern, spherical, ..., or a model
                                            spec (see Nested models) */
    int nugget;                          /* fit a nugget (else 0 unless fixed) */
    size_t nfix;                         /* entries in fix_name / fix_value */
    const char *fix_name[NL_FIT_MAX_FIX];/* parameters held at fix_value */
    double fix_value[NL_FIT_MAX_FIX];    /* their values */
    nl_fit_weights weights;              /* WLS weighting */
    nl_fit_likelihood likelihood;        /* ML or REML */
    const double *start;                 /* NULL, or a start value per parameter (the order of
                                            nl_fit_result.param; NaN: automatic) */
    nl_fit_intervals intervals;          /* ML/REML: profile intervals of none, every free
                                            parameter, or the scale alone */
    double max_work;                     /* ML/REML: the work budget (0: NL_FIT_ML_WORK_MAX) */
    int drift;                           /* ML/REML: the mean's terms in the coordinates,
                                            NL_DRIFT_CONSTANT (0, the default), _LINEAR,
                                            _QUADRATIC or _NONE (a known mean 0) of
                                            analysis/krige_local.h (see Drift) */
    nl_fit_search search;                /* ML/REML: the global search (default) or one local
                                            optimisation from the start (see Search) */
} nl_fit_options;

/* One fitted parameter. */
typedef struct {
    char name[16];                        /* its spec name: var, scale, nugget, nu, ...; of a
                                            nested model NAME.I (var.2) */
    double value;                         /* fitted (or fixed) value */
    double se;                            /* standard error (0 when fixed; NaN when flagged) */
    double lower, upper;                  /* 95% profile-likelihood interval (see above): its ends,
                                             NaN where not computed, upper +inf where unbounded */
    int fixed;                            /* held at the given value */
    unsigned flags;                       /* NL_FIT_PARAM_* */
} nl_fit_param;

/* A fit's result.  param has np entries, as many as the family's fitted
 * parameters: var, scale, the nugget when fitted or fixed, then the
 * family's shape parameters in its descriptor's order (core/family.h);
 * for a nested model, those of each structure in turn.
 * The fits allocate it; release it with nl_fit_result_free (a failed fit
 * leaves param NULL).  A result passed to a fit is overwritten: release a
 * previous one first. */
typedef struct {
    char spec[512];                       /* the fitted model, ready for --acf */
    size_t np;                            /* parameters (free and fixed) */
    nl_fit_param *param;                  /* np entries (see above) */
    size_t nfree;                         /* free parameters */
    double objective;                     /* WLS: weighted sum of squares; ML: -2 l at the optimum */
    double aic;                           /* see above */
    double mean;                          /* ML: the first drift coefficient (the GLS mean with
                                             a constant drift; 0 without a drift); WLS: NaN */
    size_t nobs;                          /* bins used (WLS) or data (ML) */
    int iterations;                       /* optimiser steps */
    int converged;                        /* the optimiser's test was met */
    double rcond;                         /* the information matrix's reciprocal condition
                                             number (0 when not computable) */
    unsigned flags;                       /* the OR of the parameters' flags */
    size_t ndrift;                        /* ML/REML: drift coefficients (0 for WLS) */
    double *drift;                        /* their GLS estimates at the optimum (ndrift; NULL: none) */
    double *drift_se;                     /* their standard errors, sqrt diag (X' C^-1 X)^-1 */
    int starts;                           /* ML/REML: local optimisations run (see Search) */
    int restarts;                         /* ML/REML: restarts from a lower profile point */
    double gradient;                      /* ML/REML: the largest component of the projected
                                             gradient of -2 l at the optimum (transformed units) */
} nl_fit_result;

/* Release a result's parameters (param = NULL, np = 0; NULL or a released
 * result is a no-op). */
void nl_fit_result_free(nl_fit_result *res);

/* Check the options alone (family, fixes, dim) as the fits do: NL_OK or
 * NL_EINVAL with the fits' message.  Thread-safe. */
int nl_fit_check_options(const nl_fit_options *o, int dim);

/* WLS fit to an empirical semivariogram of nbins bins: mean pair distance
 * distance[j] (> 0; the model is isotropic in those units), semivariance
 * gamma[j], pair count pairs[j] (bins with 0 pairs are skipped).  dim (1..3)
 * is the data's dimension (for the spherical model's validity and the spec's
 * evaluation).  Fills *res. */
int nl_fit_variogram(const double *distance, const double *gamma, const double *pairs, size_t nbins, int dim,
                     const nl_fit_options *o, nl_fit_result *res);

/* The estimated work of a likelihood fit of n data with options o, in
 * floating-point operations (see "Cost" above); 0 when the options are
 * invalid.  Thread-safe. */
double nl_fit_ml_work(size_t n, int dim, const nl_fit_options *o);

/* ML or REML fit to n data: coords[i * dim + a] the a-th coordinate of point
 * i, values[i] its value.  Allocates an n x n matrix (checked against the
 * memory limit) and frees it before returning. */
int nl_fit_ml(const double *coords, const double *values, size_t n, int dim, const nl_fit_options *o,
              nl_fit_result *res);

/* The same with p covariates in the drift: design[i * p + c] the c-th
 * covariate at point i (row-major n x p; the caller's units), columns of X
 * after the terms of o->drift (so o->drift = NL_DRIFT_CONSTANT gives an
 * intercept and the covariates, as gstat's z ~ c1 + c2; NL_DRIFT_NONE the
 * covariates alone).  res->drift lists the coefficients in X's order.
 * p = 0 (design may be NULL) is nl_fit_ml.  Errors as nl_fit_ml, and
 * NL_EINVAL for a non-finite covariate or linearly dependent columns. */
int nl_fit_ml_design(const double *coords, const double *values, size_t n, int dim, const double *design, size_t p,
                     const nl_fit_options *o, nl_fit_result *res);

#ifdef __cplusplus
}
#endif

#endif
