/* Hermite coefficients by Gauss-Hermite quadrature (GSL). */
#include "nonlin.h"
#include "acf.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/wk.h"
#include "../synth/fft.h"
#include "../synth/shape.h"

#include <stdlib.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>
#include <string.h>

/* The expansion finite, and the quadrature's variance that of the
 * distribution (to 1%) where it is known in closed form: tails too heavy
 * for the 400 nodes (lognormal with a large sigma) or values near the
 * overflow threshold make the series wrong, not just truncated. */
static int check_expansion(const nl_dist *to, double m1, const nl_hermite *h)
{
    double dv = nl_dist_variance(to);
    int ok = isfinite(m1) && isfinite(h->variance) && isfinite(h->truncation);
    for (int n = 0; ok && n < h->terms; n++)
        ok = isfinite(h->c[n]);
    if (!ok)
        return NL_ERROR(NL_EINVAL, "%s: the Hermite expansion overflows (output mean %g, variance %g); expected a "
                        "distribution whose mean and variance stay below 1e150", nl_dist_spec(to), m1, h->variance);
    if (!(h->variance > 0))
        return NL_ERROR(NL_EINVAL, "%s: the output is constant to rounding (variance %g about the mean %g); "
                        "expected a distribution with a spread", nl_dist_spec(to), h->variance, m1);
    if (isfinite(dv) && fabs(h->variance - dv) > 1e-2 * dv)
        return NL_ERROR(NL_EINVAL, "%s: the quadrature finds an output variance of %g, the distribution has %g: "
                        "its tails are too heavy for the Hermite expansion; expected a lighter-tailed g (e.g. a "
                        "smaller sigma)", nl_dist_spec(to), h->variance, dv);
    return NL_OK;
}

/* c_n = E[g(Z) He_n(Z)] / n! for an expr: nonlinearity, by adaptive
 * quadrature (GSL QAGS) of g He_n phi over |z| <= 40 (phi(40) ~ 1e-348):
 * Gauss-Hermite nodes converge slowly when g has a jump or a kink (sgn(x)'s
 * c_1 was off by 1e-3 with 400 nodes), bisection finds them. */
struct hterm {
    const nl_dist *g;
    int n;      /* He_n; -1: g^2 (the second moment) */
};

static double hterm_f(double z, void *p)
{
    const struct hterm *t = p;
    double g = nl_dist_transform(t->g, z), phi = exp(-0.5 * z * z) / sqrt(2 * M_PI), a = 1, b = z;
    if (!isfinite(g))
        return 0;
    if (t->n < 0)
        return g * g * phi;
    if (t->n == 0)
        return g * phi;
    for (int k = 1; k < t->n; k++) {
        double c = z * b - k * a;
        a = b, b = c;
    }
    return g * b * phi;
}

static int expand_adaptive(const nl_dist *to, int terms, nl_hermite *h)
{
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(4000);
    struct hterm t = {to, 0};
    gsl_function F = {hterm_f, &t};
    double m2 = 0, err;
    int st = NL_OK;
    if (!w)
        return NL_ERROR(NL_ENOMEM, "out of memory for the quadrature");
    memset(h, 0, sizeof *h);
    h->terms = terms;
    for (t.n = -1; t.n < terms && !st; t.n++) {
        /* |E[g He_n]| <= sqrt(E[g^2] n!): the scale of each integral */
        double v, scale = t.n < 0 ? 1 : sqrt(m2 * gsl_sf_fact((unsigned)t.n));
        if (gsl_integration_qags(&F, -40, 40, 1e-14 * scale, 1e-12, 4000, w, &v, &err) && !(err <= 1e-9 * scale))
            st = NL_ERROR(NL_EINVAL, "%s: the Hermite coefficient %d does not converge (%g +- %g); expected a g "
                          "that grows slower than exp(x^2 / 4)", nl_dist_spec(to), t.n, v, err);
        if (t.n < 0 && !(isfinite(v) && v > 0))
            st = NL_ERROR(NL_EINVAL, "%s: E[g(Z)^2] = %g; expected a finite positive second moment",
                          nl_dist_spec(to), v);
        if (t.n < 0)
            m2 = v;
        else
            h->c[t.n] = v / gsl_sf_fact((unsigned)t.n);
    }
    gsl_integration_workspace_free(w);
    if (st)
        return st;
    h->variance = m2 - h->c[0] * h->c[0];
    h->truncation = h->variance;
    for (int n = 1; n < terms; n++)
        h->truncation -= h->c[n] * h->c[n] * gsl_sf_fact((unsigned)n);
    return check_expansion(to, h->c[0], h);
}

static int hermite_expand(const nl_dist *to, int terms, nl_hermite *h)
{
    const size_t nodes = 400;
    gsl_integration_fixed_workspace *w;
    double he[NL_HERMITE_MAX + 1], m1 = 0, m2 = 0;
    if (terms < 2 || terms > NL_HERMITE_MAX)
        return NL_ERROR(NL_EINVAL, "terms: expected 2 to %d Hermite terms, got %d", NL_HERMITE_MAX, terms);
    if (nl_dist_is_function(to))
        return expand_adaptive(to, terms, h);
    /* weight exp(-u^2); E[f(Z)] = pi^-1/2 int f(sqrt 2 u) exp(-u^2) du */
    w = gsl_integration_fixed_alloc(gsl_integration_fixed_hermite, nodes, 0, 1, 0, 0);
    if (!w)
        return NL_ERROR(NL_ENOMEM, "out of memory for the quadrature");
    memset(h, 0, sizeof *h);
    h->terms = terms;
    const double *x = gsl_integration_fixed_nodes(w), *wt = gsl_integration_fixed_weights(w);
    for (size_t i = 0; i < nodes; i++) {
        double z = M_SQRT2 * x[i], p = wt[i] / sqrt(M_PI), G = nl_dist_transform(to, z);
        if (!isfinite(G))
            continue;
        he[0] = 1, he[1] = z;
        for (int n = 1; n < terms; n++)
            he[n + 1] = z * he[n] - n * he[n - 1];
        for (int n = 0; n < terms; n++)
            h->c[n] += p * G * he[n];
        m1 += p * G, m2 += p * G * G;
    }
    gsl_integration_fixed_free(w);
    h->variance = m2 - m1 * m1;
    h->truncation = h->variance;
    for (int n = 1; n < terms; n++) {
        h->c[n] /= gsl_sf_fact((unsigned)n);
        h->truncation -= h->c[n] * h->c[n] * gsl_sf_fact((unsigned)n);
    }
    return check_expansion(to, m1, h);
}

double nl_hermite_cov(const nl_hermite *h, double rho)
{
    double s = 0, p = 1;
    for (int n = 1; n < h->terms; n++) {
        p *= rho;
        s += h->c[n] * h->c[n] * gsl_sf_fact((unsigned)n) * p;
    }
    return s;
}

/* Steps of the scan of [0, 1] and of [-1, 0] that brackets a root.  The
 * series need not be monotone: an even g (x^2, |x|) has only even terms and
 * an even covariance in rho, a mixed one can turn. */
enum { INVERT_STEPS = 512 };

/* Bisect cov(rho) = cov between a and b, where the difference changes sign. */
static double bisect(const nl_hermite *h, double cov, double a, double b)
{
    double fa = nl_hermite_cov(h, a) - cov;
    for (int i = 0; i < 100; i++) {
        double mid = 0.5 * (a + b), f = nl_hermite_cov(h, mid) - cov;
        if ((f <= 0) == (fa <= 0))
            a = mid, fa = f;
        else
            b = mid;
    }
    return 0.5 * (a + b);
}

/* The root nearest 0 on the side sign (+1 or -1) of 0, or NAN. */
static double invert_side(const nl_hermite *h, double cov, double sign)
{
    double a = 0, fa = -cov;  /* cov(0) = 0: the series starts at n = 1 */
    if (fa == 0)
        return 0;
    for (int i = 1; i <= INVERT_STEPS; i++) {
        double b = sign * i / (double)INVERT_STEPS, fb = nl_hermite_cov(h, b) - cov;
        if (fb == 0)
            return b;
        if ((fa < 0) != (fb < 0))
            return bisect(h, cov, a, b);
        a = b, fa = fb;
    }
    return NAN;
}

double nl_hermite_invert(const nl_hermite *h, double cov)
{
    double first = cov >= 0 ? 1 : -1, r;
    if (!isfinite(cov))
        return NAN;
    r = invert_side(h, cov, first);
    return isnan(r) ? invert_side(h, cov, -first) : r;
}

/* The rho in [-1, 1] whose output covariance is nearest `cov` (on the scan's
 * grid): where a target is out of reach, the design's best stand-in.  (Not
 * the end of the interval on the target's side: through an even g the
 * covariance never goes negative, and the nearest to a negative target is
 * rho = 0, not -1.) */
static double nearest(const nl_hermite *h, double cov)
{
    double best = 0, dbest = fabs(cov);
    for (int i = -INVERT_STEPS; i <= INVERT_STEPS; i++) {
        double r = i / (double)INVERT_STEPS, d = fabs(nl_hermite_cov(h, r) - cov);
        if (d < dbest)
            best = r, dbest = d;
    }
    return best;
}

int nl_nonlin_design(const nl_hermite *h, const double *target, size_t n, double spacing, double *rho, double *S,
                     double *err, size_t *unreachable)
{
    double var = nl_hermite_cov(h, 1.0), scale, e = 0;
    size_t bad = 0;
    int st;
    nl_field *R = nl_field_alloc(1, &n, &spacing, &st), *Sp = R ? nl_field_alloc(1, &n, &spacing, &st) : NULL;
    if (!Sp) {
        nl_field_free(R);
        return st;
    }
    if (!(target[0] > 0)) {
        nl_field_free(R), nl_field_free(Sp);
        return NL_ERROR(NL_EINVAL, "design: the target variance must be positive, got %g", target[0]);
    }
    scale = var / target[0];
    for (size_t j = 0; j < n; j++) {
        double r = nl_hermite_invert(h, target[j] * scale);
        if (isnan(r)) {  /* beyond what g can produce: the nearest it can */
            bad++;
            r = nearest(h, target[j] * scale);
        }
        R->data[j] = r;
    }
    R->data[0] = 1;
    /* project onto valid (non-negative) spectra */
    if ((st = nl_wk_acf_to_spectrum(R, Sp)) == NL_OK) {
        for (size_t k = 0; k < n; k++)
            Sp->data[k] = fmax(Sp->data[k], 0);
        st = nl_wk_spectrum_to_acf(Sp, R);
    }
    if (!st) {
        double r0 = R->data[0];
        for (size_t k = 0; k < n; k++)
            Sp->data[k] /= r0;
        for (size_t j = 0; j < n; j++) {
            rho[j] = R->data[j] / r0;
            e = fmax(e, fabs(nl_hermite_cov(h, fmax(-1, fmin(1, rho[j]))) - target[j] * scale) / var);
        }
        if (S)
            for (size_t k = 0; k < n; k++)
                S[k] = Sp->data[k];
    }
    nl_field_free(R), nl_field_free(Sp);
    *err = e;
    if (unreachable)
        *unreachable = bad;
    return st;
}

void nl_nonlin_output_acf(const nl_hermite *h, const double *acf, size_t n, double r0, double *out)
{
    for (size_t i = 0; i < n; i++)
        out[i] = nl_hermite_cov(h, fmax(-1, fmin(1, acf[i] / r0)));
}

int nl_nonlin_verify(const nl_field *S, const nl_dist *d, size_t realizations, size_t nlags, double *meas)
{
    nl_synth_fft_plan *p;
    nl_field *x, *full;
    int st;
    if (S->dim != 1 || !realizations || nlags > S->n[0])
        return NL_ERROR(NL_EINVAL, "verify: expected a 1D spectrum, at least one realization and at most %zu lags, "
                        "got %dD, %zu, %zu", S->n[0], S->dim, realizations, nlags);
    if (!(x = nl_field_alloc(1, S->n, S->h, &st)))
        return st;
    if ((st = nl_synth_fft_plan_spectrum(S, NL_SYNTH_FFT_CLAMP, &p))) {
        nl_field_free(x);
        return st;
    }
    for (size_t i = 0; i < nlags; i++)
        meas[i] = 0;
    for (size_t s = 1; s <= realizations && !st; s++) {
        nl_synth_fft_execute(p, s, x);
        if ((st = nl_synth_shape(x, d, 0)) || (st = nl_acf_full(x, NAN, NL_ACF_UNBIASED, &full)))
            break;
        for (size_t i = 0; i < nlags; i++)
            meas[i] += full->data[i] / (double)realizations;
        nl_field_free(full);
    }
    nl_synth_fft_plan_free(p), nl_field_free(x);
    return st;
}

double nl_nonlin_max_deviation(const double *meas, const double *target, size_t n, double scale, double var)
{
    double e = 0;
    for (size_t i = 0; i < n; i++)
        e = fmax(e, fabs(meas[i] - target[i] * scale) / var);
    return e;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_hermite_expand(const nl_dist *to, int terms, nl_hermite *h)
{
    int st;
    nl_gsl_enter();
    st = hermite_expand(to, terms, h);
    nl_gsl_leave();
    return st;
}
