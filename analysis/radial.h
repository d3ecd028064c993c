/* Radial (isotropic) averages of a quantity on a wrapped grid.
 *
 * Sample i of axis a of the grid g sits at nl_wrap(i, m_a) * unit_a, with
 * unit_a = h_a for lag grids and 1 / (m_a h_a) for frequency grids.  Bin b
 * (0 <= b < nbins) collects the samples whose distance d satisfies
 * (b - 0.5) step <= d < (b + 0.5) step; r[b] is the mean distance of its
 * samples, v[b] their mean value and cnt[b] their number (r = v = NAN when
 * empty). */
#ifndef NL_RADIAL_H
#define NL_RADIAL_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

enum { NL_GRID_LAG = 0, NL_GRID_FREQ = 1 };

/* kind: NL_GRID_LAG (g an ACF estimate, core/autocorr.h: distances in
 * length units) or NL_GRID_FREQ (g a spectrum, core/wk.h: distances in
 * cycles per unit length); step in the same units.  r, v and cnt are the
 * caller's arrays of nbins entries.  Returns NL_OK or NL_EINVAL (step not
 * positive).  Reentrant. */
int nl_radial(const nl_field *g, int kind, double step, size_t nbins, double *r, double *v, size_t *cnt);

#ifdef __cplusplus
}
#endif

#endif
