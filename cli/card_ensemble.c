/* The data files of the ensemble card (`noiselab card` of K fields): the
 * mean over the fields of the ACF along each axis, of the periodogram (1D
 * per ordinate, 2D radially averaged, and its map) and of the histogram's
 * density, each with its standard error (analysis/ensemble.h), against the
 * model with its 95% bands for the mean of K fields: the ACF's and the
 * histogram's over sqrt(K), the periodogram's chi-square with 2K (1D) or
 * K times the bin's ordinates (2D) degrees of freedom. */
#include "cli.h"
#include "card.h"
#include "../analysis/acf.h"
#include "../analysis/bands.h"
#include "../analysis/ensemble.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The estimates of every field, one row each, and what their means need. */
typedef struct {
    size_t K, L, nf, nb;     /* fields, lags, 1D ordinates (f > 0) or 2D radial bins */
    double *acf[2];          /* K rows of L lags per axis */
    double *lag[2];          /* the lags (length units) */
    double *spec;            /* K rows of nf (1D) or nb (2D) */
    double *freq;            /* their frequencies */
    size_t *cnt;             /* 2D: ordinates per radial bin */
    double step;             /* 2D: the radial bins' width */
    double *hist;            /* K rows of CARD_HIST_BINS densities */
    double edges[CARD_HIST_BINS + 1];
    nl_field *Psum;          /* the sum of the periodograms */
} rows_t;

static void rows_alloc(rows_t *r, const cli_card *c, const nl_field *x)
{
    nl_moments mo;
    int st;
    r->L = c->maxlag + 1;
    r->nf = x->n[0] / 2;
    r->step = x->dim == 2 ? fmax(1 / ((double)x->n[0] * x->h[0]), 1 / ((double)x->n[1] * x->h[1])) : 0;
    r->nb = x->dim == 2 ? (size_t)(fmin(0.5 / x->h[0], 0.5 / x->h[1]) / r->step) + 1 : r->nf;
    for (int a = 0; a < 2; a++) {
        r->acf[a] = cli_malloc(r->K * r->L * sizeof(double));
        r->lag[a] = cli_malloc(r->L * sizeof(double));
    }
    r->spec = cli_malloc(r->K * r->nb * sizeof(double));
    r->freq = cli_malloc(r->nb * sizeof(double));
    r->cnt = cli_malloc(r->nb * sizeof(size_t));
    r->hist = cli_malloc(r->K * CARD_HIST_BINS * sizeof(double));
    if ((st = nl_moments_compute(x, &mo)))
        cli_die_status(st);
    for (int b = 0; b <= CARD_HIST_BINS; b++)  /* mean -+ 4 sd of field 1 */
        r->edges[b] = mo.mean + sqrt(mo.variance) * (-4 + 8.0 * b / CARD_HIST_BINS);
    r->Psum = cli_field_alloc(x->dim, x->n, x->h);
}

/* Field k's ACF, periodogram and histogram into row k. */
static void estimate(const cli_card *c, rows_t *r, size_t k, const nl_field *x)
{
    nl_field *full, *P;
    double cnt[CARD_HIST_BINS];
    int st;
    if ((st = nl_acf_full(x, NAN, 0, &full)))
        cli_die_status(st);
    for (int a = 0; a < x->dim; a++)
        if ((st = nl_acf_axis(full, a, r->L - 1, r->lag[a], r->acf[a] + k * r->L)))
            cli_die_status(st);
    nl_field_free(full);
    if ((st = nl_psd_periodogram(x, NAN, &P)))
        cli_die_status(st);
    if (x->dim == 1)
        for (size_t j = 0; j < r->nf; j++)
            r->spec[k * r->nf + j] = P->data[j + 1], r->freq[j] = (double)(j + 1) / ((double)x->n[0] * x->h[0]);
    else
        nl_radial(P, NL_GRID_FREQ, r->step, r->nb, r->freq, r->spec + k * r->nb, r->cnt);
    for (size_t i = 0; i < P->count; i++)
        r->Psum->data[i] += P->data[i];
    if (k == 0 && x->dim == 2)
        cli_card_write_map(c, "first.bin", P, c->block, NULL);
    nl_field_free(P);
    if ((st = nl_hist_count(x, r->edges, CARD_HIST_BINS, cnt)))
        cli_die_status(st);
    for (int b = 0; b < CARD_HIST_BINS; b++)
        r->hist[k * CARD_HIST_BINS + b] = cnt[b] / ((double)x->count * (r->edges[b + 1] - r->edges[b]));
}

/* The mean and se of the K rows of m columns (rows replaced: mean, se). */
static void mean_se(const rows_t *r, const double *v, size_t m, double *mean, double *se)
{
    int st;
    if ((st = nl_ensemble_mean_se(v, r->K, m, mean, se)))
        cli_die_status(st);
}

/* acf.tsv as the one-field card's (lag, mean, lo, hi, R, E per axis), the
 * se of each axis after them. */
static void write_acf(const cli_card *c, const rows_t *r, const nl_field *x, const nl_model *m)
{
    size_t L = r->L;
    double *a = cli_malloc(14 * L * sizeof *a);
    for (int ax = 0; ax < x->dim; ax++) {
        double *lag = a + 6 * ax * L, *v = lag + L, *lo = v + L, *hi = lo + L, *R = hi + L, *E = R + L;
        memcpy(lag, r->lag[ax], L * sizeof *lag);
        mean_se(r, r->acf[ax], L, v, a + (6 * x->dim + ax) * L);
        cli_card_model_lags(m, x, ax, lag, L, R);
        cli_card_acf_band(c, m, x, ax, E, lo, hi);
    }
    FILE *fp = cli_card_open(c, "acf.tsv");
    for (size_t i = 0; i < L; i++) {
        for (int k = 0; k < 7 * x->dim; k++)
            fprintf(fp, "%s%.8g", k ? "\t" : "", a[k * L + i]);
        fprintf(fp, "\n");
    }
    cli_card_close(fp);
    free(a);
}

/* 1D per.tsv / 2D radial.tsv: f, mean, model, band lo, hi, se. */
static void write_spectrum(cli_card *c, const rows_t *r, const nl_field *x, const nl_model *m)
{
    size_t nb = r->nb;
    double *mean = cli_malloc(4 * nb * sizeof *mean), *se = mean + nb, *t = se + nb, *rr = t + nb;
    nl_field *S = m ? cli_card_model_spectrum(r->Psum, m, c->spec) : NULL;
    mean_se(r, r->spec, nb, mean, se);
    for (size_t b = 0; b < nb; b++)
        t[b] = NAN;
    if (S && x->dim == 1)
        for (size_t j = 0; j < nb; j++)
            t[j] = S->data[j + 1];
    else if (S)
        nl_radial(S, NL_GRID_FREQ, r->step, nb, rr, t, r->cnt);
    FILE *fp = cli_card_open(c, x->dim == 1 ? "per.tsv" : "radial.tsv");
    double mx = 0;
    for (size_t b = 0; b < nb; b++)
        mx = mean[b] > mx ? mean[b] : mx;
    for (size_t b = x->dim == 1 ? 0 : 1; b < nb; b++) {  /* below 1e-12 of the top: rounding */
        double lo, hi, nu = x->dim == 1 ? (2 * (b + 1) == x->n[0] ? 1.0 : 2.0) : (double)r->cnt[b];
        double tb = t[b] > 1e-12 * mx ? t[b] : NAN;
        cli_card_chisq(nu * (double)r->K, &lo, &hi);
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", r->freq[b], mean[b] > 1e-12 * mx ? mean[b] : NAN, tb,
                tb * lo, tb * hi, se[b]);
    }
    cli_card_close(fp);
    if (x->dim == 2) {
        for (size_t i = 0; i < r->Psum->count; i++)
            r->Psum->data[i] /= (double)r->K;
        cli_card_write_map(c, "per.bin", r->Psum, c->block, &c->top);
        if (S)
            cli_card_write_map(c, "model.bin", S, c->block, NULL);
    }
    nl_field_free(S);
    free(mean);
}

/* hist.tsv: bin centre, mean density, the Gaussian of field 1's moments,
 * the model's density, its band for the mean of K fields, se. */
static void write_hist(const cli_card *c, const rows_t *r, const nl_field *x, const nl_model *m)
{
    enum { B = CARD_HIST_BINS };
    double mean[B], se[B], md[B], sd[B], mu = 0.5 * (r->edges[0] + r->edges[B]), s = (r->edges[B] - mu) / 4;
    int st;
    mean_se(r, r->hist, B, mean, se);
    for (int b = 0; b < B; b++)
        md[b] = sd[b] = NAN;
    if (m && (st = nl_hist_model_band(m, x->dim, x->n, x->h, r->edges, B, md, sd)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
    FILE *fp = cli_card_open(c, "hist.tsv");
    fprintf(fp, "x\tdensity\tgauss\tmodel\tlo\thi\tse\n");
    for (int b = 0; b < B; b++) {
        double mid = 0.5 * (r->edges[b] + r->edges[b + 1]), z = (mid - mu) / s;
        double h = 1.959964 * sd[b] / sqrt((double)r->K), g = exp(-0.5 * z * z) / (s * sqrt(2 * M_PI));
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", mid, mean[b], g, md[b], fmax(0, md[b] - h),
                md[b] + h, se[b]);
    }
    cli_card_close(fp);
}

static void rows_free(rows_t *r)
{
    for (int a = 0; a < 2; a++)
        free(r->acf[a]), free(r->lag[a]);
    free(r->spec), free(r->freq), free(r->cnt), free(r->hist);
    nl_field_free(r->Psum);
}

void cli_card_ensemble_write(cli_card *c, cli_inputs *in, const nl_field *first, const nl_model *m)
{
    rows_t r = {.K = in->count};
    c->K = in->count;
    rows_alloc(&r, c, first);
    cli_card_write_field(c, first);
    if (first->dim == 2)
        cli_card_map_geometry(c, first);
    for (size_t k = 0; k < r.K; k++) {
        nl_field *x = k ? cli_inputs_read(in, k, first) : NULL;
        estimate(c, &r, k, x ? x : first);
        nl_field_free(x);
    }
    write_acf(c, &r, first, m);
    write_spectrum(c, &r, first, m);
    write_hist(c, &r, first, m);
    rows_free(&r);
}
