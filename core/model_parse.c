/* Parsing of model specs into nl_model, by the family registry
 * (core/family.h). */
#include "expr_internal.h"
#include "families/families_internal.h"
#include "model_internal.h"
#include "nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char aniso_keys[] = "sep angle ratio zratio";

static int parse_number(const char *name, const char *key, const char *s, size_t len, double *v)
{
    char buf[64];
    char *end;
    if (len == 0 || len >= sizeof buf)
        return NL_ERROR(NL_EINVAL, "%s: %.*s: expected a number, got \"%.*s\"", name, (int)strlen(key),
                        key, (int)len, s);
    memcpy(buf, s, len);
    buf[len] = 0;
    *v = strtod(buf, &end);
    if (*end || !isfinite(*v))
        return NL_ERROR(NL_EINVAL, "%s: %s: expected a finite number, got \"%s\"", name, key, buf);
    return NL_OK;
}

/* The keys of a parameter table, space separated, as messages list them. */
static void table_keys(const nl_family_param *params, size_t np, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = 0;
    for (size_t k = 0; k < np && len < size; k++)
        len += (size_t)snprintf(buf + len, size - len, "%s%s", k ? " " : "", params[k].name);
}

/* An anisotropy key: sep, or angle, ratio, zratio with its value. */
static void set_aniso(nl_model *m, const char *key, double v)
{
    if (strcmp(key, "sep") == 0)
        m->sep = 1;
    else if (strcmp(key, "angle") == 0)
        m->angle = v * M_PI / 180.0;
    else if (strcmp(key, "ratio") == 0)
        m->ratio = v;
    else if (strcmp(key, "zratio") == 0)
        m->zratio = v;
    m->aniso_given = 1;
}

static int table_index(const nl_family_param *params, size_t np, const char *key)
{
    for (size_t k = 0; k < np; k++)
        if (strcmp(params[k].name, key) == 0)
            return (int)k;
    return -1;
}

/* "k=v,k=v,sep": the keys of the table params[0..np-1] into vals[], the
 * anisotropy keys into m; `name` (the family's or a peer's) begins the
 * messages. */
static int parse_keys(nl_model *m, const char *name, const nl_family_param *params, size_t np, double *vals,
                      const char *s)
{
    while (*s) {
        size_t len = strcspn(s, ",");
        const char *eq = memchr(s, '=', len);
        size_t klen = eq ? (size_t)(eq - s) : len;
        char key[32];
        int k, aniso;
        if (klen == 0 || klen >= sizeof key)
            return NL_ERROR(NL_EINVAL, "%s: expected key=value, got \"%.*s\"", name, (int)len, s);
        memcpy(key, s, klen);
        key[klen] = 0;
        k = table_index(params, np, key);
        aniso = nl_model_word_in(aniso_keys, key, klen);
        if (k < 0 && !aniso) {
            char keys[256];
            table_keys(params, np, keys, sizeof keys);
            return NL_ERROR(NL_EINVAL, "%s: unknown parameter \"%s\" (expected one of: %s %s)", name, key, keys,
                            aniso_keys);
        }
        if (k < 0 && strcmp(key, "sep") == 0) {
            if (eq)
                return NL_ERROR(NL_EINVAL, "%s: sep takes no value, got \"%.*s\"", name, (int)len, s);
            set_aniso(m, key, 0);
        } else {
            double v = 0;
            int st;
            if (!eq)
                return NL_ERROR(NL_EINVAL, "%s: %s: expected %s=VALUE", name, key, key);
            st = parse_number(name, key, eq + 1, len - klen - 1, &v);
            if (st)
                return st;
            if (k >= 0)
                vals[k] = v;
            else
                set_aniso(m, key, v);
        }
        s += len;
        if (*s == ',')
            s++;
    }
    return NL_OK;
}

int nl_model_parse_params(nl_model *m, const char *s)
{
    return parse_keys(m, m->fam->name, m->fam->params, m->fam->nparams, m->p, s);
}

/* The range of one parameter (core/family.h, nl_param_range). */
static int check_range(const char *name, const nl_family_param *p, double v)
{
    if (p->range == NL_RANGE_NONNEG && !(v >= 0))
        return NL_ERROR(NL_EINVAL, "%s: %s: expected a number >= 0, got %g", name, p->name, v);
    if ((p->range == NL_RANGE_POSITIVE || p->range == NL_RANGE_UPTO) && !(v > 0))
        return NL_ERROR(NL_EINVAL, "%s: %s: expected a positive number, got %g", name, p->name, v);
    if (p->range == NL_RANGE_UPTO && !(v <= p->hi))
        return NL_ERROR(NL_EINVAL, "%s: %s: expected 0 < %s <= %g (%s), got %.17g", name, p->name, p->name, p->hi,
                        p->why, v);
    return NL_OK;
}

static int check_positive(const char *name, const char *key, double v)
{
    if (!(v > 0))
        return NL_ERROR(NL_EINVAL, "%s: %s: expected a positive number, got %g", name, key, v);
    return NL_OK;
}

/* Every parameter in its range: scale, var, the anisotropy ratios, the
 * nugget, then the shape parameters in the family's order, then the
 * family's own checks. */
static int validate(nl_model *m)
{
    static const nl_param_role first[] = {NL_ROLE_SCALE, NL_ROLE_VARIANCE};
    const nl_family *f = m->fam;
    const char *name = f->name;
    int st, k;
    for (size_t i = 0; i < 2; i++)
        if ((k = nl_family_role_index(f, first[i])) >= 0 && (st = check_range(name, &f->params[k], m->p[k])))
            return st;
    if ((st = check_positive(name, "ratio", m->ratio)) || (st = check_positive(name, "zratio", m->zratio)))
        return st;
    if ((k = nl_family_role_index(f, NL_ROLE_NUGGET)) >= 0 && (st = check_range(name, &f->params[k], m->p[k])))
        return st;
    for (size_t i = 0; i < f->nparams; i++)
        if (f->params[i].role == NL_ROLE_SHAPE && (st = check_range(name, &f->params[i], m->p[i])))
            return st;
    return f->check ? f->check(m) : NL_OK;
}

/* The family's defaults into m; the cached var, scale and nugget after
 * parsing. */
static void set_defaults(nl_model *m)
{
    for (size_t k = 0; k < m->fam->nparams; k++)
        m->p[k] = m->fam->params[k].def;
}

static void set_cache(nl_model *m)
{
    int k;
    m->var = (k = nl_family_role_index(m->fam, NL_ROLE_VARIANCE)) >= 0 ? m->p[k] : 1;
    m->scale = (k = nl_family_role_index(m->fam, NL_ROLE_SCALE)) >= 0 ? m->p[k] : 1;
    m->nugget = (k = nl_family_role_index(m->fam, NL_ROLE_NUGGET)) >= 0 ? m->p[k] : 0;
    m->cosa = cos(m->angle);
    m->sina = sin(m->angle);
}

/* "ARG;k=v,...": the argument before the last ';', the keys after it. */
static int parse_argument(nl_model *m, const char *rest)
{
    const char *semi = strrchr(rest, ';');
    char *arg = strndup(rest, semi ? (size_t)(semi - rest) : strlen(rest));
    int st;
    if (!arg)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    st = m->fam->parse_argument(m, arg);
    free(arg);
    if (!st && semi)
        st = nl_model_parse_params(m, semi + 1);
    return st;
}

/* A required parameter of the table that the spec did not give. */
static int missing(const char *name, const nl_family_param *params, size_t np, const double *vals)
{
    for (size_t k = 0; k < np; k++)
        if (isnan(vals[k]))
            return NL_ERROR(NL_EINVAL, "%s: missing parameter %s (e.g. %s:%s=%s)", name, params[k].name, name,
                            params[k].name, params[k].example);
    return NL_OK;
}

/* A peer's name (core/family.h, nl_family_alias): its keys with its
 * defaults, each in its range, then converted into the family's. */
static int parse_peer(nl_model *m, const nl_family_alias *a, const char *rest)
{
    double q[NL_FAMILY_MAX_PARAMS];
    int st;
    for (size_t k = 0; k < a->nparams; k++)
        q[k] = a->params[k].def;
    if ((st = parse_keys(m, a->name, a->params, a->nparams, q, rest)) ||
        (st = missing(a->name, a->params, a->nparams, q)))
        return st;
    for (size_t k = 0; k < a->nparams; k++)
        if ((st = check_range(a->name, &a->params[k], q[k])))
            return st;
    a->convert(q, m->p);
    if (strcmp(a->peer, "gstat") == 0)
        nl_peer_gstat_anis(m);
    return NL_OK;
}

static int unknown(const char *spec, size_t nlen)
{
    char list[1024];
    nl_family_names(0, 0, " or ", list, sizeof list);
    return NL_ERROR(NL_EINVAL, "model: unknown model \"%.*s\" (expected %s; see noiselab models)", (int)nlen, spec,
                    list);
}

int nl_model_parse(const char *spec, nl_model **out)
{
    nl_model *m;
    const nl_family_alias *peer = NULL;
    const char *colon, *rest;
    size_t nlen;
    int st, composite;
    *out = NULL;
    if (!spec || !*spec)
        return NL_ERROR(NL_EINVAL, "model: expected a model spec such as markov:scale=8, got \"\"");
    if ((st = nl_model_spec_is_composite(spec, &composite)))
        return st;
    if (composite)
        return nl_model_parse_composite(spec, out);
    colon = strchr(spec, ':');
    nlen = colon ? (size_t)(colon - spec) : strlen(spec);
    rest = colon ? colon + 1 : "";
    m = calloc(1, sizeof *m);
    if (!m || !(m->spec = strdup(spec))) {
        free(m);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    m->ratio = 1;
    m->zratio = 1;
    if (!(m->fam = nl_family_find(spec, nlen)) && !(peer = nl_family_find_peer(spec, nlen, &m->fam))) {
        nl_model_free(m);
        return unknown(spec, nlen);
    }
    set_defaults(m);
    if (peer)
        st = parse_peer(m, peer, rest);
    else if (m->fam->flags & NL_FAMILY_ARGUMENT)
        st = parse_argument(m, rest);
    else
        st = nl_model_parse_params(m, rest);
    if (!st)
        st = missing(m->fam->name, m->fam->params, m->fam->nparams, m->p);
    if (!st)
        st = validate(m);
    if (st) {
        nl_model_free(m);
        return st;
    }
    set_cache(m);
    *out = m;
    return NL_OK;
}

void nl_model_free(nl_model *m)
{
    if (!m)
        return;
    for (size_t i = 0; i < m->nterms; i++)
        nl_model_free(m->terms[i]);
    free(m->terms);
    nl_expr_free(m->eval);
    free(m->table);
    free(m->spec);
    free(m);
}

const char *nl_model_spec(const nl_model *m) { return m->spec; }

int nl_model_is_spectral(const nl_model *m) { return (m->fam->flags & NL_FAMILY_SPECTRAL) != 0; }

/* A sum or product has what every term has. */
static int every_term(const nl_model *m, int (*has)(const nl_model *))
{
    for (size_t i = 0; i < m->nterms; i++)
        if (!has(m->terms[i]))
            return 0;
    return 1;
}

int nl_model_has_acf(const nl_model *m)
{
    return m->nterms ? every_term(m, nl_model_has_acf) : m->fam->acf || m->fam->profile;
}

int nl_model_is_reentrant(const nl_model *m)
{
    return m->nterms ? every_term(m, nl_model_is_reentrant) : !(m->fam->flags & NL_FAMILY_EXPRESSION);
}

int nl_model_check_dim(const nl_model *m, int dim)
{
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    if (nl_model_is_spectral(m) && m->aniso_given)
        return NL_ERROR(NL_EINVAL, "%s: sep, angle, ratio and zratio apply to autocorrelation models, "
                        "not to spectra", m->spec);
    return m->fam->check_dim ? m->fam->check_dim(m, dim) : NL_OK;
}
