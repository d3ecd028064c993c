/* image: the empirical autocorrelation of an exemplar (Lewis 1987, eq. 15),
 * tabulated by core/model_image.c. */
#include "families_internal.h"
#include "../nl_error.h"

static const nl_family_param params[] = {NL_PARAM_NUGGET};

static int parse_argument(nl_model *m, const char *path)
{
    if (!*path)
        return NL_ERROR(NL_EINVAL, "image: expected a file name after \"image:\"");
    return nl_model_image_load(m, path);
}

static double profile(const nl_model *m, double t) { return nl_model_image_acf(m, t, 0); }

static double acf(const nl_model *m, int dim, const double *lag)
{
    return dim == 1 ? profile(m, lag[0]) : nl_model_image_acf(m, lag[0], lag[1]);
}

static int isotropic(const nl_model *m)
{
    (void)m;
    return 0;
}

static int check_dim(const nl_model *m, int dim)
{
    if (dim == 3)
        return NL_ERROR(NL_EINVAL, "%s: an exemplar image gives a 1D or 2D autocorrelation, not 3D", m->spec);
    if (m->aniso_given)
        return NL_ERROR(NL_EINVAL, "%s: an exemplar's autocorrelation takes no sep, angle or ratio", m->spec);
    return NL_OK;
}

const nl_family nl_family_image = {
    .name = "image",
    .aliases = "",
    .argument = "FILE",
    .usage = "PNG (8/16-bit grey) or EXR",
    .formula = "R = empirical autocorrelation of the exemplar (Lewis 1987, eq. 15)",
    .flags = NL_FAMILY_ARGUMENT | NL_FAMILY_FILE,
    .validity = "the exemplar's empirical autocorrelation, positive semi-definite in 1D and 2D",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .parse_argument = parse_argument,
    .profile = profile,
    .acf = acf,
    .isotropic = isotropic,
    .check_dim = check_dim,
};
