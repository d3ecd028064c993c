/* The timing and row helpers shared by the files of `noiselab bench`
 * (bench/bench.c, bench/bench_blas.c). */
#ifndef NL_BENCH_H
#define NL_BENCH_H

#include "../core/model.h"

#include <stddef.h>

/* Monotonic wall-clock time, seconds. */
double cli_bench_now(void);
/* The median of v[0..n-1] (sorts v in place). */
double cli_bench_median(double *v, int n);
/* One TSV row: case, samples, seconds, floor, floor seconds, ratio,
 * samples per second, and the bare floor (bare NULL: none, "-"). */
void cli_bench_row(const char *name, size_t samples, double t, const char *floor_name, double tf, const char *bare,
                   double tb);
/* The BLAS rows: this machine's DGEMM rate and global kriging of np points
 * onto g x g with the variance against n^2 m flops at that rate. */
void cli_bench_blas(const nl_model *m, size_t np, size_t g, int reps);

#endif
