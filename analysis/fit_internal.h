/* The parameters of a fit and their transforms, shared by the fitting
 * files (analysis/fit_param.c, fit_wls.c, fit_ml.c). */
#ifndef NL_FIT_INTERNAL_H
#define NL_FIT_INTERNAL_H

#include "fit.h"
#include "../core/model.h"

typedef enum { NL_FIT_LOG, NL_FIT_LOGIT2 } nl_fit_transform;

typedef struct {
    const char *family;                          /* the model family */
    int dim;                                     /* the data's dimension */
    size_t np;                                   /* parameters */
    const char *name[NL_FIT_MAX_PARAMS];         /* spec names */
    double value[NL_FIT_MAX_PARAMS];             /* current values */
    int fixed[NL_FIT_MAX_PARAMS];                /* held fixed */
    nl_fit_transform tr[NL_FIT_MAX_PARAMS];      /* how a free one is optimised */
    size_t nfree;                                /* free parameters */
    size_t free_idx[NL_FIT_MAX_PARAMS];          /* their indices */
} nl_fit_params;

/* Check the family and the fixes, set names, fixed values, NaN elsewhere. */
int nl_fit_params_init(const nl_fit_options *o, int dim, nl_fit_params *p);

/* Index of a parameter by name, or -1. */
int nl_fit_params_find(const nl_fit_params *p, const char *name);

/* Free parameters to and from the optimiser's unbounded coordinates u. */
void nl_fit_params_to_u(const nl_fit_params *p, double *u);
void nl_fit_params_from_u(nl_fit_params *p, const double *u);

/* d value / d u of the k-th free parameter at the current values. */
double nl_fit_params_dvalue(const nl_fit_params *p, size_t k);

/* The spec of the current values into buf (NL_EINVAL when it does not fit). */
int nl_fit_params_spec(const nl_fit_params *p, char *buf, size_t size);

/* Parse the current values into a model (nl_model_free releases it). */
int nl_fit_params_model(const nl_fit_params *p, nl_model **m);

/* Copy names, values and the spec into res; se from the covariance cov of
 * u (nfree x nfree, row-major; NULL: NaN). */
int nl_fit_params_result(const nl_fit_params *p, const double *cov, nl_fit_result *res);

#endif
