/* The JSON sidecar of the headerless raw formats (formats_internal.h):
 * what the file itself cannot say, its size, range, spacing, origin and
 * byte order, in a small file beside it (height.r16 -> height.r16.json). */
#include "formats_internal.h"
#include "../nl_error.h"
#include "../provenance.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int nl_raw_sidecar_write(const char *path, const char *format, const nl_field *f, const nl_meta *meta,
                         const nl_write_options *o, const double *range)
{
    char buf[4096];
    const char *side = o->sidecar;
    double h[3] = {f->h[0], f->h[1], f->h[2]}, origin[3];
    int st;
    if (side && !*side)
        return NL_OK;
    if (!side) {
        if (snprintf(buf, sizeof buf, "%s.json", path) >= (int)sizeof buf)
            return NL_ERROR(NL_EINVAL, "%s: path too long for its sidecar", path);
        side = buf;
    }
    if ((st = nl_meta_origin(meta, f->dim, f->n, h, origin)))
        return st;
    json_t *n = json_array(), *hs = json_array(), *os = json_array();
    for (int a = 0; a < f->dim; a++) {
        json_array_append_new(n, json_integer((json_int_t)f->n[a]));
        json_array_append_new(hs, json_real(h[a]));
        json_array_append_new(os, json_real(origin[a]));
    }
    json_t *j = json_pack("{s:s,s:o,s:s,s:o,s:o}", "format", format, "size", n, "byte_order", "little", "spacing", hs,
                          "origin", os);
    if (j && range)
        json_object_set_new(j, "range", json_pack("[f,f]", range[0], range[1]));
    if (!j)
        return NL_ERROR(NL_ENOMEM, "out of memory writing %s", side);
    st = json_dump_file(j, side, JSON_REAL_PRECISION(17));
    json_decref(j);
    return st ? NL_ERROR(NL_EIO, "cannot write %s: %s", side, strerror(errno)) : NL_OK;
}

/* An array of 1 to 3 numbers into v (*k of them); 0 when it is not one. */
static int numbers(json_t *a, double *v, int *k)
{
    if (!json_is_array(a) || json_array_size(a) < 1 || json_array_size(a) > 3)
        return 0;
    *k = (int)json_array_size(a);
    for (int i = 0; i < *k; i++) {
        json_t *x = json_array_get(a, (size_t)i);
        if (!json_is_number(x))
            return 0;
        v[i] = json_number_value(x);
    }
    return 1;
}

/* The checks of nl_raw_sidecar_read on the object j of sidecar side. */
static int parse(json_t *j, const char *side, const char *format, size_t count, nl_read_options *r, double *h,
                 double *origin)
{
    json_t *sz = json_object_get(j, "size"), *bo = json_object_get(j, "byte_order");
    double v[3];
    int k, dim;
    size_t c = 1;
    if (!numbers(sz, v, &dim))
        return NL_ERROR(NL_EINPUT, "%s: size: expected 1 to 3 positive integers, x first", side);
    for (int a = 0; a < dim; a++) {
        if (!json_is_integer(json_array_get(sz, (size_t)a)) || !(v[a] >= 1) || v[a] > 0x1p40)
            return NL_ERROR(NL_EINPUT, "%s: size: expected 1 to 3 positive integers, x first", side);
        r->n[a] = (size_t)v[a], c *= r->n[a];
    }
    if (c != count)
        return NL_ERROR(NL_EINPUT, "%s: size makes %zu samples; the file holds %zu", side, c, count);
    r->dim = dim;
    if (bo && (!json_is_string(bo) || strcmp(json_string_value(bo), "little")))
        return NL_ERROR(NL_EINPUT, "%s: byte_order: expected \"little\"", side);
    json_t *rg = json_object_get(j, "range");
    if (strcmp(format, "r16") == 0) {
        if (!numbers(rg, v, &k) || k != 2 || !(v[0] < v[1]) || !isfinite(v[1] - v[0]))
            return NL_ERROR(NL_EINPUT, "%s: range: expected [lo, hi] with lo < hi, both finite", side);
        r->lo = v[0], r->hi = v[1];
    }
    json_t *hs = json_object_get(j, "spacing"), *os = json_object_get(j, "origin");
    if (hs && (!numbers(hs, v, &k) || k != dim))
        return NL_ERROR(NL_EINPUT, "%s: spacing: expected %d positive numbers", side, dim);
    for (int a = 0; hs && a < dim; a++)
        if (!(v[a] > 0) || !isfinite(v[a]))
            return NL_ERROR(NL_EINPUT, "%s: spacing: expected %d positive numbers", side, dim);
        else
            h[a] = v[a];
    if (os && (!numbers(os, v, &k) || k != dim))
        return NL_ERROR(NL_EINPUT, "%s: origin: expected %d finite numbers", side, dim);
    for (int a = 0; os && a < dim; a++)
        if (!isfinite(v[a]))
            return NL_ERROR(NL_EINPUT, "%s: origin: expected %d finite numbers", side, dim);
        else
            origin[a] = v[a];
    return NL_OK;
}

int nl_raw_sidecar_read(const char *path, const char *format, size_t count, nl_read_options *r, double *h,
                        double *origin, int *found)
{
    char side[4096];
    json_error_t e;
    FILE *fp;
    int st;
    *found = 0;
    if (snprintf(side, sizeof side, "%s.json", path) >= (int)sizeof side || !(fp = fopen(side, "r")))
        return NL_OK;
    *found = 1;
    for (int a = 0; a < 3; a++)
        h[a] = 1, origin[a] = 0;
    json_t *j = json_loadf(fp, JSON_REJECT_DUPLICATES, &e);
    fclose(fp);
    if (!j)
        return NL_ERROR(NL_EINPUT, "%s: not JSON (line %d: %s); expected the sidecar of %s", side, e.line, e.text,
                        path);
    st = json_is_object(j) ? parse(j, side, format, count, r, h, origin)
                           : NL_ERROR(NL_EINPUT, "%s: expected a JSON object (the sidecar of %s)", side, path);
    json_decref(j);
    return st;
}

int nl_raw_sidecar_apply(nl_field *f, nl_meta *meta, const double *h, const double *origin)
{
    for (int a = 0; a < f->dim; a++)
        f->h[a] = h[a];
    return meta ? nl_meta_set_origin(meta, f->dim, h, origin) : NL_OK;
}
