/* The format registry (core/format.h): round trips of every format in each
 * dimension it holds, its header layouts, the XDMF sidecar, and refusals. */
#include "../core/format.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <float.h>
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

/* A field of "high-entropy" values (GSL's advice) of dim axes. */
static nl_field *field(int dim)
{
    static const size_t sizes[3][3] = {{101, 1, 1}, {13, 7, 1}, {5, 4, 3}};
    double h[3] = {0.5, 2.25, 3};
    nl_field *f = nl_field_alloc(dim, sizes[dim - 1], h, NULL);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(2.385 * (double)i) * 7.25 + 0.125 * (double)i;
    return f;
}

static nl_field *read_back(const char *p, const nl_read_options *o, nl_meta *m)
{
    nl_field *g;
    cr_assert_eq(nl_field_read_opts(p, o, &g, m), NL_OK, "%s: %s", p, nl_errmsg());
    return g;
}

/* Float formats hold the samples exactly at their precision: float64
 * bit for bit, float32 as (float) rounds them; the shape comes back unless
 * the format needs it given (f32: the read options carry it). */
static void float_round_trip(const char *name, const char *file, int prec, int dim)
{
    nl_field *f = field(dim), *g;
    nl_write_options w = {.format = name, .precision = prec};
    nl_read_options r = {.dim = dim};
    nl_meta m = {0};
    const nl_format *t = nl_format_find(name);
    int at = snprintf(m.size, sizeof m.size, "%zu", f->n[0]);
    for (int a = 1; a < dim; a++)
        at += snprintf(m.size + at, sizeof m.size - (size_t)at, "x%zu", f->n[a]);
    snprintf(m.spacing, sizeof m.spacing, dim == 1 ? "0.5" : dim == 2 ? "0.5,2.25" : "0.5,2.25,3");
    memcpy(r.n, f->n, sizeof r.n);
    cr_assert_eq(nl_field_write(path(file), f, &m, &w), NL_OK, "%s %dD: %s", name, dim, nl_errmsg());
    g = read_back(path(file), &r, NULL);
    for (int a = 0; a < dim && (t->meta & NL_FORMAT_META_SPACING); a++)
        cr_assert_eq(g->h[a], f->h[a], "%s %dD spacing %d", name, dim, a);
    cr_assert_eq(g->dim, dim, "%s", name);
    for (int a = 0; a < 3; a++)
        cr_assert_eq(g->n[a], f->n[a], "%s %dD axis %d", name, dim, a);
    for (size_t i = 0; i < f->count; i++)
        cr_assert_eq(g->data[i], prec == 64 ? f->data[i] : (double)(float)f->data[i], "%s %dD sample %zu", name,
                     dim, i);
    nl_field_free(f);
    nl_field_free(g);
}

Test(formats, float_formats_round_trip_1d_2d_3d)
{
    for (int dim = 1; dim <= 3; dim++) {
        float_round_trip("npy", "a.npy", 64, dim);
        float_round_trip("npy", "b.npy", 32, dim);
        float_round_trip("exr", "a.exr", 32, dim);
        float_round_trip("f32", "a.f32", 32, dim);
    }
}

/* TSV prints 10 significant digits: within 5e-10 relative. */
Test(formats, tsv_round_trip_1d_ten_digits)
{
    nl_field *f = field(1), *g;
    cr_assert_eq(nl_field_write(path("a.tsv"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    g = read_back(path("a.tsv"), NULL, NULL);
    cr_assert_eq(g->count, f->count);
    for (size_t i = 0; i < f->count; i++)
        cr_assert(fabs(g->data[i] - f->data[i]) <= 5e-10 * fabs(f->data[i]), "sample %zu", i);
    nl_field_free(f);
    nl_field_free(g);
}

/* 16-bit codes: the mapping rounds to the nearest of 65536 levels, so the
 * value read back is within half a step (hi - lo) / 65535 / 2 of the
 * written one (plus a few ulps of the linear map in double). */
static void int_round_trip(const char *file, int dim, double lo, double hi)
{
    nl_field *f = field(dim), *g;
    nl_write_options w = {.lo = lo, .hi = hi};
    nl_read_options r = {.dim = dim, .lo = lo, .hi = hi};
    nl_meta m = {0}, back;
    strcpy(m.seed, "42");
    strcpy(m.spacing, "0.5,2.25");
    memcpy(r.n, f->n, sizeof r.n);
    if (!(lo < hi)) { /* the field's range, which the PNG records and the raw file cannot */
        lo = hi = f->data[0];
        for (size_t i = 0; i < f->count; i++)
            lo = fmin(lo, f->data[i]), hi = fmax(hi, f->data[i]);
        r.lo = lo, r.hi = hi;
    }
    cr_assert_eq(nl_field_write(path(file), f, &m, &w), NL_OK, "%s: %s", file, nl_errmsg());
    g = read_back(path(file), strstr(file, ".png") ? NULL : &r, &back);
    double half = (hi - lo) / 65535 / 2 * (1 + 1e-9);
    for (size_t i = 0; i < f->count; i++) {
        double want = fmin(fmax(f->data[i], lo), hi); /* clamped to the range */
        cr_assert(fabs(g->data[i] - want) <= half, "%s sample %zu: %.17g for %.17g (half step %g)", file, i,
                  g->data[i], want, half);
    }
    if (strstr(file, ".png")) {
        cr_assert_str_eq(back.seed, "42");
        cr_assert_eq(g->h[0], 0.5);
        cr_assert_eq(g->h[1], 2.25);
    }
    nl_field_free(f);
    nl_field_free(g);
}

Test(formats, png16_and_r16_within_half_a_step)
{
    int_round_trip("a.png", 2, 0, 0);
    int_round_trip("b.png", 2, -3.5, 9.25); /* clamps: the field spans about -7 .. 23 */
    for (int dim = 1; dim <= 3; dim++)
        int_round_trip("a.r16", dim, 0, 0);
    int_round_trip("b.raw", 2, -1, 30);
}

/* A raw file read without a size is a square, as Unity reads it. */
Test(formats, raw_square_by_default)
{
    size_t n[2] = {6, 6};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *g;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = (double)i;
    cr_assert_eq(nl_field_write(path("sq.f32"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    g = read_back(path("sq.f32"), NULL, NULL);
    cr_assert_eq(g->dim, 2);
    cr_assert_eq(g->n[0], 6);
    cr_assert_eq(g->data[7], 7.0);
    nl_field_free(g);
    f->n[0] = 9, f->n[1] = 4; /* 36 samples, but not square, and no sidecar: still read as 6 x 6 */
    nl_write_options w = {.sidecar = ""};
    cr_assert_eq(nl_field_write(path("sq.r16"), f, NULL, &w), NL_OK, "%s", nl_errmsg());
    g = read_back(path("sq.r16"), NULL, NULL);
    cr_assert_eq(g->n[0], 6);
    nl_field_free(g);
    nl_field_free(f);
}

static size_t slurp(const char *p, unsigned char *buf, size_t cap)
{
    FILE *fp = fopen(p, "rb");
    cr_assert(fp, "%s", p);
    size_t n = fread(buf, 1, cap, fp);
    fclose(fp);
    return n;
}

/* NEP 1 / numpy/lib/format.py version 1.0: magic, version, a little-endian
 * header length making the data start at a multiple of 64, the dict with
 * the shape slowest axis first, then the samples. */
Test(formats, npy_header_is_version_1_0)
{
    static unsigned char buf[4096];
    nl_field *f = field(3);
    cr_assert_eq(nl_field_write(path("h.npy"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    size_t n = slurp(path("h.npy"), buf, sizeof buf);
    size_t hl = buf[8] | (size_t)buf[9] << 8;
    cr_assert_eq(memcmp(buf, "\x93NUMPY\x01\x00", 8), 0);
    cr_assert_eq((10 + hl) % 64, 0, "data at %zu", 10 + hl);
    cr_assert_eq(buf[10 + hl - 1], '\n');
    cr_assert(strstr((char *)buf + 10, "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4, 5), }"));
    cr_assert_eq(n, 10 + hl + 8 * f->count);
    nl_field_free(f);
    f = field(1);
    cr_assert_eq(nl_field_write(path("h1.npy"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    slurp(path("h1.npy"), buf, sizeof buf);
    cr_assert(strstr((char *)buf + 10, "'shape': (101,), }"), "%.60s", buf + 10);
    nl_field_free(f);
}

/* XDMF lists axes slowest first: Dimensions "nz ny nx", spacing "hz hy hx". */
Test(formats, xdmf_sidecar_names_dims_and_spacing)
{
    static unsigned char buf[4096];
    size_t n[3] = {9, 7, 5};
    double h[3] = {0.5, 2.25, 3}, o[3] = {1, 2, 4};
    cr_assert_eq(nl_xdmf_write(path("a.xmf"), "a&b.h5", 3, n, h, o, 1), NL_OK, "%s", nl_errmsg());
    buf[slurp(path("a.xmf"), buf, sizeof buf - 1)] = 0;
    const char *s = (const char *)buf;
    cr_assert(strstr(s, "TopologyType=\"3DCoRectMesh\" Dimensions=\"5 7 9\""), "%s", s);
    cr_assert(strstr(s, ">3 2.25 0.5</DataItem>"), "%s", s);
    cr_assert(strstr(s, ">4 2 1</DataItem>"), "%s", s);
    cr_assert(strstr(s, "<DataItem Dimensions=\"5 7 9\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
                         "a&amp;b.h5:/field</DataItem>"), "%s", s);
    cr_assert_eq(nl_xdmf_write(path("b.xmf"), "b.h5", 2, n, NULL, NULL, 0), NL_OK, "%s", nl_errmsg());
    buf[slurp(path("b.xmf"), buf, sizeof buf - 1)] = 0;
    cr_assert(strstr(s, "\"2DCoRectMesh\" Dimensions=\"7 9\""), "%s", s);
    cr_assert(strstr(s, "ORIGIN_DXDY\""), "%s", s);
    cr_assert(strstr(s, "Precision=\"4\""), "%s", s);
    h[1] = 0;
    cr_assert_eq(nl_xdmf_write(path("c.xmf"), "c.h5", 2, n, h, NULL, 0), NL_EINVAL);
}

/* Every format is found by its name and by each of its extensions (the
 * first registered wins a shared one); names are unique. */
Test(formats, registry_is_consistent)
{
    cr_assert_geq(nl_format_count(), 7);
    cr_assert_null(nl_format_get(nl_format_count()));
    for (size_t i = 0; i < nl_format_count(); i++) {
        const nl_format *t = nl_format_get(i);
        char p[64];
        cr_assert_eq(nl_format_find(t->name), t, "%s", t->name);
        cr_assert(t->summary && *t->summary && t->dims && t->types, "%s", t->name);
        cr_assert(t->magic_len <= 8, "%s", t->name);
        cr_assert((t->flags & (NL_FORMAT_EXTERNAL | NL_FORMAT_OFF)) ? !t->write && !t->read : t->write && t->read, "%s",
                  t->name);
        for (const char *e = t->extensions; *e;) {
            size_t k = strcspn(e, " ");
            snprintf(p, sizeof p, "x%.*s", (int)k, e);
            cr_assert_eq(nl_format_for_path(p), t, "%s", p);
            e += k + (e[k] == ' ');
        }
    }
    cr_assert_null(nl_format_find("gif"));
    cr_assert_eq(nl_format_for_path("X.NPY"), nl_format_find("npy"));
}

static void refused(const char *file, const nl_field *f, const nl_write_options *o, int want, const char *needle)
{
    unlink(path(file));
    cr_assert_eq(nl_field_write(path(file), f, NULL, o), want, "%s: %s", file, nl_errmsg());
    cr_assert(strstr(nl_errmsg(), needle), "%s: \"%s\" lacks \"%s\"", file, nl_errmsg(), needle);
    cr_assert_neq(access(path(file), F_OK), 0, "%s written", file);
}

Test(formats, writes_refused_before_writing)
{
    nl_field *f2 = field(2), *f3 = field(3);
    nl_write_options gif = {.format = "gif"}, dbl = {.precision = 64}, odd = {.precision = 16},
                     inv = {.lo = 2, .hi = 1};
    refused("a.foo", f2, NULL, NL_EINVAL, "unknown extension; expected one of .exr, .tsv, .npy");
    refused("a.exr", f2, &gif, NL_EINVAL, "format \"gif\": unknown; expected one of exr, tsv, npy");
    refused("a.png", f3, NULL, NL_EINVAL, "does not hold 3D fields");
    refused("a.tsv", f2, NULL, NL_EINVAL, "does not hold 2D fields");
    refused("a.exr", f2, &dbl, NL_EINVAL, "precision 64");
    refused("a.npy", f2, &odd, NL_EINVAL, "precision 16: expected 32 or 64");
    refused("a.png", f2, &inv, NL_EINVAL, "range 2,1");
    refused("a.h5", f2, NULL, NL_EINVAL, "libnoiselab_mpi");
    f2->data[5] = INFINITY;
    refused("b.npy", f2, NULL, NL_EINVAL, "sample 5 is inf");
    f2->data[5] = 1e300;
    refused("b.exr", f2, NULL, NL_EINVAL, "within float32");
    f2->data[5] = NAN;
    refused("b.png", f2, NULL, NL_EINVAL, "no missing-value code");
    cr_assert_eq(nl_field_write(path("nan.npy"), f2, NULL, NULL), NL_OK, "a NaN is a missing value: %s",
                 nl_errmsg());
    nl_field_free(f2);
    nl_field_free(f3);
}

/* Reading goes by content before the name: a .npy named .dat is .npy. */
Test(formats, read_by_content_then_extension)
{
    nl_field *f = field(2), *g;
    nl_read_options tsv = {.format = "tsv"}, bad = {.format = "gif"};
    cr_assert_eq(nl_field_write(path("x.npy"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    char from[512];
    snprintf(from, sizeof from, "%s", path("x.npy"));
    cr_assert_eq(rename(from, path("x.dat")), 0);
    g = read_back(path("x.dat"), NULL, NULL);
    cr_assert_eq(g->n[0], 13);
    nl_field_free(g);
    cr_assert_eq(nl_field_read_opts(path("x.dat"), &tsv, &g, NULL), NL_EINPUT); /* forced: not a TSV */
    cr_assert_eq(nl_field_read_opts(path("x.dat"), &bad, &g, NULL), NL_EINVAL);
    cr_assert_null(g);
    nl_field_free(f);
}

/* Hostile .npy files: refused with a message, never read past the end. */
static void npy_refused(const char *header, size_t more, size_t data, int want, const char *needle)
{
    unsigned char buf[512] = {0};
    size_t hl = strlen(header), claim = hl + more; /* more: bytes the header claims beyond its text */
    memcpy(buf, "\x93NUMPY\x01\x00", 8);
    buf[8] = (unsigned char)(claim & 0xff), buf[9] = (unsigned char)(claim >> 8);
    memcpy(buf + 10, header, hl);
    FILE *fp = fopen(path("h.npy"), "wb");
    fwrite(buf, 1, 10 + hl + data, fp);
    fclose(fp);
    nl_field *g;
    cr_assert_eq(nl_field_read(path("h.npy"), &g, NULL), want, "%s: %s", header, nl_errmsg());
    cr_assert(strstr(nl_errmsg(), needle), "\"%s\" lacks \"%s\"", nl_errmsg(), needle);
    cr_assert_null(g);
}

Test(formats, hostile_npy_refused)
{
    const char *ok = "{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4), }";
    npy_refused(ok, 200, 0, NL_EINPUT, "is truncated");
    npy_refused(ok, 0, 100, NL_EINPUT, ".npy data of 100 bytes");
    npy_refused("{'descr': '<f8', 'fortran_order': False, 'shape': (4000000000, 4000000000), }", 0, 0,
                NL_ETOOBIG, "");
    npy_refused("{'descr': '>f8', 'fortran_order': False, 'shape': (4,), }", 0, 32, NL_EINPUT, "'>f8'");
    npy_refused("{'descr': '<f8', 'fortran_order': True, 'shape': (4,), }", 0, 32, NL_EINPUT, "fortran_order");
    npy_refused("{'descr': '<f8', 'fortran_order': False, 'shape': (), }", 0, 8, NL_EINPUT, "shape ()");
    npy_refused("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1, 1, 1), }", 0, 8, NL_EINPUT,
                "1 to 3 axes");
    npy_refused("{'descr': '<f8', 'descr': '<f8', 'shape': (1,), }", 0, 8, NL_EINPUT, "given twice");
    npy_refused("{'descr': '<f8', 'fortran_order': False, 'shape': (0,), }", 0, 0, NL_EINPUT, "positive");
    npy_refused("{'descr': '<f8', 'fortran_order': False, 'shape': (-1,), }", 0, 0, NL_EINPUT, "positive");
    npy_refused("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), 'x': 1}", 0, 8, NL_EINPUT,
                "unknown key 'x'");
}
