/* Rows of `noiselab bench` for the BLAS-bound work: this machine's DGEMM
 * rate, and global kriging with the variance against the n^2 m flops of
 * its triangular solves at that rate, measured in the same run. */
#include "../analysis/krige.h"
#include "../cli/cli.h"
#include "bench.h"
#include "../core/field.h"
#include "../core/model.h"
#include "../core/rng.h"

#include <gsl/gsl_cblas.h>
#include <stdio.h>
#include <stdlib.h>

/* Flops per second of C = A B, n x n, all threads (the fastest of reps). */
static double dgemm_rate(size_t n, int reps)
{
    double *a = malloc(n * n * sizeof *a), *b = malloc(n * n * sizeof *b), *c = calloc(n * n, sizeof *c), best = 1e300;
    if (!a || !b || !c)
        cli_die(1, "out of memory");
    for (size_t i = 0; i < n * n; i++)
        a[i] = 1.0 / (double)(i % 7 + 1), b[i] = 1.0 / (double)(i % 5 + 2);
    for (int r = 0; r <= reps; r++) { /* the first run warms up */
        double t0 = cli_bench_now();
        cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, (int)n, (int)n, (int)n, 1.0, a, (int)n, b, (int)n, 0.0,
                    c, (int)n);
        if (r && cli_bench_now() - t0 < best)
            best = cli_bench_now() - t0;
    }
    free(a), free(b), free(c);
    return 2.0 * (double)n * (double)n * (double)n / best;
}

/* Ordinary kriging of np random points onto the g x g cell centres of the
 * unit square with the variance (plan and grid, as `noiselab krige` does),
 * against n^2 m flops at the DGEMM rate: the triangular solves L^-1 K of
 * the n x m cross-covariances, the part of the work that grows as n^2 m. */
void cli_bench_blas(const nl_model *m, size_t np, size_t g, int reps)
{
    size_t n[2] = {g, g};
    double h[2] = {1.0 / (double)g, 1.0 / (double)g}, lo[2] = {0, 0}, t[16];
    double *pts = malloc(2 * np * sizeof *pts), *val = malloc(np * sizeof *val);
    nl_field *e = nl_field_alloc(2, n, h, NULL), *v = nl_field_alloc(2, n, h, NULL);
    int st;
    if (!pts || !val || !e || !v)
        cli_die(1, "out of memory");
    for (size_t i = 0; i < np; i++)
        pts[2 * i] = nl_rng_uniform(5, 0, 2 * i), pts[2 * i + 1] = nl_rng_uniform(5, 0, 2 * i + 1),
        val[i] = nl_rng_gauss(5, 1, i);
    double rate = dgemm_rate(2000, reps);
    cli_bench_row("dgemm 2000^3", 2000 * 2000, 1.6e10 / rate, "itself", 1.6e10 / rate, NULL, 0);
    for (int r = 0; r < reps && r < 16; r++) {
        nl_krige_plan *p;
        double t0 = cli_bench_now();
        if ((st = nl_krige_plan_alloc(m, 2, np, pts, val, 0, 0, 0, &p)) || (st = nl_krige_eval_grid(p, lo, e, v)))
            cli_die_status(st);
        nl_krige_plan_free(p);
        t[r] = cli_bench_now() - t0;
    }
    double tk = cli_bench_median(t, reps < 16 ? reps : 16), fl = (double)np * (double)np * (double)(g * g) / rate;
    char name[96];
    snprintf(name, sizeof name, "krige %zu points -> %zu^2 +variance (grid)", np, g);
    cli_bench_row(name, g * g, tk, "n^2 m flops at the dgemm rate", fl, "n^2 m flops at the dgemm rate", fl);
    nl_field_free(e), nl_field_free(v), free(pts), free(val);
}
