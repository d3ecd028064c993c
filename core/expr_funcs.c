/* The functions an expression may call (core/expr_internal.h): libmatheval's
 * set, with its definitions, and the special functions covariance models are
 * written with (Bessel J, Y, K of real order, Gamma, incomplete gamma, erfc,
 * sinc), through GSL under the library's guard.  Every function returns NAN
 * outside its domain and never aborts. */
#include "expr_internal.h"
#include "gsl_guard_internal.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* libmatheval 1.1.11's own definitions (lib/xmath.c), kept so that an
 * expression evaluates as it did: acot(-1) = atan(-1), not 3 pi / 4. */
static double f_cot(double x) { return 1 / tan(x); }
static double f_sec(double x) { return 1 / cos(x); }
static double f_csc(double x) { return 1 / sin(x); }
static double f_acot(double x) { return atan(1 / x); }
static double f_asec(double x) { return acos(1 / x); }
static double f_acsc(double x) { return asin(1 / x); }
static double f_coth(double x) { return 1 / tanh(x); }
static double f_sech(double x) { return 1 / cosh(x); }
static double f_csch(double x) { return 1 / sinh(x); }
static double f_acoth(double x) { return 0.5 * log((x + 1) / (x - 1)); }
static double f_asech(double x) { return acosh(1 / x); }
static double f_acsch(double x) { return asinh(1 / x); }
static double f_step(double x) { return x < 0 ? 0 : 1; }
static double f_delta(double x) { return x == 0 ? INFINITY : 0; }
static double f_nandelta(double x) { return x == 0 ? NAN : 0; }

/* sin(x)/x, 1 at 0: the unnormalised cardinal sine (numpy's sinc is
 * sin(pi x)/(pi x)).  sin(x)/x is accurate to rounding for every x != 0. */
static double f_sinc(double x) { return x == 0 ? 1 : sin(x) / x; }

/* A GSL special function's value, through the guard: an underflow is the
 * (tiny or zero) value GSL computed, an overflow +-inf, any other error NAN. */
static double gsl_value(int status, const gsl_sf_result *r)
{
    if (status == GSL_SUCCESS || status == GSL_EUNDRFLW)
        return r->val;
    if (status == GSL_EOVRFLW)
        return r->val;
    return NAN;
}

static int is_int(double nu) { return nu == floor(nu) && fabs(nu) < 1e9; }

/* J_nu, Y_nu, K_nu of real order, x >= 0, nu >= 0 (GSL). */
static double jnu(double nu, double x)
{
    gsl_sf_result r;
    return gsl_value(gsl_sf_bessel_Jnu_e(nu, x, &r), &r);
}

static double ynu(double nu, double x)
{
    gsl_sf_result r;
    return gsl_value(gsl_sf_bessel_Ynu_e(nu, x, &r), &r);
}

/* J_nu(x) of real order (DLMF 10.2.2).  Negative x: J_n(-x) = (-1)^n J_n(x)
 * for integer n (DLMF 10.4.1), complex otherwise (NAN).  Negative order:
 * J_-n = (-1)^n J_n; J_-nu = cos(nu pi) J_nu - sin(nu pi) Y_nu (DLMF 10.4.7,
 * infinite at x = 0: NAN there). */
static double f_besselj(double nu, double x)
{
    double y;
    if (isnan(nu) || isnan(x) || isinf(nu))
        return NAN;
    if (isinf(x))
        return 0;
    if (x == 0) /* J_0(0) = 1, J_nu(0) = 0 for nu > 0 and integer nu < 0; J_-nu(0) infinite */
        return nu == 0 ? 1 : nu > 0 || is_int(nu) ? 0 : NAN;
    nl_gsl_enter();
    if (is_int(nu)) {
        int n = (int)fabs(nu);
        y = jnu(n, fabs(x));
        if ((x < 0) != (nu < 0) && n % 2)
            y = -y;
    } else if (x < 0) {
        y = NAN;
    } else if (nu >= 0) {
        y = jnu(nu, x);
    } else {
        y = cos(-nu * M_PI) * jnu(-nu, x) - sin(-nu * M_PI) * ynu(-nu, x);
    }
    nl_gsl_leave();
    return y;
}

/* Y_nu(x) of real order for x > 0 (DLMF 10.2.3; -inf at 0, complex below:
 * NAN for x <= 0).  Negative order: Y_-n = (-1)^n Y_n; Y_-nu = sin(nu pi)
 * J_nu + cos(nu pi) Y_nu (DLMF 10.4.8). */
static double f_bessely(double nu, double x)
{
    double y;
    if (isnan(nu) || isinf(nu) || !(x > 0))
        return NAN;
    if (isinf(x))
        return 0;
    nl_gsl_enter();
    if (is_int(nu)) {
        int n = (int)fabs(nu);
        y = ynu(n, x);
        if (nu < 0 && n % 2)
            y = -y;
    } else if (nu >= 0) {
        y = ynu(nu, x);
    } else {
        y = sin(-nu * M_PI) * jnu(-nu, x) + cos(-nu * M_PI) * ynu(-nu, x);
    }
    nl_gsl_leave();
    return y;
}

/* K_nu(x), the modified Bessel function of the second kind, for x > 0
 * (DLMF 10.25.3); even in nu (DLMF 10.27.3); +inf at x = 0 for every order;
 * NAN for x < 0 (complex). */
static double f_besselk(double nu, double x)
{
    gsl_sf_result r;
    double y;
    if (isnan(nu) || isinf(nu) || isnan(x) || x < 0)
        return NAN;
    if (x == 0)
        return INFINITY;
    if (isinf(x))
        return 0;
    nl_gsl_enter();
    y = gsl_value(gsl_sf_bessel_Knu_e(fabs(nu), x, &r), &r);
    nl_gsl_leave();
    return y;
}

/* Gamma(x) (DLMF 5.2.1): NAN at its poles 0, -1, -2, ...; +-inf past
 * overflow (x > 171.6). */
static double f_gamma(double x)
{
    gsl_sf_result r;
    double y;
    if (isnan(x) || (x <= 0 && x == floor(x)))
        return NAN;
    if (x > 172)
        return INFINITY;
    nl_gsl_enter();
    y = gsl_value(gsl_sf_gamma_e(x, &r), &r);
    nl_gsl_leave();
    return y;
}

/* log |Gamma(x)| (NAN at the poles). */
static double f_lgamma(double x)
{
    gsl_sf_result r;
    double y;
    if (isnan(x) || (x <= 0 && x == floor(x)))
        return NAN;
    nl_gsl_enter();
    y = gsl_value(gsl_sf_lngamma_e(x, &r), &r);
    nl_gsl_leave();
    return y;
}

/* The regularised lower and upper incomplete gamma functions P(a, x) =
 * gamma(a, x) / Gamma(a) and Q(a, x) = Gamma(a, x) / Gamma(a) = 1 - P
 * (DLMF 8.2.4), a > 0, x >= 0: scipy's gammainc and gammaincc, R's
 * pgamma(x, a) and pgamma(x, a, lower = FALSE). */
static double f_gammainc(double a, double x)
{
    gsl_sf_result r;
    double y;
    if (!(a > 0) || !(x >= 0) || isinf(a))
        return NAN;
    if (isinf(x))
        return 1;
    nl_gsl_enter();
    y = gsl_value(gsl_sf_gamma_inc_P_e(a, x, &r), &r);
    nl_gsl_leave();
    return y;
}

static double f_gammaincc(double a, double x)
{
    gsl_sf_result r;
    double y;
    if (!(a > 0) || !(x >= 0) || isinf(a))
        return NAN;
    if (isinf(x))
        return 0;
    nl_gsl_enter();
    y = gsl_value(gsl_sf_gamma_inc_Q_e(a, x, &r), &r);
    nl_gsl_leave();
    return y;
}

/* The non-normalised upper incomplete gamma function Gamma(a, x) =
 * int_x^inf t^(a-1) e^-t dt (DLMF 8.2.2) for any real a and x > 0, and
 * x = 0 with a > 0 (where it is Gamma(a)): Mathematica's Gamma[a, x], as
 * truncated power-law models use it with a <= 0. */
static double f_gammaupper(double a, double x)
{
    gsl_sf_result r;
    double y;
    if (isnan(a) || isinf(a) || isnan(x) || x < 0 || (x == 0 && a <= 0))
        return NAN;
    if (isinf(x))
        return 0;
    nl_gsl_enter();
    y = gsl_value(gsl_sf_gamma_inc_e(a, x, &r), &r);
    nl_gsl_leave();
    return y;
}

static const nl_expr_fun1 funs1[] = {
    {"exp", exp},         {"log", log},         {"sqrt", sqrt},       {"sin", sin},
    {"cos", cos},         {"tan", tan},         {"cot", f_cot},       {"sec", f_sec},
    {"csc", f_csc},       {"asin", asin},       {"acos", acos},       {"atan", atan},
    {"acot", f_acot},     {"asec", f_asec},     {"acsc", f_acsc},     {"sinh", sinh},
    {"cosh", cosh},       {"tanh", tanh},       {"coth", f_coth},     {"sech", f_sech},
    {"csch", f_csch},     {"asinh", asinh},     {"acosh", acosh},     {"atanh", atanh},
    {"acoth", f_acoth},   {"asech", f_asech},   {"acsch", f_acsch},   {"abs", fabs},
    {"step", f_step},     {"delta", f_delta},   {"nandelta", f_nandelta},
    {"erf", erf},         {"erfc", erfc},       {"sinc", f_sinc},     {"gamma", f_gamma},
    {"lgamma", f_lgamma},
};

static const nl_expr_fun2 funs2[] = {
    {"besselj", f_besselj},     {"bessely", f_bessely},     {"besselk", f_besselk},
    {"gammainc", f_gammainc},   {"gammaincc", f_gammaincc}, {"gammaupper", f_gammaupper},
};

/* libmatheval's constants, with its spelling (1_pi is one token there). */
static const nl_expr_const consts[] = {
    {"e", M_E},         {"pi", M_PI},       {"log2e", M_LOG2E},      {"log10e", M_LOG10E},
    {"ln2", M_LN2},     {"ln10", M_LN10},   {"pi_2", M_PI_2},        {"pi_4", M_PI_4},
    {"1_pi", M_1_PI},   {"2_pi", M_2_PI},   {"2_sqrtpi", M_2_SQRTPI}, {"sqrt2", M_SQRT2},
    {"sqrt1_2", M_SQRT1_2},
};

const nl_expr_fun1 *nl_expr_funs1(size_t *n)
{
    *n = sizeof funs1 / sizeof *funs1;
    return funs1;
}

const nl_expr_fun2 *nl_expr_funs2(size_t *n)
{
    *n = sizeof funs2 / sizeof *funs2;
    return funs2;
}

const nl_expr_const *nl_expr_consts(size_t *n)
{
    *n = sizeof consts / sizeof *consts;
    return consts;
}

void nl_expr_function_names(char *buf, size_t size)
{
    size_t n1, n2, o = 0;
    const nl_expr_fun1 *f1 = nl_expr_funs1(&n1);
    const nl_expr_fun2 *f2 = nl_expr_funs2(&n2);
    buf[0] = 0;
    for (size_t i = 0; i < n1 + n2 && o < size; i++) {
        int k = snprintf(buf + o, size - o, "%s%s", i == n1 ? ", or with two arguments " : i ? " " : "",
                         i < n1 ? f1[i].name : f2[i - n1].name);
        if (k < 0)
            break;
        o += (size_t)k;
    }
}
