/* Named distributions through GSL's densities, CDFs and inverse CDFs. */
#include "dist.h"
#include "gsl_guard_internal.h"
#include "expr_internal.h"
#include "nl_error.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { D_GAUSS, D_UNIFORM, D_LAPLACE, D_HYPERBOLIC, D_LOGNORMAL, D_CHI2, D_POWER, D_TABLE, D_EXPR };

struct nl_dist {
    int kind;         /* D_* */
    char *spec;       /* as given */
    double p1, p2;    /* parameters (mean/sd, a/b, a, zeta/sigma, P) */
    double *u, *y;    /* table: quantile samples */
    size_t n;         /* table length */
    nl_expr *eval;    /* expr: the compiled g(x) */
};

/* An expression nonlinearity g(x) of the standardised Gaussian input x:
 * one variable, x, and g finite wherever shaping and the Hermite
 * quadrature evaluate it (|x| <= NL_DIST_XMAX, probed at 2001 points). */
static int parse_expr(nl_dist *d, const char *text)
{
    static const char *const x[] = {"x"};
    const char *bad;
    int st;
    if (!*text)
        return NL_ERROR(NL_EINVAL, "expr: expected a function of x after \"expr:\" (e.g. expr:x^2)");
    if ((st = nl_expr_create(d->spec, text, &d->eval)))
        return st;
    if ((bad = nl_expr_bind(d->eval, x, 1)))
        return NL_ERROR(NL_EINVAL, "%s: unknown variable \"%s\" (expected x, the standardised Gaussian input)",
                        d->spec, bad);
    for (int i = 0; i <= 2000; i++) {
        double x = NL_DIST_XMAX * (i - 1000) / 1000.0, g = nl_dist_transform(d, x);
        if (!isfinite(g))
            return NL_ERROR(NL_EINVAL, "%s: g(%g) = %g; expected a function finite for |x| <= %g", d->spec, x, g,
                            NL_DIST_XMAX);
    }
    return NL_OK;
}

static int param(const char *spec, const char *key, double def, double *v)
{
    const char *p = strchr(spec, ':');
    size_t kl = strlen(key);
    *v = def;
    while (p && *p) {
        p++;
        if (strncmp(p, key, kl) == 0 && p[kl] == '=') {
            char *end;
            *v = strtod(p + kl + 1, &end);
            if (end == p + kl + 1 || (*end && *end != ',') || !isfinite(*v))
                return NL_ERROR(NL_EINVAL, "%s: %s: expected a number", spec, key);
            return NL_OK;
        }
        p = strchr(p, ',');
    }
    return NL_OK;
}

static int check_keys(const char *spec, const char *keys)
{
    const char *p = strchr(spec, ':');
    while (p && *p) {
        char key[32];
        size_t l;
        p++;
        l = strcspn(p, "=,");
        if (l == 0 || l >= sizeof key || p[l] != '=')
            return NL_ERROR(NL_EINVAL, "%s: expected key=value, got \"%.*s\"", spec, (int)strcspn(p, ","), p);
        memcpy(key, p, l);
        key[l] = 0;
        char pad[64];
        snprintf(pad, sizeof pad, " %s ", key);
        if (!strstr(keys, pad))
            return NL_ERROR(NL_EINVAL, "%s: unknown parameter \"%s\" (expected:%s)", spec, key, keys);
        p = strchr(p, ',');
    }
    return NL_OK;
}

static int load_table(nl_dist *d, const char *path)
{
    FILE *fp = fopen(path, "r");
    char line[512];
    size_t cap = 256, lineno = 0;
    int header = 1;
    if (!fp)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    d->u = malloc(cap * sizeof *d->u);
    d->y = malloc(cap * sizeof *d->y);
    while (d->u && d->y && fgets(line, sizeof line, fp)) {
        double u, y;
        char extra;
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        if (header) {
            header = 0;
            continue;
        }
        if (sscanf(line, "%lf %lf %c", &u, &y, &extra) != 2 || !isfinite(u) || !isfinite(y)) {
            fclose(fp);
            return NL_ERROR(NL_EINPUT, "table:%s:%zu: expected two numbers u y", path, lineno);
        }
        if ((d->n == 0 && u != 0) || (d->n > 0 && (u <= d->u[d->n - 1] || y < d->y[d->n - 1])) || u > 1) {
            fclose(fp);
            return NL_ERROR(NL_EINPUT, "table:%s:%zu: expected u increasing from 0 to 1 and y non-decreasing", path,
                            lineno);
        }
        if (d->n == cap) {
            cap *= 2;
            double *nu = realloc(d->u, cap * sizeof *nu), *ny = nu ? realloc(d->y, cap * sizeof *ny) : NULL;
            if (!nu || !ny) {
                fclose(fp);
                if (nu)
                    d->u = nu;
                return NL_ERROR(NL_ENOMEM, "out of memory");
            }
            d->u = nu, d->y = ny;
        }
        d->u[d->n] = u, d->y[d->n++] = y;
    }
    fclose(fp);
    if (!d->u || !d->y)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if (d->n < 2 || d->u[d->n - 1] != 1)
        return NL_ERROR(NL_EINPUT, "table:%s: expected at least two rows, the last with u = 1", path);
    return NL_OK;
}

/* Values not infinite as far into the tails as shaping evaluates the
 * quantile (u in [1e-300, 1 - 1e-16], synth/shape.c), nor their span. */
static int check_tails(const nl_dist *d)
{
    double lo = nl_dist_quantile(d, 1e-300), hi = nl_dist_quantile(d, 1 - 1e-16);
    /* NaN: GSL's chi-square inverse gives up that far out (the callers skip it) */
    if (isinf(lo) || isinf(hi) || isinf(hi - lo))
        return NL_ERROR(NL_EINVAL, "%s: the quantiles at u = 1e-300 and 1 - 1e-16 are %g and %g; expected "
                        "parameters whose values and their span stay finite", d->spec, lo, hi);
    return NL_OK;
}

int nl_dist_parse(const char *spec, nl_dist **out)
{
    static const struct {
        const char *name;
        int kind;
        const char *keys;
    } names[] = {{"gauss", D_GAUSS, " mean sd "},    {"uniform", D_UNIFORM, " a b "},
                 {"laplace", D_LAPLACE, " a "},      {"hyperbolic", D_HYPERBOLIC, " "},
                 {"lognormal", D_LOGNORMAL, " zeta sigma "}, {"chi2-1", D_CHI2, " "},
                 {"power", D_POWER, " p "}};
    nl_dist *d;
    size_t nl = strcspn(spec, ":");
    int st = NL_OK;
    *out = NULL;
    d = calloc(1, sizeof *d);
    if (!d || !(d->spec = strdup(spec))) {
        free(d);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    d->kind = -1;
    if (nl == 4 && strncmp(spec, "expr", 4) == 0 && spec[4] == ':') {
        d->kind = D_EXPR;
        st = parse_expr(d, spec + 5);
        if (st) {
            nl_dist_free(d);
            return st;
        }
        *out = d;
        return NL_OK;
    }
    if (nl == 5 && strncmp(spec, "table", 5) == 0) {
        d->kind = D_TABLE;
        st = spec[5] == ':' && spec[6] ? load_table(d, spec + 6)
                                       : NL_ERROR(NL_EINVAL, "table: expected table:FILE with columns u y");
    } else {
        for (size_t i = 0; i < sizeof names / sizeof *names; i++)
            if (strlen(names[i].name) == nl && strncmp(spec, names[i].name, nl) == 0) {
                d->kind = names[i].kind;
                st = check_keys(spec, names[i].keys);
            }
        if (d->kind < 0)
            st = NL_ERROR(NL_EINVAL, "distribution: unknown \"%.*s\" (expected gauss, uniform, laplace, hyperbolic, "
                          "lognormal, chi2-1, power:p=P, table:FILE or expr:g(x))", (int)nl, spec);
    }
    if (!st) {
        switch (d->kind) {
        case D_GAUSS:
            if (!(st = param(spec, "mean", 0, &d->p1)) && !(st = param(spec, "sd", 1, &d->p2)) && !(d->p2 > 0))
                st = NL_ERROR(NL_EINVAL, "%s: sd: expected a positive number, got %g", spec, d->p2);
            break;
        case D_UNIFORM:
            if (!(st = param(spec, "a", 0, &d->p1)) && !(st = param(spec, "b", 1, &d->p2)) && !(d->p2 > d->p1))
                st = NL_ERROR(NL_EINVAL, "%s: expected a < b, got a=%g, b=%g", spec, d->p1, d->p2);
            break;
        case D_LAPLACE:
            if (!(st = param(spec, "a", 1, &d->p1)) && !(d->p1 > 0))
                st = NL_ERROR(NL_EINVAL, "%s: a: expected a positive scale, got %g", spec, d->p1);
            break;
        case D_LOGNORMAL:
            if (!(st = param(spec, "zeta", 0, &d->p1)) && !(st = param(spec, "sigma", 1, &d->p2)) && !(d->p2 > 0))
                st = NL_ERROR(NL_EINVAL, "%s: sigma: expected a positive number, got %g", spec, d->p2);
            break;
        case D_POWER:
            if (!(st = param(spec, "p", NAN, &d->p1)) && !(d->p1 > 0))
                st = NL_ERROR(NL_EINVAL, "%s: p: expected a positive exponent (e.g. power:p=2.5)", spec);
            break;
        default:
            break;
        }
    }
    if (!st)
        st = check_tails(d);
    if (st) {
        nl_dist_free(d);
        return st;
    }
    *out = d;
    return NL_OK;
}

void nl_dist_free(nl_dist *d)
{
    if (!d)
        return;
    nl_expr_free(d->eval);
    free(d->u), free(d->y), free(d->spec), free(d);
}

int nl_dist_is_function(const nl_dist *d) { return d->kind == D_EXPR; }

double nl_dist_transform(const nl_dist *d, double x)
{
    if (d->kind == D_EXPR)
        return nl_expr_eval(d->eval, &x);
    /* u inside (0, 1), so that every quantile is finite */
    double u = fmin(fmax(gsl_cdf_ugaussian_P(x), 1e-300), 1 - 1e-16);
    return nl_dist_quantile(d, u);
}

const char *nl_dist_spec(const nl_dist *d) { return d->spec; }

static double table_interp(const double *x, const double *y, size_t n, double v)
{
    size_t lo = 0, hi = n - 1;
    if (v <= x[0])
        return y[0];
    if (v >= x[n - 1])
        return y[n - 1];
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (x[mid] <= v)
            lo = mid;
        else
            hi = mid;
    }
    return x[hi] > x[lo] ? y[lo] + (y[hi] - y[lo]) * (v - x[lo]) / (x[hi] - x[lo]) : y[hi];
}

/* Of the GSL functions used here only the chi-square ones have an error path
 * (the inverse fails to converge for u below about 1e-300; probed over
 * extreme arguments), so only they are guarded. */
static double chi2_cdf(double y)
{
    double v;
    nl_gsl_enter();
    v = gsl_cdf_chisq_P(y, 1);
    nl_gsl_leave();
    return v;
}

static double chi2_quantile(double u)
{
    double v;
    nl_gsl_enter();
    v = gsl_cdf_chisq_Pinv(u, 1);
    nl_gsl_leave();
    return v;
}

double nl_dist_cdf(const nl_dist *d, double y)
{
    switch (d->kind) {
    case D_GAUSS: return gsl_cdf_gaussian_P(y - d->p1, d->p2);
    case D_UNIFORM: return gsl_cdf_flat_P(y, d->p1, d->p2);
    case D_LAPLACE: return gsl_cdf_laplace_P(y, d->p1);
    case D_HYPERBOLIC: return 2 / M_PI * atan(exp(M_PI * y / 2));
    case D_LOGNORMAL: return gsl_cdf_lognormal_P(y, d->p1, d->p2);
    case D_CHI2: return chi2_cdf(y);
    case D_POWER: return y <= 0 ? 0 : y >= 1 ? 1 : pow(y, 1 / d->p1);
    case D_EXPR: return NAN;
    default: return table_interp(d->y, d->u, d->n, y);
    }
}

double nl_dist_pdf(const nl_dist *d, double y)
{
    switch (d->kind) {
    case D_GAUSS: return gsl_ran_gaussian_pdf(y - d->p1, d->p2);
    case D_UNIFORM: return gsl_ran_flat_pdf(y, d->p1, d->p2);
    case D_LAPLACE: return gsl_ran_laplace_pdf(y, d->p1);
    case D_HYPERBOLIC: return 0.5 / cosh(M_PI * y / 2);
    case D_LOGNORMAL: return gsl_ran_lognormal_pdf(y, d->p1, d->p2);
    case D_CHI2: return gsl_ran_chisq_pdf(y, 1);
    case D_POWER: return y <= 0 || y > 1 ? 0 : pow(y, 1 / d->p1 - 1) / d->p1;
    default: return NAN;
    }
}

double nl_dist_quantile(const nl_dist *d, double u)
{
    switch (d->kind) {
    case D_GAUSS: return d->p1 + gsl_cdf_gaussian_Pinv(u, d->p2);
    case D_UNIFORM: return gsl_cdf_flat_Pinv(u, d->p1, d->p2);
    case D_LAPLACE: return gsl_cdf_laplace_Pinv(u, d->p1);
    case D_HYPERBOLIC: return 2 / M_PI * log(tan(M_PI * u / 2));
    case D_LOGNORMAL: return gsl_cdf_lognormal_Pinv(u, d->p1, d->p2);
    case D_CHI2: return chi2_quantile(u);
    case D_POWER: return pow(u, d->p1);
    case D_EXPR: return NAN;
    default: return table_interp(d->u, d->y, d->n, u);
    }
}

double nl_dist_mean(const nl_dist *d)
{
    switch (d->kind) {
    case D_GAUSS: return d->p1;
    case D_UNIFORM: return 0.5 * (d->p1 + d->p2);
    case D_LAPLACE: case D_HYPERBOLIC: return 0;
    case D_LOGNORMAL: return exp(d->p1 + 0.5 * d->p2 * d->p2);
    case D_CHI2: return 1;
    case D_POWER: return 1 / (d->p1 + 1);
    default: return NAN;
    }
}

double nl_dist_variance(const nl_dist *d)
{
    switch (d->kind) {
    case D_GAUSS: return d->p2 * d->p2;
    case D_UNIFORM: return (d->p2 - d->p1) * (d->p2 - d->p1) / 12;
    case D_LAPLACE: return 2 * d->p1 * d->p1;
    case D_HYPERBOLIC: return 1;
    case D_LOGNORMAL: return (exp(d->p2 * d->p2) - 1) * exp(2 * d->p1 + d->p2 * d->p2);
    case D_CHI2: return 2;
    case D_POWER: return 1 / (2 * d->p1 + 1) - 1 / ((d->p1 + 1) * (d->p1 + 1));
    default: return NAN;
    }
}

/* Raw moments E[U^(kP)] = 1 / (kP + 1) of power:p=P turned into central
 * ones; k = 3 or 4 gives the skewness or the excess kurtosis. */
static double power_shape(double P, int k)
{
    double m1 = 1 / (P + 1), m2 = 1 / (2 * P + 1), m3 = 1 / (3 * P + 1), m4 = 1 / (4 * P + 1);
    double c2 = m2 - m1 * m1, c3 = m3 - 3 * m1 * m2 + 2 * m1 * m1 * m1;
    double c4 = m4 - 4 * m1 * m3 + 6 * m1 * m1 * m2 - 3 * m1 * m1 * m1 * m1;
    return k == 3 ? c3 / pow(c2, 1.5) : c4 / (c2 * c2) - 3;
}

static double finite_or_nan(double v) { return isfinite(v) ? v : NAN; }

double nl_dist_skewness(const nl_dist *d)
{
    double s2 = d->p2 * d->p2;
    switch (d->kind) {
    case D_GAUSS: case D_UNIFORM: case D_LAPLACE: case D_HYPERBOLIC: return 0;
    case D_LOGNORMAL: return finite_or_nan((exp(s2) + 2) * sqrt(expm1(s2)));
    case D_CHI2: return sqrt(8);
    case D_POWER: return finite_or_nan(power_shape(d->p1, 3));
    default: return NAN;
    }
}

double nl_dist_kurtosis(const nl_dist *d)
{
    double s2 = d->p2 * d->p2;
    switch (d->kind) {
    case D_GAUSS: return 0;
    case D_UNIFORM: return -1.2;
    case D_LAPLACE: return 3;
    case D_HYPERBOLIC: return 2;
    case D_LOGNORMAL: return finite_or_nan(exp(4 * s2) + 2 * exp(3 * s2) + 3 * exp(2 * s2) - 6);
    case D_CHI2: return 12;
    case D_POWER: return finite_or_nan(power_shape(d->p1, 4));
    default: return NAN;
    }
}
