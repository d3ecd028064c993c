/* libmatheval's syntax rewritten for muParser (core/expr_internal.h):
 * the tokens are libmatheval's (lib/scanner.l of 1.1.11: numbers
 * ({d}+|{d}+.{d}*|{d}*.{d}+)([Ee][+-]?{d}+)?, identifiers [_a-zA-Z][_a-zA-Z0-9]*,
 * the longest match first, so 2_pi is one constant), and muParser receives
 * only names it was given: _kI for each number and constant (its value read
 * here with strtod, as libmatheval's atof did), _vI for each variable, the
 * function names of core/expr_funcs.c, # (a left-associative power, as
 * libmatheval's bison grammar has %left '^'), + - * / ( ) and ','. */
#include "expr_internal.h"
#include "nl_error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    nl_expr_lexed *l;
    size_t cap;        /* capacity of l->out and l->map */
    size_t len;        /* characters written */
    size_t capc, capv; /* capacities of consts and vars */
} sink;

static int ident(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

/* Append txt[0..n-1], which came from text index `from`; a space first
 * where two names would run together. */
static int put(sink *s, const char *txt, size_t n, size_t from)
{
    if (n && s->len && ident(s->l->out[s->len - 1]) && ident(txt[0])) {
        int st = put(s, " ", 1, from);
        if (st)
            return st;
    }
    if (s->len + n + 1 > s->cap) {
        size_t cap = 2 * (s->len + n + 1) + 64;
        char *o = realloc(s->l->out, cap);
        size_t *m;
        if (!o)
            return NL_ERROR(NL_ENOMEM, "out of memory");
        s->l->out = o;
        if (!(m = realloc(s->l->map, cap * sizeof *m)))
            return NL_ERROR(NL_ENOMEM, "out of memory");
        s->l->map = m;
        s->cap = cap;
    }
    memcpy(s->l->out + s->len, txt, n);
    for (size_t i = 0; i < n; i++)
        s->l->map[s->len + i] = from;
    s->len += n;
    s->l->out[s->len] = 0;
    s->l->map[s->len] = from;
    return NL_OK;
}

static int put_const(sink *s, double v, size_t from)
{
    char name[32];
    nl_expr_lexed *l = s->l;
    if (l->nconsts == s->capc) {
        double *c = realloc(l->consts, (2 * s->capc + 8) * sizeof *c);
        if (!c)
            return NL_ERROR(NL_ENOMEM, "out of memory");
        l->consts = c, s->capc = 2 * s->capc + 8;
    }
    l->consts[l->nconsts] = v;
    return put(s, name, (size_t)snprintf(name, sizeof name, "_k%zu", l->nconsts++), from);
}

static int put_var(sink *s, const char *w, size_t n, size_t from)
{
    char name[32];
    nl_expr_lexed *l = s->l;
    size_t i = 0;
    while (i < l->nvars && !(strlen(l->vars[i]) == n && memcmp(l->vars[i], w, n) == 0))
        i++;
    if (i == l->nvars) {
        if (l->nvars == s->capv) {
            char **v = realloc(l->vars, (2 * s->capv + 8) * sizeof *v);
            if (!v)
                return NL_ERROR(NL_ENOMEM, "out of memory");
            l->vars = v, s->capv = 2 * s->capv + 8;
        }
        if (!(l->vars[i] = strndup(w, n)))
            return NL_ERROR(NL_ENOMEM, "out of memory");
        l->nvars++;
    }
    /* the name itself where it cannot meet one of ours (_kI, _vI) */
    if (w[0] != '_' && n <= 64)
        return put(s, w, n, from);
    return put(s, name, (size_t)snprintf(name, sizeof name, "_v%zu", i), from);
}

static int digit(char c) { return c >= '0' && c <= '9'; }
static int letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

/* Length of the number at p (libmatheval's regex), 0 if none. */
static size_t number_len(const char *p)
{
    size_t i = 0, d = 0;
    while (digit(p[i]))
        i++, d++;
    if (p[i] == '.') {
        i++;
        while (digit(p[i]))
            i++, d++;
    }
    if (!d)
        return 0;
    if (p[i] == 'e' || p[i] == 'E') {
        size_t j = i + 1;
        if (p[j] == '+' || p[j] == '-')
            j++;
        if (digit(p[j])) {
            while (digit(p[j]))
                j++;
            i = j;
        }
    }
    return i;
}

static const nl_expr_const *find_const(const char *w, size_t n)
{
    size_t nc;
    const nl_expr_const *c = nl_expr_consts(&nc);
    for (size_t i = 0; i < nc; i++)
        if (strlen(c[i].name) == n && memcmp(c[i].name, w, n) == 0)
            return &c[i];
    return NULL;
}

/* The longest constant spelled from p (2_sqrtpi, 1_pi start with a digit). */
static const nl_expr_const *const_at(const char *p, size_t *len)
{
    size_t nc;
    const nl_expr_const *c = nl_expr_consts(&nc), *best = NULL;
    *len = 0;
    for (size_t i = 0; i < nc; i++) {
        size_t k = strlen(c[i].name);
        if (k > *len && strncmp(p, c[i].name, k) == 0)
            best = &c[i], *len = k;
    }
    return best;
}

static int is_function(const char *w, size_t n)
{
    size_t n1, n2;
    const nl_expr_fun1 *f1 = nl_expr_funs1(&n1);
    const nl_expr_fun2 *f2 = nl_expr_funs2(&n2);
    for (size_t i = 0; i < n1; i++)
        if (strlen(f1[i].name) == n && memcmp(f1[i].name, w, n) == 0)
            return 1;
    for (size_t i = 0; i < n2; i++)
        if (strlen(f2[i].name) == n && memcmp(f2[i].name, w, n) == 0)
            return 1;
    return 0;
}

static const char *skip_space(const char *p)
{
    while (*p == ' ' || *p == '\t')
        p++;
    return p;
}

/* An identifier at text + i of length n. */
static int word(sink *s, const char *what, const char *text, size_t i, size_t n)
{
    const char *w = text + i;
    const nl_expr_const *c = find_const(w, n);
    if (c)
        return put_const(s, c->value, i);
    int call = *skip_space(w + n) == '(';
    if (is_function(w, n)) {
        if (!call)
            return NL_ERROR(NL_EINVAL, "%s: function \"%.*s\" at position %zu takes its arguments in parentheses, "
                            "e.g. %.*s(t)", what, (int)n, w, i + 1, (int)n, w);
        return put(s, w, n, i); /* muParser wants the '(' right after the name: spaces are dropped */
    }
    if (call) {
        char list[640];
        nl_expr_function_names(list, sizeof list);
        return NL_ERROR(NL_EINVAL, "%s: unknown function \"%.*s\" at position %zu (expected one of %s)", what, (int)n, w,
                        i + 1, list);
    }
    return put_var(s, w, n, i);
}

/* A run of signs where an operand is expected: -(-x) = x exactly, so an
 * even count of '-' is dropped and an odd count is one '-'. */
static size_t signs(sink *s, const char *text, size_t i, int *st)
{
    size_t j = i, minus = 0;
    while (text[j] == '-' || text[j] == '+' || text[j] == ' ' || text[j] == '\t')
        minus += text[j++] == '-';
    *st = minus % 2 ? put(s, "-", 1, i) : NL_OK;
    return j;
}

int nl_expr_lex(const char *what, const char *text, nl_expr_lexed *l)
{
    sink s = {.l = l};
    int st = NL_OK, operand = 1; /* an operand is expected (unary position) */
    size_t i = 0;
    memset(l, 0, sizeof *l);
    st = put(&s, "", 0, 0);
    while (!st && text[i]) {
        char c = text[i];
        size_t n, k;
        const nl_expr_const *dc;
        if (c == ' ' || c == '\t') {
            i++;
        } else if (operand && (c == '-' || c == '+')) {
            i = signs(&s, text, i, &st);
        } else if (digit(c) || c == '.') {
            n = number_len(text + i);
            dc = const_at(text + i, &k);
            if (dc && k > n)
                st = put_const(&s, dc->value, i), n = k;
            else if (n)
                st = put_const(&s, strtod(text + i, NULL), i);
            else
                return NL_ERROR(NL_EINVAL, "%s: unexpected '.' at position %zu; expected a number such as 0.5", what,
                                i + 1);
            i += n, operand = 0;
        } else if (letter(c)) {
            n = 1;
            while (letter(text[i + n]) || digit(text[i + n]))
                n++;
            st = word(&s, what, text, i, n);
            i += n, operand = 0;
        } else {
            char one = c == '^' ? '#' : c;
            st = put(&s, &one, 1, i);
            operand = c != ')';
            i++;
        }
    }
    return st;
}

void nl_expr_lexed_free(nl_expr_lexed *l)
{
    for (size_t i = 0; i < l->nvars; i++)
        free(l->vars[i]);
    free(l->vars), free(l->consts), free(l->out), free(l->map);
    memset(l, 0, sizeof *l);
}
