/* TSV tables: write columns, write and read a 1D field with its provenance. */
#include "io.h"
#include "io_read_internal.h"
#include "provenance.h"
#include "nl_error.h"

#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


int nl_tsv_fwrite(FILE *fp, const char *comment, int ncols, const char *const *names, size_t nrows,
                  const double *const *cols)
{
    if (comment)
        fprintf(fp, "# %s\n", comment);
    for (int c = 0; c < ncols; c++)
        fprintf(fp, "%s%c", names[c], c + 1 < ncols ? '\t' : '\n');
    for (size_t r = 0; r < nrows; r++)
        for (int c = 0; c < ncols; c++)
            if (isnan(cols[c][r])) /* a missing value, as R writes it */
                fprintf(fp, "NA%c", c + 1 < ncols ? '\t' : '\n');
            else
                fprintf(fp, "%.10g%c", cols[c][r], c + 1 < ncols ? '\t' : '\n');
    if (fflush(fp) || ferror(fp))
        return NL_ERROR(NL_EIO, "writing the table failed: %s", strerror(errno));
    return NL_OK;
}

int nl_tsv_write(const char *path, const char *comment, int ncols, const char *const *names,
                 size_t nrows, const double *const *cols)
{
    FILE *fp = fopen(path, "w");
    int st;
    if (!fp)
        return NL_ERROR(NL_EIO, "%s: cannot write: %s", path, strerror(errno));
    st = nl_tsv_fwrite(fp, comment, ncols, names, nrows, cols);
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    return st;
}

/* "# key: value" lines of the non-empty fields of meta; a control
 * character in a value (a path with a newline) is written as a space. */
static void write_meta(FILE *fp, const nl_meta *meta)
{
    for (int i = 0; meta && i < NL_META_NKEYS; i++) {
        const char *v = nl_meta_value(meta, i);
        size_t n = strnlen(v, nl_meta_capacity(i));
        if (!n)
            continue;
        fprintf(fp, "# %s: ", nl_meta_key(i));
        for (size_t k = 0; k < n; k++)
            fputc((unsigned char)v[k] < 0x20 || v[k] == 0x7f ? ' ' : v[k], fp);
        fputc('\n', fp);
    }
}

/* The first sample's place from meta->origin, in samples ("X[,...]", any
 * real; 0 when empty). */
static int origin_index(const nl_meta *meta, double *x)
{
    nl_meta only = {0};
    nl_provenance p;
    *x = 0;
    if (!meta || !meta->origin[0])
        return NL_OK;
    memcpy(only.origin, meta->origin, sizeof only.origin);
    if (nl_provenance_parse(&only, NL_PROV_ORIGIN, &p))
        return NL_ERROR(NL_EINVAL, "TSV: origin \"%.*s\": expected numbers X[,Y[,Z]]", (int)sizeof meta->origin,
                        meta->origin);
    *x = p.origin[0];
    return NL_OK;
}

int nl_tsv_write_field(const char *path, const nl_field *f, const nl_meta *meta, const char *coord,
                       const double *t)
{
    double x0;
    FILE *fp;
    int st;
    if (f->dim != 1)
        return NL_ERROR(NL_EINVAL, "%s: a TSV holds a 1D field, got %dD", path, f->dim);
    if ((st = origin_index(meta, &x0)))
        return st;
    if (!(fp = fopen(path, "w")))
        return NL_ERROR(NL_EIO, "%s: cannot write: %s", path, strerror(errno));
    write_meta(fp, meta);
    fprintf(fp, "%s\tvalue\n", coord ? coord : "t");
    for (size_t i = 0; i < f->count; i++) { /* t = (X + i) h: the window's own coordinates; NaN: missing, NA */
        double ti = t ? t[i] : (x0 + (double)i) * f->h[0];
        if (isnan(f->data[i]))
            fprintf(fp, "%.10g\tNA\n", ti);
        else
            fprintf(fp, "%.10g\t%.10g\n", ti, f->data[i]);
    }
    if ((fflush(fp) || ferror(fp)) && !st)
        st = NL_ERROR(NL_EIO, "%s: writing the table failed: %s", path, strerror(errno));
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    return st;
}

/* A comment line before the header: "# key: value" into meta when the key
 * is one of nl_meta's (once, fitting its capacity, no control character);
 * anything else is a comment. */
static int read_meta_line(const char *path, size_t lineno, const char *line, nl_meta *meta)
{
    for (int i = 0; i < NL_META_NKEYS; i++) {
        size_t k = strlen(nl_meta_key(i)), len;
        if (line[1] == ' ' && strncmp(line + 2, nl_meta_key(i), k) == 0 && line[2 + k] == ':' && line[3 + k] == ' ') {
            const char *v = line + 4 + k;
            len = strcspn(v, "\r\n");
            if (*nl_meta_slot(meta, i))
                return NL_ERROR(NL_EINPUT, "%s:%zu: # %s: recorded twice; expected it once", path, lineno,
                                nl_meta_key(i));
            if (len >= nl_meta_capacity(i))
                return NL_ERROR(NL_EINPUT, "%s:%zu: # %s: expected at most %zu bytes, got %zu", path, lineno,
                                nl_meta_key(i), nl_meta_capacity(i) - 1, len);
            for (size_t c = 0; c < len; c++)
                if ((unsigned char)v[c] < 0x20 || v[c] == 0x7f)
                    return NL_ERROR(NL_EINPUT, "%s:%zu: # %s: expected text without control characters, got "
                                    "byte 0x%02x at %zu", path, lineno, nl_meta_key(i), (unsigned char)v[c], c);
            memcpy(nl_meta_slot(meta, i), v, len);
            return NL_OK;
        }
    }
    return NL_OK;
}

/* The spacing of a series with a coordinate column: t1 - t0, or the
 * recorded spacing when it agrees (t1 - t0 of a window far from 0 carries
 * the rounding of the printed coordinates). */
static double series_spacing(const nl_meta *meta, int tcol, double t0, double t1)
{
    double h = (tcol >= 0 && t1 - t0 > 0) ? t1 - t0 : 1.0, hs;
    char *end;
    if (tcol < 0 || !meta->spacing[0])
        return h;
    hs = strtod(meta->spacing, &end);
    return (end != meta->spacing && !*end && isfinite(hs) && hs > 0 && fabs(hs - h) <= 1e-6 * hs) ? hs : h;
}

/* Split a line at tabs into at most `max` fields; returns the count. */
static int split(char *line, char **fld, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = 0;
    for (char *p = line; n < max;) {
        fld[n++] = p;
        p = strchr(p, '\t');
        if (!p)
            break;
        *p++ = 0;
    }
    return n;
}

/* The columns of a 1D series from its header: the "value" column (*vcol) and
 * an optional first coordinate column named t or x (*tcol, else -1). */
static int header_columns(const char *path, size_t lineno, char **fld, int ncol, int *vcol, int *tcol)
{
    *vcol = -1;
    *tcol = -1;
    for (int c = 0; c < ncol; c++)
        if (strcmp(fld[c], "value") == 0)
            *vcol = c;
    if (*vcol < 0)
        return NL_ERROR(NL_EINPUT, "%s:%zu: expected a column named \"value\" in the header, got %d column%s "
                        "starting \"%s\"",
                        path, lineno, ncol, ncol > 1 ? "s" : "", fld[0]);
    if (ncol > 2)
        return NL_ERROR(NL_EINPUT,
                        "%s:%zu: expected a 1D series (columns t value), got %d columns: scattered points "
                        "or several coordinates are not a series",
                        path, lineno, ncol);
    if (ncol == 2) {
        int c = 1 - *vcol; /* the other column: the coordinate of a series, t or x, in either order */
        if (strcmp(fld[c], "t") != 0 && strcmp(fld[c], "x") != 0)
            return NL_ERROR(NL_EINPUT, "%s:%zu: expected a 1D series (columns t value, or x value), got a column "
                            "\"%s\" beside \"value\"", path, lineno, fld[c]);
        *tcol = c;
    }
    return NL_OK;
}

/* The coordinate of row n: finite, and on the regular increasing grid
 * t0 + n h set by the first two rows (to a thousandth of a step, so that
 * coordinates printed to 10 digits pass). */
static int check_coordinate(const char *path, size_t lineno, const char *text, size_t n, double *t0, double *t1)
{
    char *end;
    double t = strtod(text, &end), h, want;
    if (end == text || *end || !isfinite(t))
        return NL_ERROR(NL_EINPUT, "%s:%zu: expected a finite coordinate, got \"%s\"", path, lineno, text);
    if (n < 2) {
        *(n == 0 ? t0 : t1) = t;
        if (n == 1 && !(t > *t0 && isfinite(t - *t0)))
            return NL_ERROR(NL_EINPUT,
                            "%s:%zu: expected an increasing coordinate column, got %.10g after %.10g (a series "
                            "that is constant or decreasing in its coordinate)",
                            path, lineno, t, *t0);
        return NL_OK;
    }
    h = *t1 - *t0;
    want = *t0 + (double)n * h;
    if (!(fabs(t - want) <= 1e-3 * h + 1e-9 * fabs(want)))
        return NL_ERROR(NL_EINPUT,
                        "%s:%zu: expected a regular coordinate column (step %.10g), got %.10g where %.10g was "
                        "due; resample the series onto a regular grid",
                        path, lineno, h, t, want);
    return NL_OK;
}

/* Grow v to hold one more sample, checked against the memory available. */
static int grow(const char *path, double **v, size_t *cap, size_t n)
{
    size_t want = 2 * *cap;
    double *nv;
    int st;
    if (n < *cap)
        return NL_OK;
    if ((st = nl_size_check(1, &want, sizeof **v, 2, NULL)))
        return NL_ERROR(st, "%s: more than %zu samples do not fit in the memory available (NOISELAB_MEMORY_LIMIT "
                        "or the machine's)", path, n);
    nv = realloc(*v, want * sizeof **v);
    if (!nv)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    *v = nv;
    *cap = want;
    return NL_OK;
}

/* One data row: the sample into v[*n] and the coordinate checked. */
static int read_row(const char *path, size_t lineno, char *line, int ncol, int vcol, int tcol, double **v,
                    size_t *cap, size_t *n, double *t0, double *t1)
{
    char *fld[64], *end;
    double x;
    int k = split(line, fld, 64), st;
    if (k != ncol)
        return NL_ERROR(NL_EINPUT, "%s:%zu: expected %d columns, got %d", path, lineno, ncol, k);
    x = strtod(fld[vcol], &end);
    if (end == fld[vcol] || *end || !isfinite(x))
        return NL_ERROR(NL_EINPUT, "%s:%zu: expected a finite number, got \"%s\"", path, lineno, fld[vcol]);
    if (tcol >= 0 && (st = check_coordinate(path, lineno, fld[tcol], *n, t0, t1)))
        return st;
    if ((st = grow(path, v, cap, *n)))
        return st;
    (*v)[(*n)++] = x;
    return NL_OK;
}

/* fgets that refuses a line longer than the buffer (it would be split)
 * and binary bytes. */
static char *get_line(char *line, int size, FILE *fp, const char *path, size_t lineno, int *st)
{
    if (!fgets(line, size, fp))
        return NULL;
    if (!strchr(line, '\n') && !feof(fp)) { /* a full buffer: a NUL byte stops strlen short of it */
        if (strlen(line) + 1 < (size_t)size)
            *st = NL_ERROR(NL_EINPUT, "%s:%zu: expected text, found a NUL byte (a binary file that is not EXR or PNG?)",
                           path, lineno);
        else
            *st = NL_ERROR(NL_EINPUT, "%s:%zu: expected lines shorter than %d characters", path, lineno, size - 1);
        return NULL;
    }
    return line;
}

int nl_tsv_read_field(const char *path, nl_field **out)
{
    FILE *fp = fopen(path, "r");
    int st;
    *out = NULL;
    if (!fp)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    st = nl_tsv_read_stream(fp, path, out, NULL);
    fclose(fp);
    return st;
}

int nl_tsv_read_stream(FILE *fp, const char *path, nl_field **out, nl_meta *meta)
{
    char line[4096], *fld[64];
    int ncol = 0, vcol = -1, tcol = -1, st = NL_OK;
    size_t cap = 1024, n = 0, lineno = 0;
    double *v = NULL, t0 = 0, t1 = 0;
    nl_meta own;

    *out = NULL;
    if (!meta)
        meta = &own;
    memset(meta, 0, sizeof *meta);
    while (get_line(line, sizeof line, fp, path, lineno + 1, &st)) {
        lineno++;
        if (line[0] == '#' && (st = read_meta_line(path, lineno, line, meta)))
            break;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        ncol = split(line, fld, 64);
        break;
    }
    if (!st && ncol == 0)
        st = NL_ERROR(NL_EINPUT, "%s: expected a TSV header line, found none", path);
    if (!st)
        st = header_columns(path, lineno, fld, ncol, &vcol, &tcol);
    if (!st && !(v = malloc(cap * sizeof *v)))
        st = NL_ERROR(NL_ENOMEM, "out of memory");
    while (!st && get_line(line, sizeof line, fp, path, lineno + 1, &st)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        st = read_row(path, lineno, line, ncol, vcol, tcol, &v, &cap, &n, &t0, &t1);
    }
    if (!st && ferror(fp))
        st = NL_ERROR(NL_EINPUT, "%s: read failed", path);
    if (!st && n < 2)
        st = NL_ERROR(NL_EINPUT, "%s: expected at least 2 samples, got %zu", path, n);
    if (!st) {
        double h = series_spacing(meta, tcol, t0, t1);
        nl_field *f = nl_field_alloc(1, &n, &h, &st);
        if (f) {
            memcpy(f->data, v, n * sizeof *v);
            *out = f;
        }
    }
    free(v);
    return st;
}
