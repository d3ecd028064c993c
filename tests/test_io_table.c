/* core/io_table.h: every column kept by name, the rows' text kept and
 * written back with added columns, and what is refused (naming file, line
 * and column). */
#include "util.h"
#include "../core/io_table.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A byte order mark, comments, an empty line and CRLF line ends are
 * skipped; names and numbers as written; the text of each row kept as read
 * (0.10 stays 0.10) and written back with the added columns, NaN as NA. */
Test(io_table, read_keep_and_write_back)
{
    const char *path = scratch_file("t.tsv", "\xEF\xBB\xBF# a comment\r\nx\ty\tdist\tfold\r\n\r\n0.10\t2\t3.5e2\t1\r\n"
                                             "# another\n-1\t0x10\t7\t2\n");
    nl_table *t;
    cr_assert_eq(nl_table_read(path, &t), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(t->n, 2);
    cr_assert_eq(t->ncols, 4);
    cr_expect_str_eq(t->names[0], "x");
    cr_expect_eq(nl_table_column(t, "dist"), 2);
    cr_expect_eq(nl_table_column(t, "value"), -1);
    cr_expect_eq(t->cols[2][0], 350.0);
    cr_expect_eq(t->cols[1][1], 16.0);
    cr_expect_str_eq(t->rows[0], "0.10\t2\t3.5e2\t1");
    int dim;
    double *pts, *val;
    cr_assert_eq(nl_table_points(t, "dist", &dim, &pts, &val), NL_OK);
    cr_expect_eq(dim, 2);
    cr_expect(pts[2] == -1 && pts[3] == 16 && val[1] == 7);
    free(pts), free(val);
    double e[2] = {1.0 / 3, NAN};
    const double *cols[] = {e};
    const char *names[] = {"estimate"};
    char out[600], buf[256];
    snprintf(out, sizeof out, "%s/w.tsv", scratch_dir());
    cr_assert_eq(nl_table_write(out, t, 1, names, cols), NL_OK);
    FILE *fp = fopen(out, "r");
    cr_assert(fp);
    size_t len = fread(buf, 1, sizeof buf - 1, fp);
    buf[len] = 0;
    fclose(fp);
    cr_expect_str_eq(buf, "x\ty\tdist\tfold\testimate\n0.10\t2\t3.5e2\t1\t0.33333333333333331\n-1\t0x10\t7\t2\tNA\n");
    nl_table_free(t);
}

/* Refused: each message names the file, the line and the column. */
Test(io_table, refusals_name_line_and_column)
{
    static const struct {
        const char *text, *needle;
    } bad[] = {
        {"x\ty\n1\tNA\n", "t.tsv:2: column \"y\" holds \"NA\""},
        {"x\ty\n1\t2\n3\tabc\n", "t.tsv:3: column \"y\" holds \"abc\""},
        {"x\ty\n1\t1e999\n", "column \"y\" holds \"1e999\""},
        {"x\ty\n1\t\n", "column \"y\" holds \"\""},
        {"x\ty\n1\t2 \n", "column \"y\" holds \"2 \""},
        {"x\ty\n1\n", "t.tsv:2: 1 cells; expected 2"},
        {"x\ty\n1\t2\t3\n", "more cells than the 2 columns"},
        {"x\tx\n1\t2\n", "column \"x\" is named twice"},
        {"x\t\ty\n1\t2\t3\n", "column 2 of the header is empty"},
        {"x\ty\n", "expected at least one data row"},
        {"# only a comment\n", "expected a header line"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        nl_table *t = (nl_table *)1;
        int st = nl_table_read(scratch_file("t.tsv", bad[i].text), &t);
        cr_expect_eq(st, NL_EINPUT, "case %zu", i);
        cr_expect_null(t, "case %zu", i);
        cr_expect(strstr(nl_errmsg(), bad[i].needle), "case %zu: \"%s\" does not name \"%s\"", i, nl_errmsg(),
                  bad[i].needle);
    }
    nl_table *t;
    cr_expect_eq(nl_table_read("/nonexistent/t.tsv", &t), NL_EINPUT);
    cr_assert_eq(nl_table_read(scratch_file("t.tsv", "y\tz\n1\t2\n"), &t), NL_OK);
    int dim;
    double *pts;
    cr_expect_eq(nl_table_points(t, NULL, &dim, &pts, NULL), NL_EINPUT);
    cr_expect(strstr(nl_errmsg(), "no column \"x\""), "%s", nl_errmsg());
    nl_table_free(t);
}
