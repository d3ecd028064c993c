/* The parameters of a fit and their transforms, shared by the fitting
 * files (analysis/fit_param.c, fit_wls.c, fit_ml.c). */
#ifndef NL_FIT_INTERNAL_H
#define NL_FIT_INTERNAL_H

#include "fit.h"
#include "../core/model.h"

/* The most parameters of a fit (a sum of up to NL_FIT_MAX_STRUCTURES
 * structures, each with up to NL_FAMILY_MAX_PARAMS): the size of the
 * optimisers' work arrays. */
#define NL_FIT_MAX_PARAMS 24
/* The most structures of a fitted sum or product. */
#define NL_FIT_MAX_STRUCTURES 8

#include <gsl/gsl_matrix.h>

/* How a free parameter is optimised: as log(v), or as the logit of v / hi
 * (0 < v < hi). */
typedef enum { NL_FIT_LOG, NL_FIT_LOGIT } nl_fit_transform;

typedef struct {
    const char *family;                          /* the model family, or the spec of a sum */
    int dim;                                     /* the data's dimension */
    size_t np;                                   /* parameters */
    char name[NL_FIT_MAX_PARAMS][16];            /* spec names (of a sum: NAME.I) */
    double value[NL_FIT_MAX_PARAMS];             /* current values */
    double given[NL_FIT_MAX_PARAMS];             /* the value the model spec gives (a start), NaN none */
    int fixed[NL_FIT_MAX_PARAMS];                /* held fixed */
    nl_fit_transform tr[NL_FIT_MAX_PARAMS];      /* how a free one is optimised */
    double hi[NL_FIT_MAX_PARAMS];                /* NL_FIT_LOGIT: the upper end */
    const nl_family_param *param[NL_FIT_MAX_PARAMS]; /* the family's descriptor of each */
    size_t term[NL_FIT_MAX_PARAMS];              /* the structure it belongs to (from 0) */
    size_t nstruct;                              /* structures (1: one family) */
    const nl_family *fam[NL_FIT_MAX_STRUCTURES]; /* each structure's family */
    char op[NL_FIT_MAX_STRUCTURES];              /* the operator after each ('+', '*'; 0 last) */
    int composite;                               /* a sum or product: names carry .I */
    size_t nugget_term;                          /* the structure nl_fit_options.nugget adds a
                                                    nugget to (NL_FIT_MAX_STRUCTURES: none) */
    size_t nfree;                                /* free parameters */
    size_t free_idx[NL_FIT_MAX_PARAMS];          /* their indices */
    double ulo[NL_FIT_MAX_PARAMS], uhi[NL_FIT_MAX_PARAMS]; /* the search box of each parameter's
                                                    transformed value (-700, 700: none) */
} nl_fit_params;

/* The likelihood of the data at the current parameters (analysis/fit_ml.c). */
typedef struct {
    nl_fit_params *p;       /* parameters */
    const double *x, *z;    /* coordinates (n x dim), values */
    size_t n;               /* data */
    nl_fit_likelihood lik;  /* ML or REML */
    gsl_matrix *C;          /* n x n covariance, then its Cholesky factor L */
    gsl_vector *y;          /* L^-1 z */
    size_t q;               /* drift terms (columns of X; 0: a known mean 0) */
    gsl_matrix *X, *A;      /* n x q design, L^-1 X (NULL when q = 0) */
    gsl_matrix *M;          /* q x q: X' C^-1 X, then its Cholesky factor */
    gsl_vector *beta;       /* q GLS drift coefficients of the last evaluation */
    double hmin, hmax;      /* the smallest and largest distance between two data */
    double quad;            /* r' C^-1 r of the last evaluation */
} nl_fit_mldata;

/* -2 l (ML or REML) at the free parameters u (p->value updated, u taken
 * into the search box); NL_FIT_ML_BAD where the covariance or X' C^-1 X is
 * not positive definite. */
#define NL_FIT_ML_BAD 1e300
double nl_fit_ml_minus2l_u(nl_fit_mldata *d, const double *u);

/* The same plus (u_k - box_k)^2 for each free k != skip outside the search
 * box (SIZE_MAX: none skipped): the optimisers' objective, which leads a
 * simplex back into the box instead of across a plateau. */
double nl_fit_ml_minus2l_box(nl_fit_mldata *d, const double *u, size_t skip);
/* That penalty alone. */
double nl_fit_ml_penalty(const nl_fit_params *p, const double *u, size_t skip);

/* The design of the drift (analysis/fit_drift.c): X's n x q columns, the
 * polynomial terms of drift (NL_DRIFT_*: 1; 1, u_a; 1, u_a, u_a u_b for
 * a <= b, u the coordinates centred on and divided by the half-widths of
 * the bounding box, as analysis/krige_local.c) then the p columns of design
 * (n x p row-major; NULL when p = 0).  *X NULL when q = 0.  NL_EINVAL for
 * an unknown drift, non-finite design entries, q + nfree + 1 > n, or
 * columns that are linearly dependent (X' X singular); NL_ENOMEM. */
int nl_fit_drift_design(int drift, const double *x, size_t n, int dim, const double *design, size_t p,
                        size_t nfree, gsl_matrix **X);

/* Drift terms of the polynomial drift in dim dimensions (0 for NL_DRIFT_NONE). */
size_t nl_fit_drift_terms(int drift, int dim);

/* The global search of a likelihood fit (analysis/fit_search.c): from the
 * parameters' current values, a local optimisation, a profile grid over
 * the first free scale and refinement of its best points (global 0: the
 * local optimisation alone), then the
 * projected-gradient test.  Fills u (the optimum), res->objective,
 * iterations, converged, starts; flags (nfree) gets NL_FIT_PARAM_AT_BOUND
 * for parameters at their search box.  NL_OK, NL_ENOMEM, NL_EFAIL (no
 * positive definite covariance found). */
int nl_fit_ml_search(nl_fit_mldata *d, int global, nl_fit_result *res, double *u, unsigned *flags);

/* A local optimisation of every free parameter from u (in/out): Nelder-
 * Mead rounds until the projected gradient test passes or maxround rounds
 * are spent.  Returns -2 l at u; *conv the gradient test's verdict; adds
 * the simplex steps to *steps. */
double nl_fit_ml_refine(nl_fit_mldata *d, double *u, int maxround, int *conv, int *steps);

/* The largest component of the projected gradient of -2 l at u in the
 * transformed coordinates (central differences; a component pointing out
 * of the search box at its edge is dropped). */
double nl_fit_ml_gradient(nl_fit_mldata *d, const double *u);

/* Profile-likelihood intervals (analysis/fit_profile.c) of the free
 * parameters chosen by `which` (NL_FIT_INTERVALS_*) around the optimum
 * u_hat (-2 l = f_hat), cov the Hessian's covariance of u (a first guess of
 * the widths; NaN allowed).  Fills lower[k], upper[k] for each of the
 * d->p->np parameters (values, NaN for parameters not profiled) and leaves
 * d at u_hat.  flags (per free parameter): those flagged
 * NL_FIT_PARAM_SINGULAR on entry are not profiled (an end beyond a fit
 * range is that end); an interval narrower than the solver's tolerance (a profile
 * that rises past the cutoff within one tolerance of the optimum, as where
 * the covariance stops being positive definite) is left NaN and flagged
 * NL_FIT_PARAM_SINGULAR.  NL_OK, NL_FIT_PROFILE_LOWER (below) or NL_ENOMEM. */
/* When a profile point lies more than NL_FIT_PROFILE_DROP below f_hat (the
 * optimum was not the minimum), the profiles stop: better (nfree) receives
 * that point and the return is NL_FIT_PROFILE_LOWER (the caller restarts
 * from it). */
#define NL_FIT_PROFILE_LOWER 100
#define NL_FIT_PROFILE_DROP 1e-2
int nl_fit_profile(nl_fit_mldata *d, const double *u_hat, double f_hat, const double *cov, int which,
                   double *lower, double *upper, unsigned *flags, double *better);

/* The identifiability test of an information matrix (analysis/fit_info.c):
 * info (k x k, row-major, of the free transformed parameters; entries of
 * flagged parameters ignored) whose eigenvalues below NL_FIT_RCOND_MIN
 * times the largest (or not positive) make singular directions; each
 * parameter with over NL_FIT_NULL_SHARE of a singular direction's weight
 * is flagged NL_FIT_PARAM_SINGULAR in flags (k entries, in/out; a
 * non-finite entry flags its row and column).  Returns the reciprocal
 * condition number of the unflagged block (0 when none).  cov, when not
 * NULL, receives the pseudo-inverse over the regular directions (NaN in
 * flagged rows and columns).  NL_ENOMEM leaves -1. */
#define NL_FIT_NULL_SHARE 0.1
double nl_fit_info_check(const double *info, size_t k, unsigned *flags, double *cov);

/* Flag the free parameters whose values sit at an end of their family's
 * fit range or of their search box (NL_FIT_PARAM_AT_BOUND in flags, nfree
 * entries). */
void nl_fit_params_at_bound(const nl_fit_params *p, unsigned *flags);

/* The likelihood fits' search box: each free scale between hmin / 10 and
 * NL_FIT_SCALE_REACH hmax (hmin, hmax: the smallest and largest distance
 * between data), each variance and nugget below NL_FIT_VAR_REACH times
 * var (the sample variance), each nugget above NL_FIT_NUGGET_FLOOR var. */
#define NL_FIT_NUGGET_FLOOR 1e-10
void nl_fit_params_box(nl_fit_params *p, double hmin, double hmax, double var);

/* Is free parameter k at the upper end of its search box (a scale or a
 * variance running away) or a scale at its lower end? */
int nl_fit_params_runaway(const nl_fit_params *p, size_t k);

/* A likelihood fit's refusals before it starts (analysis/fit_mlcheck.c):
 * too few or too many data, work over the budget, non-finite data, no
 * variation, coincident points without a nugget.  NL_OK or a status with
 * its message. */
int nl_fit_ml_check(const nl_fit_params *p, const double *x, const double *z, size_t n, const nl_fit_options *o);

/* Check the family and the fixes, set names, fixed values, NaN elsewhere. */
int nl_fit_params_init(const nl_fit_options *o, int dim, nl_fit_params *p);

/* Start values of the free parameters: start[k] where given (finite and
 * positive; NULL: none), else the sill split 9:1 between var and nugget
 * (all of it to var without a nugget), the scale, and each shape
 * parameter's start in its family's descriptor (omega: 1 / scale). */
void nl_fit_params_start(nl_fit_params *p, double sill, double scale, const double *start);

/* Index of a parameter by name, or -1. */
int nl_fit_params_find(const nl_fit_params *p, const char *name);

/* Is a nugget fitted, or fixed above 0? */
int nl_fit_params_has_nugget(const nl_fit_params *p);

/* Free parameters to and from the optimiser's unbounded coordinates u. */
void nl_fit_params_to_u(const nl_fit_params *p, double *u);
void nl_fit_params_from_u(nl_fit_params *p, const double *u);

/* d value / d u of the k-th free parameter at the current values. */
double nl_fit_params_dvalue(const nl_fit_params *p, size_t k);

/* The spec of the current values into buf (NL_EINVAL when it does not fit). */
int nl_fit_params_spec(const nl_fit_params *p, char *buf, size_t size);

/* Parse the current values into a model (nl_model_free releases it). */
int nl_fit_params_model(const nl_fit_params *p, nl_model **m);

/* Allocate res->param and copy names, values and the spec into res; se
 * from the covariance cov of u (nfree x nfree, row-major; NULL: NaN), the
 * intervals from lower and upper (np each; NULL: NaN).  NL_OK, NL_ENOMEM,
 * or NL_EINVAL when the spec does not fit (res->param then NULL). */
int nl_fit_params_result(const nl_fit_params *p, const double *cov, const double *lower, const double *upper,
                         nl_fit_result *res);

/* Apply the free parameters' flags (nfree entries) to res: se, lower and
 * upper NaN where flagged; res->flags their OR. */
void nl_fit_result_flags(const nl_fit_params *p, const unsigned *flags, nl_fit_result *res);

#endif
