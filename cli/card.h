/* The data behind `noiselab card` (cli/card_data.c for one field,
 * cli/card_ensemble.c for an ensemble), shared with the script that draws
 * them (cli/card_script.c). */
#ifndef CLI_CARD_H
#define CLI_CARD_H

#include "inputs.h"
#include "../core/field.h"
#include "../core/model.h"

#include <stdio.h>
#include <stddef.h>

enum { CARD_HIST_BINS = 40 };

typedef struct {
    const char *spec;  /* --acf/--spectrum as given, or NULL */
    const char *name;  /* the input's name, for the title */
    const char *out;   /* the temporary output PNG */
    const char *dir;   /* the temporary folder of the data */
    int dim;           /* 1 or 2 */
    size_t K;          /* fields: 1, or an ensemble's */
    size_t n[2];       /* samples per axis of the field(s) */
    double lo, hi;     /* the field's grey range: mean -+ 3 sd */
    size_t stride;     /* the field is shown every stride-th sample */
    size_t fn[2];      /* samples shown per axis */
    double fdx, fdy;   /* their spacing, length units */
    size_t block;      /* the periodogram is shown as block x block means */
    size_t pn[2];      /* blocks per axis */
    double pdx, pdy;   /* block spacing, cycles per unit */
    double px0, py0;   /* the first block's centre frequency */
    size_t seg, nseg;  /* Welch: segment side and number of segments */
    double welch_nu;   /* Welch: equivalent degrees of freedom */
    double wdx, wdy;   /* Welch frequency spacing */
    double wx0, wy0;   /* Welch's lowest frequency per axis */
    double top;        /* log10 of the largest periodogram ordinate: the maps' top */
    size_t maxlag;     /* ACF lags 0..maxlag, in samples */
} cli_card;

/* Moments, display sizes and segment length for field x (1D >= 64 samples,
 * 2D >= 32 x 32); exits 2 on a constant field. */
void cli_card_prepare(cli_card *c, const nl_field *x);

/* Every data file of the one-field card into c->dir (m may be NULL); sets
 * c->top, c->nseg and c->welch_nu.  Exits on error. */
void cli_card_write(cli_card *c, const nl_field *x, const nl_model *m);

/* The ensemble card's data files: the mean estimates over the fields of
 * `in` (field 0 is `first`, read already) and their standard errors, with
 * the model's bands over sqrt(K) (m may be NULL).  Exits on error. */
void cli_card_ensemble_write(cli_card *c, cli_inputs *in, const nl_field *first, const nl_model *m);

/* The gnuplot script of the card into fp. */
void cli_card_script(FILE *fp, const cli_card *c, int have_model);

/* Shared by the data writers: a data file of the card's folder, and its close. */
FILE *cli_card_open(const cli_card *c, const char *name);
void cli_card_close(FILE *fp);

/* The model's ACF band along axis (nl_acf_model_band) scaled to the mean of
 * K fields: mean, lo, hi hold maxlag + 1 entries; NAN without a model.
 * Exits on error. */
void cli_card_acf_band(const cli_card *c, const nl_model *m, const nl_field *x, int axis, double *mean, double *lo,
                       double *hi);

/* The model's spectrum on the grid of g (its dim, n and h), finite
 * everywhere; exits 2 otherwise. */
nl_field *cli_card_model_spectrum(const nl_field *g, const nl_model *m, const char *spec);

/* The 2D maps' frequency spacings and origins (periodogram and Welch). */
void cli_card_map_geometry(cli_card *c, const nl_field *x);

/* The 95% band factors of a chi-square_nu / nu estimate (nl_band_chisq);
 * NAN when nu is 0. */
void cli_card_chisq(double nu, double *lo, double *hi);

/* The model's R at the n lags (length units) along axis of fields like x
 * (NAN without a model); exits on error. */
void cli_card_model_lags(const nl_model *m, const nl_field *x, int axis, const double *lag, size_t n, double *out);

/* The field as the card shows it: field.bin (2D) or field.tsv (1D). */
void cli_card_write_field(const cli_card *c, const nl_field *x);

/* A centred log10 map of spectrum P as block x block means, float64; sets
 * *top (may be NULL) to log10 of the largest value. */
void cli_card_write_map(const cli_card *c, const char *name, const nl_field *P, size_t block, double *top);

#endif
