/* Experiment: FFT-synthesised fields against their target autocorrelation.
 *
 * usage: fft_acf SPEC WxH REALIZATIONS MAXLAG PREFIX
 * Synthesises REALIZATIONS fields (seeds 1..M), estimates each one's
 * unbiased ACF with the known mean 0 along x and y, and writes
 *   PREFIX.tsv           lag, mean and standard error of the ensemble along
 *                        x and y, target R along x and y
 *   PREFIX-field.png     the realization of seed 1 (mean +- 3 sd)
 *   PREFIX-verdict.json  max |z| over lags and axes against its threshold
 * The standard error is the ensemble's own spread, sd / sqrt(M); under a
 * correct synthesis z = (mean - R) / se follows Student's t with M - 1
 * degrees of freedom, and with 2 (MAXLAG + 1) lags tested at a family-wise
 * false alarm rate of 1e-3 the Bonferroni threshold is the t quantile at
 * 1 - 1e-3 / (4 (MAXLAG + 1)).  Exit status 1 when the verdict fails. */
#include "../analysis/verdict.h"
#include "../core/io.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/fft.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    size_t n[2], M, L;
    nl_model *m;
    nl_synth_fft_plan *p;
    nl_field *x;
    nl_verdict *v;
    long (*lags)[2];
    double *mean, *se, *target, zmax, zcrit, h[2] = {1, 1};
    char path[1024];
    FILE *fp;
    int st;

    if (argc != 6 || sscanf(argv[2], "%zux%zu", &n[0], &n[1]) != 2) {
        fprintf(stderr, "usage: fft_acf SPEC WxH REALIZATIONS MAXLAG PREFIX\n");
        return 2;
    }
    M = strtoul(argv[3], NULL, 10);
    L = strtoul(argv[4], NULL, 10) + 1;
    if ((st = nl_model_parse(argv[1], &m)) || (st = nl_synth_fft_plan_alloc(m, 2, n, h, 0, &p))) {
        fprintf(stderr, "fft_acf: %s\n", nl_errmsg());
        return 2;
    }
    x = nl_field_alloc(2, n, h, &st);
    lags = calloc(2 * L, sizeof *lags);
    mean = calloc(2 * L, sizeof *mean), se = calloc(2 * L, sizeof *se), target = calloc(2 * L, sizeof *target);
    for (size_t i = 0; i < L; i++) /* along x, then along y */
        lags[i][0] = (long)i, lags[L + i][1] = (long)i;
    if (!x || !lags || !mean || !se || !target || (st = nl_verdict_alloc(2, n, 2 * L, lags, &v))) {
        fprintf(stderr, "fft_acf: %s\n", nl_errmsg());
        return 2;
    }
    for (size_t s = 1; s <= M; s++) {
        nl_synth_fft_execute(p, s, x);
        if (s == 1) {
            snprintf(path, sizeof path, "%s-field.png", argv[5]);
            if ((st = nl_png_write_field(path, x, -3 * sqrt(nl_model_acf(m, 1, (double[]){0})),
                                         3 * sqrt(nl_model_acf(m, 1, (double[]){0}))))) {
                fprintf(stderr, "fft_acf: %s\n", nl_errmsg());
                return 1;
            }
        }
        nl_verdict_add(v, x);
    }
    nl_verdict_stats(v, mean, se);
    for (size_t i = 0; i < L; i++) {
        double lx[2] = {(double)i, 0}, ly[2] = {0, (double)i};
        target[i] = nl_model_acf(m, 2, lx);
        target[L + i] = nl_model_acf(m, 2, ly);
    }
    zmax = nl_verdict_zmax(2 * L, mean, se, target, NULL);
    zcrit = nl_verdict_threshold(1e-3, 2 * L, M - 1);
    snprintf(path, sizeof path, "%s.tsv", argv[5]);
    fp = fopen(path, "w");
    fprintf(fp, "# %s on %zux%zu, %zu realizations (seeds 1..%zu), unbiased ACF with known mean 0\n", argv[1], n[0],
            n[1], M, M);
    fprintf(fp, "lag\tmean_x\tse_x\tmean_y\tse_y\ttarget_x\ttarget_y\n");
    for (size_t i = 0; i < L; i++)
        fprintf(fp, "%zu\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", i, mean[i], se[i], mean[L + i], se[L + i], target[i],
                target[L + i]);
    fclose(fp);
    snprintf(path, sizeof path, "%s-verdict.json", argv[5]);
    fp = fopen(path, "w");
    fprintf(fp,
            "{\"model\": \"%s\", \"size\": \"%zux%zu\", \"realizations\": %zu, \"lags\": %zu, "
            "\"max_abs_z\": %.3f, \"threshold\": %.3f, \"pass\": %s}\n",
            argv[1], n[0], n[1], M, 2 * L, zmax, zcrit, zmax <= zcrit ? "true" : "false");
    fclose(fp);
    printf("%s: max |z| = %.2f over %zu lags (threshold %.2f): %s\n", argv[1], zmax, 2 * L, zcrit,
           zmax <= zcrit ? "pass" : "FAIL");
    nl_field_free(x);
    nl_synth_fft_plan_free(p);
    nl_model_free(m);
    nl_verdict_free(v);
    free(lags), free(mean), free(se), free(target);
    return zmax <= zcrit ? 0 : 1;
}
