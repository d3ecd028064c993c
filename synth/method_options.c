/* The generic options of a synthesis method: defaults, values from text,
 * look-ups (synth/method.h). */
#include "method_internal.h"
#include "../core/nl_error.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int nl_method_option_index(const nl_method_type *t, const char *name)
{
    for (int k = 0; t && name && k < t->noptions; k++)
        if (!strcmp(t->options[k].name, name))
            return k;
    return -1;
}

/* The index of `s` among the '|'-separated words (prefix: s begins with the
 * word, its length in *len), or -1. */
static int word_index(const char *words, const char *s, int prefix, size_t *len)
{
    const char *w = words;
    for (int i = 0; w && *w; i++) {
        size_t n = strcspn(w, "|");
        if (prefix ? !strncmp(s, w, n) : strlen(s) == n && !strncmp(s, w, n)) {
            *len = n;
            return i;
        }
        w += n + (w[n] == '|');
    }
    return -1;
}

static int set_int(const nl_method_option *r, nl_method_value *v, const char *s, const char *label)
{
    char *end;
    unsigned long long x;
    size_t n;
    if (r->words && word_index(r->words, s, 0, &n) == 0) {
        v->i = 0;
        return NL_OK;
    }
    errno = 0;
    x = strtoull(s, &end, 10);
    if (*s < '0' || *s > '9' || *end || errno || x < (unsigned long long)r->min)
        return NL_ERROR(NL_EINVAL, "%s: expected an integer >= %.0f, got \"%s\"", label, r->min, s);
    if (x > (unsigned long long)r->max)
        return NL_ERROR(NL_EINVAL, "%s: expected %.0f to %.0f, got \"%s\"", label, r->min, r->max, s);
    v->i = (long)x;
    return NL_OK;
}

static int set_double(const nl_method_option *r, nl_method_value *v, const char *s, const char *label)
{
    size_t n = 0;
    int k = r->words ? word_index(r->words, s, 1, &n) : -1;
    const char *num = s + (k >= 0 ? n : 0);
    char *end;
    double x;
    errno = 0;
    x = strtod(num, &end);
    int bad = end == num || *end || !isfinite(x) || (r->words && errno);
    if (bad && !r->words)
        return NL_ERROR(NL_EINVAL, "%s: expected a finite number, got \"%s\"", label, s);
    int open = (r->flags & NL_METHOD_OPEN) != 0;
    if (bad || (open ? !(x > r->min && x < r->max) : !(x >= r->min && x <= r->max)))
        return NL_ERROR(NL_EINVAL, "%s: expected %s, got \"%s\"", label, r->expect, s);
    v->d = x;
    v->i = k;
    return NL_OK;
}

static int set_value(const nl_method_option *r, nl_method_value *v, const char *s, const char *label)
{
    size_t n;
    int st = NL_OK;
    switch (r->type) {
    case NL_METHOD_INT: st = set_int(r, v, s ? s : "", label); break;
    case NL_METHOD_DOUBLE: st = set_double(r, v, s ? s : "", label); break;
    case NL_METHOD_CHOICE:
        if ((v->i = s ? word_index(r->words, s, 0, &n) : -1) < 0)
            st = NL_ERROR(NL_EINVAL, "%s: expected %s, got \"%s\"", label, r->expect, s ? s : "");
        break;
    case NL_METHOD_FLAG: v->i = 1; break;
    case NL_METHOD_STRING: v->s = s, v->field = NULL; break;
    }
    return st;
}

void nl_method_options_default(const nl_method_type *t, nl_method_options *o)
{
    memset(o, 0, sizeof *o);
    o->type = t;
    for (int k = 0; k < t->noptions; k++)
        if (t->options[k].def && !set_value(&t->options[k], &o->v[k], t->options[k].def, t->options[k].name))
            o->v[k].set = 1;
}

int nl_method_options_set(nl_method_options *o, const char *name, const char *text, const char *label)
{
    int k = nl_method_option_index(o->type, name), st;
    if (k < 0)
        return NL_ERROR(NL_EINVAL, "%s: synth %s takes no such option", label ? label : name,
                        o->type ? o->type->name : "(none)");
    if ((st = set_value(&o->type->options[k], &o->v[k], text, label ? label : name)))
        return st;
    o->v[k].set = 2;
    return NL_OK;
}

const nl_method_value *nl_method_options_get(const nl_method_options *o, const char *name)
{
    int k = nl_method_option_index(o->type, name);
    return k < 0 ? NULL : &o->v[k];
}

int nl_method_options_given(const nl_method_options *o, const char *name)
{
    const nl_method_value *v = nl_method_options_get(o, name);
    return v && v->set == 2;
}

int nl_method_opt_set(const nl_method_options *o, const char *name)
{
    const nl_method_value *v = nl_method_options_get(o, name);
    return v && v->set;
}

long nl_method_opt_int(const nl_method_options *o, const char *name)
{
    const nl_method_value *v = nl_method_options_get(o, name);
    return v && v->set ? v->i : 0;
}

double nl_method_opt_double(const nl_method_options *o, const char *name)
{
    const nl_method_value *v = nl_method_options_get(o, name);
    return v && v->set ? v->d : 0.0;
}

const char *nl_method_opt_string(const nl_method_options *o, const char *name)
{
    const nl_method_value *v = nl_method_options_get(o, name);
    return v && v->set ? v->s : NULL;
}
