/* sinc: the cardinal sine (wave) hole effect R = var sin(a)/a, a =
 * |t|/scale, R(0) = var: jbessel with nu = 1/2, positive definite in 1D
 * to 3D only (Yaglom 1987; RandomFields' RMwave). */
#include "families_internal.h"

static const nl_family_param params[] = {NL_PARAM_SCALE, NL_PARAM_VAR, NL_PARAM_NUGGET};

static double profile(const nl_model *m, double t)
{
    double a = nl_family_a(m, t);
    return a == 0 ? m->var : m->var * sin(a) / a;
}

/* jbessel's spectrum at nu = 1/2: 1D pi scale on |f| < k0 = 1/(2 pi
 * scale); 2D 1 / (2 pi k0 sqrt(k0^2 - |f|^2)); 3D the sphere |f| = k0, no
 * density (NAN). */
static double spectrum(const nl_model *m, int dim, const double *f)
{
    return nl_spectrum_jbessel(m->var, m->scale, 0.5, dim, nl_family_fnorm(m, dim, f));
}

/* gstat's Wav, psill sin(pi h/range) / (pi h/range) (gstat/src/vario_fn.c,
 * fn_wave), and Hol, psill sin(h/range) / (h/range) (fn_hole). */
NL_PEER_VLN(from_wav, 1 / M_PI)
NL_PEER_VLN(from_hol, 1)

static const nl_family_alias peers[] = {
    {.name = "Wav", .peer = "gstat", .formula = "psill sin(pi h/range) / (pi h/range)", .nparams = 3,
     .params = nl_peer_gstat_params, .convert = from_wav},
    {.name = "Hol", .peer = "gstat", .formula = "psill sin(h/range) / (h/range)", .nparams = 3,
     .params = nl_peer_gstat_params, .convert = from_hol},
};

const nl_family nl_family_sinc = {
    .name = "sinc",
    .aliases = "RMwave",
    .formula = "R = var sin(a)/a, a = |t|/scale; 1D S = var pi scale for |f| < 1/(2 pi scale), 2D S = var / (2 pi "
               "k0 sqrt(k0^2 - |f|^2)) for |f| < k0 = 1/(2 pi scale)",
    .flags = NL_FAMILY_FIT,
    .max_dim = 3,
    .validity = "positive definite in 1D, 2D and 3D only (jbessel with nu = 1/2; Yaglom 1987)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .profile = profile,
    .spectrum = spectrum,
};
