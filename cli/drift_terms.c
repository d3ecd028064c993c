/* --drift TERMS: the terms of a drift (cli/drift_terms.h). */
#include "drift_terms.h"
#include "cli.h"
#include "../analysis/krige_local.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_drift_parse(const char *s0, const char *data, cli_drift *d)
{
    const char *s = s0;
    memset(d, 0, sizeof *d);
    d->poly = NL_DRIFT_CONSTANT;
    for (;;) {
        size_t len = strcspn(s, ",");
        char t[64];
        if (len == 0 || len >= sizeof t)
            cli_die(2, "--drift: expected comma-separated terms (linear, quadratic, x, y, z or column names of "
                    "%s), got \"%s\"", data, s0);
        memcpy(t, s, len), t[len] = 0;
        if (strcmp(t, "linear") == 0 || strcmp(t, "quadratic") == 0) {
            int q = t[0] == 'l' ? NL_DRIFT_LINEAR : NL_DRIFT_QUADRATIC;
            d->poly = q > d->poly ? q : d->poly;
        } else if ((t[0] == 'x' || t[0] == 'y' || t[0] == 'z') && !t[1])
            d->axes |= 1u << (t[0] == 'x' ? 0 : t[0] == 'y' ? 1 : 2);
        else if (strcmp(t, "constant") != 0) {
            for (size_t j = 0; j < d->ncov; j++)
                if (strcmp(d->cov[j], t) == 0)
                    cli_die(2, "--drift: \"%s\" is named twice in \"%s\"; expected each term once", t, s0);
            if (d->ncov == CLI_DRIFT_MAX_COV)
                cli_die(2, "--drift: more than %d covariates in \"%s\"", CLI_DRIFT_MAX_COV, s0);
            snprintf(d->cov[d->ncov++], sizeof d->cov[0], "%s", t);
        }
        if (!s[len])
            break;
        s += len + 1;
    }
}

int cli_drift_poly(const cli_drift *d, const char *s, int dim)
{
    if (d->axes && d->axes != (1u << dim) - 1)
        cli_die(2, "--drift: \"%s\" names some of the %d coordinates; expected all of them (x,y%s) or none, as "
                "linear does", s, dim, dim == 3 ? ",z" : "");
    if (d->axes && dim == 1 && !(d->axes & 1))
        cli_die(2, "--drift: \"%s\": the data have one coordinate, x", s);
    return d->axes && d->poly == NL_DRIFT_CONSTANT ? NL_DRIFT_LINEAR : d->poly;
}

double *cli_drift_columns(const nl_table *t, size_t ncov, const char (*names)[64])
{
    double *cov = cli_malloc((t->n * ncov + 1) * sizeof *cov);
    for (size_t j = 0; j < ncov; j++) {
        long c = nl_table_column(t, names[j]);
        if (c < 0)
            cli_die(2, "--drift: %s has no column \"%s\"; expected it (a covariate named in --drift: the terms are "
                    "constant, linear, quadratic, x, y, z or columns of the data)", t->path, names[j]);
        for (size_t i = 0; i < t->n; i++)
            cov[i * ncov + j] = t->cols[c][i];
    }
    return cov;
}
