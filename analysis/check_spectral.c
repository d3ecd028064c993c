/* Validity and smoothness of a spectral model (power:, spectrum:) from its
 * closed-form d-dimensional density S: no R is sampled but the few lags of
 * subdivision's 1D matrix. */
#include "check_internal.h"
#include "../core/nl_error.h"
#include "../core/wk.h"
#include "slope.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The geometric scan: k = 1e-6 * 1.02^j, j < SCAN_N, reaching 1e6. */
#define SCAN_N 1396
#define SCAN_K0 1e-6
#define SCAN_Q 1.02
/* Points of the linear scan over [0, K]. */
#define LIN_N 4097

typedef struct {
    const nl_model *m;
    int dim, axis;
    double pw;  /* the integrand is k^pw S(k) */
} radial;

static double s_axis(const nl_model *m, int dim, int axis, double k)
{
    double f[3] = {0, 0, 0};
    f[axis] = k;
    return nl_model_spectrum(m, dim, f);
}

static double radial_integrand(double k, void *p)
{
    const radial *r = p;
    return pow(k, r->pw) * s_axis(r->m, r->dim, 0, k);
}

/* The surface of the unit sphere in dim dimensions (1D: the two points). */
static double sphere(int dim) { return dim == 1 ? 2 : dim == 2 ? 2 * M_PI : 4 * M_PI; }

/* Omega_d int_lo^hi k^pw S(k) dk of an isotropic S: QAG over [lo, 1e-6]
 * and then over factors of 10 up to min(K, hi) (so that a peak near 0 and
 * a long tail are both resolved); for hi infinite the tail beyond K from
 * the fitted decay S ~ k^-b, S(K) K^(pw + 1) / (b - pw - 1) (nothing when
 * S falls faster than any power: S(K) < 1e-12 of its peak there).  NAN
 * when GSL fails or the tail diverges (b <= pw + 1). */
static double radial_moment(const nl_model *m, int dim, double pw, double lo, double K, double hi, double b)
{
    radial r = {m, dim, 0, pw};
    gsl_function F = {radial_integrand, &r};
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(2000);
    double sum = 0, v, err, a = lo, top = fmin(K, hi);
    int st = 0;
    if (!w)
        return NAN;
    while (!st && a < top) {
        double e = fmin(a < SCAN_K0 ? SCAN_K0 : 10 * a, top);
        st = gsl_integration_qag(&F, a, e, 0, 1e-10, 2000, GSL_INTEG_GAUSS61, w, &v, &err);
        sum += v, a = e;
    }
    gsl_integration_workspace_free(w);
    if (isinf(hi) && isfinite(b))
        sum = b > pw + 1 ? sum + radial_integrand(K, &r) * K / (b - pw - 1) : NAN;
    return st ? NAN : sphere(dim) * sum;
}

/* The scan along one axis: values into s[0..SCAN_N] (s[SCAN_N] at k = 0). */
static int scan_axis(const nl_model *m, int dim, int axis, double *s)
{
    double k = SCAN_K0;
    for (int j = 0; j <= SCAN_N; j++, k *= SCAN_Q) {
        double kk = j == SCAN_N ? 0 : k;
        s[j] = s_axis(m, dim, axis, kk);
        if (!isfinite(s[j]))
            return NL_ERROR(NL_EINVAL, "%s: S is not a finite number at |k| = %g in %dD; expected a finite "
                            "density at every frequency", nl_model_spec(m), kk, dim);
    }
    return NL_OK;
}

static double scan_k(int j) { return j == SCAN_N ? 0 : SCAN_K0 * pow(SCAN_Q, j); }

/* Track the smallest value and where it is. */
static void take_min(double v, double k, double *smin, double *kmin)
{
    if (v < *smin)
        *smin = v, *kmin = k;
}

/* The d-dimensional grid of nl_wk_sample_spectrum over [-K, K]^d (which
 * also refuses uneven and non-finite spectra): its minimum, and its
 * Riemann sums of S and fx^2 S. */
static int grid_sums(const nl_model *m, int dim, double K, double *smin, double *kmin, double *var, double *m2)
{
    nl_field *S;
    double df, cell;
    int st;
    if ((st = nl_check_grid_spectrum(m, dim, 0.5 / K, &S)))
        return st;
    df = 1 / ((double)S->n[0] * S->h[0]);
    cell = pow(df, dim);
    *var = *m2 = 0;
    for (size_t i = 0; i < S->count; i++) {
        double fx = (double)nl_wrap(i % S->n[0], S->n[0]) * df;
        take_min(S->data[i], nl_check_grid_k(S, i), smin, kmin);
        *var += S->data[i] * cell;
        *m2 += fx * fx * S->data[i] * cell;
    }
    nl_field_free(S);
    return NL_OK;
}

/* Min of S along the axes' scans and on a linear scan of [0, K] along x. */
static void scan_min(const nl_model *m, int dim, const double *s, double K, double *smin, double *kmin)
{
    for (int j = 0; j <= SCAN_N; j++)
        take_min(s[j], scan_k(j), smin, kmin);
    for (int j = 0; j < LIN_N; j++) {
        double k = K * j / (LIN_N - 1);
        take_min(s_axis(m, dim, 0, k), k, smin, kmin);
    }
}

/* The tail exponent B of S ~ k^-B along x: the log-log slope over
 * [kt, 16 kt], kt where |S| first falls below 1e-6 of its peak beyond the
 * peak; INFINITY when S vanishes beyond kt (band-limited, *edge set) or
 * its decay steepens by half across [kt, 4 kt], [4 kt, 16 kt] (faster than
 * any power). */
static double tail_exponent(const double *s, double peak, double *edge)
{
    double k[SCAN_N], a[SCAN_N];
    int jp = 0, jt = -1, last = -1;
    nl_slope lo, hi, all;
    for (int j = 0; j < SCAN_N; j++) {
        k[j] = scan_k(j), a[j] = fabs(s[j]);
        if (a[j] > a[jp])
            jp = j;
        if (a[j] > 0)
            last = j;
    }
    for (int j = jp; j < SCAN_N && jt < 0; j++)
        if (a[j] < 1e-6 * peak)
            jt = j;
    if (jt < 0)
        jt = SCAN_N - 141;  /* no fall to 1e-6 by 1e6 / 16: fit the last factor 16 */
    if (last < SCAN_N - 1 && a[last] >= 1e-200 * peak) {
        *edge = k[last];  /* nothing beyond: band-limited */
        return INFINITY;
    }
    if (nl_psd_slope(k, a, SCAN_N, k[jt], 4 * k[jt], 1, &lo) ||
        nl_psd_slope(k, a, SCAN_N, 4 * k[jt], 16 * k[jt], 1, &hi) || hi.slope < 1.5 * lo.slope)
        return INFINITY;
    if (nl_psd_slope(k, a, SCAN_N, k[jt], 16 * k[jt], 1, &all))
        return INFINITY;
    return -all.slope;
}

/* Smallest eigenvalue of the covariance of the infinite unit grid: the
 * minimum over the Brillouin zone [-1/2, 1/2)^d of sum_m S(f + m). */
static double aliased_min(const nl_model *m, int dim)
{
    int nt = dim == 1 ? 1024 : dim == 2 ? 32 : 8, M = dim == 1 ? 64 : dim == 2 ? 16 : 4, w = 2 * M + 1;
    long nth = dim == 1 ? nt : dim == 2 ? (long)nt * nt : (long)nt * nt * nt;
    long nal = dim == 1 ? w : dim == 2 ? (long)w * w : (long)w * w * w;
    double best = INFINITY;
    for (long t = 0; t < nth; t++) {
        double sum = 0;
        for (long q = 0; q < nal; q++) {
            double f[3] = {0, 0, 0};
            long tt = t, qq = q;
            for (int a = 0; a < dim; a++, tt /= nt, qq /= w)
                f[a] = -0.5 + (double)(tt % nt) / nt + (double)(qq % w - M);
            sum += nl_model_spectrum(m, dim, f);
        }
        best = fmin(best, sum);
    }
    return best;
}

/* Variance and R''(0) from S. */
static int moments(const nl_model *m, int dim, nl_check *c, double K, double gvar, double gm2)
{
    double fmin = 0, fmax = INFINITY, v;
    if (nl_model_family(m) == &nl_family_power) {
        nl_model_param(m, "var", &c->variance);
        nl_model_param(m, "fmin", &fmin);
        nl_model_param(m, "fmax", &fmax);
    } else if (dim == 1 || c->isotropic) {
        c->variance = radial_moment(m, dim, dim - 1, 0, K, INFINITY, c->density_decay);
    } else {
        c->variance = gvar;
    }
    v = c->variance;
    if (isfinite(v) && v <= 0 && c->min_spectrum < -1e-6) {
        /* not a covariance, and nothing is relative to R(0) */
        c->r2 = c->min_eigenvalue = NAN;
        return NL_OK;
    }
    if (!isfinite(v) || !(v > 0))
        return NL_ERROR(NL_EINVAL, "%s: the integral of S over %dD frequencies (the variance) is %s; expected a "
                        "positive finite variance (a density that falls faster than |k|^-%d)", nl_model_spec(m), dim,
                        isfinite(v) ? "not positive" : "divergent or not computable", dim);
    if (v < 1e-200 || v > 1e200)
        return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a variance between 1e-200 and 1e200 (the checks "
                        "are relative to R(0): rescale the model)", nl_model_spec(m), v);
    c->r2 = -INFINITY;
    if (c->differentiable_order != 0) {
        double mom = dim == 1 || c->isotropic
                         ? radial_moment(m, dim, dim + 1, fmin, fmin > 0 ? fmax : K, fmax, c->density_decay) / dim
                         : gm2;
        c->r2 = isfinite(mom) ? -4 * M_PI * M_PI * mom : -INFINITY;
    }
    return NL_OK;
}

int nl_check_spectral(const nl_model *m, int dim, nl_check *c)
{
    double *s = malloc(3 * (SCAN_N + 1) * sizeof *s), peak = 0, K = 0, smin = INFINITY, kmin = 0, gvar = 0, gm2 = 0, b;
    int axes = c->isotropic || dim == 1 ? 1 : dim, st = NL_OK, power = nl_model_family(m) == &nl_family_power;
    if (!s)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (int a = 0; a < axes && !st; a++)
        st = scan_axis(m, dim, a, s + a * (SCAN_N + 1));
    for (int j = 0; !st && j < axes * (SCAN_N + 1); j++)
        peak = fmax(peak, fabs(s[j]));
    /* the band that holds S: up to where it stays below 1e-12 of its peak */
    for (int j = 0; !st && j < axes * (SCAN_N + 1); j++)
        if (fabs(s[j]) >= 1e-12 * peak && j % (SCAN_N + 1) != SCAN_N)
            K = fmax(K, scan_k(j % (SCAN_N + 1)) * SCAN_Q);
    if (!st && !(peak > 0))
        st = NL_ERROR(NL_EINVAL, "%s: S = 0 at every frequency scanned (|k| from 1e-6 to 1e6); expected a "
                      "positive density", nl_model_spec(m));
    if (!st && power)
        nl_model_param(m, "fmax", &K);
    if (!st)
        st = grid_sums(m, dim, K, &smin, &kmin, &gvar, &gm2);
    if (st) {
        free(s);
        return st;
    }
    scan_min(m, dim, s, K, &smin, &kmin);
    c->spectral = 1;
    c->scale = 16;
    c->spectrum_kmax = K;
    c->min_spectrum = smin / peak;
    c->min_spectrum_k = kmin;
    c->min_r = NAN;
    c->band_edge = NAN;
    if (power) {
        nl_model_param(m, "d", &c->density_decay);
        nl_model_param(m, "fmax", &c->band_edge);
        b = INFINITY;
    } else {
        b = tail_exponent(s, peak, &c->band_edge);
        c->density_decay = b;
    }
    c->band_limited = isfinite(c->band_edge);
    free(s);
    /* int k^(d-1) k^-b dk diverges for b <= d (0.02 of slack for the fit;
     * the quadrature of a divergent tail can stop at a finite value) */
    if (b <= dim + 0.02)
        return NL_ERROR(NL_EINVAL, "%s: S falls as |k|^-%.3g, so its integral over %dD frequencies (the "
                        "variance) diverges; expected a density that falls faster than |k|^-%d",
                        nl_model_spec(m), b, dim, dim);
    c->spectral_decay = isinf(b) ? b : b - (dim - 1);
    c->differentiable_order = nl_check_order(c->spectral_decay);
    c->eig_spacing = 1;
    if ((st = moments(m, dim, c, K, gvar, gm2)))
        return st;
    if (c->variance > 0)
        c->min_eigenvalue = aliased_min(m, dim) / c->variance;
    if (power) {  /* its R is a quadrature: the 4 points of the matrix on the x axis */
        c->singular_checked = 1;
        c->singular_below = nl_check_singular_spacing(m, dim, c->scale);
    }
    nl_check_verdict(c);
    return NL_OK;
}
