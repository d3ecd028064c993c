/* TSV tables: write columns, read a 1D field. */
#include "io.h"
#include "io_read_internal.h"
#include "nl_error.h"

#include <errno.h>
#include <math.h>
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

int nl_tsv_read_field(const char *path, nl_field **out)
{
    FILE *fp = fopen(path, "r");
    int st;
    *out = NULL;
    if (!fp)
        return NL_ERROR(NL_EINPUT, "%s: cannot open: %s", path, strerror(errno));
    st = nl_tsv_read_stream(fp, path, out);
    fclose(fp);
    return st;
}

int nl_tsv_read_stream(FILE *fp, const char *path, nl_field **out)
{
    char line[4096], *fld[64];
    int ncol = 0, vcol, tcol = -1, st = NL_OK;
    size_t cap = 1024, n = 0, lineno = 0;
    double *v = NULL, t0 = 0, t1 = 0;

    *out = NULL;
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        ncol = split(line, fld, 64);
        break;
    }
    if (ncol == 0)
        return NL_ERROR(NL_EINPUT, "%s: expected a TSV header line, found none", path);
    vcol = ncol - 1;
    for (int c = 0; c < ncol; c++)
        if (strcmp(fld[c], "value") == 0)
            vcol = c;
    if (strcmp(fld[0], "t") == 0 || strcmp(fld[0], "x") == 0)
        tcol = 0;
    v = malloc(cap * sizeof *v);
    if (!v)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    while (!st && fgets(line, sizeof line, fp)) {
        char *end;
        double x;
        int k;
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        k = split(line, fld, 64);
        if (k != ncol) {
            st = NL_ERROR(NL_EINPUT, "%s:%zu: expected %d columns, got %d", path, lineno, ncol, k);
            break;
        }
        x = strtod(fld[vcol], &end);
        if (end == fld[vcol] || *end || !isfinite(x)) {
            st = NL_ERROR(NL_EINPUT, "%s:%zu: expected a finite number, got \"%s\"", path, lineno, fld[vcol]);
            break;
        }
        if (tcol >= 0 && n < 2)
            *(n == 0 ? &t0 : &t1) = strtod(fld[tcol], NULL);
        if (n == cap) {
            double *nv = realloc(v, 2 * cap * sizeof *v);
            if (!nv) {
                st = NL_ERROR(NL_ENOMEM, "out of memory");
                break;
            }
            v = nv;
            cap *= 2;
        }
        v[n++] = x;
    }
    if (!st && ferror(fp))
        st = NL_ERROR(NL_EINPUT, "%s: read failed", path);
    if (!st && n < 2)
        st = NL_ERROR(NL_EINPUT, "%s: expected at least 2 samples, got %zu", path, n);
    if (!st) {
        double h = (tcol >= 0 && t1 - t0 > 0) ? t1 - t0 : 1.0;
        nl_field *f = nl_field_alloc(1, &n, &h, &st);
        if (f) {
            memcpy(f->data, v, n * sizeof *v);
            *out = f;
        }
    }
    free(v);
    return st;
}
