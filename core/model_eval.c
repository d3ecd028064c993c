/* Evaluation of R(lag) and S(f) for every model family. */
#include "gsl_guard_internal.h"
#include "model_internal.h"

#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>
#include <matheval.h>
#include <string.h>

static double eval_expr(void *ev, const char *const *names, double *values, int n)
{
    return evaluator_evaluate(ev, n, (char **)names, values);
}

static double acf_expr(const nl_model *m, double t, double x, double y, double z, double r)
{
    static const char *const names[] = {"t", "x", "y", "z", "r"};
    double v[] = {t, x, y, z, r};
    return eval_expr(m->eval, names, v, 5);
}

/* Above this nu, GSL's K_nu costs time proportional to nu (2 s of CPU for
 * 31 lags at nu = 1e7), and the large-nu form below omits terms of order
 * 1 / nu^2 < 1e-12. */
#define MATERN_NU_ASYMPTOTIC 1e6
/* Beyond it nu is no longer a shape parameter but an input error (gauss is
 * the model); the value is NaN, which every method refuses as "not finite",
 * as GSL's K_nu did for nu of 1e300 and more. */
#define MATERN_NU_MAX 1e15

/* The Matern correlation for large nu as a function of a = u / sqrt(2 nu):
 * from the uniform (Debye) expansion of K_nu(nu z) (Abramowitz and Stegun
 * 9.7.8) and Stirling's series of Gamma(nu),
 *     ln R = -a^2 / 2 + (a^4 - 4 a^2) / (8 nu) + O(a^6 / nu^2),
 * the Gauss limit exp(-a^2 / 2) (off by up to 0.23 / nu) with its first
 * correction.  The omitted terms are R times a polynomial in a^2 over nu^2,
 * small while a^2 << nu (R underflows before a^2 reaches 1500, where a^2 / nu
 * is still < 2e-3); at nu = 2e6 the form agrees with K_nu to the 1e-8 that
 * K_nu's own logarithms keep (tests/test_model.c). */
static double matern_large_nu(double nu, double u)
{
    double a2 = u * u / (2 * nu);
    return exp(-a2 / 2 + (a2 * a2 - 4 * a2) / (8 * nu));
}

/* The only GSL calls of the closed-form models, so the only guarded path:
 * markov, gauss and the others never touch the guard. */
static double matern(double nu, double u)
{
    gsl_sf_result lk, lg;
    int st;
    if (u == 0)
        return 1.0;
    if (nu > MATERN_NU_MAX)
        return NAN;
    if (nu > MATERN_NU_ASYMPTOTIC)
        return matern_large_nu(nu, u);
    nl_gsl_enter();
    st = gsl_sf_bessel_lnKnu_e(nu, u, &lk) || gsl_sf_lngamma_e(nu, &lg);
    nl_gsl_leave();
    if (st)
        return 0.0;
    return exp((1 - nu) * M_LN2 - lg.val + nu * log(u) + lk.val);
}

/* The 1D profile R1(t) of a model, t signed. */
static double profile(const nl_model *m, double t)
{
    double a = fabs(t) / m->scale;
    switch (m->kind) {
    case NL_MODEL_MARKOV: return m->var * exp(-a);
    case NL_MODEL_GAUSS: return m->var * exp(-a * a);
    case NL_MODEL_MARKAUSSIAN: return m->var * exp(-pow(a, m->alpha));
    case NL_MODEL_OSCILLATORY: return m->var * cos(m->omega * t) * exp(-a);
    case NL_MODEL_GAUSS_OSC: return m->var * cos(m->omega * t) * exp(-a * a);
    case NL_MODEL_MATERN: return m->var * matern(m->nu, sqrt(2 * m->nu) * a);
    /* the spherical model of range `scale` (Matheron 1971; gstat "Sph", GSTools Spherical with len_scale = a) */
    case NL_MODEL_SPHERICAL: return a < 1 ? m->var * (1 - a * (1.5 - 0.5 * a * a)) : 0.0;
    case NL_MODEL_EXPR: return acf_expr(m, t, t, 0, 0, fabs(t));
    case NL_MODEL_IMAGE: return nl_model_image_acf(m, t, 0);
    default: return NAN;
    }
}

static double acf_continuous(const nl_model *m, int dim, const double *lag);

/* The nugget is white noise: it adds to R at lag 0 exactly and nowhere else. */
double nl_model_acf(const nl_model *m, int dim, const double *lag)
{
    double v = acf_continuous(m, dim, lag);
    if (m->nugget != 0) {
        int zero = 1;
        for (int a = 0; a < dim; a++)
            zero &= lag[a] == 0;
        if (zero)
            v += m->nugget;
    }
    return v;
}

static double acf_continuous(const nl_model *m, int dim, const double *lag)
{
    double u, v, w, r;
    if (m->kind == NL_MODEL_POWER) {
        double r2 = 0;
        for (int a = 0; a < dim; a++)
            r2 += lag[a] * lag[a];
        return nl_model_power_acf(m, dim, sqrt(r2));
    }
    if (nl_model_is_spectral(m))
        return NAN;
    if (dim == 1)
        return profile(m, lag[0]);
    if (m->kind == NL_MODEL_IMAGE)
        return nl_model_image_acf(m, lag[0], lag[1]);
    /* Stam and Fiume's ellipsoid: rotate by -angle, then shrink the y and z
     * axes by their length ratios. */
    u = m->cosa * lag[0] + m->sina * lag[1];
    v = (-m->sina * lag[0] + m->cosa * lag[1]) / m->ratio;
    w = dim == 3 ? lag[2] / m->zratio : 0;
    if (m->sep) {
        double r0 = profile(m, 0), p = profile(m, u) * profile(m, v);
        if (dim == 3)
            p *= profile(m, w) / r0;
        return p / r0;
    }
    r = sqrt(u * u + v * v + w * w);
    if (m->kind == NL_MODEL_EXPR)
        return acf_expr(m, r, u, v, w, r);
    return profile(m, r);
}

/* Integral of k^-d over fmin <= |k| <= fmax in `dim` dimensions. */
static double power_norm(const nl_model *m, int dim)
{
    static const double shell[] = {0, 2.0, 2 * M_PI, 4 * M_PI};
    double e = dim - 1 - m->d;  /* integrand k^e dk over the radius */
    double radial;
    if (fabs(e + 1) < 1e-12)
        radial = log(m->fmax / m->fmin);
    else
        radial = (pow(m->fmax, e + 1) - pow(m->fmin, e + 1)) / (e + 1);
    return shell[dim] * radial;
}

/* Two-sided 1D spectrum of a Markov (exponential) and a Gaussian ACF. */
static double s_markov(double var, double s, double f)
{
    double q = 2 * M_PI * f * s;
    return var * 2 * s / (1 + q * q);
}

static double s_gauss(double var, double s, double f)
{
    double q = M_PI * f * s;
    return var * s * sqrt(M_PI) * exp(-q * q);
}

double nl_model_spectrum(const nl_model *m, int dim, const double *f)
{
    double k2 = 0, k, f0 = m->omega / (2 * M_PI);
    for (int a = 0; a < dim; a++)
        k2 += f[a] * f[a];
    k = sqrt(k2);
    switch (m->kind) {
    case NL_MODEL_POWER:
        if (k < m->fmin || k > m->fmax || k == 0)
            return 0.0;
        return m->var / power_norm(m, dim) * pow(k, -m->d);
    case NL_MODEL_SPECTRUM: {
        static const char *const names[] = {"f", "fx", "fy", "fz", "k"};
        double v[] = {dim == 1 ? f[0] : k, f[0], dim > 1 ? f[1] : 0, dim > 2 ? f[2] : 0, k};
        return eval_expr(m->eval, names, v, 5);
    }
    default:
        break;
    }
    if (dim != 1)
        return NAN;
    switch (m->kind) {
    case NL_MODEL_MARKOV: return s_markov(m->var, m->scale, f[0]);
    case NL_MODEL_GAUSS: return s_gauss(m->var, m->scale, f[0]);
    case NL_MODEL_OSCILLATORY:
        return 0.5 * (s_markov(m->var, m->scale, f[0] - f0) + s_markov(m->var, m->scale, f[0] + f0));
    case NL_MODEL_GAUSS_OSC:
        return 0.5 * (s_gauss(m->var, m->scale, f[0] - f0) + s_gauss(m->var, m->scale, f[0] + f0));
    default: return NAN;
    }
}

static const nl_model_info catalogue[] = {
    {"markov", "[scale=1,var=1,nugget=0]", "R = var exp(-|t|/scale) (+ nugget at t = 0, as every R model); 1D S = var 2 scale / (1 + (2 pi f scale)^2)"},
    {"gauss", "[scale=1,var=1,nugget=0]", "R = var exp(-(t/scale)^2); 1D S = var scale sqrt(pi) exp(-(pi f scale)^2)"},
    {"markaussian", "alpha=A [,scale=1,var=1,nugget=0]", "R = var exp(-|t/scale|^alpha), 0 < alpha <= 2"},
    {"oscillatory", "omega=W [,scale=1,var=1,nugget=0]", "R = var cos(omega t) exp(-|t|/scale)"},
    {"gauss-osc", "omega=W [,scale=1,var=1,nugget=0]", "R = var cos(omega t) exp(-(t/scale)^2)"},
    {"matern", "nu=V [,scale=1,var=1,nugget=0]",
     "R = var 2^(1-nu)/Gamma(nu) u^nu K_nu(u), u = sqrt(2 nu) |t| / scale"},
    {"spherical", "[scale=1,var=1,nugget=0]",
     "R = var (1 - 1.5 a + 0.5 a^3) for a = |t|/scale < 1, else 0 (scale = range); valid in 1D to 3D"},

    {"power", "d=D [,fmin=1/1024,fmax=0.5,var=1]",
     "S = c |f|^-d for fmin <= |f| <= fmax (0 elsewhere), c such that the integral of S is var"},
    {"expr:EXPR", "variables t, x, y, z, r [;nugget=0]", "R = EXPR (libmatheval syntax), e.g. expr:cos(10*t)*exp(-abs(t))"},
    {"spectrum:EXPR", "variables f, fx, fy, fz, k", "S = EXPR, a non-negative two-sided density"},
    {"image:FILE", "PNG (8/16-bit grey) or EXR [;nugget=0]", "R = empirical autocorrelation of the exemplar (Lewis 1987, eq. 15)"},
};

const nl_model_info *nl_model_catalogue(size_t *count)
{
    *count = sizeof catalogue / sizeof *catalogue;
    return catalogue;
}

double nl_model_acf_d2(const nl_model *m, double t)
{
    static const char *const names[] = {"t", "x", "y", "z", "r"};
    double v[] = {t, t, 0, 0, fabs(t)}, y;
    void *d1, *d2, *dr1, *dr2;
    if (m->kind != NL_MODEL_EXPR)
        return NAN;
    /* R is a function of t (= x in 1D) and r = |t|: d/dt = d/dt + sign(t) d/dr */
    d1 = evaluator_derivative(m->eval, "t");
    dr1 = evaluator_derivative(m->eval, "r");
    if (!d1 || !dr1) {
        if (d1) evaluator_destroy(d1);
        if (dr1) evaluator_destroy(dr1);
        return NAN;
    }
    d2 = evaluator_derivative(d1, "t");
    dr2 = evaluator_derivative(dr1, "r");
    y = d2 && dr2 ? evaluator_evaluate(d2, 5, (char **)names, v) + evaluator_evaluate(dr2, 5, (char **)names, v)
                  : NAN;
    if (d2) evaluator_destroy(d2);
    if (dr2) evaluator_destroy(dr2);
    evaluator_destroy(d1);
    evaluator_destroy(dr1);
    return y;
}

int nl_model_is_isotropic(const nl_model *m)
{
    if (m->sep || m->angle != 0 || m->ratio != 1 || m->zratio != 1 || m->kind == NL_MODEL_IMAGE)
        return 0;
    if (m->kind == NL_MODEL_EXPR || m->kind == NL_MODEL_SPECTRUM) {
        char **names;
        int n;
        evaluator_get_variables(m->eval, &names, &n);
        for (int i = 0; i < n; i++)
            if (strchr("xyz", names[i][0]) || strcmp(names[i], "fx") == 0 || strcmp(names[i], "fy") == 0 ||
                strcmp(names[i], "fz") == 0)
                return 0;
    }
    return 1;
}
