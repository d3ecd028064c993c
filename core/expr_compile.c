/* Expressions compiled by muParser: see expr_internal.h. */
#include "expr_internal.h"
#include "nl_error.h"

#include <math.h>
#include <muParserDLL.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct nl_expr {
    muParserHandle_t h;  /* the muParser object */
    nl_expr_lexed l;     /* the rewritten text, its constants and variables */
    double *slot;        /* value of _vI, read by muParser at each evaluation */
    size_t *bound;       /* _vI takes values[bound[I]] (nl_expr_bind) */
};

static int allowed(unsigned char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           (c && strchr("_.,+-*/^() \t", c));
}

size_t nl_expr_bad_char(const char *text)
{
    size_t i = 0;
    while (text[i] && allowed((unsigned char)text[i]))
        i++;
    return i;
}

/* `text` with every byte outside printable ASCII written \xHH (at most
 * `size` - 1 bytes, cut with "..."), so that a message stays one line. */
static void escape(const char *text, char *buf, size_t size)
{
    size_t o = 0;
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        char one[8];
        int k = *p >= 0x20 && *p < 0x7f ? snprintf(one, sizeof one, "%c", *p) : snprintf(one, sizeof one, "\\x%02x", *p);
        if (o + (size_t)k + 4 > size) {
            memcpy(buf + o, "...", 4);
            return;
        }
        memcpy(buf + o, one, (size_t)k);
        o += (size_t)k;
    }
    buf[o] = 0;
}

/* muParser's error codes (muParserDef.h, EErrorCodes) in our words. */
static const char *reason(int code)
{
    switch (code) {
    case 0: return "unexpected operator";
    case 1: return "unexpected name";
    case 2: return "unexpected end";
    case 3: return "unexpected ','";
    case 5: return "unexpected number";
    case 6: return "unexpected variable";
    case 7: return "unexpected parenthesis";
    case 11: return "missing parenthesis";
    case 12: return "unexpected function";
    case 14: return "too many arguments";
    case 15: return "too few arguments";
    case 25: return "empty";
    case 37: return "too long (muParser takes at most 20000 characters once rewritten)";
    default: return "not understood";
    }
}

static int parse_error(const char *what, const char *text, const nl_expr *e, const char *why, int pos)
{
    char shown[160];
    size_t len = strlen(e->l.out ? e->l.out : "");
    escape(text, shown, sizeof shown);
    if (pos < 0 || !e->l.map)
        return NL_ERROR(NL_EINVAL, "%s: malformed expression \"%s\": %s", what, shown, why);
    return NL_ERROR(NL_EINVAL, "%s: malformed expression \"%s\": %s at position %zu", what, shown, why,
                    ((size_t)pos <= len ? e->l.map[pos] : strlen(text)) + 1);
}

static double power(double a, double b) { return pow(a, b); }

/* Give muParser our functions, constants, variables and power operator. */
static void define(nl_expr *e)
{
    size_t n1, n2;
    const nl_expr_fun1 *f1 = nl_expr_funs1(&n1);
    const nl_expr_fun2 *f2 = nl_expr_funs2(&n2);
    char name[32];
    mupClearFun(e->h);
    mupClearConst(e->h);
    for (size_t i = 0; i < n1; i++)
        mupDefineFun1(e->h, f1[i].name, f1[i].f, 1);
    for (size_t i = 0; i < n2; i++)
        mupDefineFun2(e->h, f2[i].name, f2[i].f, 1);
    for (size_t i = 0; i < e->l.nconsts; i++) {
        snprintf(name, sizeof name, "_k%zu", i);
        mupDefineConst(e->h, name, e->l.consts[i]);
    }
    for (size_t i = 0; i < e->l.nvars; i++) {
        const char *v = e->l.vars[i];
        if (v[0] == '_' || strlen(v) > 64)
            snprintf(name, sizeof name, "_v%zu", i), v = name;
        mupDefineVar(e->h, v, &e->slot[i]);
    }
    /* muParser's own ^ is right-associative: 2^3^2 would be 512 */
    mupDefineOprt(e->h, "#", power, 7 /* prPOW */, muOPRT_ASCT_LEFT, 1);
}

int nl_expr_create(const char *what, const char *text, nl_expr **out)
{
    size_t at = nl_expr_bad_char(text);
    char c[8];
    nl_expr *e;
    int st = NL_OK, n = 0, failed;
    *out = NULL;
    if (text[at]) {
        char shown[160];
        unsigned char b = (unsigned char)text[at];
        escape(text, shown, sizeof shown);
        if (b > 0x20 && b < 0x7f)
            snprintf(c, sizeof c, "'%c'", b);
        else
            snprintf(c, sizeof c, "\\x%02x", b);
        return NL_ERROR(NL_EINVAL, "%s: unexpected character %s at position %zu of \"%s\"; expected " NL_EXPR_CHARS,
                        what, c, at + 1, shown);
    }
    if (!(e = calloc(1, sizeof *e)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((st = nl_expr_lex(what, text, &e->l))) {
        nl_expr_free(e);
        return st;
    }
    e->slot = calloc(e->l.nvars + 1, sizeof *e->slot);
    e->bound = calloc(e->l.nvars + 1, sizeof *e->bound);
    if (!e->slot || !e->bound || !(e->h = mupCreate(muBASETYPE_FLOAT))) {
        nl_expr_free(e);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    define(e);
    if (mupError(e->h)) {
        nl_expr_free(e);
        return NL_ERROR(NL_ENOMEM, "%s: muParser refused a definition (out of memory?)", what);
    }
    /* muParser compiles at the first evaluation */
    mupSetExpr(e->h, e->l.out);
    failed = mupError(e->h); /* reads and clears the flag */
    if (!failed) {
        mupEvalMulti(e->h, &n);
        failed = mupError(e->h);
    }
    if (failed)
        st = parse_error(what, text, e, reason(mupGetErrorCode(e->h)),
                         mupGetErrorCode(e->h) == 37 || mupGetErrorCode(e->h) == 25 ? -1 : mupGetErrorPos(e->h));
    else if (n != 1)
        st = parse_error(what, text, e, "',' outside the arguments of a function", -1);
    if (st) {
        nl_expr_free(e);
        return st;
    }
    *out = e;
    return NL_OK;
}

void nl_expr_free(nl_expr *e)
{
    if (!e)
        return;
    if (e->h)
        mupRelease(e->h);
    nl_expr_lexed_free(&e->l);
    free(e->slot), free(e->bound), free(e);
}

size_t nl_expr_nvars(const nl_expr *e) { return e->l.nvars; }

const char *nl_expr_var(const nl_expr *e, size_t i) { return e->l.vars[i]; }

const char *nl_expr_bind(nl_expr *e, const char *const *names, size_t n)
{
    for (size_t i = 0; i < e->l.nvars; i++) {
        size_t k = 0;
        while (k < n && strcmp(names[k], e->l.vars[i]))
            k++;
        if (k == n)
            return e->l.vars[i];
    }
    for (size_t i = 0; i < e->l.nvars; i++)
        for (size_t k = 0; k < n; k++)
            if (!strcmp(names[k], e->l.vars[i]))
                e->bound[i] = k;
    return NULL;
}

double nl_expr_eval(nl_expr *e, const double *values)
{
    for (size_t i = 0; i < e->l.nvars; i++)
        e->slot[i] = values[e->bound[i]];
    return mupEval(e->h);
}
