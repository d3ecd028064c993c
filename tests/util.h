/* Shared helpers for the tests. */
#ifndef NL_TEST_UTIL_H
#define NL_TEST_UTIL_H

#include "../core/model.h"

#include <jansson.h>
#include <stddef.h>

/* Run the noiselab binary ($NOISELAB) with the shell words of `args`; the
 * exit status is returned, stdout and stderr go to the buffers (NUL
 * terminated, truncated to their size). */
int run_noiselab(const char *args, char *out, size_t outlen, char *err, size_t errlen);

/* Run noiselab with `args` (as run_noiselab) and parse its stdout as JSON;
 * the test fails on a non-zero exit or output that is not JSON.  Release
 * with json_decref. */
json_t *run_noiselab_json(const char *args);

/* A fresh scratch directory for this test process; path is static. */
const char *scratch_dir(void);
/* TEXT written to NAME in scratch_dir(); the path (static) lasts until the next call. */
const char *scratch_file(const char *name, const char *text);

/* Does a file exist? */
int file_exists(const char *path);

/* Number of lines in s. */
int count_lines(const char *s);

/* The model of a spec that must parse (the test fails naming the spec and
 * the message otherwise); released by nl_model_free. */
nl_model *test_model(const char *spec);

/* Sparse convolution's plan options (synth/sparse.h): radius, cell, density; flags 0. */
#define SPARSE_OPTS(r, c, d) (&(nl_synth_sparse_options){.radius = (r), .cell = (c), .density = (d)})

#endif
