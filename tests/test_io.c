/* File I/O: EXR, PNG and TSV round trips and malformed inputs. */
#include "../core/io.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/fft.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char path_buf[512];
static const char *path(const char *name)
{
    snprintf(path_buf, sizeof path_buf, "%s/%s", scratch_dir(), name);
    return path_buf;
}

static void exr_round_trip(int dim, const size_t *n)
{
    double h[3] = {0.5, 2.25, 3};
    nl_field *f = nl_field_alloc(dim, n, h, NULL), *g;
    nl_meta meta, back;
    memset(&meta, 0, sizeof meta);
    strcpy(meta.model, "expr:exp(-abs(t))");
    strcpy(meta.method, "fft");
    strcpy(meta.seed, "18446744073709551615");
    snprintf(meta.spacing, sizeof meta.spacing, "0.5,2.25,3");
    if (dim == 1)
        snprintf(meta.size, sizeof meta.size, "%zu", n[0]), strcpy(meta.spacing, "0.5");
    else if (dim == 2)
        snprintf(meta.size, sizeof meta.size, "%zux%zu", n[0], n[1]), strcpy(meta.spacing, "0.5,2.25");
    else
        snprintf(meta.size, sizeof meta.size, "%zux%zux%zu", n[0], n[1], n[2]);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(2.385 * (double)i) * 1e3;
    cr_assert_eq(nl_exr_write(path("a.exr"), f, &meta), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_exr_read(path("a.exr"), &g, &back), 0, "%s", nl_errmsg());
    cr_assert_eq(g->dim, dim);
    cr_assert_eq(g->count, f->count);
    for (int a = 0; a < dim; a++) {
        cr_assert_eq(g->n[a], f->n[a]);
        cr_assert_eq(g->h[a], f->h[a]);
    }
    for (size_t i = 0; i < f->count; i++)
        cr_assert_eq(g->data[i], (double)(float)f->data[i], "sample %zu", i);
    cr_assert_str_eq(back.model, meta.model);
    cr_assert_str_eq(back.seed, meta.seed);
    cr_assert_str_eq(back.size, meta.size);
    nl_field_free(f);
    nl_field_free(g);
}

Test(io, exr_round_trip_1d_2d_3d)
{
    size_t n1[1] = {1000}, n2[2] = {37, 41}, n3[3] = {9, 7, 5};
    exr_round_trip(1, n1);
    exr_round_trip(2, n2);
    exr_round_trip(3, n3);
}

Test(io, exr_malformed_inputs_are_refused)
{
    size_t n[2] = {64, 64};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *g;
    FILE *fp = fopen(path("junk.exr"), "w");
    long size;
    fputs("this is not an EXR file", fp);
    fclose(fp);
    cr_assert_eq(nl_exr_read(path("junk.exr"), &g, NULL), NL_EINPUT);
    cr_assert_eq(nl_exr_read(path("missing.exr"), &g, NULL), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "missing.exr") != NULL);
    /* a valid file truncated to half its length */
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = cos((double)i);
    cr_assert_eq(nl_exr_write(path("t.exr"), f, NULL), 0);
    fp = fopen(path("t.exr"), "r+");
    fseek(fp, 0, SEEK_END);
    size = ftell(fp);
    fclose(fp);
    cr_assert_eq(truncate(path("t.exr"), size / 2), 0);
    cr_assert_eq(nl_exr_read(path("t.exr"), &g, NULL), NL_EINPUT);
    nl_field_free(f);
}

Test(io, exr_unwritable_path)
{
    size_t n[1] = {8};
    nl_field *f = nl_field_alloc(1, n, NULL, NULL);
    cr_assert_eq(nl_exr_write("/nonexistent/dir/a.exr", f, NULL), NL_EIO);
    nl_field_free(f);
}

/* 8-bit value v is written as v and read back as v * 257 / 65535 = v / 255. */
Test(io, png_round_trip)
{
    size_t n[2] = {17, 5};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *g;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = (double)((i * 37) % 256);
    cr_assert_eq(nl_png_write_field(path("a.png"), f, 0, 255), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_png_read(path("a.png"), &g), 0, "%s", nl_errmsg());
    cr_assert_eq(g->n[0], 17);
    cr_assert_eq(g->n[1], 5);
    for (size_t i = 0; i < f->count; i++)
        cr_assert_float_eq(g->data[i], f->data[i] / 255.0, 1e-12, "pixel %zu", i);
    nl_field_free(g);
    cr_assert_eq(nl_png_read(path("junk.exr"), &g), NL_EINPUT);
    nl_field_free(f);
}

Test(io, tsv_round_trip_and_errors)
{
    static const char *const names[] = {"t", "value"};
    double t[5] = {0, 0.25, 0.5, 0.75, 1}, v[5] = {1.5, -2, 3.25, 1e-300, 7};
    const double *cols[2] = {t, v};
    nl_field *f;
    FILE *fp;
    cr_assert_eq(nl_tsv_write(path("a.tsv"), "a comment", 2, names, 5, cols), 0);
    cr_assert_eq(nl_field_read(path("a.tsv"), &f, NULL), 0, "%s", nl_errmsg());
    cr_assert_eq(f->count, 5);
    cr_assert_eq(f->h[0], 0.25);
    for (int i = 0; i < 5; i++)
        cr_assert_eq(f->data[i], v[i]);
    nl_field_free(f);
    fp = fopen(path("bad.tsv"), "w");
    fputs("t\tvalue\n0\t1\n1\tnan\n", fp);
    fclose(fp);
    cr_assert_eq(nl_tsv_read_field(path("bad.tsv"), &f), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), ":3:") != NULL, "names the line: %s", nl_errmsg());
    fp = fopen(path("bad2.tsv"), "w");
    fputs("t\tvalue\n0\t1\n1\n", fp);
    fclose(fp);
    cr_assert_eq(nl_tsv_read_field(path("bad2.tsv"), &f), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "expected 2 columns") != NULL, "%s", nl_errmsg());
}

/* Lossless round trip of synthesised fields, including gauss:scale=6 on
 * 256x256 with seed 1, whose chunk at row 160 OpenEXRCore 3.1.5 corrupted
 * under ZIP compression (incompressible chunk).  Every sample must come back
 * as the float it was written as. */
Test(io, exr_round_trip_of_synthesised_fields)
{
    const char *specs[] = {"gauss:scale=6", "spectrum:1", "markov:scale=3"};
    size_t sizes[][2] = {{256, 256}, {512, 300}, {1000, 17}};
    for (int s = 0; s < 3; s++)
        for (int z = 0; z < 3; z++)
            for (uint64_t seed = 1; seed <= 3; seed++) {
                nl_model *m;
                nl_synth_fft_plan *p;
                nl_field *f = nl_field_alloc(2, sizes[z], NULL, NULL), *g;
                cr_assert_eq(nl_model_parse(specs[s], &m), 0);
                cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, sizes[z], NULL, NL_SYNTH_FFT_CLAMP, &p), 0, "%s", nl_errmsg());
                cr_assert_eq(nl_synth_fft_execute(p, seed, f), 0);
                cr_assert_eq(nl_exr_write(path("s.exr"), f, NULL), 0);
                cr_assert_eq(nl_exr_read(path("s.exr"), &g, NULL), 0);
                for (size_t i = 0; i < f->count; i++)
                    cr_assert_eq(g->data[i], (double)(float)f->data[i], "%s %zux%zu seed %d: sample %zu", specs[s],
                                 sizes[z][0], sizes[z][1], (int)seed, i);
                nl_field_free(f), nl_field_free(g), nl_synth_fft_plan_free(p), nl_model_free(m);
            }
}

Test(io, non_finite_samples_are_refused)
{
    size_t n[2] = {8, 8};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *g;
    f->data[13] = NAN;
    cr_assert_eq(nl_exr_write(path("nan.exr"), f, NULL), 0);
    cr_assert_eq(nl_field_read(path("nan.exr"), &g, NULL), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "sample 13") != NULL, "%s", nl_errmsg());
    nl_field_free(f);
}

/* A 1D field written as TSV with its provenance reads back with the same
 * samples (to the 10 significant digits printed: relative 5e-10), the same
 * record, and the recorded spacing 1/3 exactly (t1 - t0 of coordinates
 * printed to 10 digits is 1/3 only to 1e-10); a window's t starts at its
 * origin; a newline in a value cannot break the header; a bad origin is
 * refused before anything is written. */
Test(io, tsv_round_trip_with_provenance)
{
    size_t n = 300;
    double h = 1.0 / 3;
    nl_field *f = nl_field_alloc(1, &n, &h, NULL), *g;
    nl_meta meta, back;
    char line[256];
    FILE *fp;
    memset(&meta, 0, sizeof meta);
    strcpy(meta.model, "markov:scale=8");
    strcpy(meta.method, "subdiv:levels=6|seed-image=a\nb.png");
    strcpy(meta.seed, "7");
    strcpy(meta.spacing, "0.33333333333333331");
    strcpy(meta.origin, "-12");
    strcpy(meta.version, "0.1.0");
    for (size_t i = 0; i < n; i++)
        f->data[i] = sin(2.385 * (double)i) * 1e3;
    cr_assert_eq(nl_tsv_write_field(path("p.tsv"), f, &meta, NULL, NULL), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_field_read(path("p.tsv"), &g, &back), 0, "%s", nl_errmsg());
    cr_assert_eq(g->count, n);
    cr_assert_eq(g->h[0], h, "spacing %.17g", g->h[0]);
    for (size_t i = 0; i < n; i++)
        cr_assert(fabs(g->data[i] - f->data[i]) <= 5e-10 * fabs(f->data[i]) + 1e-300, "sample %zu", i);
    cr_assert_str_eq(back.model, meta.model);
    cr_assert_str_eq(back.method, "subdiv:levels=6|seed-image=a b.png");
    cr_assert_str_eq(back.seed, "7");
    cr_assert_str_eq(back.origin, "-12");
    fp = fopen(path("p.tsv"), "r");
    while (fgets(line, sizeof line, fp) && line[0] == '#')
        ;
    cr_assert_str_eq(line, "t\tvalue\n");
    cr_assert(fgets(line, sizeof line, fp) != NULL);
    cr_assert(strncmp(line, "-4\t", 3) == 0, "t = origin h = -4: %s", line);
    fclose(fp);
    strcpy(meta.origin, "x");
    unlink(path("q.tsv"));
    cr_assert_eq(nl_tsv_write_field(path("q.tsv"), f, &meta, NULL, NULL), NL_EINVAL);
    cr_assert_eq(access(path("q.tsv"), F_OK), -1);
    nl_field_free(f);
    nl_field_free(g);
}

/* A text field is parsed as it is read, never held whole: an endless
 * input (/dev/zero, a pipe that never ends its first line) is refused at
 * its first line, by what is wrong with it, not after reading up to the
 * memory limit (100 MB here, so that a reader that holds the file fails
 * with NL_ETOOBIG rather than the NL_EINPUT asked for); a series piped in
 * still reads. */
Test(io, text_inputs_parsed_as_read)
{
    nl_field *f;
    int fd[2];
    setenv("NOISELAB_MEMORY_LIMIT", "100000000", 1);
    cr_expect_eq(nl_field_read("/dev/zero", &f, NULL), NL_EINPUT, "%s", nl_errmsg());
    cr_expect(strstr(nl_errmsg(), "NUL byte") != NULL, "%s", nl_errmsg());
    cr_expect_null(f);
    cr_assert_eq(pipe(fd), 0);
    cr_assert(write(fd[1], "t\tvalue\n0\t1.5\n1\t-2.25\n2\t3\n", 26) == 26);
    close(fd[1]);
    char path[64];
    snprintf(path, sizeof path, "/dev/fd/%d", fd[0]);
    cr_assert_eq(nl_field_read(path, &f, NULL), 0, "%s", nl_errmsg());
    cr_expect_eq(f->count, 3);
    cr_expect_eq(f->data[1], -2.25);
    nl_field_free(f);
    close(fd[0]);
}
