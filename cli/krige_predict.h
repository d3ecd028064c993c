/* noiselab krige: prediction at the points of a table (--at), external
 * drift (--drift with covariate columns) and k-fold cross-validation
 * (--cross-validate K, --folds COLUMN) for cli/cmd_krige.c. */
#ifndef NL_CLI_KRIGE_PREDICT_H
#define NL_CLI_KRIGE_PREDICT_H

#include "opt.h"
#include "../analysis/krige_local.h"
#include "../core/io_points.h"
#include "../core/model.h"

#include <stddef.h>
#include <stdint.h>

#define KP_MAX_COV 16 /* CLI_DRIFT_MAX_COV of cli/drift_terms.h */

/* The options of this file (a group of krige's option table). */
typedef struct {
    const char *at;            /* --at PTS.tsv, or NULL */
    const char *drift;         /* --drift TERMS as given, or NULL */
    const char *folds;         /* --folds COLUMN, or NULL */
    size_t kfold;              /* --cross-validate K (0: leave-one-out) */
    uint64_t seed;             /* --seed: the folds drawn without --folds */
    int given_seed, given_drift, given_cv;
    int poly;                  /* the polynomial part of --drift: NL_DRIFT_CONSTANT, _LINEAR, _QUADRATIC */
    unsigned axes;             /* coordinates named in --drift (bit a: axis a) */
    size_t ncov;               /* covariate columns named in --drift */
    char cov[KP_MAX_COV][64];  /* their names */
    size_t nfield;                  /* --covariate NAME=FIELD given */
    char fname[KP_MAX_COV][64];     /* their names */
    const char *fpath[KP_MAX_COV];  /* their fields */
} kp_opts;

extern const cli_opt kp_rows[];

/* After the option table: --cross-validate K given as a separate word, and
 * --drift's terms; exit 2 on a bad term. */
void kp_parse(kp_opts *p, int argc, char **argv);

/* What krige's other options say (cli/cmd_krige.c). */
typedef struct {
    const char *data, *spec, *out;
    double mean, radius;  /* --mean (NAN: none), --radius (0) */
    size_t nmax;
    int json;
    const char *kind;     /* ordinary, simple, universal-... */
} kp_common;

/* The data: points, and their covariates (n * ncov) and fold ids (n) when
 * --drift names covariates or --folds is given.  With those or --at, the
 * table of --data is read by core/io_table.h (other columns allowed, the
 * values in the column "value"); else by nl_points_read. */
typedef struct {
    nl_points *pt;
    double *cov;
    long *fold;
} kp_data;

void kp_read_data(const kp_opts *p, const char *data, kp_data *d);
void kp_data_free(kp_data *d);

/* The local plan of the data (exit 2 on bad data); *m the model, freed by
 * the caller after the plan. */
nl_krige_local *kp_plan(const kp_opts *p, const kp_common *c, const kp_data *d, nl_model **m);

/* --at: predict at the table's points, write -o; returns 0. */
int kp_predict_at(const kp_opts *p, const kp_common *c);

/* Cross-validation predictions: leave-one-out or by folds (drawn from --seed
 * or read); *fold_out (may be NULL) receives the fold ids used (NULL for
 * leave-one-out), to free.  Returns the number of folds (n for
 * leave-one-out).  Exit 2 on failure. */
size_t kp_cross_validate(const kp_opts *p, const nl_krige_local *k, const kp_data *d, double *pred, double *var,
                         nl_krige_cv_summary *s, long **fold_out);

/* Kriging onto the grid of f (cell centres lo + (i + 0.5) h, as
 * nl_krige_local_grid): with covariates, their values at the cells from the
 * fields of --covariate (each of the grid's size, sample i at cell i).
 * Exit 2 on a missing or mismatched field or a failed location. */
void kp_grid(const kp_opts *p, const nl_krige_local *k, const double *lo, nl_field *f, nl_field *vf);

/* Report the locations without data (NaN estimates) on stderr; their count. */
size_t kp_missing(const double *est, size_t count, const char *what);

#endif
