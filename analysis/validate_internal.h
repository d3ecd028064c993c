/* Internals shared by the validation sources (analysis/validate.h). */
#ifndef NL_VALIDATE_INTERNAL_H
#define NL_VALIDATE_INTERNAL_H

#include "validate.h"

/* Lag (lx, ly, lz) of lag l along direction dir in dim. */
void nl_validate_dir_lag(int dim, int dir, long l, long *lag);

/* Every tested lag in order (directions by index, lags 0.., then the map):
 * *out (malloc'ed, v->ntests rows) or NL_ENOMEM. */
int nl_validate_lags_alloc(const nl_validate_result *v, long (**out)[3]);

/* The same order for per-direction arrays a[dir][lag] and a map array:
 * into flat (v->ntests values). */
void nl_validate_flatten(const nl_validate_result *v, const double (*a)[NL_VALIDATE_MAXLAG + 1], const double *map,
                         double *flat);

/* Band of each frequency of the n-grid (-1: zero frequency), into band[N]. */
void nl_validate_bands_of(const nl_validate_result *v, int *band);

/* The method's summaries from its flat mean and se (v->ntests values), its
 * periodogram's band sums b1 and sums of squares b2 over the realizations
 * against the expected band means, and (NULL: none) its exact expected ACF
 * (flat): the effect sizes, variance ratio, spectrum and verdict. */
void nl_validate_summarise(const nl_validate_result *v, const double *mean, const double *se, const double *b1,
                           const double *b2, const double *expected, const double *exact,
                           nl_validate_method_result *r);

/* v->exact_effect and exact_worst from the exact ACF (flat). */
void nl_validate_exact_effect(nl_validate_result *v, const double *exact);

/* The expected band means of the periodogram (band_periodic, band_fejer). */
int nl_validate_spectrum_targets(const nl_model *m, nl_validate_result *v);

#endif
