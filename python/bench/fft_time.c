/* The C side of tools/bench-python.sh: the median time of FFT synthesis
 * (nl_synth_fft_execute) of one plan, made once outside the timing.
 * usage: fft_time N RUNS SPEC  -> prints "exec_s<TAB>alloc_exec_s": the median
 * of RUNS executes into one field, and of RUNS field allocations + executes +
 * frees (what noiselab.Plan.__call__ does for each new array). */
#include "core/field.h"
#include "core/model.h"
#include "core/nl_error.h"
#include "synth/fft.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int main(int argc, char **argv)
{
    if (argc != 4)
        return fprintf(stderr, "usage: fft_time N RUNS SPEC\n"), 2;
    size_t n[2] = {strtoul(argv[1], NULL, 10), strtoul(argv[1], NULL, 10)};
    int runs = atoi(argv[2]), st;
    nl_model *m;
    nl_synth_fft_plan *p;
    double *t = malloc((size_t)(runs > 0 ? runs : 1) * sizeof *t), e, a;
    if (!t || runs < 1 || (st = nl_model_parse(argv[3], &m)) || (st = nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p)))
        return fprintf(stderr, "fft_time: %s\n", nl_errmsg()), 1;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    if (!f || nl_synth_fft_execute(p, 0, f)) /* warm-up */
        return fprintf(stderr, "fft_time: %s\n", nl_errmsg()), 1;
    for (int r = 0; r < runs; r++) {
        double t0 = now();
        nl_synth_fft_execute(p, (uint64_t)r + 1, f);
        t[r] = now() - t0;
    }
    e = median(t, runs);
    for (int r = 0; r < runs; r++) {
        double t0 = now();
        nl_field *g = nl_field_alloc(2, n, NULL, &st);
        if (!g || nl_synth_fft_execute(p, (uint64_t)r + 1, g))
            return fprintf(stderr, "fft_time: %s\n", nl_errmsg()), 1;
        nl_field_free(g);
        t[r] = now() - t0;
    }
    a = median(t, runs);
    printf("%.6f\t%.6f\n", e, a);
    nl_field_free(f), nl_synth_fft_plan_free(p), nl_model_free(m), free(t);
    return 0;
}
