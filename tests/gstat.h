/* Running R with gstat from the tests, when it is installed. */
#ifndef NL_TEST_GSTAT_H
#define NL_TEST_GSTAT_H

#include <stddef.h>

/* Is Rscript on the PATH with the gstat package?  Prints a skip message
 * naming `what` (once per call) and returns 0 when not. */
int gstat_available(const char *what);

/* Run the R program `script` (Rscript, working directory: the scratch
 * directory) and read up to max numbers it prints (whitespace-separated)
 * into v; returns how many were read, -1 when R failed. */
long gstat_run(const char *script, double *v, size_t max);

/* Write n points of dim coordinates with values to path as a points TSV
 * (header x[, y[, z]], value; 17 significant digits). */
void gstat_write_points(const char *path, int dim, size_t n, const double *pts, const double *val);

#endif
