/* The ensemble drivers' common steps (internal to analysis/ensemble_*.c). */
#ifndef NL_ENSEMBLE_INTERNAL_H
#define NL_ENSEMBLE_INTERNAL_H

#include "ensemble.h"

/* Field k of s into *f, lent until nl_ensemble_put.  `first` holds the
 * first field's dim, n and h (data NULL): filled when k = 0, checked
 * against for k > 0 (NL_EINVAL, the field handed back, when they differ);
 * NULL: fields of any size.
 * Returns NL_OK, NL_EINVAL or the source's status. */
int nl_ensemble_get(const nl_ensemble_source *s, size_t k, nl_field *first, const nl_field **f);

/* Hand field k back to s. */
void nl_ensemble_put(const nl_ensemble_source *s, size_t k, const nl_field *f);

/* K rows of m doubles (NULL on failure): NL_ETOOBIG beyond the memory
 * available (nl_size_check), NL_ENOMEM. */
int nl_ensemble_rows_alloc(size_t K, size_t m, double **rows);

/* Record the failing field in *bad (when not NULL) and return st. */
int nl_ensemble_fail(int st, size_t k, size_t *bad);

#endif
