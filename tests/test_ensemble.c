/* Ensembles (analysis/ensemble.h and the several inputs of acf, psd and
 * hist): the mean and standard error, exact on small cases, and the
 * lesson they serve: K periodograms of white noise average to its level
 * with a standard error of about level / sqrt(K). */
#include "../analysis/ensemble.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "util.h"

#include <criterion/criterion.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>

Test(ensemble, mean_and_standard_error_known_answer)
{
    const double v[] = {1, 2, 3, 6, 5, 10}; /* 3 rows of 2 */
    double m[2], se[2];
    cr_assert_eq(nl_ensemble_mean_se(v, 3, 2, m, se), 0);
    cr_expect_float_eq(m[0], 3, 1e-15);
    cr_expect_float_eq(m[1], 6, 1e-15);
    cr_expect_float_eq(se[0], 2 / sqrt(3), 1e-15); /* sd 2 over sqrt 3 */
    cr_expect_float_eq(se[1], 4 / sqrt(3), 1e-15);
    cr_expect_eq(nl_ensemble_mean_se(v, 1, 2, m, se), NL_EINVAL);
    cr_expect_eq(nl_ensemble_mean_se(v, 3, 0, m, se), NL_EINVAL);
}

/* K white-noise series of n samples, sd 1.3, as value-only TSV files wK.tsv. */
static void white_files(int K, size_t n)
{
    char path[512];
    for (int k = 0; k < K; k++) {
        snprintf(path, sizeof path, "%s/w%d.tsv", scratch_dir(), k);
        FILE *fp = fopen(path, "w");
        cr_assert(fp);
        fprintf(fp, "value\n");
        for (size_t i = 0; i < n; i++)
            fprintf(fp, "%.17g\n", 1.3 * nl_rng_gauss(40 + (uint64_t)k, 0, i));
        fclose(fp);
    }
}

static double at(json_t *j, const char *key, size_t i)
{
    return json_real_value(json_array_get(json_object_get(j, key), i));
}

/* The two-sided periodogram of white noise of variance s^2 = 1.69 (unit
 * spacing) has level s^2 at every frequency, each ordinate exponential
 * (sd = mean).  The mean of K = 16 has relative sd 1/4; over the 511
 * interior frequencies of n = 1024 (independent ordinates) the average of
 * mean / level has sd 0.25 / sqrt(511) = 0.011: within 5%.  The standard
 * error of each mean is near level / 4 (the sample sd of 16 exponentials
 * averages about 0.95 of theirs): its average over the frequencies, sd
 * ~0.004, lies in [0.20, 0.30] of the level. */
Test(ensemble, psd_of_white_noise)
{
    char args[1024] = "psd", *p = args + 3;
    double m = 0, s = 0;
    white_files(16, 1024);
    for (int k = 0; k < 16; k++)
        p += sprintf(p, " w%d.tsv", k);
    sprintf(p, " --json");
    json_t *j = run_noiselab_json(args);
    cr_assert_eq(json_integer_value(json_object_get(j, "fields")), 16);
    cr_assert_eq(json_array_size(json_object_get(j, "se")), 513);
    for (size_t i = 1; i < 512; i++)
        m += at(j, "psd", i) / 1.69 / 511, s += at(j, "se", i) / 1.69 / 511;
    cr_expect(fabs(m - 1) < 0.05, "mean level %g of 1", m);
    cr_expect(s > 0.20 && s < 0.30, "mean standard error %g of the level, expected about 0.25", s);
    json_decref(j);
}

/* Two inputs: the mean of the two single estimates, to the 10 digits of
 * the JSON; the standard error of two values is |a - b| / 2. */
Test(ensemble, two_inputs_average_the_single_estimates)
{
    static const char *const cmd[] = {"acf %s --max-lag 8 --json", "psd %s --welch 64 --json",
                                      "hist %s --bins 7 --json"};
    static const char *const key[] = {"acf", "psd", "counts"}, *const sek[] = {"se", "se", "counts_se"};
    char args[256];
    white_files(2, 512);
    for (int c = 0; c < 3; c++) {
        json_t *a, *b, *e;
        snprintf(args, sizeof args, cmd[c], "w0.tsv");
        a = run_noiselab_json(args);
        snprintf(args, sizeof args, cmd[c], "w1.tsv");
        b = run_noiselab_json(args);
        snprintf(args, sizeof args, cmd[c], "w0.tsv w1.tsv");
        e = run_noiselab_json(args);
        size_t n = json_array_size(json_object_get(e, key[c]));
        cr_assert(n > 0);
        for (size_t i = 0; i < n && c < 2; i++) {
            double x = at(a, key[c], i), y = at(b, key[c], i), tol = 1e-9 * (fabs(x) + fabs(y)) + 1e-300;
            cr_expect_float_eq(at(e, key[c], i), (x + y) / 2, tol, "%s row %zu", cmd[c], i);
            cr_expect_float_eq(at(e, sek[c], i), fabs(x - y) / 2, tol, "%s se %zu", cmd[c], i);
        }
        if (c == 2) { /* common bins over both ranges: the mean counts add up to the mean n */
            double t = 0;
            for (size_t i = 0; i < n; i++)
                t += at(e, key[c], i);
            cr_expect_float_eq(t, 512, 1e-9);
            double ma = json_real_value(json_object_get(a, "mean")), mb = json_real_value(json_object_get(b, "mean"));
            cr_expect_float_eq(json_real_value(json_object_get(e, "mean")), (ma + mb) / 2, 1e-9);
        }
        json_decref(a), json_decref(b), json_decref(e);
    }
}

/* --realizations K --acf SPEC --size N --seed S analyses the fields that
 * noiselab synth fft makes with seeds S..S+K-1: the same estimate as from
 * those files, but for the files' rounding to 10 digits (a relative error
 * of 5e-10 per sample, about 1e-9 of the power in a quadratic estimate:
 * 1e-7 of the largest ordinate is ample). */
Test(ensemble, realizations_are_the_synthesised_files)
{
    char err[4096];
    double mx = 0;
    for (int s = 5; s <= 7; s++) {
        char args[256];
        snprintf(args, sizeof args, "synth fft --acf markov:scale=8 --size 512 --seed %d -o r%d.tsv", s, s);
        cr_assert_eq(run_noiselab(args, 0, 0, err, sizeof err), 0, "%s", err);
    }
    json_t *a = run_noiselab_json("psd r5.tsv r6.tsv r7.tsv --json");
    json_t *b = run_noiselab_json("psd --realizations 3 --acf markov:scale=8 --size 512 --seed 5 --json");
    size_t n = json_array_size(json_object_get(a, "psd"));
    cr_assert_eq(json_array_size(json_object_get(b, "psd")), n);
    for (size_t i = 0; i < n; i++)
        mx = fmax(mx, at(a, "psd", i));
    for (size_t i = 0; i < n; i++) {
        cr_expect_float_eq(at(b, "psd", i), at(a, "psd", i), 1e-7 * mx, "row %zu", i);
        cr_expect_float_eq(at(b, "se", i), at(a, "se", i), 1e-7 * mx, "se row %zu", i);
    }
    json_decref(a), json_decref(b);
}
