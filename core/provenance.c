/* Provenance: the typed record and its key/value text (core/provenance.h). */
#include "provenance.h"
#include "family.h"
#include "model.h"
#include "nl_error.h"

#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define KEY(k) {#k, offsetof(nl_meta, k), sizeof(((nl_meta *)0)->k)}
static const struct {
    const char *key; /* "model", ... */
    size_t off;      /* offsetof(nl_meta, ...) */
    size_t len;      /* capacity, the NUL included */
} keys[NL_META_NKEYS] = {
    KEY(model), KEY(method), KEY(seed), KEY(spacing), KEY(size), KEY(version), KEY(flags), KEY(origin),
};
#undef KEY

enum { K_MODEL, K_METHOD, K_SEED, K_SPACING, K_SIZE, K_VERSION, K_FLAGS, K_ORIGIN };

const char *nl_meta_key(int i) { return i >= 0 && i < NL_META_NKEYS ? keys[i].key : NULL; }

const char *nl_meta_value(const nl_meta *m, int i)
{
    return i >= 0 && i < NL_META_NKEYS ? (const char *)m + keys[i].off : NULL;
}

size_t nl_meta_capacity(int i) { return i >= 0 && i < NL_META_NKEYS ? keys[i].len : 0; }

char *nl_meta_slot(nl_meta *m, int i) { return i >= 0 && i < NL_META_NKEYS ? (char *)m + keys[i].off : NULL; }

void nl_provenance_init(nl_provenance *p) { memset(p, 0, sizeof *p); }

/* snprintf into key i, counting what would not fit. */
static int put(nl_meta *kv, int i, size_t *at, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static int put(nl_meta *kv, int i, size_t *at, const char *fmt, ...)
{
    va_list ap;
    size_t cap = keys[i].len;
    char *d = (char *)kv + keys[i].off;
    va_start(ap, fmt);
    int k = vsnprintf(d + *at, cap - *at, fmt, ap);
    va_end(ap);
    if (k < 0 || (size_t)k >= cap - *at)
        return NL_ERROR(NL_ETOOBIG, "provenance: the %s does not fit in %zu bytes", keys[i].key, cap - 1);
    *at += (size_t)k;
    return NL_OK;
}

static int check_record(const nl_provenance *p)
{
    if (p->dim < 0 || p->dim > 3 || p->nspacing < 0 || p->nspacing > 3 || p->norigin < 0 || p->norigin > 3)
        return NL_ERROR(NL_EINVAL, "provenance: expected 0 to 3 sizes, spacings and origin numbers, got "
                        "%d, %d and %d", p->dim, p->nspacing, p->norigin);
    for (int a = 0; a < p->dim; a++)
        if (!p->n[a])
            return NL_ERROR(NL_EINVAL, "provenance: size %d is 0; expected at least 1 sample", a);
    for (int a = 0; a < p->nspacing; a++)
        if (!(p->h[a] > 0) || !isfinite(p->h[a]))
            return NL_ERROR(NL_EINVAL, "provenance: spacing %g: expected a positive finite number", p->h[a]);
    if (!memchr(p->model, 0, sizeof p->model) || !memchr(p->method, 0, sizeof p->method) ||
        !memchr(p->flags, 0, sizeof p->flags) || !memchr(p->version, 0, sizeof p->version))
        return NL_ERROR(NL_EINVAL, "provenance: a text member is not NUL-terminated");
    return NL_OK;
}

int nl_provenance_format(const nl_provenance *p, nl_meta *kv)
{
    size_t at[NL_META_NKEYS] = {0};
    int st;
    memset(kv, 0, sizeof *kv);
    if ((st = check_record(p)))
        return st;
    st = put(kv, K_MODEL, &at[K_MODEL], "%s", p->model);
    if (!st)
        st = put(kv, K_METHOD, &at[K_METHOD], "%s", p->method);
    if (!st)
        st = put(kv, K_FLAGS, &at[K_FLAGS], "%s", p->flags);
    if (!st)
        st = put(kv, K_VERSION, &at[K_VERSION], "%s", p->version);
    if (!st && p->has_seed)
        st = put(kv, K_SEED, &at[K_SEED], "%" PRIu64, p->seed);
    for (int a = 0; !st && a < p->nspacing; a++)
        st = put(kv, K_SPACING, &at[K_SPACING], "%s%.17g", a ? "," : "", p->h[a]);
    for (int a = 0; !st && a < p->dim; a++)
        st = put(kv, K_SIZE, &at[K_SIZE], "%s%zu", a ? "x" : "", p->n[a]);
    for (int a = 0; !st && a < p->norigin; a++)
        st = put(kv, K_ORIGIN, &at[K_ORIGIN], "%s%.17g", a ? "," : "", p->origin[a]);
    if (st)
        memset(kv, 0, sizeof *kv);
    return st;
}

/* The refusal of key i's value v: one line, the value quoted. */
static int refuse(int i, const char *v, const char *expected)
{
    char q[84];
    size_t k = 0;
    if (i == K_SEED) /* at most 31 bytes: as given, the message synth --from has always printed */
        return NL_ERROR(NL_EINPUT, "noiselab.%s: expected %s, got \"%s\"", keys[i].key, expected, v);
    for (; v[k] && k < 80; k++) /* a control character would break the line */
        q[k] = (unsigned char)v[k] < 0x20 || v[k] == 0x7f ? '?' : v[k];
    snprintf(q + k, sizeof q - k, "%s", v[k] ? "..." : "");
    return NL_ERROR(NL_EINPUT, "noiselab.%s: expected %s, got \"%s\"", keys[i].key, expected, q);
}

static int parse_seed(const char *v, nl_provenance *p)
{
    char *end;
    unsigned long long s;
    errno = 0;
    s = strtoull(v, &end, 10);
    if (*v < '0' || *v > '9' || *end || errno)
        return refuse(K_SEED, v, "an integer from 0 to 2^64-1");
    p->seed = (uint64_t)s, p->has_seed = 1;
    return NL_OK;
}

static int parse_size(const char *v, nl_provenance *p)
{
    const char *s = v;
    int a = 0;
    for (;; a++) {
        char *end;
        unsigned long long n;
        errno = 0;
        n = (*s >= '0' && *s <= '9') ? strtoull(s, &end, 10) : 0;
        if (a == 3 || !n || errno || n > SIZE_MAX || (*end && *end != 'x'))
            return refuse(K_SIZE, v, "N, NxM or NxMxK with each N >= 1");
        p->n[a] = (size_t)n;
        if (!*end)
            break;
        s = end + 1;
    }
    p->dim = a + 1;
    for (a = p->dim; a < 3; a++)
        p->n[a] = 1;
    return NL_OK;
}

static int parse_spacing(const char *v, nl_provenance *p)
{
    const char *s = v;
    int a = 0;
    for (;; a++) {
        char *end = (char *)s;
        double h = isspace((unsigned char)*s) ? 0 : strtod(s, &end); /* strtod would skip a newline */
        if (a == 3 || !(h > 0) || !isfinite(h) || (*end && *end != ','))
            return refuse(K_SPACING, v, "1 to 3 positive finite numbers separated by commas");
        p->h[a] = h;
        if (!*end)
            break;
        s = end + 1;
    }
    p->nspacing = a + 1;
    return NL_OK;
}

static int parse_origin(const char *v, nl_provenance *p)
{
    const char *s = v;
    int a = 0;
    for (;; a++) {
        char *end = (char *)s;
        double x = isspace((unsigned char)*s) ? NAN : strtod(s, &end);
        if (a == 3 || end == s || !(fabs(x) <= 0x1p53) || (*end && *end != ','))
            return refuse(K_ORIGIN, v, "1 to 3 numbers X[,Y[,Z]] within +-2^53 samples, separated by commas");
        p->origin[a] = x;
        if (!*end)
            break;
        s = end + 1;
    }
    p->norigin = a + 1;
    return NL_OK;
}

/* A text key: copied when it holds no control character. */
static int parse_text(int i, const char *v, char *dst, size_t cap)
{
    for (const unsigned char *c = (const unsigned char *)v; *c; c++)
        if (*c < 0x20 || *c == 0x7f)
            return NL_ERROR(NL_EINPUT, "noiselab.%s: expected text without control characters, got byte 0x%02x "
                            "at %zu", keys[i].key, *c, (size_t)((const char *)c - v));
    snprintf(dst, cap, "%s", v);
    return NL_OK;
}

/* A record is data: a model whose spec names a file (image:FILE) is checked
 * for its family and its text, and the file is not opened. */
static int parse_model(const char *v, nl_provenance *p)
{
    const nl_family *f = nl_family_find(v, strcspn(v, ":"));
    nl_model *m;
    int st;
    if (f && (f->flags & NL_FAMILY_FILE))
        return parse_text(K_MODEL, v, p->model, sizeof p->model);
    st = nl_model_parse(v, &m);
    if (st)
        return st;
    nl_model_free(m);
    snprintf(p->model, sizeof p->model, "%s", v);
    return NL_OK;
}

static int parse_key(int i, const char *v, nl_provenance *p)
{
    switch (i) {
    case K_SEED: return parse_seed(v, p);
    case K_MODEL: return parse_model(v, p);
    case K_SIZE: return parse_size(v, p);
    case K_SPACING: return parse_spacing(v, p);
    case K_ORIGIN: return parse_origin(v, p);
    case K_METHOD: return parse_text(i, v, p->method, sizeof p->method);
    case K_FLAGS: return parse_text(i, v, p->flags, sizeof p->flags);
    default: return parse_text(i, v, p->version, sizeof p->version);
    }
}

int nl_provenance_parse(const nl_meta *kv, unsigned sel, nl_provenance *p)
{
    static const int order[NL_META_NKEYS] = {K_SEED, K_MODEL, K_SIZE, K_SPACING, K_ORIGIN, K_METHOD, K_FLAGS,
                                             K_VERSION};
    nl_provenance_init(p);
    for (int j = 0; j < NL_META_NKEYS; j++) {
        int i = order[j], st;
        const char *v = nl_meta_value(kv, i);
        if (!(sel & (1u << i)))
            continue;
        if (!memchr(v, 0, keys[i].len))
            st = NL_ERROR(NL_EINPUT, "noiselab.%s: expected at most %zu bytes, got a value that fills the record",
                          keys[i].key, keys[i].len - 1);
        else
            st = *v ? parse_key(i, v, p) : NL_OK;
        if (st) {
            nl_provenance_init(p);
            return st;
        }
    }
    return NL_OK;
}
