/* Reading a model's parameters back by name (the values in effect after
 * parsing, defaults included). */
#include "model.h"
#include "model_internal.h"
#include "nl_error.h"

#include <string.h>

double nl_model_p(const nl_model *m, const char *name) { return m->p[nl_family_param_index(m->fam, name)]; }

int nl_model_param(const nl_model *m, const char *name, double *value)
{
    int k = nl_family_param_index(m->fam, name);
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
