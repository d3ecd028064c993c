/* hyperspherical: the D-dimensional spherical model ("Euclid's hat"), the
 * volume of the intersection of two D-balls of diameter `scale` whose
 * centres are |t| apart over the volume of one (Matern 1960; Gneiting 1999,
 * 2002; GSTools' HyperSpherical with len_scale = scale and D its field
 * dimension).  With a = |t|/scale < 1 (each cap's volume, Li 2011):
 *     R = var I_{1-a^2}((D+1)/2, 1/2),
 * I the regularised incomplete beta function: 1 - a for D = 1, gstat's
 * circular for D = 2, the spherical model for D = 3.  Positive definite in
 * d dimensions iff d <= D. */
#include "families_internal.h"
#include "../gsl_guard_internal.h"
#include "../nl_error.h"

#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>

enum { D };

static const nl_family_param params[] = {
    {.name = "dim", .def = 3, .range = NL_RANGE_POSITIVE},
    {.name = "scale", .role = NL_ROLE_SCALE, .def = 1, .range = NL_RANGE_POSITIVE, .start = 2},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

/* I_{1-a^2}(b, 1/2), near a = 0 as 1 - I_{a^2}(1/2, b) (A&S 26.5.2) so
 * that the lag keeps its digits, near a = 1 with 1 - a^2 = (1-a)(1+a). */
double nl_euclid_hat(double b, double a)
{
    gsl_sf_result r;
    int st;
    if (a >= 1)
        return 0.0;
    nl_gsl_enter();
    st = a * a < 0.5 ? gsl_sf_beta_inc_e(0.5, b, a * a, &r) : gsl_sf_beta_inc_e(b, 0.5, (1 - a) * (1 + a), &r);
    nl_gsl_leave();
    if (st)
        return NAN;
    return a * a < 0.5 ? 1 - r.val : r.val;
}

/* |B^(f)|^2 / vol(B) for the ball B of radius c = s/2 in R^D, B^(f) =
 * c^(D/2) |f|^(-D/2) J_(D/2)(2 pi c |f|) (Stein and Weiss 1971, IV.3):
 *     S = Gamma(D/2+1) J_(D/2)(pi s k)^2 / (pi^(D/2) k^D),
 * at k = 0 the volume pi^(D/2) c^D / Gamma(D/2+1). */
double nl_spectrum_euclid_hat(double var, double s, int dim, double k)
{
    gsl_sf_result g;
    double h = 0.5 * dim, j = 0;
    int st;
    if (isnan(k))
        return NAN;
    nl_gsl_enter();
    st = gsl_sf_lngamma_e(h + 1, &g) || (k > 0 && nl_family_jnu(h, M_PI * s * k, &j));
    nl_gsl_leave();
    if (st)
        return NAN;
    if (k == 0)
        return var * exp(h * log(M_PI) + dim * log(0.5 * s) - g.val);
    return var * exp(g.val - h * log(M_PI) - dim * log(k)) * j * j;
}

static int check(const nl_model *m)
{
    double d = m->p[D];
    if (d != floor(d) || d > 1000)
        return NL_ERROR(NL_EINVAL, "%s: dim: expected a whole number of dimensions from 1 to 1000, got %g", m->spec,
                        d);
    return NL_OK;
}

static double profile(const nl_model *m, double t)
{
    return m->var * nl_euclid_hat(0.5 * (m->p[D] + 1), nl_family_a(m, t));
}

static double spectrum(const nl_model *m, int dim, const double *f)
{
    return dim == (int)m->p[D] ? nl_spectrum_euclid_hat(m->var, m->scale, dim, nl_family_fnorm(m, dim, f)) : NAN;
}

static int check_dim(const nl_model *m, int dim)
{
    if (dim > m->p[D])
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite in %dD: the spherical model of dim=%g is positive "
                        "definite up to %g dimensions (Gneiting 1999)", m->spec, dim, m->p[D], m->p[D]);
    return NL_OK;
}

/* GSTools' HyperSpherical(var, len_scale, nugget) of field dimension dim
 * (default 3). */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "dim", .def = 3, .range = NL_RANGE_POSITIVE},
};

static const nl_family_alias peers[] = {
    {.name = "HyperSpherical", .peer = "GSTools",
     .formula = "var (1 - x 2F1(1/2, -(dim-1)/2; 3/2; x^2) / 2F1(1/2, -(dim-1)/2; 3/2; 1)), x = h/len_scale < 1",
     .nparams = 4, .params = gstools_params, .convert = nl_peer_shape_first},
};

const nl_family nl_family_hyperspherical = {
    .name = "hyperspherical",
    .aliases = "",
    .formula = "R = var I_{1-a^2}((dim+1)/2, 1/2), a = |t|/scale < 1, else 0 (I the regularised incomplete beta "
               "function; scale = range); S in closed form in dim dimensions",
    .validity = "positive definite in d dimensions iff d <= dim (Matern 1960; Gneiting 1999)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .check = check,
    .profile = profile,
    .spectrum = spectrum,
    .check_dim = check_dim,
};
