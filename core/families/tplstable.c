/* tplstable: the truncated power law of stable modes (Hesse, Prykhodko,
 * Schlueter and Attinger 2014; Mueller, Schueler, Zech, Attinger and
 * Heisse 2022, GSTools' TPLStable): the superposition of correlations
 * exp(-(r/l)^alpha) over lengths lower < l < scale with variance density
 * proportional to l^(2 hurst - 1), which is, with b = 2 hurst / alpha and
 * the generalised exponential integral E_s(x) = x^(s-1) Gamma(1-s, x),
 *     R = var b E_(1+b)((r/scale)^alpha)                    (lower = 0),
 *     R = var (scale^2h b E_(1+b)((r/scale)^alpha) - lower^2h b E_(1+b)((r/lower)^alpha))
 *         / (scale^2h - lower^2h)                           (lower > 0),
 * a positive mixture of stable correlations, so positive definite in every
 * dimension for 0 < alpha <= 2 and hurst > 0.  tplgaussian (alpha = 2) and
 * tplexponential (alpha = 1) are its two common cases.  `scale` is the
 * upper cut-off (GSTools' len_up = len_low + len_scale). */
#include "families_internal.h"
#include "../gsl_guard_internal.h"
#include "../nl_error.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_expint.h>
#include <gsl/gsl_sf_gamma.h>

enum { HURST, ALPHA, SCALE, LOWER };

static const nl_family_param params[] = {
    {.name = "hurst", .def = NAN, .placeholder = "H", .example = "0.5", .range = NL_RANGE_POSITIVE},
    {.name = "alpha", .def = NAN, .placeholder = "A", .example = "1.5", .range = NL_RANGE_UPTO, .hi = 2,
     .why = "above 2 the modes are not positive definite"},
    NL_PARAM_SCALE,
    {.name = "lower", .def = 0, .range = NL_RANGE_NONNEG},
    NL_PARAM_VAR, NL_PARAM_NUGGET,
};

/* b E_(1+b)(x) = b x^b Gamma(-b, x), 1 at x = 0 and 0 where it underflows
 * (x > 700: below e^-700).  For x > 1 GSL's Gamma(a, x), which takes a < 0
 * (a continued fraction there); for x <= 1, where GSL 2.7 is off by up to
 * 2e-6 at a = -0.2, x = 1e-4, the recurrence Gamma(a, x) = (Gamma(a+1, x)
 * - x^a e^-x) / a (Abramowitz and Stegun 6.5.22) down from a + n in (0, 1]
 * (Gamma(0, x) = E_1(x) for whole b), whose terms x^a e^-x dominate for
 * x <= 1, so nothing cancels. */
static double tpl_mode_sum(double b, double x)
{
    gsl_sf_result g;
    int st, n = (int)ceil(b);
    if (x == 0)
        return 1.0;
    if (x > 700)
        return 0.0;
    nl_gsl_enter();
    if (x > 1)
        st = gsl_sf_gamma_inc_e(-b, x, &g);
    else if (n == b)
        st = gsl_sf_expint_E1_e(x, &g);
    else
        st = gsl_sf_gamma_inc_e(n - b, x, &g);
    nl_gsl_leave();
    if (st)
        return st == GSL_EUNDRFLW ? 0.0 : NAN;
    if (x <= 1)
        for (int j = n - 1; j >= 0; j--)
            g.val = (g.val - pow(x, j - b) * exp(-x)) / (j - b);
    return b * exp(b * log(x)) * g.val;
}

double nl_tpl_cor(double h, double alpha, double lo, double hi, double r)
{
    double b = 2 * h / alpha, up = tpl_mode_sum(b, pow(r / hi, alpha)), wu, wl;
    if (lo == 0)
        return up;
    wu = pow(hi, 2 * h);
    wl = pow(lo, 2 * h);
    return (wu * up - wl * tpl_mode_sum(b, pow(r / lo, alpha))) / (wu - wl);
}

void nl_tpl_from_gstools(const double *q, double *p)
{
    p[0] = q[3];
    p[1] = q[4] + q[1];
    p[2] = q[4];
    p[3] = q[0];
    p[4] = q[2];
}

int nl_tpl_check(const nl_model *m, int scale, int lower)
{
    if (!(m->p[lower] < m->p[scale]))
        return NL_ERROR(NL_EINVAL, "%s: lower: expected a lower cut-off below scale=%g (the upper one), got %g",
                        m->spec, m->p[scale], m->p[lower]);
    return NL_OK;
}

static int check(const nl_model *m) { return nl_tpl_check(m, SCALE, LOWER); }

static double profile(const nl_model *m, double t)
{
    return m->var * nl_tpl_cor(m->p[HURST], m->p[ALPHA], m->p[LOWER], m->scale, fabs(t));
}

/* GSTools' TPLStable(var, len_scale, nugget, hurst, alpha, len_low) with
 * its defaults; its upper cut-off len_up = len_low + len_scale is our
 * scale. */
static const nl_family_param gstools_params[] = {
    NL_PARAM_VAR, NL_PEER_LEN_SCALE, NL_PARAM_NUGGET,
    {.name = "hurst", .def = 0.5, .range = NL_RANGE_POSITIVE},
    {.name = "alpha", .def = 1.5, .range = NL_RANGE_UPTO, .hi = 2, .why = "above 2 the modes are not positive definite"},
    {.name = "len_low", .def = 0, .range = NL_RANGE_NONNEG},
};

static void from_gstools(const double *q, double *p)
{
    p[HURST] = q[3];
    p[ALPHA] = q[4];
    p[SCALE] = q[5] + q[1];
    p[LOWER] = q[5];
    p[4] = q[0];
    p[5] = q[2];
}

static const nl_family_alias peers[] = {
    {.name = "TPLStable", .peer = "GSTools",
     .formula = "var b E_(1+b)((h/len_up)^alpha), b = 2 hurst/alpha, len_up = len_low + len_scale (len_low = 0)",
     .nparams = 6, .params = gstools_params, .convert = from_gstools},
};

const nl_family nl_family_tplstable = {
    .name = "tplstable",
    .aliases = "",
    .formula = "R = var b E_(1+b)((|t|/scale)^alpha), b = 2 hurst/alpha, E_s(x) = x^(s-1) Gamma(1-s, x) (lower = "
               "0; with lower > 0 the difference of the two cut-offs' terms weighted by cut-off^(2 hurst))",
    .validity = "positive definite in every dimension for 0 < alpha <= 2, hurst > 0 (a positive mixture of stable "
                "correlations; Hesse et al. 2014)",
    .nparams = sizeof params / sizeof *params,
    .params = params,
    .npeers = sizeof peers / sizeof *peers,
    .peers = peers,
    .check = check,
    .profile = profile,
};
