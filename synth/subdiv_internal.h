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

#endif
