/* The drift terms of --drift TERMS (noiselab krige, fit, variogram):
 * comma-separated constant, linear, quadratic, x, y, z (the coordinates: all
 * of them or none, as linear) or the names of covariate columns of the
 * data table (gstat's z ~ sdist with --drift sdist; z ~ x + y + sdist with
 * --drift x,y,sdist or linear,sdist). */
#ifndef NL_CLI_DRIFT_TERMS_H
#define NL_CLI_DRIFT_TERMS_H

#include "../core/io_table.h"

#include <stddef.h>

#define CLI_DRIFT_MAX_COV 16

typedef struct {
    int poly;                        /* NL_DRIFT_CONSTANT, _LINEAR or _QUADRATIC named */
    unsigned axes;                   /* coordinates named (bit a: axis a) */
    size_t ncov;                     /* covariate columns named */
    char cov[CLI_DRIFT_MAX_COV][64]; /* their names, in the order given */
} cli_drift;

/* Parse TERMS s into *d; exit 2 on an empty or too long term, a covariate
 * named twice or more than CLI_DRIFT_MAX_COV; data says where the columns
 * live ("--data"). */
void cli_drift_parse(const char *s, const char *data, cli_drift *d);

/* The polynomial drift (NL_DRIFT_*) of d for data of dim coordinates: x, y
 * (and z) as linear; exit 2 when s names some coordinates only. */
int cli_drift_poly(const cli_drift *d, const char *s, int dim);

/* The ncov columns called names of t as a new n x ncov row-major array
 * (free); exit 2 naming the first that t lacks. */
double *cli_drift_columns(const nl_table *t, size_t ncov, const char (*names)[64]);

#endif
