/* Valid neighbours of a model that is not positive definite: the nearest
 * valid oscillation frequency, the separable product, the spherical model. */
#include "check_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* 1 when spec parses and checks positive definite in dim, else 0. */
static int valid(const char *spec, int dim)
{
    nl_model *m;
    nl_check c;
    int ok;
    if (nl_model_parse(spec, &m))
        return 0;
    ok = nl_check_model(m, dim, &c) == NL_OK && c.positive_definite;
    nl_model_free(m);
    return ok;
}

/* Append line to buf (size bytes) after a '\n' if buf is not empty. */
static void add(char *buf, size_t size, const char *line)
{
    size_t n = strlen(buf);
    snprintf(buf + n, size - n, "%s%s", n ? "\n" : "", line);
}

/* ",scale=S,var=V" for the values that differ from the defaults. */
static void scale_var(const nl_model *m, char *out, size_t size)
{
    double s = 1, v = 1;
    size_t n;
    nl_model_param(m, "scale", &s);
    nl_model_param(m, "var", &v);
    out[0] = 0;
    if (s != 1)
        snprintf(out, size, ",scale=%.15g", s);
    n = strlen(out);
    if (v != 1)
        snprintf(out + n, size - n, ",var=%.15g", v);
}

/* oscillatory, gauss-osc: the largest omega valid in dim, by bisection
 * (validity is lost as omega grows: the d-dimensional spectrum of
 * cos(omega r) times a decay turns negative near k = 0; gauss-osc in 3D at
 * omega = sqrt(2), oscillatory in 2D at omega = 1 / scale), less 2% for the
 * frequency resolution of check's scans, rounded down to 3 significant
 * digits and verified. */
static void largest_omega(const nl_model *m, int dim, char *buf, size_t size)
{
    const char *fam = nl_model_family(m)->name;
    double lo = 0, hi = 0, w;
    char spec[256], rest[128];
    nl_model_param(m, "omega", &hi);
    scale_var(m, rest, sizeof rest);
    for (int i = 0; i < 12; i++) {
        double mid = 0.5 * (lo + hi);
        snprintf(spec, sizeof spec, "%s:omega=%.17g%s", fam, mid, rest);
        if (valid(spec, dim))
            lo = mid;
        else
            hi = mid;
    }
    lo *= 0.98;  /* a margin for the scans' resolution of the boundary */
    if (!(lo > 0))
        return;
    for (int t = 0; t < 4; t++) {
        double p = pow(10, 2 - floor(log10(lo)));
        w = (floor(lo * p) - t) / p;
        snprintf(spec, sizeof spec, "%s:omega=%.3g%s", fam, w, rest);
        if (w > 0 && valid(spec, dim)) {
            add(buf, size, spec);
            return;
        }
    }
}

/* An isotropic model valid in 1D: its separable product R(x) R(y) R(z) is
 * valid in every dimension (a product of covariances). */
static void separable(const nl_model *m, int dim, char *buf, size_t size)
{
    const char *spec = nl_model_spec(m);
    nl_check c1;
    char s[1024];
    if (nl_check_model(m, 1, &c1) != NL_OK || !c1.positive_definite)
        return;
    if (nl_model_family(m)->flags & NL_FAMILY_ARGUMENT)
        snprintf(s, sizeof s, "%s%s", spec, strrchr(spec, ';') ? ",sep" : ";sep");
    else
        snprintf(s, sizeof s, "%s%s", spec, strchr(spec, ':') ? ",sep" : ":sep");
    if (strlen(s) < sizeof s - 1 && valid(s, dim))
        add(buf, size, s);
}

/* An isotropic expression that vanishes beyond a lag a (found by
 * bisection between the last nonzero and the first zero lag): the
 * spherical model of range a, valid up to 3D. */
static void spherical(const nl_model *m, int dim, double L, char *buf, size_t size)
{
    double zero[3] = {0, 0, 0}, v = nl_model_acf(m, dim, zero), lo = 0, hi = L, a;
    char s[256];
    for (int i = 1; i <= 64; i++) {
        double lag[3] = {L * (1 + i / 16.0), 0, 0};
        if (nl_model_acf(m, dim, lag) != 0)
            return;  /* not compactly supported within 5 L */
    }
    for (int i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi), lag[3] = {mid, 0, 0};
        if (nl_model_acf(m, dim, lag) != 0)
            lo = mid;
        else
            hi = mid;
    }
    a = hi;
    if (!(a > 0))
        return;
    if (v == 1 && a == 1)
        snprintf(s, sizeof s, "expr:step(1-r)*(1-1.5*r+0.5*r^3)");
    else if (v == 1)
        snprintf(s, sizeof s, "expr:step(%.6g-r)*(1-1.5*r/%.6g+0.5*(r/%.6g)^3)", a, a, a);
    else
        snprintf(s, sizeof s, "expr:%.15g*step(%.6g-r)*(1-1.5*r/%.6g+0.5*(r/%.6g)^3)", v, a, a, a);
    if (valid(s, dim))
        add(buf, size, s);
}

int nl_check_neighbours(const nl_model *m, const nl_check *c, char *buf, size_t size)
{
    const nl_family *k = nl_model_family(m);
    double omega;
    if (!size)
        return NL_OK;
    buf[0] = 0;
    /* a sum or product: no single parameter or key to move */
    if (c->positive_definite || !c->isotropic || nl_model_is_spectral(m) || k == &nl_family_image ||
        (k->flags & NL_FAMILY_COMPOSITE))
        return NL_OK;
    /* a family with an oscillation frequency */
    if (nl_model_param(m, "omega", &omega) == NL_OK)
        largest_omega(m, c->dim, buf, size);
    if (k == &nl_family_expr)
        spherical(m, c->dim, c->scale, buf, size);
    separable(m, c->dim, buf, size);
    return NL_OK;
}
