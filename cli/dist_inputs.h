/* The analysis commands' distributed runs (acf, psd, hist under an MPI
 * launcher with one .h5 input): every process reads its slab and takes part
 * in the estimate (through cli_h5's hooks), and rank 0 alone writes the
 * outputs and prints.  Errors that depend on the options or the field's
 * size are found by every process alike (each exits 2 with the same
 * message, rank 0's shown); the collective steps agree on their status. */
#ifndef NL_CLI_DIST_INPUTS_H
#define NL_CLI_DIST_INPUTS_H

#include "inputs.h"

/* Launched under MPI with one .h5 file as input (no --realizations)?
 * Other inputs under a launcher with several processes exit 2 (each
 * process would analyse the whole fields); with one, 0 (the ordinary run). */
int cli_dist_wanted(const cli_inputs *in, const char *cmd);

/* Exit 2: "CMD: OPT is not available in a distributed run ...". */
void cli_dist_refuse(const char *cmd, const char *opt) __attribute__((noreturn));

/* Collective: the slab of the one input, and a header (dim, n, h, count;
 * no samples) of the whole field for the command's checks; exits on error
 * on every process. */
void cli_dist_read(const cli_inputs *in, cli_slab *s, nl_field *header);

/* Exit on every process unless st is NL_OK: "FILE: message" (exit 2 for
 * the input's fault, 1 otherwise), as the commands report an estimator's
 * failure. */
void cli_dist_check(const cli_inputs *in, int st);

void cli_dist_free(cli_slab *s);

/* The process that prints and writes outputs (rank 0)? */
int cli_dist_leader(void);

#endif
