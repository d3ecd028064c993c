/* Plan FFT synthesis once, execute it for several seeds, and compare the
 * average estimated autocorrelation along x with the model's R (the
 * README's "Using the library" example).
 * Build: cc fft_acf.c $(pkg-config --cflags --libs noiselab) */
#include <noiselab.h>

#include <math.h>
#include <stdio.h>

#define SEEDS 16
#define MAXLAG 8

int main(void)
{
    const size_t n[2] = {128, 128};
    nl_model *m = NULL;
    nl_synth_fft_plan *plan = NULL;
    nl_acf_plan *est = NULL;
    nl_field *f = NULL, *acf = NULL;
    double lag[MAXLAG + 1], val[MAXLAG + 1], avg[MAXLAG + 1] = {0};

    int st = nl_model_parse("markov:scale=8", &m);
    if (st == NL_OK)
        st = nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &plan); /* the costly part, once */
    if (st == NL_OK)
        st = nl_acf_plan_alloc(2, n, &est); /* the estimator's FFTW plans, once */
    if (st == NL_OK)
        f = nl_field_alloc(2, n, NULL, &st);
    if (st == NL_OK)
        acf = nl_acf_plan_output_alloc(est, NULL, &st);
    for (uint64_t seed = 1; st == NL_OK && seed <= SEEDS; seed++) {
        st = nl_synth_fft_execute(plan, seed, f); /* one realization per seed */
        if (st == NL_OK)
            st = nl_acf_plan_execute(est, f, NAN, NL_ACF_BIASED, acf); /* NAN: subtract the sample mean */
        if (st == NL_OK)
            st = nl_acf_axis(acf, 0, MAXLAG, lag, val);
        for (int i = 0; st == NL_OK && i <= MAXLAG; i++)
            avg[i] += val[i] / SEEDS;
    }
    if (st == NL_OK) {
        printf("lag\testimate\tmodel\n");
        for (int i = 0; i <= MAXLAG; i++) {
            double l[2] = {lag[i], 0};
            printf("%g\t%.4f\t%.4f\n", lag[i], avg[i], nl_model_acf(m, 2, l));
        }
    } else {
        fprintf(stderr, "fft_acf: %s\n", nl_errmsg());
    }
    nl_field_free(acf);
    nl_field_free(f);
    nl_acf_plan_free(est);
    nl_synth_fft_plan_free(plan);
    nl_model_free(m);
    return st == NL_OK ? 0 : 1;
}
