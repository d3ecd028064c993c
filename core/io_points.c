/* Scattered data points from TSV. */
#include "io_points.h"
#include "io_read_internal.h"
#include "nl_error.h"
#include "field.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void nl_points_free(nl_points *p)
{
    if (!p)
        return;
    free(p->pts), free(p->val), free(p);
}

int nl_tsv_row(const char *line, size_t cols, double *v)
{
    const char *p = line;
    char *end;
    for (size_t c = 0; c < cols; c++) {
        double x = strtod(p, &end);
        if (end == p || !isfinite(x) || (c + 1 < cols && *end != '\t') ||
            (c + 1 == cols && *end && *end != '\n' && *end != '\r'))
            return 0;
        v[c] = x;
        p = end + 1;
    }
    return 1;
}

/* The rows of fp after the header: *raw (n * cols) and *n. */
static int read_rows(FILE *fp, const char *path, size_t cols, size_t lineno, double **raw, size_t *n)
{
    char line[4096];
    size_t cap = 256;
    double *v = malloc(cap * cols * sizeof *v);
    int full = 0;
    *n = 0;
    while (v && !full && fgets(line, sizeof line, fp)) {
        lineno++;
        if (nl_tsv_skipped(line))
            continue;
        if (*n == cap) {
            size_t want[2] = {2 * cap, cols};
            if (nl_size_check(2, want, sizeof *v, 2, NULL)) {
                free(v);
                return NL_ERROR(NL_ETOOBIG, "%s:%zu: more than %zu points do not fit in the memory available", path,
                                lineno, *n);
            }
            double *w = realloc(v, 2 * cap * cols * sizeof *v);
            if (!w) {
                full = 1;
                break;
            }
            v = w, cap *= 2;
        }
        if (!nl_tsv_row(line, cols, v + *n * cols)) {
            free(v);
            return NL_ERROR(NL_EINPUT, "%s:%zu: expected %zu tab-separated finite numbers", path, lineno, cols);
        }
        (*n)++;
    }
    if (!v || full || ferror(fp)) {
        free(v);
        return ferror(fp) ? NL_ERROR(NL_EINPUT, "%s: read error", path) : NL_ERROR(NL_ENOMEM, "out of memory");
    }
    *raw = v;
    return NL_OK;
}

/* Split the rows into coordinates and values by the header's columns. */
static int split(const double *raw, size_t n, const nl_point_columns *c, nl_points **out)
{
    nl_points *p = calloc(1, sizeof *p);
    int dim = c->dim;
    if (!p || !(p->pts = malloc(n * (size_t)dim * sizeof *p->pts)) || !(p->val = malloc(n * sizeof *p->val))) {
        nl_points_free(p);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu points", n);
    }
    p->dim = dim, p->n = n;
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < dim; a++)
            p->pts[i * (size_t)dim + (size_t)a] = raw[i * c->cols + (size_t)c->at[a]];
        p->val[i] = raw[i * c->cols + (size_t)c->at[3]];
    }
    *out = p;
    return NL_OK;
}

int nl_points_read(const char *path, nl_points **out)
{
    FILE *fp = fopen(path, "r");
    size_t lineno = 0, n;
    nl_point_columns c;
    double *raw = NULL;
    int st;
    *out = NULL;
    if (!fp)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    if (!(st = nl_point_columns_read(fp, path, 1, &lineno, &c)) && !(st = read_rows(fp, path, c.cols, lineno, &raw, &n)) &&
        !n)
        st = NL_ERROR(NL_EINPUT, "%s: expected at least one data row", path);
    fclose(fp);
    if (!st)
        st = split(raw, n, &c, out);
    free(raw);
    return st;
}
