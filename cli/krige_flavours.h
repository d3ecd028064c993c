/* noiselab krige's flavours: --block, --transform and --indicator
 * (cli/krige_flavours.c), their option rows and their runs; the numerics
 * are analysis/krige_flavours.h's. */
#ifndef NL_CLI_KRIGE_FLAVOURS_H
#define NL_CLI_KRIGE_FLAVOURS_H

#include "opt.h"
#include "../analysis/krige_flavours.h"
#include "../core/io_points.h"

#include <stddef.h>

#define CLI_KRIGE_NK_MAX 256

/* The flavours' options (a group of rows in krige's options). */
typedef struct {
    const char *block;       /* --block WxH[xD] */
    int block_points;        /* --block-points N (0: Gauss-Legendre) */
    const char *transform;   /* --transform log|boxcox:LAMBDA */
    const char *indicator;   /* --indicator T1,T2,... */
    const char *iacf[CLI_KRIGE_NK_MAX]; /* --indicator-acf, once per threshold */
    size_t niacf;            /* how many --indicator-acf */
    int any;                 /* one of them was given */
} cli_krige_fl;

extern const cli_opt cli_krige_fl_rows[];

/* The help of the rows above, appended to krige's. */
#define CLI_KRIGE_FL_HELP                                                                                           \
    "--block WxH[xD]: block kriging (as gstat's block = c(W, H)): the mean over the block of\n"                     \
    "those edges centred at each cell, and its kriging variance; point-to-block covariances are\n"                  \
    "averages over a discretisation of the block, the block variance the double average\n"                          \
    "(Journel and Huijbregts 1978).  --block-points N: N regular points per axis (gstat's\n"                        \
    "nblockdiscr); by default gstat's 4-point Gauss-Legendre rule per axis (16 points in 2D).\n"                    \
    "--transform log|boxcox:LAMBDA: trans-Gaussian kriging (gstat's krigeTg): ordinary kriging\n"                   \
    "of (z^LAMBDA - 1)/LAMBDA (log z), back-transformed with Cressie's bias correction; data > 0.\n"                \
    "--indicator T1,T2,...: indicator kriging of P(value <= Tk), increasing thresholds, with\n"                     \
    "--acf (one model for all) or --indicator-acf SPEC once per threshold; GSLIB's order-\n"                        \
    "relation correction (clip to [0, 1], average of the upward and downward passes); -o\n"                         \
    "OUT.exr writes OUT.1.exr .. OUT.K.exr, a 1D .tsv one table of columns x, p1 .. pK; the\n"                      \
    "cells corrected are reported.  With --cross-validate: --transform in the data's units,\n"                      \
    "--indicator the corrected probabilities and each threshold's Brier score; --block is\n"                        \
    "refused (the data are points).\n"

/* What krige parsed, for a flavour's run. */
typedef struct {
    const char *data, *spec, *out, *vout; /* --data, --acf, -o, --variance */
    int json, cv, drift, gdim;            /* --json, --cross-validate, --drift, grid dimension */
    double mean, radius;                  /* --mean (NAN: none), --radius */
    size_t nmax, g[3];                    /* --nmax, --grid */
    double lo[3], hi[3];                  /* --extent */
} cli_krige_fl_ctx;

/* Check the flavours against krige's other options (exit 2 naming them)
 * before any work; *spec (--acf) is set to the first --indicator-acf when
 * --acf is not given. */
void cli_krige_fl_check(const cli_krige_fl *f, const char **spec, int cv, int simple, int drift, const char *vout);

/* Run the flavour onto the grid or in cross-validation; frees pt. */
int cli_krige_fl_run(const cli_krige_fl *f, const cli_krige_fl_ctx *c, nl_points *pt);

#endif
