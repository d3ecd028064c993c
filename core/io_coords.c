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

/* The header: its column count and whether the last is "value". */
static int header(FILE *fp, const char *path, size_t *lineno, size_t *cols, int *has_value)
{
    char line[4096];
    *cols = 0;
    while (!*cols && fgets(line, sizeof line, fp)) {
        ++*lineno;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        line[strcspn(line, "\r\n")] = 0;
        const char *last = line, *p = line;
        for (*cols = 1; (p = strchr(p, '\t')); ++*cols)
            last = ++p;
        *has_value = strcmp(last, "value") == 0;
    }
    if (!*cols)
        return NL_ERROR(NL_EINPUT, "%s: expected a header line x [y [z]] and at least one row", path);
    if (*cols - (size_t)*has_value < 1 || *cols - (size_t)*has_value > 3)
        return NL_ERROR(NL_EINPUT, "%s:%zu: expected a header of 1 to 3 coordinate columns (x [y [z]], then "
                        "optionally value), got %zu columns", path, *lineno, *cols);
    return NL_OK;
}

int nl_coords_read(const char *path, int *dim, size_t *n, double **pts)
{
    FILE *fp = fopen(path, "r");
    char line[4096];
    size_t lineno = 0, cols, cap = 256;
    int has_value = 0, st;
    double *v = NULL;
    *pts = NULL, *n = 0;
    if (!fp)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    if ((st = header(fp, path, &lineno, &cols, &has_value))) {
        fclose(fp);
        return st;
    }
    *dim = (int)(cols - (size_t)has_value);
    double *r = malloc(cols * sizeof *r);
    v = malloc(cap * (size_t)*dim * sizeof *v);
    while (!st && v && r && fgets(line, sizeof line, fp)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
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
        else
            memcpy(v + *n * (size_t)*dim, r, (size_t)*dim * sizeof *v), ++*n;
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
