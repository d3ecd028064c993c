/* noiselab validate: what it works on, and its report (cli/validate_report.c). */
#ifndef NL_CLI_VALIDATE_REPORT_H
#define NL_CLI_VALIDATE_REPORT_H

#include "cli.h"
#include "../analysis/check.h"
#include "../analysis/validate.h"
#include "../core/model.h"

/* What validate works on and what it found. */
typedef struct {
    const char *spec, *dir;  /* model as given, output directory (NULL: none) */
    const char *spectrum;    /* --spectrum as given (spec is --acf until the options are checked) */
    int spectral;            /* given with --spectrum */
    int dim;                 /* 1..3 */
    int json;                /* --json */
    int force;               /* --force: write into an existing folder that holds files */
    int N_given, tol_given;  /* --neighborhood and --tol given */
    size_t N, M;             /* side, realizations */
    nl_validate_options o;   /* realizations, tolerance, method options */
    nl_model *m;             /* the parsed model */
    nl_check k;              /* its check */
    nl_validate_result r;    /* lags, targets, thresholds and the methods' results */
} cli_validate;

/* 0 when every method that ran is within the tolerance (and one ran), 3
 * otherwise. */
int cli_validate_status(const cli_validate *v);

/* "model", "own exact ACF" or "none" (NL_VALIDATE_CLAIM_*). */
const char *cli_validate_claim_name(int claim);

/* For an unresolved verdict, the realizations that would likely resolve it:
 * the interval's half-width hi - est shrinks as 1 / sqrt(M), so about
 * M (half-width / |E - est|)^2; 0 when resolved or est = E. */
double cli_validate_to_resolve(const nl_validate_result *res, const nl_validate_method_result *r);

/* Everything found, as JSON (owned by the caller). */
json_t *cli_validate_json(const cli_validate *v);

/* DIR/index.md, verdict.json, acf.tsv, spectrum.tsv and the plots. */
void cli_validate_write(const cli_validate *v);

#endif
