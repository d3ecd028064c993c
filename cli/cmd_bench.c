/* noiselab bench: speed of the methods against this machine's floor. */
#include "cli.h"
#include "../core/fftw_plan.h"
#include "../analysis/acf.h"
#include "../core/model.h"
#include "../core/rng.h"
#include "../synth/fft.h"
#include "../synth/rank1.h"
#include "../synth/subdiv.h"
#include <complex.h>
#include <math.h>

#include <fftw3.h>
#include <getopt.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char help[] =
    "usage: noiselab bench [--quick] [--repeat R]\n\n"
    "Times each method and the floor it is measured against, in the same run, and\n"
    "prints TSV: case, samples, median seconds, floor, floor median seconds, ratio\n"
    "(ours / floor) and samples per second.  Medians of R runs (default 5; 3 with\n"
    "--quick, which also uses 1024^2 fields instead of 4096^2).  Floors: for FFT\n"
    "synthesis the bare FFTW r2c + c2r of the same size; for subdivision the\n"
    "Gaussian random numbers it draws (one per new sample); for the ACF estimate\n"
    "the FFTW r2c + c2r of the zero-padded size.\n";

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double median(double *v, int n)
{
    gsl_sort(v, 1, (size_t)n);
    return gsl_stats_median_from_sorted_data(v, 1, (size_t)n);
}

/* Bare r2c + c2r of an n x n grid. */
static double fft_floor(size_t n, int reps)
{
    double *x = fftw_alloc_real(n * n), t[16];
    fftw_complex *c = fftw_alloc_complex(n * (n / 2 + 1));
    fftw_plan f = fftw_plan_dft_r2c_2d((int)n, (int)n, x, c, nl_fftw_flags(n * n));
    fftw_plan b = fftw_plan_dft_c2r_2d((int)n, (int)n, c, x, nl_fftw_flags(n * n));
    for (size_t i = 0; i < n * n; i++)
        x[i] = (double)(i % 7);
    for (int r = 0; r < reps; r++) {
        double t0 = now();
        fftw_execute(f);
        fftw_execute(b);
        t[r] = now() - t0;
    }
    fftw_destroy_plan(f), fftw_destroy_plan(b), fftw_free(x), fftw_free(c);
    return median(t, reps);
}

static double rng_floor(size_t count, int reps)
{
    double *x = malloc(count * sizeof *x), t[16];
    for (int r = 0; r < reps; r++) {
        double t0 = now();
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < count; i++)
            x[i] = nl_rng_gauss(1, 0, i);
        t[r] = now() - t0;
    }
    free(x);
    return median(t, reps);
}

static void row(const char *name, size_t samples, double t, const char *floor_name, double tf)
{
    printf("%s\t%zu\t%.4f\t%s\t%.4f\t%.2f\t%.3g\n", name, samples, t, floor_name, tf, t / tf, (double)samples / t);
    fflush(stdout);
}

int cmd_bench(int argc, char **argv)
{
    static const struct option opts[] = {{"quick", no_argument, 0, 'q'}, {"repeat", required_argument, 0, 'r'},
                                         {"help", no_argument, 0, 'h'}, {0}};
    int c, quick = 0, reps = 0, st;
    size_t n, nn[2];
    double t[16];
    nl_model *m;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":h", opts, NULL)) != -1) {
        switch (c) {
        case 'q': quick = 1; break;
        case 'r':
            reps = (int)cli_parse_count("--repeat", optarg, 1);
            if (reps > 16)
                cli_die(2, "--repeat: expected 1 to 16, got \"%s\"", optarg);
            break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("bench", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "bench: unexpected argument \"%s\"", argv[optind]);
    if (!reps)
        reps = quick ? 3 : 5;
    n = quick ? 1024 : 4096;
    nn[0] = nn[1] = n;
    if ((st = nl_model_parse("markaussian:alpha=1.4,scale=64", &m)))
        cli_die_status(st);
    printf("case\tsamples\tmedian_s\tfloor\tfloor_median_s\tratio\tsamples_per_s\n");

    /* FFT synthesis: execute only (the plan is made once and reused) */
    {
        synth_fft_plan *p;
        nl_field *f = nl_field_alloc(2, nn, NULL, &st);
        if (!f || (st = synth_fft_plan_alloc(m, 2, nn, NULL, 0, &p)))
            cli_die_status(st);
        for (int r = 0; r < reps; r++) {
            double t0 = now();
            synth_fft_execute(p, (uint64_t)r + 1, f);
            t[r] = now() - t0;
        }
        row("synth fft 2D", n * n, median(t, reps), "fftw r2c+c2r", fft_floor(n, reps));
        synth_fft_plan_free(p);
        nl_field_free(f);
    }
    /* subdivision, 4x4 neighbourhood, coarse grid 8x8 (coefficients made once) */
    {
        int L = 0;
        while ((n >> (L + 1)) >= 8)
            L++;
        subdiv_coeffs *co;
        nl_field *f = nl_field_alloc(2, nn, NULL, &st);
        if (!f || (st = subdiv_coeffs_alloc(m, 2, L, (double)(1 << L), 2, 1e-4, 6, &co)))
            cli_die_status(st);
        for (int r = 0; r < reps; r++) {
            double t0 = now();
            subdiv_synth_periodic(co, m, (uint64_t)r + 1, 0, f);
            t[r] = now() - t0;
        }
        row("synth subdiv 2D N=2", n * n, median(t, reps), "gaussian rng", rng_floor(n * n, reps));
        subdiv_coeffs_free(co);
        nl_field_free(f);
    }
    /* ACF estimate of a half-size field (its padded FFT is n x n) */
    {
        size_t h2[2] = {n / 2, n / 2};
        nl_field *f = nl_field_alloc(2, h2, NULL, &st), *full;
        if (!f)
            cli_die_status(st);
        for (size_t i = 0; i < f->count; i++)
            f->data[i] = nl_rng_gauss(3, 0, i);
        for (int r = 0; r < reps; r++) {
            double t0 = now();
            an_acf_full(f, 0.0, 0, &full);
            t[r] = now() - t0;
            nl_field_free(full);
        }
        row("acf 2D", f->count, median(t, reps), "fftw r2c+c2r padded", fft_floor(n, reps));
        nl_field_free(f);
    }
    /* rank-1 lattice synthesis (Keller) against the tensor-product FFT with
     * the same number of points, s = 2, 3, 4: both are one O(N log N)
     * transform; the lattice does the whole field with a 1D FFT of length N */
    {
        static const int side[5] = {0, 0, 128, 32, 16};
        for (int sd = 2; sd <= 4; sd++) {
            size_t M = (size_t)(quick ? side[sd] / 2 : side[sd]), NN = 1;
            int dims[4];
            for (int a = 0; a < sd; a++)
                NN *= M, dims[a] = (int)M;
            rank1_lattice L;
            if ((st = rank1_korobov(NN, sd, 0, &L)))
                cli_die_status(st);
            double *cf = malloc(2 * NN * sizeof *cf), *f = malloc(NN * sizeof *f), tr[16], tt[16];
            fftw_complex *b = fftw_alloc_complex(NN);
            fftw_plan p = fftw_plan_dft(sd, dims, b, b, FFTW_BACKWARD, nl_fftw_flags(NN));
            for (int r = 0; r < reps; r++) {
                double t0 = now();
                for (size_t k = 0; k < NN; k++) {
                    double k2 = 0;
                    for (int a = 0; a < sd; a++)
                        k2 += (double)(L.k[k * sd + a] * L.k[k * sd + a]);
                    cf[2 * k] = exp(-k2 / 64) * nl_rng_gauss2(1, 0, k, 0);
                    cf[2 * k + 1] = exp(-k2 / 64) * nl_rng_gauss2(1, 0, k, 1);
                }
                rank1_synthesize(&L, cf, 1, f, NULL, NULL);
                tr[r] = now() - t0;
                t0 = now();
                for (size_t k = 0; k < NN; k++)
                    b[k] = exp(-(double)(k % 7) / 64) * (nl_rng_gauss2(1, 0, k, 0) + I * nl_rng_gauss2(1, 0, k, 1));
                fftw_execute(p);
                tt[r] = now() - t0;
            }
            char name[64], fl[64];
            snprintf(name, sizeof name, "rank1 %dD N=%zu", sd, NN);
            snprintf(fl, sizeof fl, "tensor FFT %dD %zu^%d", sd, M, sd);
            row(name, NN, median(tr, reps), fl, median(tt, reps));
            fftw_destroy_plan(p), fftw_free(b), free(cf), free(f), rank1_free(&L);
        }
    }
    nl_model_free(m);
    return 0;
}
