/* Experiment: how often the card's bands hold the estimates of fields of
 * the model, the coverage they promise being 95%.  For K fields of MODEL
 * (exact stationary fields by circulant embedding for the ACF and the
 * histogram; FFT fields for the spectra, whose periodogram then has the
 * sampled model spectrum as its expectation exactly), it counts per lag,
 * ordinate or bin the share of fields inside the band:
 *   acf       nl_acf_model_band along x, 1D n = N1 and 2D N2 x N2, lags 0,
 *             L/4, L/2, L (L = n/8, at most 32), with the Monte-Carlo sd over
 *             the model's
 *   per       the periodogram ordinates 0 < f < 1/2 of 1D fields of N1,
 *             against S [0.0253, 3.689] (chi-square 2)
 *   welch     Welch (segments of N1/16) against the chi-square band of its
 *             equivalent degrees of freedom (nl_welch_edf)
 *   hist      the density of 40 bins over -+ 4 sd of 2D fields N2 x N2
 *             against nl_hist_model_band (the bins with p > 0.005)
 * usage: card_bands MODEL N1 N2 K
 * prints TSV: what, where, coverage, sd ratio (acf) or bins counted. */
#include "../analysis/acf.h"
#include "../analysis/bands.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/welch.h"
#include "../core/model.h"
#include "../core/wk.h"
#include "../synth/circulant.h"
#include "../synth/fft.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void die(const char *what)
{
    fprintf(stderr, "card_bands: %s failed\n", what);
    exit(1);
}

/* The ACF band's coverage along x for fields of dim axes of n. */
static void acf(const nl_model *m, int dim, size_t n, int K)
{
    size_t nn[2] = {n, n}, L = n / 8 > 32 ? 32 : n / 8, at[4] = {0, L / 4, L / 2, L};
    double mean[33], lo[33], hi[33], lag[33], v[33], s[4] = {0}, q[4] = {0};
    int in[4] = {0};
    nl_synth_circulant_plan *p;
    nl_field *x = nl_field_alloc(dim, nn, NULL, NULL), *full;
    if (nl_acf_model_band(m, dim, nn, NULL, 0, L, mean, lo, hi) ||
        nl_synth_circulant_plan_alloc(m, dim, nn, NULL, 0, 8, &p))
        die("the ACF band");
    for (int r = 0; r < K; r++) {
        if (nl_synth_circulant_execute(p, (uint64_t)r + 1, x) || nl_acf_full(x, NAN, 0, &full) ||
            nl_acf_axis(full, 0, L, lag, v))
            die("an ACF estimate");
        for (int i = 0; i < 4; i++) {
            double d = v[at[i]] - mean[at[i]];
            in[i] += v[at[i]] >= lo[at[i]] && v[at[i]] <= hi[at[i]];
            s[i] += d, q[i] += d * d;
        }
        nl_field_free(full);
    }
    for (int i = 0; i < 4; i++) {
        double mu = s[i] / K, sd = sqrt(q[i] / K - mu * mu);
        printf("acf %dD n=%zu\tlag %zu\t%.4f\t%.4f\n", dim, n, at[i], (double)in[i] / K,
               sd / ((hi[at[i]] - mean[at[i]]) / 1.959964));
    }
    nl_synth_circulant_plan_free(p);
    nl_field_free(x);
}

/* Periodogram and Welch coverage over the ordinates of 1D FFT fields. */
static void spectra(const nl_model *m, size_t n, int K)
{
    size_t seg = n / 16, segs, inP = 0, inW = 0, cntP = 0, cntW = 0;
    double nu, lP, hP, lW, hW;
    nl_synth_fft_plan *p;
    nl_field *x = nl_field_alloc(1, &n, NULL, NULL), *S = nl_field_alloc(1, &n, NULL, NULL),
             *SW = nl_field_alloc(1, &seg, NULL, NULL), *P, *W;
    if (nl_synth_fft_plan_alloc(m, 1, &n, NULL, 0, &p) || nl_wk_sample_spectrum(m, S) || nl_wk_sample_spectrum(m, SW) ||
        nl_welch_edf(1, &n, seg, &nu) || nl_band_chisq(2, &lP, &hP) || nl_band_chisq(nu, &lW, &hW))
        die("the spectral bands");
    for (int r = 0; r < K; r++) {
        if (nl_synth_fft_execute(p, (uint64_t)r + 1, x) || nl_psd_periodogram(x, NAN, &P) ||
            nl_psd_welch(x, seg, NAN, &W, &segs))
            die("a spectrum estimate");
        for (size_t k = 1; k < n / 2; k++, cntP++)
            inP += P->data[k] >= lP * S->data[k] && P->data[k] <= hP * S->data[k];
        for (size_t k = 2; k < seg / 2; k++, cntW++)  /* off the window's lobe at 0 */
            inW += W->data[k] >= lW * SW->data[k] && W->data[k] <= hW * SW->data[k];
        nl_field_free(P), nl_field_free(W);
    }
    printf("periodogram 1D n=%zu\t0<f<1/2\t%.4f\t%zu\n", n, (double)inP / (double)cntP, cntP);
    printf("welch 1D n=%zu nu=%.1f\t2/S<=f<1/2\t%.4f\t%zu\n", n, nu, (double)inW / (double)cntW, cntW);
    nl_synth_fft_plan_free(p);
    nl_field_free(x), nl_field_free(S), nl_field_free(SW);
}

/* Histogram coverage per bin of 2D circulant fields. */
static void hist(const nl_model *m, size_t n, int K)
{
    enum { B = 40 };
    size_t nn[2] = {n, n}, in = 0, cnt = 0;
    double e[B + 1], dens[B], sd[B], c[B], r0;
    nl_synth_circulant_plan *p;
    nl_field *x = nl_field_alloc(2, nn, NULL, NULL);
    double zero[3] = {0, 0, 0};
    r0 = nl_model_acf(m, 2, zero);
    for (int b = 0; b <= B; b++)
        e[b] = sqrt(r0) * (-4 + 8.0 * b / B);
    if (nl_hist_model_band(m, 2, nn, NULL, e, B, dens, sd) || nl_synth_circulant_plan_alloc(m, 2, nn, NULL, 0, 8, &p))
        die("the histogram band");
    for (int r = 0; r < K; r++) {
        if (nl_synth_circulant_execute(p, (uint64_t)r + 1, x) || nl_hist_count(x, e, B, c))
            die("a histogram");
        for (int b = 1; b < B - 1; b++) {
            double w = e[b + 1] - e[b], d = c[b] / ((double)x->count * w);
            if (dens[b] * w < 0.005)
                continue;
            in += fabs(d - dens[b]) <= 1.959964 * sd[b], cnt++;
        }
    }
    printf("hist 2D n=%zu\tbins p>0.005\t%.4f\t%zu\n", n, (double)in / (double)cnt, cnt);
    nl_synth_circulant_plan_free(p);
    nl_field_free(x);
}

int main(int argc, char **argv)
{
    nl_model *m;
    if (argc != 5 || nl_model_parse(argv[1], &m)) {
        fprintf(stderr, "usage: card_bands MODEL N1 N2 K\n");
        return 2;
    }
    size_t n1 = strtoul(argv[2], NULL, 10), n2 = strtoul(argv[3], NULL, 10);
    int K = atoi(argv[4]);
    printf("what\twhere\tcoverage\tsd_ratio_or_count\n");
    acf(m, 1, n1, K);
    acf(m, 2, n2, K);
    spectra(m, n1, K);
    hist(m, n2, K);
    nl_model_free(m);
    return 0;
}
