/* The report of noiselab coeffs beyond the coefficients themselves. */
#ifndef NL_CLI_COEFFS_H
#define NL_CLI_COEFFS_H

#include "cli.h"
#include "../core/model.h"
#include "../synth/subdiv.h"

/* A correlated level's filter: {"taps", "filter", "filter_error",
 * "covariance": [{"a", "b", "offset", "realised", "target"}]}, offsets
 * 0..2M along x (and y in 2D). */
json_t *cli_coeffs_filter_json(const nl_subdiv_level *l, const nl_model *m, int dim);

/* The exact expected ACF of a periodic field of n samples made with c,
 * against the target, per direction; *err the largest |exact - R| / R(0).
 * Exits through cli_check/cli_die on failure. */
json_t *cli_coeffs_error_json(const nl_subdiv_coeffs *c, const nl_model *m, const size_t *n, double *err);

#endif
