/* An empirical variogram from a TSV table: noiselab variogram -o's
 * (distance, gamma, pairs) or gstat's (np, dist, gamma) column names. */
#include "variogram.h"
#include "../core/io_read_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Rows read at most: far beyond any variogram's bins (NL_VG_MAXBINS). */
#define VG_READ_MAX 1000000

/* The column (0 distance, 1 gamma, 2 pairs) a header name names, or -1. */
static int column_of(const char *name, size_t len)
{
    static const char *const names[][2] = {{"distance", "dist"}, {"gamma", "gamma"}, {"pairs", "np"}};
    for (int c = 0; c < 3; c++)
        for (int k = 0; k < 2; k++)
            if (strlen(names[c][k]) == len && memcmp(name, names[c][k], len) == 0)
                return c;
    return -1;
}

/* The header: three names, each of the columns once; at[c] its position. */
static int header(const char *path, size_t lineno, char *line, int *at)
{
    static const char *const what[] = {"distance (or dist)", "gamma", "pairs (or np)"};
    char *s = line;
    int ncol = 0;
    at[0] = at[1] = at[2] = -1;
    if ((unsigned char)s[0] == 0xEF && (unsigned char)s[1] == 0xBB && (unsigned char)s[2] == 0xBF)
        s += 3;
    s[strcspn(s, "\r\n")] = 0;
    for (;;) {
        size_t len = strcspn(s, "\t");
        int c = column_of(s, len);
        if (c < 0 || at[c] >= 0 || ncol == 3)
            return NL_ERROR(NL_EINPUT, "%s:%zu: column %d \"%.*s\": expected a header of distance, gamma, pairs "
                            "(noiselab variogram -o) or np, dist, gamma (gstat), each once%s", path, lineno, ncol + 1,
                            (int)(len > 40 ? 40 : len), s, c >= 0 && at[c] >= 0 ? " (given twice)" : "");
        at[c] = ncol++;
        if (!s[len])
            break;
        s += len + 1;
    }
    for (int c = 0; c < 3; c++)
        if (at[c] < 0)
            return NL_ERROR(NL_EINPUT, "%s:%zu: no %s column; expected distance, gamma, pairs (or np, dist, gamma)",
                            path, lineno, what[c]);
    return NL_OK;
}

/* One bin's checks: distance > 0, gamma >= 0, pairs a whole number >= 1. */
static int check_bin(const char *path, size_t lineno, const double *b)
{
    if (!(b[0] > 0))
        return NL_ERROR(NL_EINPUT, "%s:%zu: distance %g: expected a positive distance", path, lineno, b[0]);
    if (!(b[1] >= 0))
        return NL_ERROR(NL_EINPUT, "%s:%zu: gamma %g: expected a semivariance >= 0", path, lineno, b[1]);
    if (!(b[2] >= 1) || b[2] != floor(b[2]) || b[2] > 9007199254740992.0)
        return NL_ERROR(NL_EINPUT, "%s:%zu: pairs %g: expected a whole number of pairs >= 1 (a bin without pairs "
                        "has no gamma: leave it out)", path, lineno, b[2]);
    return NL_OK;
}

static int grow(nl_variogram *v, size_t *cap)
{
    size_t c = *cap ? 2 * *cap : 64;
    double *d = realloc(v->distance, c * sizeof *d);
    if (d)
        v->distance = d;
    double *g = d ? realloc(v->gamma, c * sizeof *g) : NULL;
    if (g)
        v->gamma = g;
    double *p = g ? realloc(v->pairs, c * sizeof *p) : NULL;
    if (p)
        v->pairs = p;
    if (!p)
        return NL_ERROR(NL_ENOMEM, "variogram: out of memory for %zu bins", c);
    *cap = c;
    return NL_OK;
}

static int read_table(FILE *fp, const char *path, nl_variogram *v)
{
    char line[4096];
    size_t lineno = 0, cap = 0;
    int at[3], have = 0, st;
    while (fgets(line, sizeof line, fp)) {
        double row[3], b[3];
        lineno++;
        if (!strchr(line, '\n') && !feof(fp))
            return NL_ERROR(NL_EINPUT, "%s:%zu: line longer than %zu characters", path, lineno, sizeof line - 2);
        if (nl_tsv_skipped(line))
            continue;
        if (!have) {
            if ((st = header(path, lineno, line, at)))
                return st;
            have = 1;
            continue;
        }
        if (!nl_tsv_row(line, 3, row))
            return NL_ERROR(NL_EINPUT, "%s:%zu: expected 3 tab-separated finite numbers", path, lineno);
        for (int c = 0; c < 3; c++)
            b[c] = row[at[c]];
        if ((st = check_bin(path, lineno, b)))
            return st;
        if (v->nbins == VG_READ_MAX)
            return NL_ERROR(NL_EINPUT, "%s:%zu: more than %d bins; expected a variogram's bins", path, lineno,
                            VG_READ_MAX);
        if (v->nbins == cap && (st = grow(v, &cap)))
            return st;
        v->distance[v->nbins] = b[0], v->gamma[v->nbins] = b[1], v->pairs[v->nbins] = b[2];
        v->nbins++;
    }
    if (ferror(fp))
        return NL_ERROR(NL_EINPUT, "%s: read error", path);
    if (!have)
        return NL_ERROR(NL_EINPUT, "%s: no header; expected distance, gamma, pairs (or np, dist, gamma), then a row per "
                        "bin", path);
    if (!v->nbins)
        return NL_ERROR(NL_EINPUT, "%s: no bins after the header; expected a row per bin", path);
    return NL_OK;
}

int nl_variogram_read(const char *path, nl_variogram **out)
{
    FILE *fp;
    nl_variogram *v;
    int st;
    *out = NULL;
    if (!(fp = fopen(path, "r")))
        return NL_ERROR(NL_EINPUT, "%s: cannot open the variogram table", path);
    if (!(v = calloc(1, sizeof *v))) {
        fclose(fp);
        return NL_ERROR(NL_ENOMEM, "variogram: out of memory");
    }
    st = read_table(fp, path, v);
    fclose(fp);
    if (st)
        nl_variogram_free(v);
    else
        *out = v;
    return st;
}
