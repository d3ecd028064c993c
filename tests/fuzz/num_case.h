/* The structured input of the number-path fuzz targets (fuzz_num.c and
 * fuzz_synthcli.c): the fuzzer's bytes decoded into a synthesis case (a
 * method, a model spec with each parameter absent or drawn from a table of
 * hostile but parseable numbers, anisotropy options, a tiny size, a
 * spacing and the method's options), so that every input reaches the
 * numbers after the parser.  Included once per target: everything here is
 * static. */
#ifndef NL_FUZZ_NUM_CASE_H
#define NL_FUZZ_NUM_CASE_H

#include "../../core/family.h"
#include "../../synth/method.h"

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Hostile but parseable numbers (as text, so the library and the command
 * line see the same value). */
static const char *const num[] = {
    "0",      "-0",     "1",     "-1",    "0.5",   "2",      "1e-300", "4.9e-324", "2.2250738585072014e-308",
    "1e308",  "1.7976931348623157e308", "-1e308",  "1e-8",   "1e8",    "1e80",     "1e-80",
    "2.0000000000000004", "1.9999999999999998", "0.001", "100", "1000", "50", "1e15", "3", "0.25",
    "7",      "64",     "-2",    "1e-5",  "0.99999999", "1.0000001", "1e4", "nan", "inf", "-inf", "4",
    "1e-3",   "200",    "0.1",   "12",    "1e6",   "1e7",    "8193",   "4096",     "1e-12",  "90", "-45"};
enum { NNUM = sizeof num / sizeof *num };

/* Small integers for integer options (levels, neighbourhoods, radii, ...). */
static const char *const ints[] = {"0", "1", "2", "3", "4", "5", "6", "7", "8", "12", "16", "17", "30", "31", "64",
                                   "256", "4096", "4097", "-1", "2147483647"};
static const char *const exprs[] = {"exp(-abs(t)/%s)", "%s*exp(-t^2)", "exp(-abs(t)^%s)", "cos(%s*t)*exp(-abs(t))",
                                    "1/(1+(t/%s)^2)",  "sin(%s*t)/t", "1-abs(t)/%s",      "exp(-r/%s)*(1+r/%s)",
                                    "exp(-abs(x)/%s-abs(y))"};
static const char *const spectra[] = {"exp(-(f/%s)^2)", "1/(1+(%s*f)^2)", "abs(f)^-%s", "%s", "exp(-k*%s)",
                                      "1/(1+(k/%s)^2)^2", "1/f"};

typedef struct {
    const uint8_t *p;
    size_t left;
} bytes;

static unsigned take(bytes *b)
{
    if (!b->left)
        return 0;
    b->left--;
    return *b->p++;
}

static const char *pick_num(bytes *b) { return num[take(b) % NNUM]; }

typedef struct {
    const nl_method_type *method;         /* a method of the registry that takes a model */
    int dim;
    size_t n[3];
    const char *h;
    char model[512];
    uint64_t seed;
    int clamp;
    const char *opt[NL_METHOD_MAX_OPTIONS]; /* each option's value as text ("" for a flag), or NULL: not given */
    long origin[2];                       /* windows of the methods that make them */
} fcase;

/* Window origins, near the integer limits too. */
static const long origins[] = {0, -1, 7, 1000, -100000, 1L << 40, -(1L << 40), LONG_MAX - 5, LONG_MIN + 5, LONG_MAX};

static void add(char *s, size_t cap, const char *fmt, const char *a, const char *v)
{
    size_t k = strlen(s);
    snprintf(s + k, cap - k, fmt, a, v);
}

static void decode_model(bytes *b, char *s, size_t cap)
{
    unsigned k = take(b) % 10;
    if (k >= 7 && k <= 8) {
        const char *t = k == 7 ? exprs[take(b) % (sizeof exprs / sizeof *exprs)]
                               : spectra[take(b) % (sizeof spectra / sizeof *spectra)];
        const char *v = pick_num(b);
        char body[256];
        snprintf(body, sizeof body, t, v, v);
        snprintf(s, cap, "%s:%s", k == 7 ? "expr" : "spectrum", body);
        if (take(b) & 1) /* options after a ';' */
            add(s, cap, ";%s=%s", take(b) & 1 ? "var" : "ratio", pick_num(b));
        return;
    }
    /* a named family of the registry, with its own parameters (besides
     * var, scale and the nugget): required ones always, others at random */
    const nl_family *f;
    do
        f = nl_family_get(take(b) % nl_family_count());
    while (f->flags & NL_FAMILY_ARGUMENT);
    snprintf(s, cap, "%s", f->name);
    char sep = ':';
    for (size_t i = 0; i < f->nparams; i++) {
        const nl_family_param *p = &f->params[i];
        unsigned c = take(b);
        if (p->role != NL_ROLE_SHAPE && p->role != NL_ROLE_BAND)
            continue;
        if (p->placeholder || (c & 1)) {
            char key[16];
            snprintf(key, sizeof key, "%c%s", sep, p->name);
            add(s, cap, "%s=%s", key, num[(c >> 1) % NNUM]);
            sep = ',';
        }
    }
    static const char *const opt[] = {"var", "scale", "angle", "ratio", "zratio"};
    unsigned mask = take(b);
    for (int i = 0; i < 5; i++)
        if (mask & (1u << i)) {
            char key[16];
            snprintf(key, sizeof key, "%c%s", sep, opt[i]);
            add(s, cap, "%s=%s", key, pick_num(b));
            sep = ',';
        }
    if (mask & 0x20)
        add(s, cap, "%s%s", sep == ':' ? ":" : ",", "sep");
}

/* The k-th method (modulo their number) of those taking a model. */
static const nl_method_type *pick_method(unsigned k)
{
    int n = 0;
    for (int i = 0; i < nl_method_count(); i++)
        n += (nl_method_at(i)->caps & NL_METHOD_MODEL) != 0;
    k %= (unsigned)n;
    for (int i = 0;; i++)
        if ((nl_method_at(i)->caps & NL_METHOD_MODEL) && k-- == 0)
            return nl_method_at(i);
}

/* Each option of the method given or not, its value by type: hostile
 * numbers, small integers, any choice, flags; text options (expressions,
 * files) are left out. */
static void decode_options(bytes *b, fcase *c)
{
    const nl_method_type *t = c->method;
    for (int k = 0; k < t->noptions; k++) {
        const nl_method_option *r = &t->options[k];
        unsigned x = take(b);
        c->opt[k] = NULL;
        if (!(x & 1) || r->type == NL_METHOD_STRING)
            continue;
        if (r->type == NL_METHOD_FLAG)
            c->opt[k] = "";
        else if (r->type == NL_METHOD_INT)
            c->opt[k] = x & 2 ? pick_num(b) : ints[(x >> 2) % (sizeof ints / sizeof *ints)];
        else if (r->type == NL_METHOD_DOUBLE)
            c->opt[k] = pick_num(b);
        else { /* a choice: its word, kept in a static table of the method's words */
            static char words[NL_METHOD_MAX_OPTIONS][64];
            const char *w = r->words;
            for (unsigned i = (x >> 1) % 4; i > 0 && strchr(w, '|'); i--)
                w = strchr(w, '|') + 1;
            snprintf(words[k], sizeof words[k], "%.*s", (int)strcspn(w, "|"), w);
            c->opt[k] = words[k];
        }
    }
}

static void decode(const uint8_t *data, size_t size, fcase *c)
{
    bytes b = {data, size};
    memset(c, 0, sizeof *c);
    c->method = pick_method(take(&b));
    c->dim = 1 + take(&b) % 3;
    for (int a = 0; a < 3; a++)
        c->n[a] = a < c->dim ? 1 + take(&b) % (c->dim == 3 ? 8 : 32) : 1;
    c->h = take(&b) & 1 ? pick_num(&b) : "1";
    decode_model(&b, c->model, sizeof c->model);
    c->seed = take(&b);
    c->clamp = take(&b) & 1;
    decode_options(&b, c);
    unsigned w = take(&b);
    if (c->method->caps & NL_METHOD_WINDOW) {
        c->origin[0] = origins[(w & 15) % (sizeof origins / sizeof *origins)];
        c->origin[1] = origins[(w >> 4) % (sizeof origins / sizeof *origins)];
    }
    if (c->method->caps & NL_METHOD_SERIAL) /* a dense factor in the plan (Cholesky): at most 256 samples */
        while (c->n[0] * c->n[1] * c->n[2] > 256)
            for (int a = 0; a < c->dim; a++)
                c->n[a] = c->n[a] > 1 ? c->n[a] / 2 : 1;
}

static void debug(const fcase *c)
{
    if (!getenv("FUZZ_DEBUG"))
        return;
    fprintf(stderr, "case: %s dim %d n %zux%zux%zu h %s model '%s' seed %llu clamp %d origin %ld,%ld",
            c->method->name, c->dim, c->n[0], c->n[1], c->n[2], c->h, c->model, (unsigned long long)c->seed, c->clamp,
            c->origin[0], c->origin[1]);
    for (int k = 0; k < c->method->noptions; k++)
        if (c->opt[k])
            fprintf(stderr, " --%s %s", c->method->options[k].name, c->opt[k]);
    fputc('\n', stderr);
}

/* FUZZ_IGNORE=tag,tag,...: findings already recorded that should not stop
 * an exploration run (tags: METHOD-nonfinite, METHOD-silent, with METHOD a
 * method or nl_acf_full, nl_psd_periodogram, nl_moments_compute, and
 * cli-METHOD-nonfinite, -stdout, -stderr, -leftover).  `make fuzz` sets none. */
static int ignored(const char *what, const char *kind)
{
    const char *list = getenv("FUZZ_IGNORE");
    char tag[64];
    snprintf(tag, sizeof tag, "%s-%s", what, kind);
    for (const char *p = list; p && (p = strstr(p, tag)); p += strlen(tag))
        if ((p == list || p[-1] == ',') && (p[strlen(tag)] == ',' || !p[strlen(tag)]))
            return 1;
    return 0;
}

static void setup(void)
{
    static int done;
    if (done++)
        return;
    setenv("NOISELAB_MEMORY_LIMIT", "16777216", 1);
    setenv("NOISELAB_FFTW", "estimate", 1);
}

#endif
