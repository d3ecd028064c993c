/* Reading a model's parameters back by name (the values in effect after
 * parsing, defaults included). */
#include "model.h"
#include "model_internal.h"
#include "nl_error.h"

#include <string.h>

typedef struct {
    const char *name;       /* as written in a spec */
    size_t offset;          /* of the double in struct nl_model */
    unsigned kinds;         /* bit k set: kind k has the parameter */
} param;

#define K(k) (1u << (k))
#define NAMED (K(NL_MODEL_MARKOV) | K(NL_MODEL_GAUSS) | K(NL_MODEL_MARKAUSSIAN) | K(NL_MODEL_OSCILLATORY) | \
               K(NL_MODEL_GAUSS_OSC) | K(NL_MODEL_MATERN) | K(NL_MODEL_SPHERICAL))
#define ACF (NAMED | K(NL_MODEL_EXPR) | K(NL_MODEL_IMAGE))

static const param params[] = {
    {"var", offsetof(struct nl_model, var), NAMED | K(NL_MODEL_POWER)},
    {"scale", offsetof(struct nl_model, scale), NAMED},
    {"nugget", offsetof(struct nl_model, nugget), ACF},
    {"alpha", offsetof(struct nl_model, alpha), K(NL_MODEL_MARKAUSSIAN)},
    {"omega", offsetof(struct nl_model, omega), K(NL_MODEL_OSCILLATORY) | K(NL_MODEL_GAUSS_OSC)},
    {"nu", offsetof(struct nl_model, nu), K(NL_MODEL_MATERN)},
    {"d", offsetof(struct nl_model, d), K(NL_MODEL_POWER)},
    {"fmin", offsetof(struct nl_model, fmin), K(NL_MODEL_POWER)},
    {"fmax", offsetof(struct nl_model, fmax), K(NL_MODEL_POWER)},
    {"ratio", offsetof(struct nl_model, ratio), ACF},
    {"zratio", offsetof(struct nl_model, zratio), ACF},
};

int nl_model_param(const nl_model *m, const char *name, double *value)
{
    for (size_t i = 0; i < sizeof params / sizeof *params; i++)
        if (strcmp(name, params[i].name) == 0) {
            if (!(params[i].kinds & K(m->kind)))
                break;
            *value = *(const double *)((const char *)m + params[i].offset);
            return NL_OK;
        }
    return NL_ERROR(NL_EINVAL, "%s: has no parameter \"%s\"", m->spec, name);
}

double nl_model_nugget(const nl_model *m) { return m->nugget; }
