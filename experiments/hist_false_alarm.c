/* Experiment: the false-alarm rate and the power of the thinned test on
 * correlated fields (nl_gof_test_thinned, which hist --against used before
 * its bootstrap, analysis/gof_boot.h), with and without the
 * effective-sample-size correction (analysis/gof_dep.h).  Each field is an FFT synthesis of MODEL on a SIZE x
 * SIZE grid (seeds 1..K), shaped to DIST (the README's demo: synth fft,
 * shape --to DIST, hist --against DIST); the false-alarm rate is the share
 * of fields whose p-value is below ALPHA against DIST, the power the share
 * rejected when the field is shaped to WRONG instead.
 * With MODE "exact" the Gaussian field (variance 1) is mapped by the exact
 * transform F^-1(Phi(x)) instead, so that each field is a sample of a
 * process whose marginal is DIST (shape standardises each field by its own
 * mean and deviation, which removes most of the slow fluctuation of the
 * empirical CDF: the test is then conservative).
 * The tests: the field thinned
 * (analysis/gof_dep.h), KS with the effective n, chi-square on at most
 * n_eff / 5 equal-probability bins counting each kept sample once.
 * usage: hist_false_alarm MODEL SIZE K DIST WRONG ALPHA BINS shape|exact
 * prints one line per test: name, rate corrected, rate uncorrected, and
 * the mean effective n and design effect. */
#include "../analysis/gof.h"
#include "../analysis/gof_dep.h"
#include "../core/dist.h"
#include "../core/model.h"
#include "../synth/fft.h"
#include "../synth/shape.h"

#include <gsl/gsl_cdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Map the standard Gaussian field f onto `to`, by shape or exactly. */
static int map(nl_field *f, const nl_dist *to, int exact)
{
    if (!exact)
        return nl_synth_shape(f, to, 0);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = nl_dist_quantile(to, f->data[i] < 0 ? gsl_cdf_ugaussian_P(f->data[i])
                                                          : 1 - gsl_cdf_ugaussian_Q(f->data[i]));
    return 0;
}

/* Rejections at alpha of KS and chi-square, thinned [0..1] and not [2..3]. */
static int count(const nl_field *f, const nl_dist *d, size_t bins, double alpha, size_t rej[4], double *neff,
                 double *stride)
{
    nl_gof_dep dep;
    nl_gof g, g0;
    if (nl_gof_test_thinned(&f, 1, d, bins, &dep, NULL, &g) || nl_gof_test(f->data, f->count, d, bins, &g0))
        return 1;
    rej[0] += g.p_ks < alpha, rej[1] += g.p_chi2 < alpha, rej[2] += g0.p_ks < alpha, rej[3] += g0.p_chi2 < alpha;
    *neff += g.n_eff, *stride += (double)dep.stride;
    return 0;
}

int main(int argc, char **argv)
{
    nl_model *m;
    nl_dist *d, *w;
    nl_synth_fft_plan *p;
    nl_field *f;
    size_t n[2], K, bins, rej[4] = {0}, pow[4] = {0};
    double alpha, neff = 0, deff = 0, nw = 0, dw = 0;
    int exact;
    if (argc != 9)
        return fprintf(stderr, "usage: hist_false_alarm MODEL SIZE K DIST WRONG ALPHA BINS shape|exact\n"), 2;
    exact = strcmp(argv[8], "exact") == 0;
    n[0] = n[1] = strtoul(argv[2], NULL, 10), K = strtoul(argv[3], NULL, 10);
    alpha = atof(argv[6]), bins = strtoul(argv[7], NULL, 10);
    if (nl_model_parse(argv[1], &m) || nl_dist_parse(argv[4], &d) || nl_dist_parse(argv[5], &w) ||
        nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p) || !(f = nl_field_alloc(2, n, NULL, NULL)))
        return fprintf(stderr, "hist_false_alarm: bad arguments\n"), 2;
    for (size_t s = 1; s <= K; s++) {
        if (nl_synth_fft_execute(p, s, f) || map(f, d, exact) || count(f, d, bins, alpha, rej, &neff, &deff))
            return fprintf(stderr, "hist_false_alarm: seed %zu failed\n", s), 1;
        if (nl_synth_fft_execute(p, s, f) || map(f, w, exact) || count(f, d, bins, alpha, pow, &nw, &dw))
            return fprintf(stderr, "hist_false_alarm: seed %zu failed\n", s), 1;
    }
    printf("fields %zu of %zux%zu, %s mapped (%s) to %s, alpha %g, %zu bins; mean effective n %.1f of %zu (KS), "
           "mean stride %.1f\n", K, n[0], n[1], argv[1], argv[8], argv[4], alpha, bins, neff / (double)K,
           f->count, deff / (double)K);
    printf("test\tfalse_alarm\tfalse_alarm_uncorrected\tpower_vs_%s\tpower_uncorrected\n", argv[5]);
    printf("ks\t%.4f\t%.4f\t%.4f\t%.4f\n", (double)rej[0] / (double)K, (double)rej[2] / (double)K,
           (double)pow[0] / (double)K, (double)pow[2] / (double)K);
    printf("chi2\t%.4f\t%.4f\t%.4f\t%.4f\n", (double)rej[1] / (double)K, (double)rej[3] / (double)K,
           (double)pow[1] / (double)K, (double)pow[3] / (double)K);
    nl_field_free(f), nl_synth_fft_plan_free(p), nl_model_free(m), nl_dist_free(d), nl_dist_free(w);
    return 0;
}
