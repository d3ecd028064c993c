/* The format registry: the list of core/formats/list.h, look-ups, the
 * lists messages print, and nl_field_write's checks and dispatch. */
#include "format.h"
#include "formats/formats_internal.h"
#include "nl_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#define NL_FORMAT(id) extern const nl_format nl_format_##id;
#include "formats/list.h"
#undef NL_FORMAT

static const nl_format *const registry[] = {
#define NL_FORMAT(id) &nl_format_##id,
#include "formats/list.h"
#undef NL_FORMAT
};

size_t nl_format_count(void) { return sizeof registry / sizeof *registry; }

const nl_format *nl_format_get(size_t i) { return i < nl_format_count() ? registry[i] : NULL; }

const nl_format *nl_format_find(const char *name)
{
    for (size_t i = 0; name && i < nl_format_count(); i++)
        if (strcmp(registry[i]->name, name) == 0)
            return registry[i];
    return NULL;
}

/* Does path end in one of the space-separated extensions exts? */
static int has_ext(const char *path, const char *exts)
{
    size_t lp = strlen(path);
    while (*exts) {
        size_t k = strcspn(exts, " ");
        if (k && lp > k && strncasecmp(path + lp - k, exts, k) == 0)
            return 1;
        exts += k + (exts[k] == ' ');
    }
    return 0;
}

const nl_format *nl_format_for_path(const char *path)
{
    for (size_t i = 0; path && i < nl_format_count(); i++)
        if (has_ext(path, registry[i]->extensions))
            return registry[i];
    return NULL;
}

void nl_format_list(int names, char *buf, size_t len)
{
    size_t at = 0;
    if (!len)
        return;
    buf[0] = 0;
    for (size_t i = 0; i < nl_format_count(); i++)
        for (const char *s = names ? registry[i]->name : registry[i]->extensions; *s;) {
            size_t k = strcspn(s, " ");
            int w = snprintf(buf + at, len - at, "%s%.*s", at ? ", " : "", (int)k, s);
            if (w < 0 || (size_t)w >= len - at)
                return;
            at += (size_t)w;
            s += k + (s[k] == ' ');
        }
}

int nl_format_resolve(const char *path, const char *format, const nl_format **out)
{
    char list[256];
    *out = format ? nl_format_find(format) : nl_format_for_path(path);
    if (*out)
        return NL_OK;
    nl_format_list(!!format, list, sizeof list);
    if (format)
        return NL_ERROR(NL_EINVAL, "format \"%s\": unknown; expected one of %s", format, list);
    return NL_ERROR(NL_EINVAL, "%s: unknown extension; expected one of %s (or a format by name)", path, list);
}

/* The value types as words, for messages. */
static const char *precision_name(int p) { return p == 64 ? "float64" : "float32"; }

/* nl_field_write's checks of f and o against format t, before anything is written. */
static int check_write(const nl_format *t, const nl_field *f, const nl_write_options *o, int *prec)
{
    int integer = !(t->types & (NL_FORMAT_F32 | NL_FORMAT_F64));
    if (t->flags & NL_FORMAT_EXTERNAL)
        return NL_ERROR(NL_EINVAL, "format %s: read and written by libnoiselab_mpi (mpi/h5.h), not here", t->name);
    if (t->flags & NL_FORMAT_OFF)
        return NL_ERROR(NL_EINVAL, "format %s: %s", t->name, t->summary);
    if (f->dim < 1 || f->dim > 3 || !(t->dims & (1u << f->dim)))
        return NL_ERROR(NL_EINVAL, "format %s: does not hold %dD fields (it holds %s)", t->name, f->dim,
                        t->dims == 4 ? "2D fields" : t->dims == 8 ? "3D fields" : t->dims == 14 ? "1D, 2D and 3D fields"
                                                                                  : "1D fields");
    *prec = o->precision ? o->precision : t->precision;
    if (o->precision && o->precision != 32 && o->precision != 64)
        return NL_ERROR(NL_EINVAL, "precision %d: expected 32 or 64", o->precision);
    if (!integer && !(t->types & (*prec == 64 ? NL_FORMAT_F64 : NL_FORMAT_F32)))
        return NL_ERROR(NL_EINVAL, "format %s: precision %d: does not store %s samples", t->name, *prec,
                        precision_name(*prec));
    if (!(isfinite(o->lo) && isfinite(o->hi)) || o->lo > o->hi)
        return NL_ERROR(NL_EINVAL, "range %g,%g: expected finite lo < hi", o->lo, o->hi);
    for (size_t i = 0; i < f->count; i++) { /* NaN: a missing value, where a float can hold it */
        double v = f->data[i];
        if (isnan(v) ? integer : !(fabs(v) <= (integer || *prec == 64 ? DBL_MAX : FLT_MAX)))
            return NL_ERROR(NL_EINVAL, "format %s: sample %zu is %g; expected %s", t->name, i, v,
                            integer ? "finite values (no missing-value code)"
                                    : *prec == 64 ? "finite values or NaN" : "values within float32 or NaN");
    }
    return NL_OK;
}

int nl_format_check(const nl_format *t, const nl_field *f, nl_write_options *o)
{
    return check_write(t, f, o, &o->precision);
}

int nl_field_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    static const nl_write_options none;
    nl_write_options w = o ? *o : none;
    const nl_format *t;
    int st;
    if ((st = nl_format_resolve(path, w.format, &t)) || (st = check_write(t, f, &w, &w.precision)))
        return st;
    return t->write(path, f, meta, &w);
}

void nl_format_range(const nl_field *f, const nl_write_options *o, double *lo, double *hi)
{
    if (o && o->lo < o->hi) {
        *lo = o->lo, *hi = o->hi;
        return;
    }
    *lo = *hi = f->data[0];
    for (size_t i = 1; i < f->count; i++) {
        if (f->data[i] < *lo)
            *lo = f->data[i];
        if (f->data[i] > *hi)
            *hi = f->data[i];
    }
    if (!(*hi > *lo))
        *hi = *lo + 1;
}

uint32_t nl_format_code(double v, double lo, double hi, uint32_t top)
{
    double c = (v - lo) / (hi - lo) * top;
    return c <= 0 ? 0 : c >= top ? top : (uint32_t)lrint(c);
}

int nl_format_raw_size(const char *path, size_t count, const nl_read_options *o, int *dim, size_t *n)
{
    if (o && o->dim) {
        size_t c = 1;
        if (o->dim < 1 || o->dim > 3)
            return NL_ERROR(NL_EINVAL, "size: expected 1 to 3 axes, got %d", o->dim);
        for (int a = 0; a < o->dim; a++)
            c *= (n[a] = o->n[a]);
        if (c != count)
            return NL_ERROR(NL_EINPUT, "%s: holds %zu samples; the size given makes %zu", path, count, c);
        *dim = o->dim;
        return NL_OK;
    }
    size_t s = (size_t)llround(sqrt((double)count));
    while (s * s > count)
        s--;
    while ((s + 1) * (s + 1) <= count)
        s++;
    if (s < 2 || s * s != count)
        return NL_ERROR(NL_EINPUT, "%s: a headerless file of %zu samples, not a square; expected a square, or its "
                        "size in the read options (Python's read(size=))", path, count);
    *dim = 2, n[0] = n[1] = s;
    return NL_OK;
}
