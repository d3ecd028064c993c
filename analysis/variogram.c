/* Empirical variogram (stub until filled in). */
#include "variogram.h"
#include "../core/nl_error.h"

void nl_variogram_options_default(nl_variogram_options *o)
{
    *o = (nl_variogram_options){.estimator = NL_VARIOGRAM_MATHERON};
}

int nl_variogram_points(const nl_points *p, const nl_variogram_options *o, nl_variogram **out)
{
    (void)p, (void)o;
    *out = NULL;
    return NL_ERROR(NL_EINVAL, "variogram: not yet");
}

int nl_variogram_field(const nl_field *f, const nl_variogram_options *o, nl_variogram **out)
{
    (void)f, (void)o;
    *out = NULL;
    return NL_ERROR(NL_EINVAL, "variogram: not yet");
}

void nl_variogram_free(nl_variogram *v)
{
    (void)v;
}
