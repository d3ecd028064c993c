/* wendland: the Wendland functions phi_{mu,k} of support `scale`, in the
 * form of Gneiting (2002, "Compactly supported correlation functions",
 * Section 3, after Wendland 1995), with a = |t|/scale < 1:
 *     k = 0: (1-a)^mu
 *     k = 1: (1-a)^(mu+1) (1 + (mu+1) a)
 *     k = 2: (1-a)^(mu+2) (1 + (mu+2) a + (mu^2 + 4 mu + 3) a^2 / 3)
 *     k = 3: (1-a)^(mu+3) (1 + (mu+3) a + (2 mu^2 + 12 mu + 15) a^2 / 5
 *                          + (mu^3 + 9 mu^2 + 23 mu + 15) a^3 / 15),
 * 0 for a >= 1; 2k times differentiable at 0, positive definite in d
 * dimensions iff mu >= (d+1)/2 + k (Wendland 1995; Zastavnyi 2006).  It is
 * RandomFields' RMgengneiting(kappa = k, mu = mu - k - 1/2). */
#include "families_internal.h"
#include "../nl_error.h"

enum { K, MU };

static const nl_family_param params[] = {
    {.name = "k", .def = NAN, .placeholder = "K", .example = "1", .range = NL_RANGE_NONNEG},
    {.name = "mu", .def = NAN, .placeholder = "M", .example = "3", .range = NL_RANGE_POSITIVE},
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 3},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

static int check(const nl_model *m)
{
    double k = m->p[K];
    if (k != 0 && k != 1 && k != 2 && k != 3)
        return NL_ERROR(NL_EINVAL, "%s: k: expected 0, 1, 2 or 3, got %g", m->spec, k);
    return NL_OK;
}

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t), mu = m->p[MU], p;
    int k = (int)m->p[K];
    if (a >= 1)
        return 0.0;
    switch (k) {
    case 0: p = 1; break;
    case 1: p = 1 + (mu + 1) * a; break;
    case 2: p = 1 + a * ((mu + 2) + a * (mu * mu + 4 * mu + 3) / 3); break;
    default:
        p = 1 + a * ((mu + 3) + a * ((2 * mu * mu + 12 * mu + 15) / 5 +
                                     a * (((mu + 9) * mu + 23) * mu + 15) / 15));
    }
    return m->var * pow(1 - a, mu + k) * p;
}

static int check_dim(const nl_model *m, int dim)
{
    double lo = 0.5 * (dim + 1) + m->p[K];
    if (m->p[MU] < lo)
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: expected mu >= (d+1)/2 + k = %g (Wendland "
                        "1995, Zastavnyi 2006), got mu=%g", m->spec, dim, lo, m->p[MU]);
    return NL_OK;
}

/* RandomFields' RMgengneiting(kappa, mu, var, scale): its exponent
 * beta = mu + 2 kappa + 1/2 is our mu + k. */
static const nl_family_param rf_params[] = {
    NL_PARAM_VAR, NL_PARAM_SCALE, NL_PARAM_NUGGET,
    {.name = "kappa", .def = NAN, .placeholder = "K", .example = "1", .range = NL_RANGE_NONNEG},
    {.name = "mu", .def = NAN, .placeholder = "M", .example = "1.5", .range = NL_RANGE_NONNEG},
};

static void from_gengneiting(const double *q, double *p)
{
    p[K] = q[3];
    p[MU] = q[4] + q[3] + 0.5;
    p[2] = q[1];
    p[3] = q[0];
    p[4] = q[2];
}

static const nl_family_alias peers[] = {
    {.name = "RMgengneiting", .peer = "RandomFields",
     .formula = "var (1-r)^b P_kappa(r), b = mu + 2 kappa + 1/2, r = h/scale < 1 (RandomFields' polynomials)",
     .nparams = 5, .params = rf_params, .convert = from_gengneiting},
};

const nl_family nl_family_wendland = {
    .name = "wendland",
    .aliases = "",
    .formula = "R = var (1-a)^(mu+k) P_k(a) for a = |t|/scale < 1, else 0; P_0 = 1, P_1 = 1 + (mu+1) a, P_2 = 1 + "
               "(mu+2) a + (mu^2+4mu+3) a^2/3, P_3 = 1 + (mu+3) a + (2mu^2+12mu+15) a^2/5 + "
               "(mu^3+9mu^2+23mu+15) a^3/15; k = 0..3",
    .validity = "positive definite in d dimensions iff mu >= (d+1)/2 + k (Wendland 1995; Gneiting 2002; "
                "Zastavnyi 2006)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .check = check,
    .profile = profile,
    .check_dim = check_dim,
};
