/* The data behind `noiselab card` (cli/card_data.c), shared with the script
 * that draws them (cli/cmd_card.c). */
#ifndef CLI_CARD_H
#define CLI_CARD_H

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>

typedef struct {
    const char *spec;  /* --acf/--spectrum as given, or NULL */
    const char *name;  /* the input's name, for the title */
    const char *out;   /* the temporary output PNG */
    const char *dir;   /* the temporary folder of the data */
    int dim;           /* 1 or 2 */
    double lo, hi;     /* the field's grey range: mean -+ 3 sd */
    size_t stride;     /* the field is shown every stride-th sample */
    size_t fn[2];      /* samples shown per axis */
    double fdx, fdy;   /* their spacing, length units */
    size_t block;      /* the periodogram is shown as block x block means */
    size_t pn[2];      /* blocks per axis */
    double pdx, pdy;   /* block spacing, cycles per unit */
    double px0, py0;   /* the first block's centre frequency */
    size_t seg, nseg;  /* Welch: segment side and number of segments */
    double wdx, wdy;   /* Welch frequency spacing */
    double wx0, wy0;   /* Welch's lowest frequency per axis */
    double top;        /* log10 of the largest periodogram ordinate: the maps' top */
    size_t maxlag;     /* ACF lags 0..maxlag, in samples */
} cli_card;

/* Moments, display sizes and segment length for field x (1D >= 64 samples,
 * 2D >= 32 x 32); exits 2 on a constant field. */
void cli_card_prepare(cli_card *c, const nl_field *x);

/* Every data file of the card into c->dir (m may be NULL); sets c->top and
 * c->nseg.  Exits on error. */
void cli_card_write(cli_card *c, const nl_field *x, const nl_model *m);

#endif
