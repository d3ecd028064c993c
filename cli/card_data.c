/* The data files of `noiselab card` for one field: the field, its ACF
 * against the model's with the model's band, periodogram and Welch
 * estimates (maps in 2D, lines in 1D) with their chi-square bands around
 * the model's spectrum, the radial spectrum and the histogram. */
#include "cli.h"
#include "card.h"
#include "../analysis/acf.h"
#include "../analysis/bands.h"
#include "../analysis/fftshift.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../analysis/welch.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { SHOW_MAX = 512 };

FILE *cli_card_open(const cli_card *c, const char *name)
{
    char path[4200];
    FILE *fp;
    snprintf(path, sizeof path, "%s/%s", c->dir, name);
    if (!(fp = fopen(path, "w")))
        cli_die(1, "card: cannot write %s", path);
    return fp;
}

void cli_card_close(FILE *fp)
{
    if (fclose(fp))
        cli_die(1, "card: writing the card's data failed");
}

void cli_card_prepare(cli_card *c, const nl_field *x)
{
    nl_moments mo;
    size_t big = x->n[0] > x->n[1] ? x->n[0] : x->n[1], small = x->dim == 2 && x->n[1] < x->n[0] ? x->n[1] : x->n[0];
    int st;
    if ((st = nl_moments_compute(x, &mo)))
        cli_die_status(st);
    if (!(mo.variance > 0))
        cli_die(2, "card: %s is constant (%g everywhere); expected a field that varies", c->name, mo.mean);
    c->n[0] = x->n[0], c->n[1] = x->n[1];
    c->lo = mo.mean - 3 * sqrt(mo.variance);
    c->hi = mo.mean + 3 * sqrt(mo.variance);
    c->seg = x->dim == 2 ? small / 4 : (x->n[0] / 16 < 16 ? 16 : x->n[0] / 16);
    c->maxlag = x->dim == 2 ? small / 4 : x->n[0] / 8;
    if (c->maxlag > (x->dim == 2 ? 64 : 128))
        c->maxlag = x->dim == 2 ? 64 : 128;
    c->stride = c->block = x->dim == 2 ? (big + SHOW_MAX - 1) / SHOW_MAX : 1;
    for (int a = 0; a < x->dim; a++) {
        c->fn[a] = (x->n[a] + c->stride - 1) / c->stride;
        c->pn[a] = x->n[a] / c->block;
    }
    c->fdx = x->h[0] * (double)c->stride;
    c->fdy = x->h[1] * (double)c->stride;
}

/* 2D: every stride-th sample as float64, x fastest; 1D: t, value. */
void cli_card_write_field(const cli_card *c, const nl_field *x)
{
    FILE *fp = cli_card_open(c, x->dim == 2 ? "field.bin" : "field.tsv");
    if (x->dim == 1) {
        fprintf(fp, "t\tvalue\n");
        for (size_t i = 0; i < x->count; i++)
            fprintf(fp, "%.8g\t%.8g\n", (double)i * x->h[0], x->data[i]);
    } else
        for (size_t j = 0; j < x->n[1]; j += c->stride)
            for (size_t i = 0; i < x->n[0]; i += c->stride)
                fwrite(&x->data[j * x->n[0] + i], sizeof(double), 1, fp);
    cli_card_close(fp);
}

void cli_card_model_lags(const nl_model *m, const nl_field *x, int axis, const double *lag, size_t n, double *out)
{
    int st;
    for (size_t i = 0; i < n; i++)
        out[i] = NAN;
    if (m && (st = nl_acf_model_values(m, x->dim, x->n, x->h, axis, lag, n, out)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
}

void cli_card_acf_band(const cli_card *c, const nl_model *m, const nl_field *x, int axis, double *mean, double *lo,
                       double *hi)
{
    int st;
    for (size_t i = 0; i <= c->maxlag; i++)
        mean[i] = lo[i] = hi[i] = NAN;
    if (!m)
        return;
    if ((st = nl_acf_model_band(m, x->dim, x->n, x->h, axis, c->maxlag, mean, lo, hi)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
    for (size_t i = 0; i <= c->maxlag; i++) {
        double half = (hi[i] - mean[i]) / sqrt((double)c->K);
        lo[i] = mean[i] - half, hi[i] = mean[i] + half;
    }
}

/* acf.tsv, one row per lag: lag_x, acf_x, lo_x, hi_x, R_x, E_x and in 2D
 * lag_y, acf_y, lo_y, hi_y, R_y, E_y: the estimate, the 95% band (the
 * model's around E, the estimate's expectation; without a model, 1D:
 * Bartlett's plug-in band around the estimate), the model's R. */
static void write_acf(const cli_card *c, const nl_field *x, const nl_model *m)
{
    size_t L = c->maxlag + 1;
    double *a = cli_malloc(12 * L * sizeof *a);
    nl_field *full;
    int st;
    if ((st = nl_acf_full(x, NAN, 0, &full)))
        cli_die_status(st);
    for (int ax = 0; ax < x->dim; ax++) {
        double *lag = a + 6 * ax * L, *v = lag + L, *lo = v + L, *hi = lo + L, *R = hi + L, *E = R + L;
        if ((st = nl_acf_axis(full, ax, c->maxlag, lag, v)))
            cli_die_status(st);
        cli_card_model_lags(m, x, ax, lag, L, R);
        cli_card_acf_band(c, m, x, ax, E, lo, hi);
        if (!m && x->dim == 1 && (st = nl_acf_bartlett_band(full, x->count, c->maxlag, v, lo, hi)))
            cli_die_status(st);
    }
    FILE *fp = cli_card_open(c, "acf.tsv");
    for (size_t i = 0; i < L; i++) {
        for (int k = 0; k < 6 * x->dim; k++)
            fprintf(fp, "%s%.8g", k ? "\t" : "", a[k * L + i]);
        fprintf(fp, "\n");
    }
    cli_card_close(fp);
    nl_field_free(full);
    free(a);
}

nl_field *cli_card_model_spectrum(const nl_field *g, const nl_model *m, const char *spec)
{
    nl_field *S = cli_field_alloc(g->dim, g->n, g->h);
    int st;
    if ((st = nl_wk_sample_spectrum(m, S)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
    for (size_t i = 0; i < S->count; i++)
        if (!isfinite(S->data[i]))
            cli_die(2, "--acf: %s has a spectrum of %g at a frequency of the card's grid; expected a finite "
                    "spectrum", spec, S->data[i]);
    return S;
}

void cli_card_write_map(const cli_card *c, const char *name, const nl_field *P, size_t block, double *top)
{
    nl_field *C;
    size_t nb0 = P->n[0] / block, nb1 = P->n[1] / block;
    double floor_v, mx = 0;
    int st;
    if ((st = nl_fftshift_alloc(P, &C)))
        cli_die_status(st);
    for (size_t i = 0; i < C->count; i++)
        mx = C->data[i] > mx ? C->data[i] : mx;
    floor_v = mx > 0 ? 1e-12 * mx : 1e-300;
    if (top)
        *top = log10(mx > 0 ? mx : 1e-300);
    FILE *fp = cli_card_open(c, name);
    for (size_t bj = 0; bj < nb1; bj++)
        for (size_t bi = 0; bi < nb0; bi++) {
            double s = 0;
            for (size_t j = bj * block; j < (bj + 1) * block; j++)
                for (size_t i = bi * block; i < (bi + 1) * block; i++)
                    s += C->data[j * C->n[0] + i];
            s /= (double)(block * block);
            s = log10(s > floor_v ? s : floor_v);
            fwrite(&s, sizeof s, 1, fp);
        }
    cli_card_close(fp);
    nl_field_free(C);
}

void cli_card_map_geometry(cli_card *c, const nl_field *x)
{
    c->pdx = (double)c->block / ((double)x->n[0] * x->h[0]);
    c->pdy = (double)c->block / ((double)x->n[1] * x->h[1]);
    c->px0 = ((double)(c->block - 1) / 2 - (double)(x->n[0] / 2)) / ((double)x->n[0] * x->h[0]);
    c->py0 = ((double)(c->block - 1) / 2 - (double)(x->n[1] / 2)) / ((double)x->n[1] * x->h[1]);
    c->wdx = 1.0 / ((double)c->seg * x->h[0]);
    c->wdy = 1.0 / ((double)c->seg * x->h[1]);
    c->wx0 = -(double)(c->seg / 2) * c->wdx;
    c->wy0 = -(double)(c->seg / 2) * c->wdy;
}

void cli_card_chisq(double nu, double *lo, double *hi)
{
    *lo = *hi = NAN;
    if (nu > 0 && nl_band_chisq(nu, lo, hi))
        cli_die_status(NL_EINVAL);
}

/* radial.tsv: the periodogram's radial average, the model's, and the 95%
 * band of the average of cnt ordinates of one field (cnt / 2 independent
 * chi-square_2 pairs f, -f: nu = cnt) around the model's. */
static void write_radial(const cli_card *c, const nl_field *P, const nl_field *S)
{
    double step = fmax(1 / ((double)P->n[0] * P->h[0]), 1 / ((double)P->n[1] * P->h[1]));
    double nyq = fmin(0.5 / P->h[0], 0.5 / P->h[1]);
    size_t nb = (size_t)(nyq / step) + 1, *cnt = cli_malloc(nb * sizeof *cnt);
    double *r = cli_malloc(4 * nb * sizeof *r), *v = r + nb, *t = v + nb, *rr = t + nb;
    nl_radial(P, NL_GRID_FREQ, step, nb, r, v, cnt);
    for (size_t b = 0; b < nb; b++)
        t[b] = NAN;
    if (S)
        nl_radial(S, NL_GRID_FREQ, step, nb, rr, t, cnt);
    FILE *fp = cli_card_open(c, "radial.tsv");
    double mx = 0;
    for (size_t b = 1; b < nb; b++)
        mx = v[b] > mx ? v[b] : mx;
    fprintf(fp, "f\tperiodogram\tmodel\tlo\thi\n");
    for (size_t b = 1; b < nb; b++) {  /* below 1e-12 of the top: rounding (as in 1D) */
        double lo, hi, tb = t[b] > 1e-12 * mx ? t[b] : NAN;
        cli_card_chisq((double)cnt[b], &lo, &hi);
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", r[b], v[b] > 1e-12 * mx ? v[b] : NAN, tb, tb * lo, tb * hi);
    }
    cli_card_close(fp);
    free(cnt), free(r);
}

/* 1D: per.tsv (f, periodogram, model, band lo, hi) and welch.tsv (f, Welch,
 * model, band lo, hi), f > 0; one ordinate is chi-square_2 (the Nyquist
 * one chi-square_1), Welch's chi-square_nu (nl_welch_edf).  Ordinates below
 * 1e-12 of the largest (rounding where the spectrum is 0, e.g. below a
 * power law's fmin) and a zero model are left out (NAN): a log axis would
 * spend twenty decades on them. */
static void write_lines(const cli_card *c, const nl_field *P, const nl_field *W, const nl_field *S,
                        const nl_field *SW)
{
    FILE *fp = cli_card_open(c, "per.tsv");
    double mx = 0, lo, hi;
    for (size_t k = 1; k <= P->n[0] / 2; k++)
        mx = P->data[k] > mx ? P->data[k] : mx;
    for (size_t k = 1; k <= P->n[0] / 2; k++) {
        double s = S && S->data[k] > 0 ? S->data[k] : NAN;
        cli_card_chisq(2 * k == P->n[0] ? 1 : 2, &lo, &hi);
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", (double)k / ((double)P->n[0] * P->h[0]),
                P->data[k] > 1e-12 * mx ? P->data[k] : NAN, s, s * lo, s * hi);
    }
    cli_card_close(fp);
    fp = cli_card_open(c, "welch.tsv");
    cli_card_chisq(c->welch_nu, &lo, &hi);
    for (size_t k = 1; k <= W->n[0] / 2; k++) {
        double s = SW && SW->data[k] > 0 ? SW->data[k] : NAN;
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", (double)k / ((double)W->n[0] * W->h[0]), W->data[k], s,
                s * lo, s * hi);
    }
    cli_card_close(fp);
}

static void write_spectra(cli_card *c, const nl_field *x, const nl_model *m)
{
    nl_field *P, *W, *S = NULL, *SW = NULL;
    int st;
    if ((st = nl_psd_periodogram(x, NAN, &P)) || (st = nl_psd_welch(x, c->seg, NAN, &W, &c->nseg)) ||
        (st = nl_welch_edf(x->dim, x->n, c->seg, &c->welch_nu)))
        cli_die_status(st);
    S = m ? cli_card_model_spectrum(P, m, c->spec) : NULL;
    SW = m ? cli_card_model_spectrum(W, m, c->spec) : NULL;
    if (x->dim == 1)
        write_lines(c, P, W, S, SW);
    else {
        cli_card_write_map(c, "per.bin", P, c->block, &c->top);
        cli_card_write_map(c, "welch.bin", W, 1, NULL);
        write_radial(c, P, S);
        cli_card_map_geometry(c, x);
    }
    nl_field_free(P), nl_field_free(W), nl_field_free(S), nl_field_free(SW);
}

/* hist.tsv: bin centre, density, the Gaussian of the field's mean and
 * variance, and with a model its density N(0, R(0)) per bin with the
 * 95% band of the density of one field (nl_hist_model_band). */
static void write_hist(const cli_card *c, const nl_field *x, const nl_model *m)
{
    double e[CARD_HIST_BINS + 1], cnt[CARD_HIST_BINS], md[CARD_HIST_BINS], sd[CARD_HIST_BINS];
    nl_moments mo;
    int st;
    if ((st = nl_moments_compute(x, &mo)) || (st = nl_hist(x, CARD_HIST_BINS, e, cnt)))
        cli_die_status(st);
    for (int b = 0; b < CARD_HIST_BINS; b++)
        md[b] = sd[b] = NAN;
    if (m && (st = nl_hist_model_band(m, x->dim, x->n, x->h, e, CARD_HIST_BINS, md, sd)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
    FILE *fp = cli_card_open(c, "hist.tsv");
    fprintf(fp, "x\tdensity\tgauss\tmodel\tlo\thi\n");
    for (int b = 0; b < CARD_HIST_BINS; b++) {
        double mid = 0.5 * (e[b] + e[b + 1]), w = e[b + 1] - e[b], z = (mid - mo.mean) / sqrt(mo.variance);
        fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", mid, cnt[b] / ((double)x->count * w),
                exp(-0.5 * z * z) / sqrt(2 * M_PI * mo.variance), md[b], fmax(0, md[b] - 1.959964 * sd[b]),
                md[b] + 1.959964 * sd[b]);
    }
    cli_card_close(fp);
}

void cli_card_write(cli_card *c, const nl_field *x, const nl_model *m)
{
    c->K = 1;
    cli_card_write_field(c, x);
    write_acf(c, x, m);
    write_spectra(c, x, m);
    write_hist(c, x, m);
}
