/* Shared between the subdivision sources; not installed. */
#ifndef NL_SYNTH_SUBDIV_INTERNAL_H
#define NL_SYNTH_SUBDIV_INTERNAL_H

#include "subdiv.h"

#include <stdint.h>

/* The counter of the random number at integer position (i, j): see
 * NL_SUBDIV_STREAM in subdiv.h. */
static inline uint64_t rng_index(int dim, long i, long j)
{
    if (dim == 1)
        return (uint64_t)i;
    return ((uint64_t)(uint32_t)j << 32) | (uint32_t)i;
}

/* NL_ENOTPD naming the first class flagged not positive definite, unless
 * allow_not_pd; NL_OK otherwise. */
int nl_subdiv_check_levels(const nl_subdiv_coeffs *c, int allow_not_pd);

/* The correlated displacements of level lv (l->filt set) for the cells
 * c0[a] .. c0[a] + n[a] - 1: out[(a n[1] + y) n[0] + x] for class a (n[1] = 1
 * in 1D).  per[a] > 0: a periodic level of per[a] cells (white numbers
 * wrap); 0: an infinite one.  NL_OK or NL_ENOMEM. */
int nl_subdiv_disp_fill(const nl_subdiv_level *l, int dim, uint64_t seed, unsigned lv, const long *c0,
                        const long *n, const long *per, double *out);

#endif
