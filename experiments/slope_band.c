/* Experiment: the log-log slope of psd --slope on fields of a band-limited
 * power law, inside the model's band and through its lower edge.  K FFT
 * syntheses of MODEL (power:d=D[,fmin=..]) on N samples (1D) or N x N
 * (2D), seeds 1..K, each rounded to 10 significant digits as a TSV file
 * holds it, then the periodogram (analysis/psd.h) and the least-squares
 * slope over [F1, F2] (analysis/slope.h: the 1D ordinates, or every 2D
 * ordinate in the band).  Prints one line: the mean slope, the scatter of
 * the slopes over the realizations, the mean standard error the fit
 * reports (its 95% half-width over Student's t), and the share of
 * realizations whose 95% interval holds -D.  The fit's interval is right
 * when the scatter equals the reported error and the share is 95%.
 * usage: slope_band MODEL D N DIM K F1 F2 */
#include "../analysis/psd.h"
#include "../analysis/slope.h"
#include "../analysis/spectral.h"
#include "../core/model.h"
#include "../synth/fft.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The slope of one realization; NL_OK or a status. */
static int one(const nl_synth_fft_plan *p, uint64_t seed, nl_field *f, double f1, double f2, nl_slope *sl)
{
    nl_field *P = NULL;
    double *fr = NULL, *v = NULL;
    size_t nf;
    int st = nl_synth_fft_execute(p, seed, f);
    for (size_t i = 0; !st && i < f->count; i++) { /* what "%.10g" in a TSV keeps */
        char buf[32];
        snprintf(buf, sizeof buf, "%.10g", f->data[i]);
        f->data[i] = strtod(buf, NULL);
    }
    if (!st)
        st = nl_psd_periodogram(f, NAN, &P);
    if (!st && f->dim == 2)
        st = nl_psd_slope_grid(P, f1, f2, sl);
    else if (!st) {
        fr = malloc(f->count * sizeof *fr), v = malloc(f->count * sizeof *v);
        st = !fr || !v || nl_psd_profile(P, fr, v, NULL, &nf) || nl_psd_slope(fr, v, nf, f1, f2, 1, sl);
    }
    free(fr), free(v);
    nl_field_free(P);
    return st;
}

int main(int argc, char **argv)
{
    nl_model *m;
    nl_synth_fft_plan *p;
    nl_field *f;
    size_t n[2], K, hit = 0;
    double d, f1, f2, s1 = 0, s2 = 0, se = 0;
    int dim;
    if (argc != 8)
        return fprintf(stderr, "usage: slope_band MODEL D N DIM K F1 F2\n"), 2;
    d = atof(argv[2]), n[0] = n[1] = strtoul(argv[3], NULL, 10), dim = atoi(argv[4]);
    K = strtoul(argv[5], NULL, 10), f1 = atof(argv[6]), f2 = atof(argv[7]);
    if ((dim != 1 && dim != 2) || K < 2 || nl_model_parse(argv[1], &m) ||
        nl_synth_fft_plan_alloc(m, dim, n, NULL, 0, &p) || !(f = nl_field_alloc(dim, n, NULL, NULL)))
        return fprintf(stderr, "slope_band: bad arguments\n"), 2;
    for (size_t s = 1; s <= K; s++) {
        nl_slope sl;
        if (one(p, s, f, f1, f2, &sl))
            return fprintf(stderr, "slope_band: seed %zu failed\n", s), 1;
        s1 += sl.slope, s2 += sl.slope * sl.slope;
        se += sl.ci95 / gsl_cdf_tdist_Qinv(0.025, (double)(sl.points - 2));
        hit += fabs(sl.slope + d) <= sl.ci95;
    }
    double mean = s1 / (double)K, sd = sqrt((s2 - s1 * s1 / (double)K) / (double)(K - 1));
    printf("%s\t%zu\t%d\t%g\t%g\t%.5f\t%.5f\t%.5f\t%.5f\t%.3f\n", argv[1], n[0], dim, f1, f2, mean,
           sd / sqrt((double)K), sd, se / (double)K, (double)hit / (double)K);
    nl_synth_fft_plan_free(p);
    nl_field_free(f);
    nl_model_free(m);
    return 0;
}
