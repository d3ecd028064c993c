/* Experiment: the false-alarm rate and the power of the bootstrap
 * goodness-of-fit test of noiselab hist --against (analysis/gof_boot.h).
 * Each field is an FFT synthesis of MODEL on a SIZE x SIZE grid, seeds
 * 1..K, divided by its ensemble standard deviation on that grid (the
 * plan's R(0): a power law's band below the grid's lowest frequency is
 * missing from it), then
 *   exact    mapped exactly by F^-1(Phi(x)) onto DIST: a sample of a process
 *            whose marginal is DIST (false alarms);
 *   shape    shaped by noiselab shape --to DIST, which fits each field's own
 *            mean and spread (false alarms of the everyday use);
 *   scale:R  multiplied by sqrt(R) (DIST should then be gauss): a field whose
 *            variance is R times the law's (power of the variance test).
 * and tested against DIST with B null draws (seed 1, as hist) and
 * chi-square on 50 bins.
 * usage: gof_boot_rates MODEL SIZE K DIST exact|shape|scale:R [B]
 * prints one line per statistic and the verdict: the share of fields with
 * p < 0.05 and its binomial standard error sqrt(r (1 - r) / K), for the
 * approximate and the rank p-values; then the mean detectable variance
 * ratios and KS distance. */
#include "../analysis/gof_boot.h"
#include "../core/dist.h"
#include "../core/model.h"
#include "../synth/fft.h"
#include "../synth/shape.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Map the Gaussian field f of variance var for the mode. */
static int map(nl_field *f, double var, const nl_dist *to, const char *mode)
{
    for (size_t i = 0; i < f->count; i++)
        f->data[i] /= sqrt(var);
    if (strcmp(mode, "shape") == 0)
        return nl_synth_shape(f, to, 0);
    if (strncmp(mode, "scale:", 6) == 0) {
        double s = sqrt(atof(mode + 6));
        for (size_t i = 0; i < f->count; i++)
            f->data[i] *= s;
        return 0;
    }
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = nl_dist_transform(to, f->data[i]);
    return 0;
}

static void line(const char *name, size_t rej, size_t rank, size_t K)
{
    double r = (double)rej / (double)K, q = (double)rank / (double)K;
    printf("%s\t%.4f\t%.4f\t%.4f\t%.4f\n", name, r, sqrt(r * (1 - r) / (double)K), q, sqrt(q * (1 - q) / (double)K));
}

int main(int argc, char **argv)
{
    nl_model *m;
    nl_dist *d;
    nl_synth_fft_plan *p;
    nl_field *f;
    nl_gof_boot b;
    nl_synth_fft_info info;
    size_t n[2], K, B, rej[NL_GOF_NSTATS + 1] = {0}, rank[NL_GOF_NSTATS] = {0}, tested[NL_GOF_NSTATS] = {0};
    double lo = 0, hi = 0, ks = 0, radius = 0;
    if (argc != 6 && argc != 7)
        return fprintf(stderr, "usage: gof_boot_rates MODEL SIZE K DIST exact|shape|scale:R [B]\n"), 2;
    n[0] = n[1] = strtoul(argv[2], NULL, 10), K = strtoul(argv[3], NULL, 10);
    B = argc == 7 ? strtoul(argv[6], NULL, 10) : NL_GOF_BOOT_DRAWS;
    if (nl_model_parse(argv[1], &m) || nl_dist_parse(argv[4], &d) || nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p) ||
        !(f = nl_field_alloc(2, n, NULL, NULL)) || K == 0)
        return fprintf(stderr, "gof_boot_rates: bad arguments\n"), 2;
    nl_synth_fft_plan_info(p, &info);
    for (size_t s = 1; s <= K; s++) {
        if (nl_synth_fft_execute(p, s, f) || map(f, info.variance, d, argv[5]) ||
            nl_gof_boot_test((const nl_field *const *)&f, 1, d, B, NL_GOF_BOOT_SEED, 50, &b))
            return fprintf(stderr, "gof_boot_rates: seed %zu failed\n", s), 1;
        for (int t = 0; t < NL_GOF_NSTATS; t++)
            if (b.stat[t].tested)
                tested[t]++, rej[t] += b.stat[t].p < 0.05, rank[t] += b.stat[t].p_rank < 0.05;
        rej[NL_GOF_NSTATS] += b.p < 0.05;
        lo += b.var_ratio_lo, hi += b.var_ratio_hi, ks += b.ks_detectable, radius += b.radius_max;
    }
    printf("# %zu fields of %zux%zu, %s %s to %s, %zu null draws, alpha 0.05; mean window radius %.1f\n", K, n[0],
           n[1], argv[1], argv[5], argv[4], B, radius / (double)K);
    printf("test\trejected\tse\trejected_rank\tse_rank\n");
    for (int t = 0; t < NL_GOF_NSTATS; t++)
        if (tested[t])
            line(nl_gof_boot_name(t), rej[t], rank[t], K);
    line("verdict", rej[NL_GOF_NSTATS], rej[NL_GOF_NSTATS], K);
    printf("# detectable 80%% at 5%%: variance ratio %.4f / %.4f, KS distance %.4f (means over the fields)\n",
           lo / (double)K, hi / (double)K, ks / (double)K);
    nl_field_free(f), nl_synth_fft_plan_free(p), nl_model_free(m), nl_dist_free(d);
    return 0;
}
