/* Tables of named numeric columns from TSV, and written back with more. */
#include "io_table.h"
#include "io_read_internal.h"
#include "field.h"
#include "nl_error.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void nl_table_free(nl_table *t)
{
    if (!t)
        return;
    for (size_t c = 0; c < t->ncols; c++)
        free(t->names ? t->names[c] : NULL), free(t->cols ? t->cols[c] : NULL);
    for (size_t i = 0; t->rows && i < t->n; i++)
        free(t->rows[i]);
    free(t->names), free(t->cols), free(t->rows), free(t->header), free(t->path), free(t);
}

long nl_table_column(const nl_table *t, const char *name)
{
    for (size_t c = 0; c < t->ncols; c++)
        if (strcmp(t->names[c], name) == 0)
            return (long)c;
    return -1;
}

/* Drop the line end (LF, CR LF) in place. */
static void chomp(char *line)
{
    size_t len = strlen(line);
    while (len && (line[len - 1] == '\n' || line[len - 1] == '\r'))
        line[--len] = 0;
}

/* The header's names into t (t->header is the line). */
static int header(nl_table *t, size_t lineno)
{
    const char *p = t->header;
    size_t cap = 8;
    if (!(t->names = calloc(cap, sizeof *t->names)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (;;) {
        size_t len = strcspn(p, "\t");
        if (len == 0)
            return NL_ERROR(NL_EINPUT, "%s:%zu: column %zu of the header is empty; expected a name per column",
                            t->path, lineno, t->ncols + 1);
        if (t->ncols == cap) {
            char **w = realloc(t->names, 2 * cap * sizeof *w);
            if (!w)
                return NL_ERROR(NL_ENOMEM, "out of memory");
            t->names = w, cap *= 2;
        }
        if (!(t->names[t->ncols] = strndup(p, len)))
            return NL_ERROR(NL_ENOMEM, "out of memory");
        t->ncols++;
        if (nl_table_column(t, t->names[t->ncols - 1]) != (long)t->ncols - 1)
            return NL_ERROR(NL_EINPUT, "%s:%zu: column \"%s\" is named twice; expected each name once", t->path,
                            lineno, t->names[t->ncols - 1]);
        if (!p[len])
            return NL_OK;
        p += len + 1;
    }
}

/* One row's cells into v (t->ncols numbers). */
static int cells(const nl_table *t, const char *line, size_t lineno, double *v)
{
    const char *p = line;
    for (size_t c = 0; c < t->ncols; c++) {
        size_t len = strcspn(p, "\t");
        char *end;
        if (!p[len] && c + 1 < t->ncols)
            return NL_ERROR(NL_EINPUT, "%s:%zu: %zu cells; expected %zu, one per column of the header", t->path,
                            lineno, c + 1, t->ncols);
        if (p[len] && c + 1 == t->ncols)
            return NL_ERROR(NL_EINPUT, "%s:%zu: more cells than the %zu columns of the header", t->path, lineno,
                            t->ncols);
        v[c] = strtod(p, &end);
        if (len == 0 || end != p + len || !isfinite(v[c]))
            return NL_ERROR(NL_EINPUT, "%s:%zu: column \"%s\" holds \"%.*s\"; expected a finite number", t->path,
                            lineno, t->names[c], (int)(len < 40 ? len : 40), p);
        p += len + 1;
    }
    return NL_OK;
}

/* Room for one more row in t->rows and *raw (cap rows). */
static int grow(nl_table *t, double **raw, size_t *cap, size_t lineno)
{
    size_t want[2] = {2 * *cap, t->ncols};
    if (nl_size_check(2, want, sizeof **raw, 3, NULL))
        return NL_ERROR(NL_ETOOBIG, "%s:%zu: more than %zu rows do not fit in the memory available", t->path, lineno,
                        t->n);
    double *w = realloc(*raw, 2 * *cap * t->ncols * sizeof *w);
    if (w)
        *raw = w;
    char **r = w ? realloc(t->rows, 2 * *cap * sizeof *r) : NULL;
    if (!r)
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu rows", 2 * *cap);
    t->rows = r, *cap *= 2;
    return NL_OK;
}

/* The rows after the header: their text into t->rows, numbers into *raw. */
static int rows(FILE *fp, nl_table *t, size_t lineno, double **raw)
{
    char *line = NULL;
    size_t len = 0, cap = 64;
    int st = NL_OK;
    *raw = malloc(cap * t->ncols * sizeof **raw);
    t->rows = malloc(cap * sizeof *t->rows);
    if (!*raw || !t->rows)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    while (!st && getline(&line, &len, fp) != -1) {
        lineno++;
        if (nl_tsv_skipped(line))
            continue;
        chomp(line);
        if (t->n == cap && (st = grow(t, raw, &cap, lineno)))
            break;
        if ((st = cells(t, line, lineno, *raw + t->n * t->ncols)))
            break;
        if (!(t->rows[t->n] = strdup(line)))
            st = NL_ERROR(NL_ENOMEM, "out of memory");
        else
            t->n++;
    }
    free(line);
    if (!st && ferror(fp))
        st = NL_ERROR(NL_EINPUT, "%s: read error", t->path);
    if (!st && !t->n)
        st = NL_ERROR(NL_EINPUT, "%s: expected at least one data row after the header", t->path);
    return st;
}

/* The header line: the first line that is not skipped. */
static int header_line(FILE *fp, nl_table *t, size_t *lineno)
{
    char *line = NULL;
    size_t len = 0;
    while (getline(&line, &len, fp) != -1) {
        ++*lineno;
        if (*lineno == 1 && strncmp(line, "\xEF\xBB\xBF", 3) == 0) /* a byte order mark */
            memmove(line, line + 3, strlen(line + 3) + 1);
        if (nl_tsv_skipped(line))
            continue;
        chomp(line);
        t->header = line;
        return header(t, *lineno);
    }
    free(line);
    return NL_ERROR(NL_EINPUT, "%s: expected a header line of column names, got %s", t->path,
                    ferror(fp) ? "a read error" : "no line");
}

/* Split the row-major numbers into columns. */
static int columns(nl_table *t, const double *raw)
{
    if (!(t->cols = calloc(t->ncols, sizeof *t->cols)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t c = 0; c < t->ncols; c++) {
        if (!(t->cols[c] = malloc(t->n * sizeof(double))))
            return NL_ERROR(NL_ENOMEM, "out of memory for %zu rows", t->n);
        for (size_t i = 0; i < t->n; i++)
            t->cols[c][i] = raw[i * t->ncols + c];
    }
    return NL_OK;
}

int nl_table_read(const char *path, nl_table **out)
{
    nl_table *t = calloc(1, sizeof *t);
    double *raw = NULL;
    size_t lineno = 0;
    int st;
    *out = NULL;
    if (!t || !(t->path = strdup(path))) {
        free(t);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    FILE *fp = fopen(path, "r");
    if (!fp)
        st = NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    else {
        if (!(st = header_line(fp, t, &lineno)) && !(st = rows(fp, t, lineno, &raw)))
            st = columns(t, raw);
        fclose(fp);
    }
    free(raw);
    if (st) {
        nl_table_free(t);
        return st;
    }
    *out = t;
    return NL_OK;
}

int nl_table_points(const nl_table *t, const char *value, int *dim, double **pts, double **val)
{
    static const char *const xyz[] = {"x", "y", "z"};
    long at[3];
    int d = 0;
    for (int a = 0; a < 3; a++)
        at[a] = nl_table_column(t, xyz[a]);
    if (at[0] < 0 || (at[2] >= 0 && at[1] < 0))
        return NL_ERROR(NL_EINPUT, "%s: no column \"%s\"; expected the coordinates x [y [z]] among the columns",
                        t->path, at[0] < 0 ? "x" : "y");
    d = at[2] >= 0 ? 3 : at[1] >= 0 ? 2 : 1;
    long v = value ? nl_table_column(t, value) : -1;
    if (value && v < 0)
        return NL_ERROR(NL_EINPUT, "%s: no column \"%s\"; expected the values in a column of that name", t->path,
                        value);
    double *p = malloc(t->n * (size_t)d * sizeof *p), *w = value ? malloc(t->n * sizeof *w) : NULL;
    if (!p || (value && !w)) {
        free(p), free(w);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu points", t->n);
    }
    for (size_t i = 0; i < t->n; i++) {
        for (int a = 0; a < d; a++)
            p[i * (size_t)d + (size_t)a] = t->cols[at[a]][i];
        if (w)
            w[i] = t->cols[v][i];
    }
    *dim = d, *pts = p;
    if (value)
        *val = w;
    return NL_OK;
}

int nl_table_write(const char *path, const nl_table *t, size_t nextra, const char *const *names,
                   const double *const *extra)
{
    FILE *fp = fopen(path, "w");
    if (!fp)
        return NL_ERROR(NL_EIO, "cannot create %s: %s", path, strerror(errno));
    fputs(t->header, fp);
    for (size_t c = 0; c < nextra; c++)
        fprintf(fp, "\t%s", names[c]);
    fputc('\n', fp);
    for (size_t i = 0; i < t->n; i++) {
        fputs(t->rows[i], fp);
        for (size_t c = 0; c < nextra; c++)
            if (isnan(extra[c][i]))
                fputs("\tNA", fp);
            else
                fprintf(fp, "\t%.17g", extra[c][i]);
        fputc('\n', fp);
    }
    int bad = ferror(fp);
    if (fclose(fp) || bad)
        return NL_ERROR(NL_EIO, "cannot write %s", path);
    return NL_OK;
}
