/* Planning, executing and describing through a method's descriptor
 * (synth/method.h). */
#include "method_internal.h"
#include "../core/taper_internal.h"
#include "../core/field_stats.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

nl_method_plan *nl_method_plan_head(size_t size, const nl_method_grid *g, const nl_method_options *o)
{
    nl_method_plan *p = calloc(1, size);
    if (!p) {
        NL_ERROR(NL_ENOMEM, "out of memory for a %s plan", o->type->name);
        return NULL;
    }
    p->type = o->type;
    p->grid = *g;
    p->opt = *o;
    return p;
}

int nl_method_check_dim(const nl_method_type *t, const nl_method_grid *g)
{
    if (g->dim < 1 || g->dim > 3 || !(t->dims & (1u << (g->dim - 1))))
        return NL_ERROR(NL_EINVAL, "synth %s: expected a %s --size, got %dD", t->name,
                        t->dims == 3 ? "1D or 2D" : "1D, 2D or 3D", g->dim);
    return NL_OK;
}

int nl_method_plan_alloc(const nl_method_type *t, const nl_model *m, const nl_method_grid *g,
                         const nl_method_options *o, nl_method_plan **out)
{
    int st;
    *out = NULL;
    if (!t || !g || !o || o->type != t)
        return NL_ERROR(NL_EINVAL, "nl_method_plan_alloc: expected a method and its own options");
    if ((st = nl_method_check_dim(t, g)))
        return st;
    if (m && !(t->caps & NL_METHOD_INTRINSIC)) {
        char what[64];
        snprintf(what, sizeof what, "synth %s", t->name);
        if ((st = nl_model_check_stationary(m, what)))
            return st;
    }
    if ((st = t->plan(m, g, o, out)))
        return st;
    /* a model that check finds invalid, refused by every method alike: after
     * the method's own plan, whose refusals say more where they apply (a
     * lag where R is not finite, an embedding that fails) */
    if (m && !(o->flags & NL_METHOD_OPT_CLAMP) && !(t->caps & NL_METHOD_INTRINSIC) &&
        (st = nl_model_sign_check(m, g->dim))) {
        nl_method_plan_free(*out);
        *out = NULL;
    }
    return st;
}

int nl_method_execute(nl_method_plan *p, uint64_t seed, nl_field *f) { return p->type->execute(p, seed, f); }

int nl_method_execute_slab(nl_method_plan *p, uint64_t seed, size_t s0, nl_field *f)
{
    if (!p->type->execute_slab)
        return NL_ERROR(NL_EINVAL, "synth %s: runs on one process (no slab execute)", p->type->name);
    return p->type->execute_slab(p, seed, s0, f);
}

int nl_method_describe(const nl_method_plan *p, char *buf, size_t size) { return p->type->describe(p, buf, size); }

const nl_method_type *nl_method_plan_type(const nl_method_plan *p) { return p->type; }

void *nl_method_plan_impl(const nl_method_plan *p) { return p->impl; }

void nl_method_plan_free(nl_method_plan *p)
{
    if (p)
        p->type->free(p);
}

int nl_method_report_of(const nl_method_plan *p, const nl_model *m, uint64_t seed, const nl_field *f,
                        nl_method_report *r)
{
    double rms = f ? nl_field_rms(f) : 0;
    int st = nl_method_describe(p, r->method, sizeof r->method);
    r->flags[0] = r->json[0] = '\0';
    r->sd = rms > 0 ? rms : 1;
    r->offset = 0;
    return st || !p->type->report ? st : p->type->report(p, m, seed, f, r);
}

int nl_method_json(nl_method_report *r, const char *fmt, ...)
{
    size_t len = strlen(r->json);
    va_list ap;
    int w;
    va_start(ap, fmt);
    w = vsnprintf(r->json + len, sizeof r->json - len, fmt, ap);
    va_end(ap);
    if (w < 0 || (size_t)w >= sizeof r->json - len)
        return NL_ERROR(NL_EINVAL, "method report: longer than %zu bytes", sizeof r->json);
    return NL_OK;
}

/* As a JSON writer writes a real (jansson's 17 digits): read back, the
 * same double. */
const char *nl_method_real(char buf[32], double x)
{
    if (!isfinite(x))
        return "nan";
    snprintf(buf, 32, "%.17g", x);
    if (strspn(buf, "0123456789-") == strlen(buf))
        strcat(buf, ".0");
    return buf;
}

int nl_method_append(char *buf, size_t size, size_t *len, const char *fmt, ...)
{
    va_list ap;
    int w;
    if (*len >= size)
        return NL_ERROR(NL_EINVAL, "method string: longer than %zu bytes", size);
    va_start(ap, fmt);
    w = vsnprintf(buf + *len, size - *len, fmt, ap);
    va_end(ap);
    if (w < 0 || (size_t)w >= size - *len)
        return NL_ERROR(NL_EINVAL, "method string: longer than %zu bytes", size);
    *len += (size_t)w;
    return NL_OK;
}
