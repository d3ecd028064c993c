/* Point tables name their columns: x, y, z and value are found by the
 * header's names in any order (a permuted table reads as the ordered one,
 * exactly), and a header that is not such names is refused naming the
 * column (an unknown name, an empty one, one given twice, x or value
 * missing, names separated by spaces).  Both readers, the data table
 * (nl_points_read) and the coordinates (nl_coords_read), share the header. */
#include "../core/io_coords.h"
#include "../core/io_points.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

static const char ordered[] = "x\ty\tz\tvalue\n0.125\t2.385\t-1.5\t7.25\n3.5\t-0.75\t9.125\t-2.5\n";

static nl_points *read_ok(const char *name, const char *text)
{
    nl_points *p = NULL;
    int st = nl_points_read(scratch_file(name, text), &p);
    cr_assert_eq(st, NL_OK, "%s: %s", name, nl_errmsg());
    return p;
}

static void same(const nl_points *a, const nl_points *b)
{
    cr_assert_eq(a->dim, b->dim);
    cr_assert_eq(a->n, b->n);
    for (size_t i = 0; i < a->n; i++) {
        cr_expect_eq(a->val[i], b->val[i]);
        for (int k = 0; k < a->dim; k++)
            cr_expect_eq(a->pts[i * (size_t)a->dim + (size_t)k], b->pts[i * (size_t)b->dim + (size_t)k]);
    }
}

Test(points_header, permuted_reads_as_ordered)
{
    nl_points *a = read_ok("ordered.tsv", ordered);
    const char *perm[] = {
        "value\tz\ty\tx\n7.25\t-1.5\t2.385\t0.125\n-2.5\t9.125\t-0.75\t3.5\n",
        "y\tx\tvalue\tz\n2.385\t0.125\t7.25\t-1.5\n-0.75\t3.5\t-2.5\t9.125\n",
        /* a byte order mark, CRLF line ends and an empty line */
        "\xef\xbb\xbfz\tvalue\tx\ty\r\n-1.5\t7.25\t0.125\t2.385\r\n\r\n9.125\t-2.5\t3.5\t-0.75\r\n",
    };
    cr_assert_eq(a->dim, 3);
    cr_expect_eq(a->pts[1], 2.385);
    for (int i = 0; i < 3; i++) {
        nl_points *b;
        char name[32];
        snprintf(name, sizeof name, "perm%d.tsv", i);
        b = read_ok(name, perm[i]);
        same(a, b);
        nl_points_free(b);
    }
    nl_points_free(a);
}

Test(points_header, coordinates_by_name)
{
    int dim;
    size_t n;
    double *p;
    cr_assert_eq(nl_coords_read(scratch_file("c.tsv", "value\ty\tx\n1\t0.25\t0.75\n"), &dim, &n, &p), NL_OK, "%s",
                 nl_errmsg());
    cr_expect_eq(dim, 2);
    cr_expect_eq(n, 1);
    cr_expect_eq(p[0], 0.75);
    cr_expect_eq(p[1], 0.25);
    free(p);
    /* a table without a header: its first row is not names (it used to be
     * taken for one and dropped) */
    cr_expect_eq(nl_coords_read(scratch_file("c0.tsv", "0.5\t0.25\n0.75\t0.5\n"), &dim, &n, &p), NL_EINPUT);
    cr_expect(strstr(nl_errmsg(), "column 1 of the header is named \"0.5\"") != NULL, "%s", nl_errmsg());
}

static void refused(const char *text, const char *needle)
{
    nl_points *p = (nl_points *)1;
    int dim;
    size_t n;
    double *c = (double *)1;
    cr_expect_eq(nl_points_read(scratch_file("bad.tsv", text), &p), NL_EINPUT, "%s", text);
    cr_expect_null(p);
    cr_expect(strstr(nl_errmsg(), needle) != NULL, "message \"%s\" should name \"%s\"", nl_errmsg(), needle);
    if (strstr(needle, "value"))
        return;  /* value is optional among coordinates */
    cr_expect_eq(nl_coords_read(scratch_file("bad.tsv", text), &dim, &n, &c), NL_EINPUT, "%s", text);
    cr_expect_null(c);
    cr_expect(strstr(nl_errmsg(), needle) != NULL, "message \"%s\" should name \"%s\"", nl_errmsg(), needle);
}

Test(points_header, bad_headers_name_the_column)
{
    refused("x\ty\tv\n0\t0\t1\n", "column 3 of the header is named \"v\"");
    refused("x\ty\televation\tvalue\n0\t0\t5\t1\n", "named \"elevation\"");
    refused("x\tx\tvalue\n0\t0\t1\n", "\"x\" twice (columns 1 and 2)");
    refused("x\ty\tvalue\tvalue\n0\t0\t1\t1\n", "\"value\" twice");
    refused("y\tvalue\n0\t1\n", "no column named \"x\"");
    refused("x\tz\tvalue\n0\t0\t1\n", "no column named \"y\"");
    refused("x\ty\n0\t1\n", "no column named \"value\"");
    refused("x\t\tvalue\n0\t0\t1\n", "column 2 of the header has no name");
    refused("x\ty\tvalue\t\n0\t0\t1\t1\n", "column 4 of the header has no name");
    refused("x y value\n0 0 1\n", "not spaces");
    refused("X\tY\tvalue\n0\t0\t1\n", "named \"X\"");
    refused("# only a comment\n\n", "expected a header line");
}
