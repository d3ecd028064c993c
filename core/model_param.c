/* Reading a model's parameters back by name (the values in effect after
 * parsing, defaults included). */
#include "model.h"
#include "model_internal.h"
#include "nl_error.h"

#include <stdlib.h>
#include <string.h>

double nl_model_p(const nl_model *m, const char *name) { return m->p[nl_family_param_index(m->fam, name)]; }

/* NAME.I of a sum or product: structure I's (from 1) parameter NAME. */
static int composite_param(const nl_model *m, const char *name, double *value)
{
    const char *dot = strrchr(name, '.');
    char *end, key[32];
    unsigned long i = dot ? strtoul(dot + 1, &end, 10) : 0;
    const nl_model *s;
    if (!dot || dot == name || !dot[1] || *end || i < 1 || (size_t)(dot - name) >= sizeof key ||
        !(s = nl_model_structure(m, i - 1)))
        return NL_ERROR(NL_EINVAL, "%s: has no parameter \"%s\" (expected NAME.I, structure I of %zu, e.g. var.1)",
                        m->spec, name, nl_model_structures(m));
    memcpy(key, name, (size_t)(dot - name));
    key[dot - name] = 0;
    return nl_model_param(s, key, value);
}

int nl_model_param(const nl_model *m, const char *name, double *value)
{
    int k;
    if (m->nterms)
        return composite_param(m, name, value);
    k = nl_family_param_index(m->fam, name);
    if (k >= 0) {
        *value = m->p[k];
        return NL_OK;
    }
    /* the anisotropy ratios of every model defined by R */
    if (!nl_model_is_spectral(m) && (strcmp(name, "ratio") == 0 || strcmp(name, "zratio") == 0)) {
        *value = name[0] == 'r' ? m->ratio : m->zratio;
        return NL_OK;
    }
    return NL_ERROR(NL_EINVAL, "%s: has no parameter \"%s\"", m->spec, name);
}

double nl_model_nugget(const nl_model *m) { return m->nugget; }
