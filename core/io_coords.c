/* Point coordinates from TSV. */
#include "io_coords.h"
#include "field.h"
#include "io_read_internal.h"
#include "nl_error.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int nl_coords_read(const char *path, int *dim, size_t *n, double **pts)
{
    FILE *fp = fopen(path, "r");
    char line[4096];
    size_t lineno = 0, cols, cap = 256;
    nl_point_columns c;
    int st;
    double *v = NULL;
    *pts = NULL, *n = 0;
    if (!fp)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    if ((st = nl_point_columns_read(fp, path, 0, &lineno, &c))) {
        fclose(fp);
        return st;
    }
    *dim = c.dim, cols = c.cols;
    double *r = malloc(cols * sizeof *r);
    v = malloc(cap * (size_t)*dim * sizeof *v);
    while (!st && v && r && fgets(line, sizeof line, fp)) {
        lineno++;
        if (nl_tsv_skipped(line))
            continue;
        if (*n == cap) {
            size_t want[2] = {2 * cap, (size_t)*dim};
            double *w = NULL;
            if ((st = nl_size_check(2, want, sizeof *v, 2, NULL)))
                st = NL_ERROR(NL_ETOOBIG, "%s:%zu: more than %zu points do not fit in the memory available", path,
                              lineno, *n);
            else if (!(w = realloc(v, 2 * cap * (size_t)*dim * sizeof *v)))
                st = NL_ERROR(NL_ENOMEM, "out of memory for %zu points", 2 * cap);
            else
                v = w, cap *= 2;
            if (st)
                break;
        }
        if (!nl_tsv_row(line, cols, r))
            st = NL_ERROR(NL_EINPUT, "%s:%zu: expected %zu tab-separated finite numbers", path, lineno, cols);
        else {
            for (int a = 0; a < *dim; a++)
                v[*n * (size_t)*dim + (size_t)a] = r[c.at[a]];
            ++*n;
        }
    }
    if (!st && (!v || !r))
        st = NL_ERROR(NL_ENOMEM, "out of memory");
    else if (!st && ferror(fp))
        st = NL_ERROR(NL_EINPUT, "%s: read error", path);
    else if (!st && !*n)
        st = NL_ERROR(NL_EINPUT, "%s: expected at least one row of coordinates", path);
    fclose(fp);
    free(r);
    if (st)
        free(v), *n = 0;
    else
        *pts = v;
    return st;
}
