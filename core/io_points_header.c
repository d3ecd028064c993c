/* The header line of a point table: its columns by name. */
#include "io_read_internal.h"
#include "nl_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[] = {"x", "y", "z", "value"};

int nl_tsv_skipped(const char *line)
{
    return line[0] == '#' || line[strspn(line, "\r")] == '\n' || line[strspn(line, "\r")] == 0;
}

/* Is name[0..len) a number (a data row where the header should be)? */
static int number(const char *name, size_t len)
{
    char buf[64], *end;
    if (len == 0 || len >= sizeof buf)
        return 0;
    memcpy(buf, name, len);
    buf[len] = 0;
    strtod(buf, &end);
    return *end == 0;
}

/* Column `col` (1-based) named name[0..len): record it in c. */
static int name_column(const char *path, size_t lineno, const char *name, size_t len, size_t col,
                       nl_point_columns *c)
{
    int k = 0;
    while (k < 4 && !(strlen(names[k]) == len && memcmp(names[k], name, len) == 0))
        k++;
    if (len == 0)
        return NL_ERROR(NL_EINPUT, "%s:%zu: column %zu of the header has no name; expected x, y, z or value", path,
                        lineno, col);
    if (k == 4) {
        const char *hint = memchr(name, ' ', len) ? ": columns are separated by tabs, not spaces"
                           : number(name, len)    ? ": a table starts with a header line of column names"
                                                  : "";
        return NL_ERROR(NL_EINPUT, "%s:%zu: column %zu of the header is named \"%.*s\"; expected x, y, z or value "
                        "(tab-separated, each once)%s", path, lineno, col, (int)len, name, hint);
    }
    if (c->at[k] >= 0)
        return NL_ERROR(NL_EINPUT, "%s:%zu: the header names \"%s\" twice (columns %d and %zu)", path, lineno,
                        names[k], c->at[k] + 1, col);
    c->at[k] = (int)col - 1;
    return NL_OK;
}

/* Split the header `line` (no line end) into c. */
static int split(const char *path, size_t lineno, const char *line, int need_value, nl_point_columns *c)
{
    const char *p = line;
    int st;
    c->cols = 0, c->dim = 0;
    for (int k = 0; k < 4; k++)
        c->at[k] = -1;
    for (;;) {
        size_t len = strcspn(p, "\t");
        if ((st = name_column(path, lineno, p, len, ++c->cols, c)))
            return st;
        if (!p[len])
            break;
        p += len + 1;
    }
    c->dim = c->at[0] < 0 ? 0 : c->at[1] < 0 ? 1 : c->at[2] < 0 ? 2 : 3;
    if (c->at[0] < 0 || (c->at[1] < 0 && c->at[2] >= 0))
        return NL_ERROR(NL_EINPUT, "%s:%zu: the header has no column named \"%s\"; expected the coordinates x, x y "
                        "or x y z%s", path, lineno, c->at[0] < 0 ? "x" : "y",
                        need_value ? " and value" : "");
    if (need_value && c->at[3] < 0)
        return NL_ERROR(NL_EINPUT, "%s:%zu: the header has no column named \"value\"; expected x [y [z]] and value, "
                        "in any order", path, lineno);
    return NL_OK;
}

int nl_point_columns_read(FILE *fp, const char *path, int need_value, size_t *lineno, nl_point_columns *c)
{
    char line[4096], *p = line;
    int found = 0;
    while (!found && fgets(line, sizeof line, fp)) {
        ++*lineno;
        if (*lineno == 1 && memcmp(line, "\xef\xbb\xbf", 3) == 0)
            p = line + 3;  /* a UTF-8 byte order mark */
        found = !nl_tsv_skipped(p);
        if (!found)
            p = line;
    }
    if (!found)
        return NL_ERROR(NL_EINPUT, "%s: expected a header line of column names (x [y [z]]%s) and at least one row",
                        path, need_value ? " value" : "");
    if (!strchr(p, '\n') && !feof(fp))
        return NL_ERROR(NL_EINPUT, "%s:%zu: the header line is longer than %zu characters", path, *lineno,
                        sizeof line - 1);
    p[strcspn(p, "\r\n")] = 0;
    return split(path, *lineno, p, need_value, c);
}
