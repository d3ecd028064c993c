/* Sums and products of structures, "A + B * C" (core/model.h, "Sums and
 * products"): splitting a spec into its structures, the sum and product
 * nodes, and their R and S.  R of a sum is the sum of its terms' R, of a
 * product their product (both covariances when every term is: Schur's
 * product theorem for the product); S of a sum is the sum of the terms'
 * closed-form spectra. */
#include "model_internal.h"
#include "nl_error.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Is the '+' at spec[i] part of a number: a sign after '=', or the sign of
 * an exponent (an e or E that follows a digit or a '.')? */
static int in_number(const char *spec, size_t i)
{
    char c = i > 0 ? spec[i - 1] : 0;
    if (c == '=')
        return 1;
    return (c == 'e' || c == 'E') && i > 1 && (isdigit((unsigned char)spec[i - 2]) || spec[i - 2] == '.');
}

/* The end of the structure that starts at spec[start]: the offset of the
 * next operator between structures, or of the terminating NUL.  An
 * argument family's argument (expr:, spectrum:, image:) runs to its ';' or
 * to the end of the spec. */
static int structure_end(const char *spec, size_t start, size_t *end)
{
    size_t i = start + strspn(spec + start, " \t"), nlen = strcspn(spec + i, ":+* \t");
    const nl_family *f = nl_family_find(spec + i, nlen);
    if (f && (f->flags & NL_FAMILY_ARGUMENT) && spec[i + nlen] == ':') {
        const char *semi = strchr(spec + i + nlen, ';');
        if (!semi) {
            *end = strlen(spec);
            return NL_OK;
        }
        i = (size_t)(semi - spec) + 1;
    }
    for (; spec[i]; i++) {
        if (spec[i] == '(' || spec[i] == ')')
            return NL_ERROR(NL_EINVAL, "model: parentheses are not taken between structures, got \"%s\" "
                            "(write the products out: A*B + A*C; '*' binds before '+')", spec);
        if (spec[i] == '*' || (spec[i] == '+' && !in_number(spec, i)))
            break;
    }
    *end = i;
    return NL_OK;
}

int nl_model_spec_is_composite(const char *spec, int *yes)
{
    size_t end;
    int st = structure_end(spec, 0, &end);
    *yes = !st && spec[end] != 0;
    return st;
}

double nl_model_composite_acf(const nl_model *m, int dim, const double *lag)
{
    int sum = m->fam == &nl_family_sum;
    double v = sum ? 0 : 1;
    for (size_t i = 0; i < m->nterms; i++) {
        double r = nl_model_acf(m->terms[i], dim, lag);
        v = sum ? v + r : v * r;
    }
    return v;
}

/* The sum of the terms' closed-form spectra; NAN where any has none, and
 * for a product (a convolution of spectra). */
static double composite_spectrum(const nl_model *m, int dim, const double *f)
{
    double v = 0;
    if (m->fam != &nl_family_sum)
        return NAN;
    for (size_t i = 0; i < m->nterms; i++)
        v += nl_model_spectrum(m->terms[i], dim, f);
    return v;
}

static int composite_isotropic(const nl_model *m)
{
    for (size_t i = 0; i < m->nterms; i++)
        if (!nl_model_is_isotropic(m->terms[i]))
            return 0;
    return 1;
}

static int composite_check_dim(const nl_model *m, int dim)
{
    for (size_t i = 0; i < m->nterms; i++) {
        int st = nl_model_check_dim(m->terms[i], dim);
        if (st)
            return st;
    }
    return NL_OK;
}

static double composite_d2(const nl_model *m, double t)
{
    double v = 0;
    if (m->fam != &nl_family_sum)
        return NAN;
    for (size_t i = 0; i < m->nterms; i++)
        v += nl_model_acf_d2(m->terms[i], t);
    return v;
}

const nl_family nl_family_sum = {
    .name = "sum",
    .aliases = "",
    .formula = "R = R_1 + R_2 + ...",
    .flags = NL_FAMILY_COMPOSITE,
    .validity = "positive definite where every term is",
    .acf = nl_model_composite_acf,
    .spectrum = composite_spectrum,
    .isotropic = composite_isotropic,
    .check_dim = composite_check_dim,
    .acf_d2 = composite_d2,
};

const nl_family nl_family_product = {
    .name = "product",
    .aliases = "",
    .formula = "R = R_1 R_2 ...",
    .flags = NL_FAMILY_COMPOSITE,
    .validity = "positive definite where every factor is (Schur's product theorem)",
    .acf = nl_model_composite_acf,
    .spectrum = composite_spectrum,
    .isotropic = composite_isotropic,
    .check_dim = composite_check_dim,
    .acf_d2 = composite_d2,
};

/* A sum or product node over terms[0..n-1] (taken over: freed with the
 * node, also on failure), spec its text. */
static int make_node(const nl_family *fam, const char *spec, size_t len, nl_model **terms, size_t n,
                     nl_model **out)
{
    nl_model *m = calloc(1, sizeof *m);
    *out = NULL;
    if (!m || !(m->spec = strndup(spec, len)) || !(m->terms = malloc(n * sizeof *m->terms))) {
        if (m)
            free(m->spec);
        free(m);
        for (size_t i = 0; i < n; i++)
            nl_model_free(terms[i]);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    memcpy(m->terms, terms, n * sizeof *terms);
    m->nterms = n;
    m->fam = fam;
    m->ratio = m->zratio = 1;
    m->var = fam == &nl_family_sum ? 0 : 1;
    for (size_t i = 0; i < n; i++) {
        m->var = fam == &nl_family_sum ? m->var + terms[i]->var : m->var * terms[i]->var;
        m->nugget += nl_model_nugget(terms[i]);
        m->scale = fmax(m->scale, terms[i]->scale);
    }
    *out = m;
    return NL_OK;
}

/* One structure, spec[start..end) less its blanks, into *out; i its
 * position (from 1) for messages. */
static int parse_structure(const char *spec, size_t start, size_t end, size_t i, nl_model **out)
{
    char *s;
    int st;
    while (start < end && isspace((unsigned char)spec[start]))
        start++;
    while (end > start && isspace((unsigned char)spec[end - 1]))
        end--;
    *out = NULL;
    if (start == end)
        return NL_ERROR(NL_EINVAL, "model: structure %zu of \"%s\" is empty (expected STRUCTURE + STRUCTURE * "
                        "STRUCTURE ..., e.g. markov:scale=8 + gauss:scale=2,var=0.5)", i, spec);
    {
        /* a file read by parsing: `synth --from` reads a recorded file only
         * when the user names it, which it checks of a spec's first family */
        const nl_family *f = nl_family_find(spec + start, strcspn(spec + start, ": \t"));
        if (f && (f->flags & NL_FAMILY_FILE))
            return NL_ERROR(NL_EINVAL, "model: structure %zu of \"%s\" reads a file (%s:): sums and products "
                            "take models defined by a formula or an expression", i, spec, f->name);
    }
    if (!(s = strndup(spec + start, end - start)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    st = nl_model_parse(s, out);
    if (!st && nl_model_is_spectral(*out)) {
        st = NL_ERROR(NL_EINVAL, "model: structure %zu of \"%s\" (%s) is defined by its spectrum: sums and "
                      "products take models defined by R", i, spec, s);
        nl_model_free(*out);
        *out = NULL;
    }
    free(s);
    return st;
}

/* Terms s[0..n-1] joined by ops[0..n-2] into a sum of products. */
static int group(const char *spec, const size_t *at, nl_model **s, const char *ops, size_t n, nl_model **out)
{
    nl_model *sum[NL_MODEL_MAX_STRUCTURES];
    size_t ns = 0, first = 0, len = strlen(spec);
    int st = NL_OK;
    for (size_t i = 0; i < n; i++) {
        if (i + 1 < n && ops[i] == '*')
            continue;
        /* s[first..i] is one product */
        for (size_t k = first; k <= i; k++)
            if (i > first && nl_model_nugget(s[k]) != 0 && !st)
                st = NL_ERROR(NL_EINVAL, "model: a nugget inside a product (structure %zu of \"%s\"): expected "
                              "nuggets as terms of the sum (white noise times a structure is white noise)",
                              k + 1, spec);
            else if (i > first && nl_model_is_intrinsic(s[k]) && !st)
                st = NL_ERROR(NL_EINVAL, "model: an intrinsic model inside a product (structure %zu of \"%s\"): "
                              "a variogram times a covariance need not be a variogram; expected it as a term of "
                              "the sum", k + 1, spec);
        if (st) {
            for (size_t k = first; k <= i; k++)
                nl_model_free(s[k]);
        } else if (i > first) {
            size_t b = first ? at[first - 1] + 1 : 0, e = i + 1 < n ? at[i] : len;
            st = make_node(&nl_family_product, spec + b, e - b, s + first, i + 1 - first, &sum[ns]);
            ns += !st;
        } else
            sum[ns++] = s[i];
        first = i + 1;
    }
    if (st) {
        for (size_t k = 0; k < ns; k++)
            nl_model_free(sum[k]);
        return st;
    }
    if (ns == 1) {
        /* one product: the whole spec */
        free(sum[0]->spec);
        if (!(sum[0]->spec = strdup(spec))) {
            nl_model_free(sum[0]);
            return NL_ERROR(NL_ENOMEM, "out of memory");
        }
        *out = sum[0];
        return NL_OK;
    }
    return make_node(&nl_family_sum, spec, len, sum, ns, out);
}

int nl_model_parse_composite(const char *spec, nl_model **out)
{
    nl_model *s[NL_MODEL_MAX_STRUCTURES];
    size_t at[NL_MODEL_MAX_STRUCTURES], n = 0, start = 0, end;
    char ops[NL_MODEL_MAX_STRUCTURES];
    int st = NL_OK;
    *out = NULL;
    for (;;) {
        if ((st = structure_end(spec, start, &end)))
            break;
        if (n == NL_MODEL_MAX_STRUCTURES) {
            st = NL_ERROR(NL_EINVAL, "model: more than %d structures in \"%.60s...\"; expected at most %d",
                          NL_MODEL_MAX_STRUCTURES, spec, NL_MODEL_MAX_STRUCTURES);
            break;
        }
        if ((st = parse_structure(spec, start, end, n + 1, &s[n])))
            break;
        n++;
        if (!spec[end])
            break;
        ops[n - 1] = spec[end];
        at[n - 1] = end;
        start = end + 1;
    }
    if (st) {
        for (size_t i = 0; i < n; i++)
            nl_model_free(s[i]);
        return st;
    }
    return group(spec, at, s, ops, n, out);
}

size_t nl_model_structures(const nl_model *m)
{
    size_t n = 0;
    if (!m->nterms)
        return 1;
    for (size_t i = 0; i < m->nterms; i++)
        n += nl_model_structures(m->terms[i]);
    return n;
}

const nl_model *nl_model_structure(const nl_model *m, size_t i)
{
    if (!m->nterms)
        return i == 0 ? m : NULL;
    for (size_t k = 0; k < m->nterms; k++) {
        size_t c = nl_model_structures(m->terms[k]);
        if (i < c)
            return nl_model_structure(m->terms[k], i);
        i -= c;
    }
    return NULL;
}

char nl_model_operator(const nl_model *m, size_t i)
{
    for (size_t k = 0; k < m->nterms; k++) {
        size_t c = nl_model_structures(m->terms[k]);
        if (i < c) {
            char op = nl_model_operator(m->terms[k], i);
            if (op || i + 1 < c)
                return op;
            return k + 1 < m->nterms ? (m->fam == &nl_family_sum ? '+' : '*') : 0;
        }
        i -= c;
    }
    return 0;
}

/* White noise alone: a structure of the nugget family (one parameter, the
 * nugget's; not an expression, whose one key is its nugget too). */
static int white_noise(const nl_model *s)
{
    const nl_family *f = nl_model_family(s);
    return f->nparams == 1 && f->params[0].role == NL_ROLE_NUGGET &&
           !(f->flags & (NL_FAMILY_SPECTRAL | NL_FAMILY_ARGUMENT | NL_FAMILY_INTRINSIC));
}

const nl_model *nl_model_intrinsic_structure(const nl_model *m)
{
    const nl_model *found = NULL;
    if (!m->nterms)
        return nl_model_is_intrinsic(m) ? m : NULL;
    if (m->fam != &nl_family_sum)
        return NULL;
    for (size_t i = 0; i < m->nterms; i++) {
        const nl_model *t = m->terms[i];
        if (t->nterms)
            return NULL;
        if (nl_model_is_intrinsic(t)) {
            if (found)
                return NULL;
            found = t;
        } else if (!white_noise(t))
            return NULL;
    }
    return found;
}
