/* OpenVDB volumes (core/formats/vdb.c): round trips exact at float32 with
 * the shape, spacing, origin and provenance; zeros kept as active voxels;
 * 1D and 2D fields refused; files that are not volumes refused; and the
 * descriptor of a build without OpenVDB, compiled apart (the format off).
 * The reading by OpenVDB's own Python module is python/tests/test_vdb.py. */
#include "../core/format.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char path_buf[512];
static const char *path(const char *name)
{
    snprintf(path_buf, sizeof path_buf, "%s/%s", scratch_dir(), name);
    return path_buf;
}

static int vdb_built(void)
{
    const nl_format *t = nl_format_find("openvdb");
    return t && !(t->flags & NL_FORMAT_OFF);
}

/* 7 x 5 x 3 "high-entropy" samples (no two alike, none exact in float32),
 * with the plane x = 0 and the last slice z = 2 all zero: a writer that
 * left zeros inactive or pruned them would shrink the box read back. */
static nl_field *cube(void)
{
    size_t n[3] = {7, 5, 3};
    double h[3] = {0.5, 2.25, 3};
    nl_field *f = nl_field_alloc(3, n, h, NULL);
    for (size_t k = 0, i = 0; k < n[2]; k++)
        for (size_t y = 0; y < n[1]; y++)
            for (size_t x = 0; x < n[0]; x++, i++)
                f->data[i] = x == 0 || k == 2 ? 0 : sin(2.385 * (double)i) * 7.25 + 0.1 * (double)i;
    return f;
}

/* Every sample comes back as (float) rounds it, bit for bit (tolerance 0:
 * float32 storage is the only rounding), with the shape and the spacing
 * exactly, the origin in samples and the provenance strings. */
Test(vdb, round_trip_exact_at_float32)
{
    if (!vdb_built())
        cr_skip_test("built without OpenVDB");
    nl_field *f = cube(), *g;
    nl_meta m = {0}, back;
    strcpy(m.model, "gauss:scale=4");
    strcpy(m.seed, "42");
    strcpy(m.origin, "7,-2");
    cr_assert_eq(nl_field_write(path("a.vdb"), f, &m, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_field_read(path("a.vdb"), &g, &back), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(g->dim, 3);
    for (int a = 0; a < 3; a++) {
        cr_assert_eq(g->n[a], f->n[a], "axis %d: %zu samples for %zu", a, g->n[a], f->n[a]);
        cr_assert_eq(g->h[a], f->h[a], "axis %d: spacing %.17g for %.17g", a, g->h[a], f->h[a]);
    }
    for (size_t i = 0; i < f->count; i++)
        cr_assert_eq(g->data[i], (double)(float)f->data[i], "sample %zu: %.17g for %.17g", i, g->data[i],
                     f->data[i]);
    cr_assert_str_eq(back.origin, "7,-2");
    cr_assert_str_eq(back.seed, "42");
    cr_assert_str_eq(back.model, "gauss:scale=4");
    cr_assert_str_eq(back.size, "7x5x3");
    nl_field_free(f);
    nl_field_free(g);
}

/* A volume is 3D: 1D and 2D fields are refused before anything is written. */
Test(vdb, refuses_1d_and_2d)
{
    size_t n[2] = {4, 4};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_field_write(path("b.vdb"), f, NULL, NULL), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "does not hold 2D fields (it holds 3D fields)") ||
                  (!vdb_built() && strstr(nl_errmsg(), "OpenVDB")),
              "%s", nl_errmsg());
    cr_assert_not(file_exists(path("b.vdb")));
    nl_field_free(f);
}

/* A truncated volume: NL_EINPUT, named, at once (OpenVDB parses on past the
 * end of a stream unless told to throw: 15 s of garbage here, 141 s and 16
 * GB through a temporary file; the limit of 5 s catches that) (a file
 * without a float grid needs OpenVDB to make it: python/tests/test_vdb.py
 * and tests/bad/vdb.cases). */
Test(vdb, refuses_truncated_files, .timeout = 5)
{
    if (!vdb_built())
        cr_skip_test("built without OpenVDB");
    nl_field *f = cube(), *g = NULL;
    char cmd[1200];
    cr_assert_eq(nl_field_write(path("c.vdb"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    snprintf(cmd, sizeof cmd, "head -c 200 %s/c.vdb > %s/t.vdb", scratch_dir(), scratch_dir());
    cr_assert_eq(system(cmd), 0);
    cr_assert_eq(nl_field_read(path("t.vdb"), &g, NULL), NL_EINPUT, "%s", nl_errmsg());
    cr_assert_null(g);
    cr_assert(strstr(nl_errmsg(), "not a readable OpenVDB file"), "%s", nl_errmsg());
    nl_field_free(f);
}

/* The build without OpenVDB: core/formats/vdb.c compiled without
 * NL_HAVE_OPENVDB (a compile of that one file and tests/api/vdb_off.c, no
 * rebuild) registers the format off, with no reader or writer and a
 * summary that names OpenVDB. */
Test(vdb, off_without_openvdb)
{
    char cmd[2048], out[256] = "", err[1024] = "";
    const char *bin = getenv("NOISELAB");
    char top[700] = ".";
    if (bin && strrchr(bin, '/')) { /* the tree of NOISELAB=TREE/bin/noiselab or TREE/build/asan/bin/noiselab */
        snprintf(top, sizeof top, "%.*s/..", (int)(strrchr(bin, '/') - bin), bin);
        if (strstr(bin, "/build/asan/bin/"))
            strcat(top, "/../..");
    }
    snprintf(cmd, sizeof cmd,
             "cd %s && cc -std=c11 -D_GNU_SOURCE -Wall -Wextra -Werror -o %s/off tests/api/vdb_off.c "
             "core/formats/vdb.c > %s/cc.txt 2>&1 && %s/off > %s/off.txt",
             top, scratch_dir(), scratch_dir(), scratch_dir(), scratch_dir());
    int rc = system(cmd);
    snprintf(cmd, sizeof cmd, "%s/cc.txt", scratch_dir());
    FILE *fp = fopen(cmd, "r");
    if (fp) {
        size_t k = fread(err, 1, sizeof err - 1, fp);
        err[k] = 0;
        fclose(fp);
    }
    cr_assert_eq(rc, 0, "%s: %s", cmd, err);
    snprintf(cmd, sizeof cmd, "%s/off.txt", scratch_dir());
    fp = fopen(cmd, "r");
    cr_assert(fp && fgets(out, sizeof out, fp));
    fclose(fp);
    cr_assert(strstr(out, "openvdb .vdb off: built without OpenVDB"), "%s", out);
}
