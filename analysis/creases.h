/* Crease detector for subdivision fields (Lewis 1987, "Creases").
 *
 * A crease is a slope discontinuity left where an early level put a vertex
 * (1D) or a grid line (2D).  We take the second difference across the
 * vertex or line: x_{i+1} - 2 x_i + x_{i-1} (periodic), in 2D along x at
 * every sample of column i and along y at every sample of row j.  Column
 * (row, vertex) i of the finest grid was created at level
 * k = L - min(tz(i), L), tz = trailing zero bits; level 0 is the coarse
 * grid.  For a stationary target process the mean squared second
 * difference is the same at every position, whatever its level, so
 *     r_k = mean square at level-k lines / mean square at level-L lines
 * is 1 in expectation for the target.  The crease index is the median of
 * r_k over the levels 1..L-1 that hold at least 64 samples.
 *
 * Flag: index > NL_CREASE_MAX.  Reference values (1D, 65536 samples, 12
 * levels): midpoint displacement H = 0.8 (f^-2.6) 1.8; generalized
 * subdivision N = 2 to power:d=2.6 1.2; exp(-|t|) 1.0.  A sampling error
 * of the index is about sqrt(2 / 64 + 2 / n_L) <= 0.18 for the smallest
 * level used, so 1.5 is beyond sampling error and beyond the residual
 * non-stationarity of generalized subdivision. */
#ifndef NL_CREASES_H
#define NL_CREASES_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

#define NL_CREASE_MAX 1.5

typedef struct {
    int levels;        /* L */
    double ratio[41];  /* r_k for k = 0..L (NAN where fewer than 64 samples) */
    size_t count[41];  /* samples created at level k */
    double index;      /* median r_k over usable levels 1..L-1 */
    int flagged;       /* index > NL_CREASE_MAX */
} nl_creases;

/* f: 1D or 2D field made by `levels` levels of refinement (each size a
 * multiple of 2^levels).  *out is filled (the caller's struct; nothing to
 * free).  NL_EINVAL: a 3D field, levels outside 1..40, a size that is not a
 * multiple of 2^levels, a field without curvature at the finest level
 * (constant or linear), or no level between the coarsest and the finest
 * with 64 samples.  Reentrant and thread-safe (f only read). */
int nl_creases_measure(const nl_field *f, int levels, nl_creases *out);

#ifdef __cplusplus
}
#endif

#endif
