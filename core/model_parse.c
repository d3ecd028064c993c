/* Parsing of model specs into nl_model. */
#include "model_internal.h"
#include "nl_error.h"

#include <math.h>
#include <matheval.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *name;
    nl_model_kind kind;
    const char *keys;      /* accepted keys, space separated */
    const char *required;  /* required key or NULL */
} family;

static const family families[] = {
    {"markov", NL_MODEL_MARKOV, "scale var nugget", NULL},
    {"gauss", NL_MODEL_GAUSS, "scale var nugget", NULL},
    {"markaussian", NL_MODEL_MARKAUSSIAN, "alpha scale var nugget", "alpha"},
    {"oscillatory", NL_MODEL_OSCILLATORY, "omega scale var nugget", "omega"},
    {"gauss-osc", NL_MODEL_GAUSS_OSC, "omega scale var nugget", "omega"},
    {"matern", NL_MODEL_MATERN, "nu scale var nugget", "nu"},
    {"spherical", NL_MODEL_SPHERICAL, "scale var nugget", NULL},
    {"power", NL_MODEL_POWER, "d fmin fmax var", "d"},
};

static const char aniso_keys[] = "sep angle ratio zratio";

static int has_word(const char *list, const char *w, size_t len)
{
    const char *p = list;
    while (*p) {
        size_t l = strcspn(p, " ");
        if (l == len && strncmp(p, w, len) == 0)
            return 1;
        p += l;
        while (*p == ' ')
            p++;
    }
    return 0;
}

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

/* Parse "k=v,k=v,sep" into m, accepting keys of `keys` plus anisotropy. */
static int parse_params(nl_model *m, const char *name, const char *keys, const char *s)
{
    while (*s) {
        size_t len = strcspn(s, ",");
        const char *eq = memchr(s, '=', len);
        size_t klen = eq ? (size_t)(eq - s) : len;
        char key[32];
        if (klen == 0 || klen >= sizeof key)
            return NL_ERROR(NL_EINVAL, "%s: expected key=value, got \"%.*s\"", name, (int)len, s);
        memcpy(key, s, klen);
        key[klen] = 0;
        if (!has_word(keys, key, klen) && !has_word(aniso_keys, key, klen))
            return NL_ERROR(NL_EINVAL, "%s: unknown parameter \"%s\" (expected one of: %s %s)", name, key,
                            keys, aniso_keys);
        if (strcmp(key, "sep") == 0) {
            if (eq)
                return NL_ERROR(NL_EINVAL, "%s: sep takes no value, got \"%.*s\"", name, (int)len, s);
            m->sep = 1;
            m->aniso_given = 1;
        } else {
            double v = 0;
            int st;
            if (!eq)
                return NL_ERROR(NL_EINVAL, "%s: %s: expected %s=VALUE", name, key, key);
            st = parse_number(name, key, eq + 1, len - klen - 1, &v);
            if (st)
                return st;
            if (strcmp(key, "scale") == 0) m->scale = v;
            else if (strcmp(key, "var") == 0) m->var = v;
            else if (strcmp(key, "nugget") == 0) m->nugget = v;
            else if (strcmp(key, "alpha") == 0) m->alpha = v;
            else if (strcmp(key, "omega") == 0) m->omega = v;
            else if (strcmp(key, "nu") == 0) m->nu = v;
            else if (strcmp(key, "d") == 0) m->d = v;
            else if (strcmp(key, "fmin") == 0) m->fmin = v;
            else if (strcmp(key, "fmax") == 0) m->fmax = v;
            else if (strcmp(key, "angle") == 0) m->angle = v * M_PI / 180.0;
            else if (strcmp(key, "ratio") == 0) m->ratio = v;
            else if (strcmp(key, "zratio") == 0) m->zratio = v;
            if (strcmp(key, "angle") == 0 || strcmp(key, "ratio") == 0 || strcmp(key, "zratio") == 0)
                m->aniso_given = 1;
        }
        s += len;
        if (*s == ',')
            s++;
    }
    return NL_OK;
}

static int check_positive(const char *name, const char *key, double v)
{
    if (!(v > 0))
        return NL_ERROR(NL_EINVAL, "%s: %s: expected a positive number, got %g", name, key, v);
    return NL_OK;
}

static int validate(nl_model *m, const char *name)
{
    int st;
    if ((st = check_positive(name, "scale", m->scale)) || (st = check_positive(name, "var", m->var)) ||
        (st = check_positive(name, "ratio", m->ratio)) || (st = check_positive(name, "zratio", m->zratio)))
        return st;
    if (!(m->nugget >= 0))
        return NL_ERROR(NL_EINVAL, "%s: nugget: expected a number >= 0, got %g", name, m->nugget);
    if (m->kind == NL_MODEL_MARKAUSSIAN && (st = check_positive(name, "alpha", m->alpha)))
        return st;
    /* exp(-|t|^alpha) is positive definite exactly for 0 < alpha <= 2 */
    if (m->kind == NL_MODEL_MARKAUSSIAN && !(m->alpha <= 2))
        return NL_ERROR(NL_EINVAL, "%s: alpha: expected 0 < alpha <= 2 (above 2 the ACF is not positive definite), "
                        "got %.17g", name, m->alpha);
    if (m->kind == NL_MODEL_MATERN && (st = check_positive(name, "nu", m->nu)))
        return st;
    if (m->kind == NL_MODEL_POWER) {
        if (!(m->fmin >= 0) || !(m->fmax > m->fmin))
            return NL_ERROR(NL_EINVAL, "%s: expected 0 <= fmin < fmax, got fmin=%g, fmax=%g", name, m->fmin,
                            m->fmax);
        if (m->fmin == 0 && m->d >= 1)
            return NL_ERROR(NL_EINVAL, "%s: fmin=0 with d=%g: the variance diverges; expected fmin > 0", name,
                            m->d);
    }
    return NL_OK;
}

/* Split "EXPR;k=v,..." at the last ';' into expression and parameters. */
static int parse_expr_model(nl_model *m, const char *name, const char *rest, int spectral)
{
    const char *semi = strrchr(rest, ';');
    size_t elen = semi ? (size_t)(semi - rest) : strlen(rest);
    char *text;
    int st = NL_OK;
    if (elen == 0)
        return NL_ERROR(NL_EINVAL, "%s: expected an expression after \"%s:\"", name, name);
    text = strndup(rest, elen);
    if (!text)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    m->eval = evaluator_create(text);
    if (!m->eval) {
        st = NL_ERROR(NL_EINVAL, "%s: malformed expression \"%s\"", name, text);
    } else {
        char **names;
        int count;
        const char *allowed = spectral ? "f fx fy fz k" : "t x y z r";
        evaluator_get_variables(m->eval, &names, &count);
        for (int i = 0; i < count && !st; i++)
            if (!has_word(allowed, names[i], strlen(names[i])))
                st = NL_ERROR(NL_EINVAL, "%s: unknown variable \"%s\" in \"%s\" (expected %s)", name, names[i],
                              text, allowed);
    }
    free(text);
    /* a spectrum is a density: its white-noise part is a constant in S, not a key */
    if (!st && semi)
        st = parse_params(m, name, spectral ? "" : "nugget", semi + 1);
    return st;
}

int nl_model_parse(const char *spec, nl_model **out)
{
    nl_model *m;
    const char *colon;
    size_t nlen;
    int st = NL_OK;
    *out = NULL;
    if (!spec || !*spec)
        return NL_ERROR(NL_EINVAL, "model: expected a model spec such as markov:scale=8, got \"\"");
    m = calloc(1, sizeof *m);
    if (!m || !(m->spec = strdup(spec))) {
        free(m);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    m->var = 1;
    m->scale = 1;
    m->ratio = 1;
    m->zratio = 1;
    m->fmin = 1.0 / 1024;
    m->fmax = 0.5;
    m->alpha = m->omega = m->nu = m->d = NAN;
    colon = strchr(spec, ':');
    nlen = colon ? (size_t)(colon - spec) : strlen(spec);

    if (nlen == 4 && strncmp(spec, "expr", 4) == 0) {
        m->kind = NL_MODEL_EXPR;
        st = parse_expr_model(m, "expr", colon ? colon + 1 : "", 0);
    } else if (nlen == 8 && strncmp(spec, "spectrum", 8) == 0) {
        m->kind = NL_MODEL_SPECTRUM;
        st = parse_expr_model(m, "spectrum", colon ? colon + 1 : "", 1);
    } else if (nlen == 5 && strncmp(spec, "image", 5) == 0) {
        const char *rest = colon ? colon + 1 : "";
        const char *semi = strrchr(rest, ';');
        char *path = strndup(rest, semi ? (size_t)(semi - rest) : strlen(rest));
        m->kind = NL_MODEL_IMAGE;
        if (!path)
            st = NL_ERROR(NL_ENOMEM, "out of memory");
        else if (!*path)
            st = NL_ERROR(NL_EINVAL, "image: expected a file name after \"image:\"");
        else
            st = nl_model_image_load(m, path);
        free(path);
        if (!st && semi)
            st = parse_params(m, "image", "nugget", semi + 1);
    } else {
        const family *fam = NULL;
        for (size_t i = 0; i < sizeof families / sizeof *families; i++)
            if (strlen(families[i].name) == nlen && strncmp(spec, families[i].name, nlen) == 0)
                fam = &families[i];
        if (!fam) {
            st = NL_ERROR(NL_EINVAL,
                          "model: unknown model \"%.*s\" (expected markov, gauss, markaussian, oscillatory, "
                          "gauss-osc, matern, spherical, power, expr:, spectrum: or image:; see noiselab models)",
                          (int)nlen, spec);
        } else {
            m->kind = fam->kind;
            st = parse_params(m, fam->name, fam->keys, colon ? colon + 1 : "");
            if (!st && fam->required && strcmp(fam->required, "alpha") == 0 && isnan(m->alpha))
                st = NL_ERROR(NL_EINVAL, "%s: missing parameter alpha (e.g. %s:alpha=1.4)", fam->name, fam->name);
            if (!st && fam->required && strcmp(fam->required, "omega") == 0 && isnan(m->omega))
                st = NL_ERROR(NL_EINVAL, "%s: missing parameter omega (e.g. %s:omega=10)", fam->name, fam->name);
            if (!st && fam->required && strcmp(fam->required, "nu") == 0 && isnan(m->nu))
                st = NL_ERROR(NL_EINVAL, "%s: missing parameter nu (e.g. %s:nu=1.5)", fam->name, fam->name);
            if (!st && fam->required && strcmp(fam->required, "d") == 0 && isnan(m->d))
                st = NL_ERROR(NL_EINVAL, "%s: missing parameter d (e.g. %s:d=2.5)", fam->name, fam->name);
            if (!st)
                st = validate(m, fam->name);
        }
    }
    if (!st && (m->kind == NL_MODEL_EXPR || m->kind == NL_MODEL_SPECTRUM || m->kind == NL_MODEL_IMAGE))
        st = validate(m, m->kind == NL_MODEL_EXPR ? "expr" : m->kind == NL_MODEL_SPECTRUM ? "spectrum" : "image");
    if (st) {
        nl_model_free(m);
        return st;
    }
    m->cosa = cos(m->angle);
    m->sina = sin(m->angle);
    *out = m;
    return NL_OK;
}

void nl_model_free(nl_model *m)
{
    if (!m)
        return;
    if (m->eval)
        evaluator_destroy(m->eval);
    free(m->table);
    free(m->spec);
    free(m);
}

nl_model_kind nl_model_get_kind(const nl_model *m) { return m->kind; }

const char *nl_model_spec(const nl_model *m) { return m->spec; }

int nl_model_is_spectral(const nl_model *m)
{
    return m->kind == NL_MODEL_POWER || m->kind == NL_MODEL_SPECTRUM;
}

int nl_model_is_reentrant(const nl_model *m) { return m->kind != NL_MODEL_EXPR && m->kind != NL_MODEL_SPECTRUM; }

int nl_model_check_dim(const nl_model *m, int dim)
{
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dimension: expected 1, 2 or 3, got %d", dim);
    if (nl_model_is_spectral(m) && m->aniso_given)
        return NL_ERROR(NL_EINVAL, "%s: sep, angle, ratio and zratio apply to autocorrelation models, "
                        "not to spectra", m->spec);
    if (m->kind == NL_MODEL_IMAGE && dim == 3)
        return NL_ERROR(NL_EINVAL, "%s: an exemplar image gives a 1D or 2D autocorrelation, not 3D", m->spec);
    if (m->kind == NL_MODEL_IMAGE && m->aniso_given)
        return NL_ERROR(NL_EINVAL, "%s: an exemplar's autocorrelation takes no sep, angle or ratio", m->spec);
    return NL_OK;
}
