/* The data files of `noiselab card`: the field, its ACF against the model's,
 * periodogram and Welch estimates (maps in 2D, lines in 1D), the radial
 * spectrum and the histogram. */
#include "cli.h"
#include "card.h"
#include "../analysis/acf.h"
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

enum { SHOW_MAX = 512, HIST_BINS = 40 };

static FILE *open_data(const cli_card *c, const char *name)
{
    char path[4200];
    FILE *fp;
    snprintf(path, sizeof path, "%s/%s", c->dir, name);
    if (!(fp = fopen(path, "w")))
        cli_die(1, "card: cannot write %s", path);
    return fp;
}

static void close_data(FILE *fp)
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
static void write_field(const cli_card *c, const nl_field *x)
{
    FILE *fp = open_data(c, x->dim == 2 ? "field.bin" : "field.tsv");
    if (x->dim == 1) {
        fprintf(fp, "t\tvalue\n");
        for (size_t i = 0; i < x->count; i++)
            fprintf(fp, "%.8g\t%.8g\n", (double)i * x->h[0], x->data[i]);
    } else
        for (size_t j = 0; j < x->n[1]; j += c->stride)
            for (size_t i = 0; i < x->n[0]; i += c->stride)
                fwrite(&x->data[j * x->n[0] + i], sizeof(double), 1, fp);
    close_data(fp);
}

/* The model's R at the lags along one axis (NAN without a model). */
static void model_lags(const nl_model *m, const nl_field *x, int axis, const double *lag, size_t n, double *out)
{
    int st;
    for (size_t i = 0; i < n; i++)
        out[i] = NAN;
    if (m && (st = nl_acf_model_values(m, x->dim, x->n, x->h, axis, lag, n, out)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
}

/* acf.tsv: 2D lag_x, acf_x, acf_y, model_x, model_y, lag_y; 1D lag, acf,
 * band low, band high, model. */
static void write_acf(const cli_card *c, const nl_field *x, const nl_model *m)
{
    size_t L = c->maxlag + 1;
    double *lag = cli_malloc(4 * L * sizeof *lag), *v = lag + L, *mod = v + L, *lo = mod + L;
    double *lagy = cli_malloc(4 * L * sizeof *lagy), *vy = lagy + L, *mody = vy + L, *hi = mody + L;
    nl_field *full;
    int st;
    if ((st = nl_acf_full(x, NAN, 0, &full)) || (st = nl_acf_axis(full, 0, c->maxlag, lag, v)))
        cli_die_status(st);
    model_lags(m, x, 0, lag, L, mod);
    if (x->dim == 2) {
        if ((st = nl_acf_axis(full, 1, c->maxlag, lagy, vy)))
            cli_die_status(st);
        model_lags(m, x, 1, lagy, L, mody);
    } else if ((st = nl_acf_bartlett_band(full, x->count, c->maxlag, v, lo, hi)))
        cli_die_status(st);
    FILE *fp = open_data(c, "acf.tsv");
    for (size_t i = 0; i < L; i++)
        if (x->dim == 2)
            fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", lag[i], v[i], vy[i], mod[i], mody[i], lagy[i]);
        else
            fprintf(fp, "%.8g\t%.8g\t%.8g\t%.8g\t%.8g\n", lag[i], v[i], lo[i], hi[i], mod[i]);
    close_data(fp);
    nl_field_free(full);
    free(lag), free(lagy);
}

/* The model's spectrum on the grid of g (its dim, n and h), finite everywhere. */
static nl_field *model_spectrum(const nl_field *g, const nl_model *m, const char *spec)
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

/* A centred log10 map of spectrum P as block x block means, float64. */
static void write_map(const cli_card *c, const char *name, const nl_field *P, size_t block, double *top)
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
    FILE *fp = open_data(c, name);
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
    close_data(fp);
    nl_field_free(C);
}

/* radial.tsv: the Welch estimate's radial average and the model's. */
static void write_radial(const cli_card *c, const nl_field *W, const nl_field *S)
{
    size_t nb = c->seg / 2 + 1, *cnt = cli_malloc(nb * sizeof *cnt);
    double *r = cli_malloc(3 * nb * sizeof *r), *v = r + nb, *t = v + nb, *rr = cli_malloc(nb * sizeof *rr);
    double step = 1.0 / ((double)c->seg * W->h[0]);
    nl_radial(W, NL_GRID_FREQ, step, nb, r, v, cnt);
    for (size_t b = 0; b < nb; b++)
        t[b] = NAN;
    if (S)
        nl_radial(S, NL_GRID_FREQ, step, nb, rr, t, cnt);
    FILE *fp = open_data(c, "radial.tsv");
    fprintf(fp, "f\twelch\ttarget\n");
    for (size_t b = 1; b < nb; b++)
        fprintf(fp, "%.8g\t%.8g\t%.8g\n", r[b], v[b], t[b]);
    close_data(fp);
    free(cnt), free(r), free(rr);
}

/* 1D: per.tsv (f, periodogram, model) and welch.tsv (f, Welch), f > 0.
 * Ordinates below 1e-12 of the largest (rounding where the spectrum is 0,
 * e.g. below a power law's fmin) and a zero model are left out (NAN): a
 * log axis would spend twenty decades on them. */
static void write_lines(const cli_card *c, const nl_field *P, const nl_field *W, const nl_field *S)
{
    FILE *fp = open_data(c, "per.tsv");
    double mx = 0;
    for (size_t k = 1; k <= P->n[0] / 2; k++)
        mx = P->data[k] > mx ? P->data[k] : mx;
    for (size_t k = 1; k <= P->n[0] / 2; k++)
        fprintf(fp, "%.8g\t%.8g\t%.8g\n", (double)k / ((double)P->n[0] * P->h[0]),
                P->data[k] > 1e-12 * mx ? P->data[k] : NAN, S && S->data[k] > 0 ? S->data[k] : NAN);
    close_data(fp);
    fp = open_data(c, "welch.tsv");
    for (size_t k = 1; k <= W->n[0] / 2; k++)
        fprintf(fp, "%.8g\t%.8g\n", (double)k / ((double)W->n[0] * W->h[0]), W->data[k]);
    close_data(fp);
}

static void write_spectra(cli_card *c, const nl_field *x, const nl_model *m)
{
    nl_field *P, *W, *S = NULL;
    int st;
    if ((st = nl_psd_periodogram(x, NAN, &P)) || (st = nl_psd_welch(x, c->seg, NAN, &W, &c->nseg)))
        cli_die_status(st);
    if (x->dim == 1) {
        S = m ? model_spectrum(P, m, c->spec) : NULL;
        write_lines(c, P, W, S);
    } else {
        S = m ? model_spectrum(W, m, c->spec) : NULL;
        write_map(c, "per.bin", P, c->block, &c->top);
        write_map(c, "welch.bin", W, 1, NULL);
        write_radial(c, W, S);
        c->pdx = (double)c->block / ((double)x->n[0] * x->h[0]);
        c->pdy = (double)c->block / ((double)x->n[1] * x->h[1]);
        c->px0 = ((double)(c->block - 1) / 2 - (double)(x->n[0] / 2)) / ((double)x->n[0] * x->h[0]);
        c->py0 = ((double)(c->block - 1) / 2 - (double)(x->n[1] / 2)) / ((double)x->n[1] * x->h[1]);
        c->wdx = 1.0 / ((double)c->seg * x->h[0]);
        c->wdy = 1.0 / ((double)c->seg * x->h[1]);
        c->wx0 = -(double)(c->seg / 2) * c->wdx;
        c->wy0 = -(double)(c->seg / 2) * c->wdy;
    }
    nl_field_free(P), nl_field_free(W), nl_field_free(S);
}

/* The histogram as a density against the Gaussian of the same moments. */
static void write_hist(const cli_card *c, const nl_field *x)
{
    double mid[HIST_BINS], dens[HIST_BINS], gauss[HIST_BINS];
    nl_moments mo;
    int st;
    if ((st = nl_moments_compute(x, &mo)) || (st = nl_hist_density(x, &mo, HIST_BINS, mid, dens, gauss)))
        cli_die_status(st);
    FILE *fp = open_data(c, "hist.tsv");
    fprintf(fp, "x\tdensity\tgauss\n");
    for (int b = 0; b < HIST_BINS; b++)
        fprintf(fp, "%.8g\t%.8g\t%.8g\n", mid[b], dens[b], gauss[b]);
    close_data(fp);
}

void cli_card_write(cli_card *c, const nl_field *x, const nl_model *m)
{
    write_field(c, x);
    write_acf(c, x, m);
    write_spectra(c, x, m);
    write_hist(c, x);
}
