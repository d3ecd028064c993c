/* Where a grid lies: noiselab.origin through nl_meta_origin and
 * nl_meta_set_origin (core/provenance.h), the older "extent=" of maps, and
 * the commands that read it (sample, krige --covariate). */
#include "../core/format.h"
#include "../core/io.h"
#include "../core/nl_error.h"
#include "../core/provenance.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Set then read back: the origin in length units within a few ulps (it is
 * stored in samples, origin / h, with 17 digits: one division and one
 * product, each within half an ulp); whole samples written as integers. */
Test(extent, set_then_read_back)
{
    nl_meta m = {0};
    size_t n[3] = {10, 7, 3};
    double h[3] = {0.1, 2.385, 1.0 / 3}, o[3] = {0.3, -4.77, 1.25}, got[3], hh[3];
    cr_assert_eq(nl_meta_set_origin(&m, 3, h, o), NL_OK, "%s", nl_errmsg());
    cr_expect_str_eq(m.origin, "3,-2,3.75"); /* 0.3 / 0.1 = 2.9999999999999996: within 1e-9 of 3 */
    memcpy(hh, h, sizeof hh);
    cr_assert_eq(nl_meta_origin(&m, 3, n, hh, got), NL_OK, "%s", nl_errmsg());
    for (int a = 0; a < 3; a++) {
        cr_expect_eq(hh[a], h[a]);
        cr_expect(fabs(got[a] - o[a]) <= 4 * 0x1p-52 * fabs(o[a]), "axis %d: %.17g, expected %.17g", a, got[a], o[a]);
    }
    h[1] = 0;
    cr_expect_eq(nl_meta_set_origin(&m, 3, h, o), NL_EINVAL);
    cr_expect_str_eq(m.origin, "3,-2,3.75"); /* unchanged */
}

/* Files written before the origin was recorded for maps: "extent=a:b" in
 * the method gives cell centres and the spacing; a recorded origin wins. */
Test(extent, legacy_extent_in_the_method)
{
    nl_meta m = {0};
    size_t n[2] = {10, 4};
    double h[3] = {1, 1, 1}, o[3];
    strcpy(m.method, "krige:ordinary,points=4,extent=0:5,-2:2");
    cr_assert_eq(nl_meta_origin(&m, 2, n, h, o), NL_OK, "%s", nl_errmsg());
    cr_expect(h[0] == 0.5 && h[1] == 1 && o[0] == 0.25 && o[1] == -1.5, "h %g %g o %g %g", h[0], h[1], o[0], o[1]);
    strcpy(m.method, "krige:ordinary,points=4,extent=0:5,2:-2");
    cr_expect_eq(nl_meta_origin(&m, 2, n, h, o), NL_EINPUT);
    strcpy(m.origin, "8,4");
    h[0] = h[1] = 0.5;
    cr_assert_eq(nl_meta_origin(&m, 2, n, h, o), NL_OK, "%s", nl_errmsg());
    cr_expect(o[0] == 4 && o[1] == 2);
    strcpy(m.origin, "8,x");
    cr_expect_eq(nl_meta_origin(&m, 2, n, h, o), NL_EINPUT);
    cr_expect(strstr(nl_errmsg(), "noiselab.origin"), "%s", nl_errmsg());
}

/* The values sample prints for pts.tsv from FILE (nearest sample), into v. */
static void sampled(const char *file, double *v, size_t np)
{
    char cmd[512], out[8192], err[1024];
    snprintf(cmd, sizeof cmd, "sample %s --points pts.tsv --interpolation nearest", file);
    cr_assert_eq(run_noiselab(cmd, out, sizeof out, err, sizeof err), 0, "%s: %s", file, err);
    char *p = out;
    size_t k = 0;
    for (char *line = strtok(p, "\n"); line && k < np; line = strtok(NULL, "\n")) {
        double x, y, z;
        if (sscanf(line, "%lf\t%lf\t%lf", &x, &y, &z) == 3)
            v[k++] = z;
    }
    cr_assert_eq(k, np, "%s: %zu values", file, k);
}

/* A window of a larger non-periodic field at origin (20, 12) samples, in
 * each format that records the origin, gives at the data's coordinates the
 * larger field's values: exactly for the float32 formats (the same
 * float32 sample), to half a 16-bit step of its range for PNG. */
Test(extent, window_sampled_at_its_coordinates)
{
    static const double pts[][2] = {{10, 6}, {12.5, 9.5}, {17.5, 13.5}, {11.25, 7.75}};
    enum { NP = sizeof pts / sizeof *pts };
    char cmd[512], out[1024], err[1024], tab[512];
    double ref[NP], v[NP];
    size_t at = (size_t)snprintf(tab, sizeof tab, "x\ty\n");
    for (int k = 0; k < NP; k++)
        at += (size_t)snprintf(tab + at, sizeof tab - at, "%g\t%g\n", pts[k][0], pts[k][1]);
    scratch_file("pts.tsv", tab);
    cr_assert_eq(run_noiselab("synth subdiv --acf markov:scale=6 --size 48x48 --nonperiodic --spacing 0.5 --seed 4 "
                              "-o big.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    sampled("big.exr", ref, NP);
    static const char *fmt[] = {"exr", "png"};
    for (int f = 0; f < 2; f++) {
        snprintf(cmd, sizeof cmd, "synth subdiv --acf markov:scale=6 --size 16x16 --nonperiodic --origin 20,12 "
                 "--spacing 0.5 --seed 4 -o win.%s", fmt[f]);
        cr_assert_eq(run_noiselab(cmd, out, sizeof out, err, sizeof err), 0, "%s", err);
        snprintf(cmd, sizeof cmd, "win.%s", fmt[f]);
        sampled(cmd, v, NP);
        for (int k = 0; k < NP; k++) /* PNG: the window's range is under 8, so half a step is under 8 / 131070 */
            cr_expect(fabs(v[k] - ref[k]) <= (f ? 8.0 / 131070 : 0), "%s point %d: %.10g, expected %.10g", fmt[f], k,
                      v[k], ref[k]);
    }
}

/* Data on cell centres of an extent that does not start at 0: the kriged
 * map, read back by sample at the data's coordinates, reproduces the data
 * (kriging interpolates exactly without a nugget; float32: 1e-6). */
Test(extent, krige_map_sampled_at_the_data)
{
    char out[1024], err[1024];
    static const double d[][3] = {{10.5, -3.5, 0.5}, {12.5, 1.5, 1.5}, {17.5, -2.5, -0.3}, {15.5, 0.5, 0.9}};
    char tab[256];
    size_t at = (size_t)snprintf(tab, sizeof tab, "x\ty\tvalue\n");
    for (int k = 0; k < 4; k++)
        at += (size_t)snprintf(tab + at, sizeof tab - at, "%g\t%g\t%g\n", d[k][0], d[k][1], d[k][2]);
    scratch_file("pts.tsv", tab);
    cr_assert_eq(run_noiselab("krige --data pts.tsv --acf markov:scale=3 --grid 10x6 --extent 10:20,-4:2 -o k.exr",
                              out, sizeof out, err, sizeof err), 0, "%s", err);
    double v[4];
    sampled("k.exr", v, 4);
    for (int k = 0; k < 4; k++)
        cr_expect(fabs(v[k] - d[k][2]) <= 1e-6, "point %d: %.10g, expected %g", k, v[k], d[k][2]);
}

/* krige --covariate: a covariate field on the kriging grid is taken; one
 * shifted by one cell is refused naming both grids. */
Test(extent, covariate_grid_must_coincide)
{
    char out[1024], err[1024];
    char tab[4096];
    size_t at = (size_t)snprintf(tab, sizeof tab, "x\ty\tvalue\tc\n");
    for (int k = 0; k < 20; k++) {
        double x = fmod(0.37 * k + 0.05, 1.0), y = fmod(0.61 * k + 0.11, 1.0), c = sin(3 * x) + 0.7 * y;
        at += (size_t)snprintf(tab + at, sizeof tab - at, "%.6f\t%.6f\t%.6f\t%.6f\n", x, y, 2 * c + sin(7 * y), c);
    }
    scratch_file("dc.tsv", tab);
    scratch_file("dcov.tsv", "x\ty\tvalue\n0.1\t0.1\t0.2\n0.9\t0.2\t1.1\n0.5\t0.8\t0.7\n0.3\t0.6\t0.4\n");
    cr_assert_eq(run_noiselab("krige --data dcov.tsv --acf markov:scale=0.5 --grid 8x8 --extent 0:1,0:1 -o on.exr",
                              out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("krige --data dcov.tsv --acf markov:scale=0.5 --grid 8x8 --extent 0.125:1.125,0:1 "
                              "-o off.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_expect_eq(run_noiselab("krige --data dc.tsv --acf markov:scale=0.4 --grid 8x8 --extent 0:1,0:1 --drift c "
                              "--covariate c=on.exr --nmax 10 -o map.exr", out, sizeof out, err, sizeof err), 0, "%s",
                 err);
    cr_expect_eq(run_noiselab("krige --data dc.tsv --acf markov:scale=0.4 --grid 8x8 --extent 0:1,0:1 --drift c "
                              "--covariate c=off.exr --nmax 10 -o map2.exr", out, sizeof out, err, sizeof err), 2);
    cr_expect(strstr(err, "off.exr lies on a grid of first sample 0.1875") && strstr(err, "first cell centre 0.0625")
              && count_lines(err) == 1, "%s", err);
}

/* synth --condition maps record their cells: first centre and spacing. */
Test(extent, conditional_map_records_its_cells)
{
    char out[1024], err[1024];
    scratch_file("cd.tsv", "x\ty\tvalue\n11\t-3\t0.5\n14\t-1\t1.5\n17\t-0.5\t-0.3\n");
    cr_assert_eq(run_noiselab("synth circulant --acf markov:scale=3 --size 16x8 --condition cd.tsv --extent 10:18,-4:0 "
                              "--seed 2 -o c.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    char path[512];
    nl_field *f;
    nl_meta m;
    double o[3];
    snprintf(path, sizeof path, "%s/c.exr", scratch_dir());
    cr_assert_eq(nl_field_read(path, &f, &m), NL_OK, "%s", nl_errmsg());
    cr_expect_str_eq(m.spacing, "0.5,0.5");
    cr_expect_str_eq(m.origin, "20.5,-7.5");
    cr_assert_eq(nl_meta_origin(&m, 2, f->n, f->h, o), NL_OK);
    cr_expect(o[0] == 10.25 && o[1] == -3.75, "%g %g", o[0], o[1]);
    nl_field_free(f);
}

/* .r16 and .f32 with their sidecar: read back without options, the size
 * (not square: 7 x 3), spacing and origin come from it, and the r16 values
 * within half a 16-bit step of the range, (hi - lo) / 131070; f32 to
 * float32 rounding (2^-24 relative). */
Test(extent, raw_round_trip_through_the_sidecar)
{
    size_t n[2] = {7, 3};
    double h[2] = {0.25, 2.385}, o[2] = {-1.5, 4.77}, got[3];
    static const char *ext[] = {"r16", "f32"};
    nl_field *f = nl_field_alloc(2, n, h, NULL), *g;
    nl_meta m = {0}, mr;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(0.7 * (double)i) * 3.1;
    cr_assert_eq(nl_meta_set_origin(&m, 2, h, o), NL_OK);
    for (int e = 0; e < 2; e++) {
        char path[512];
        snprintf(path, sizeof path, "%s/raw.%s", scratch_dir(), ext[e]);
        cr_assert_eq(nl_field_write(path, f, &m, NULL), NL_OK, "%s", nl_errmsg());
        cr_assert_eq(nl_field_read(path, &g, &mr), NL_OK, "%s: %s", ext[e], nl_errmsg());
        cr_assert(g->dim == 2 && g->n[0] == 7 && g->n[1] == 3, "%s: %dD %zu x %zu", ext[e], g->dim, g->n[0], g->n[1]);
        cr_expect(g->h[0] == h[0] && g->h[1] == h[1], "%s: spacing %g %g", ext[e], g->h[0], g->h[1]);
        cr_assert_eq(nl_meta_origin(&mr, 2, g->n, g->h, got), NL_OK);
        for (int a = 0; a < 2; a++)
            cr_expect(fabs(got[a] - o[a]) <= 4e-16 * fabs(o[a]), "%s: origin %d %.17g", ext[e], a, got[a]);
        for (size_t i = 0; i < f->count; i++)
            cr_expect(fabs(g->data[i] - f->data[i]) <= (e ? 0x1p-24 * 3.1 : 6.2 / 131070 * 1.000001), "%s: %zu", ext[e],
                      i);
        nl_field_free(g);
    }
    nl_field_free(f);
}

/* variogram of a field: lags in the file's spacing, wherever it is kept
 * (the EXR's attribute, the .f32's sidecar): the same table. */
Test(extent, variogram_takes_the_spacing_from_the_file)
{
    char out[8192], out2[8192], err[1024];
    cr_assert_eq(run_noiselab("synth subdiv --acf markov:scale=2 --size 24x24 --nonperiodic --spacing 0.25 --seed 3 "
                              "-o v.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("synth subdiv --acf markov:scale=2 --size 24x24 --nonperiodic --spacing 0.25 --seed 3 "
                              "-o v.f32", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("variogram v.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("variogram v.f32", out2, sizeof out2, err, sizeof err), 0, "%s", err);
    cr_expect_str_eq(out2, out);
}
