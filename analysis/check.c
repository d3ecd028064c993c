/* Validity, smoothness and singularity of a model defined by R. */
#include "check_internal.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/wk.h"
#include "slope.h"
#include "../synth/subdiv.h"

#include <gsl/gsl_eigen.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double acf_x(const nl_model *m, int dim, double t)
{
    double lag[3] = {t, 0, 0};
    return nl_model_acf(m, dim, lag);
}

/* Isotropic models in 2D and 3D: the radial spectrum by the Hankel
 * transform (Lewis 1987, eq. (13), nl_model_spectrum_iso) at k = 0 and 128
 * frequencies spaced by a constant factor from 0.01 / L to 64 / L.  Exact
 * where the grid is not: the grid's Riemann sum of R misses S(0) by a few
 * percent of the peak when R has a kink, which blurs the boundary of
 * validity (cos(omega r) e^-r in 2D is valid up to omega = 1 exactly; the
 * grid alone passed 1.02).  Frequencies whose quadrature fails are skipped. */
#define RADIAL_N 128
static void radial_spectrum(const nl_model *m, int dim, double L, double *smin, double *smax, double *kmin)
{
    double q = pow(6400.0, 1.0 / (RADIAL_N - 1));
    for (int j = 0; j <= RADIAL_N; j++) {
        double k = j == 0 ? 0 : 0.01 / L * pow(q, j - 1), v = nl_model_spectrum_iso(m, dim, k);
        if (isnan(v))
            continue;
        *smax = fmax(*smax, v);
        if (v < *smin)
            *smin = v, *kmin = k;
    }
}

int nl_check_grid_spectrum(const nl_model *m, int dim, double h, nl_field **out)
{
    size_t n = dim == 1 ? 4096 : dim == 2 ? 256 : 64, nn[3] = {n, n, n};
    double hh[3] = {h, h, h};
    int st;
    *out = nl_field_alloc(dim, nn, hh, NULL);
    if (!*out)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((st = nl_wk_sample_spectrum(m, *out))) {
        nl_field_free(*out);
        *out = NULL;
    }
    return st;
}

double nl_check_grid_k(const nl_field *S, size_t i)
{
    size_t n = S->n[0];
    double k2 = 0, df = 1 / ((double)n * S->h[0]);
    for (int a = 0; a < S->dim; a++, i /= n) {
        double w = (double)nl_wrap(i % n, n) * df;
        k2 += w * w;
    }
    return sqrt(k2);
}

/* The smaller of the running minimum and a new one, relative to its own
 * largest magnitude, and where it is. */
static void take_min(nl_check *c, double smin, double smax, double k)
{
    double rel = smin / fmax(smax, -smin);
    if (rel < c->min_spectrum)
        c->min_spectrum = rel, c->min_spectrum_k = k;
}

/* The d-dimensional spectrum of R on a periodic grid of extent 8 L (and
 * radially, radial_spectrum), skipped when R has not decayed by the grid's
 * edge (slow: its truncation would show); and, for models isotropic in dim,
 * the spectrum of R under a Gaussian taper (core/taper.c), exact in sign
 * whatever the decay.  The smallest value relative to the largest
 * magnitude (of the same transform) and the |k| where it is reached. */
static int spectrum_checks(const nl_model *m, int dim, int slow, double L0, double L8, nl_check *c, int *tapered)
{
    size_t n = dim == 1 ? 4096 : dim == 2 ? 256 : 64, imin = 0;
    double h = 8 * c->scale / (double)n, smax = 0, smin = INFINITY, kr = 0, kg, sr = INFINITY;
    nl_check t_min = {.min_spectrum = INFINITY};
    nl_field *S;
    int st;
    /* the lattice's spacing from L0, then 8 and 64 times coarser while
     * the taper is narrower than R's reach L8: each level is exact in sign
     * (exemplars are not: their R interpolates a table between lags) */
    for (int j = 0; j < 3 && (dim == 1 || c->isotropic) && nl_model_family(m) != &nl_family_image; j++) {
        nl_taper_result t;
        if ((st = nl_taper_spectrum(m, dim, L0 * pow(8, j), 0, &t)))
            return st;
        if (isnan(t.min))
            break;  /* R not finite on the lattice: the other tests say where */
        if (j == 0)
            c->spectrum_kmax = t.kmax;
        /* below the rounding bound a negative value proves nothing */
        take_min(&t_min, t.min < -t.rounding ? t.min : fmax(t.min, 0), t.max, t.min < -t.rounding ? t.min_k : 0);
        if (t.taper >= L8)
            break;
    }
    c->min_spectrum = INFINITY;
    if (!slow) {
        if ((st = nl_check_grid_spectrum(m, dim, h, &S)))
            return st;
        for (size_t i = 0; i < S->count; i++) {
            smax = fmax(smax, S->data[i]);
            if (S->data[i] < smin)
                smin = S->data[i], imin = i;
        }
        c->spectrum_kmax = fmax(c->spectrum_kmax, 0.5 / h);
        kg = nl_check_grid_k(S, imin);
        nl_field_free(S);
        if (dim > 1 && c->isotropic)
            radial_spectrum(m, dim, c->scale, &sr, &smax, &kr);
        if (sr < smin)
            smin = sr, kg = kr;
        take_min(c, smin, smax, kg);
    }
    /* the taper's verdict where the untapered spectrum found none (its
     * value at k = 0 is the integral of R times the taper, not of R) */
    *tapered = !(c->min_spectrum < -1e-6) && t_min.min_spectrum < c->min_spectrum;
    if (*tapered)
        c->min_spectrum = t_min.min_spectrum, c->min_spectrum_k = t_min.min_spectrum_k;
    return NL_OK;
}

/* 3D isotropic: the line spectrum S1(f) = 2 pi int_f^inf S(k) k dk must not
 * rise (S >= 0); the first f where it does, beyond 1e-6 of its peak. */
static void line_monotone(const double *S1, size_t n, double df, double peak, nl_check *c)
{
    c->monotone_3d = 1;
    for (size_t k = 1; k < n; k++)
        if (S1[k] > S1[k - 1] + 1e-6 * peak) {
            c->monotone_3d = 0;
            c->line_rise_f = (double)k * df;
            return;
        }
}

/* Decay exponent b of the spectrum of the 1D profile R(t): 65536 samples
 * over 8 L, the log-log slope over 16/L .. 128/L (above the correlation
 * scale, a factor 32 below the Nyquist rate 4096/L, so that aliased copies
 * add well under 1%); INFINITY when the spectrum at 128/L is below 1e-13 of
 * its peak (the rounding floor) and its decay steepens across the band
 * (faster than any power). */
static int profile_decay(const nl_model *m, int dim, double T, nl_check *c)
{
    size_t n = 65536, n1[1] = {n};
    double L = c->scale, h = 8 * L / (double)n, *f = malloc(n / 2 * sizeof *f), peak = 0, *b = &c->spectral_decay;
    nl_field *R = nl_field_alloc(1, n1, &h, NULL), *S = nl_field_alloc(1, n1, &h, NULL);
    nl_slope sl;
    int st = NL_OK;
    if (!R || !S || !f) {
        nl_field_free(R), nl_field_free(S), free(f);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < n; i++)
    {
        double t = (double)nl_wrap(i, n) * h;
        R->data[i] = acf_x(m, dim, t) * (isfinite(T) ? exp(-(t / T) * (t / T)) : 1);
    }
    if ((st = nl_wk_acf_to_spectrum(R, S)))
        goto done;
    for (size_t k = 0; k < n / 2; k++)
        f[k] = (double)k / (8 * L), peak = fmax(peak, fabs(S->data[k]));
    c->monotone_3d = 1;
    if (dim == 3 && c->isotropic)
        line_monotone(S->data, n / 2, 1 / (8 * L), peak, c);
    for (size_t k = 0; k < n / 2; k++)
        S->data[k] = fabs(S->data[k]);
    if (S->data[128 * 8] < 1e-13 * peak) {
        /* below rounding: a power law would still show; a faster decay
         * steepens across the band */
        nl_slope lo, hi;
        st = nl_psd_slope(f, S->data, n / 2, 16 / L, 32 / L, 1, &lo);
        if (!st && nl_psd_slope(f, S->data, n / 2, 32 / L, 64 / L, 1, &hi) == NL_OK && S->data[64 * 8] > 1e-13 * peak &&
            hi.slope > 1.5 * lo.slope)
            *b = -hi.slope;
        else
            *b = INFINITY;
    } else {
        st = nl_psd_slope(f, S->data, n / 2, 16 / L, 128 / L, 1, &sl);
        *b = -sl.slope;
    }
done:
    nl_field_free(R), nl_field_free(S), free(f);
    if (st == NL_EINVAL)
        st = NL_ERROR(NL_EINVAL, "%s: the spectrum of R shows no decay to measure between %g and %g cycles per "
                      "unit (correlation length %g lags); expected a covariance that decays within 2^20 lags",
                      nl_model_spec(m), 16 / L, 128 / L, L);
    return st;
}

/* R at every offset of a side^dim grid, once: offsets (o0, o1, o2) with
 * o_a in 1-side..side-1 stored at sum (o_a + side - 1) (2 side - 1)^a. */
static double *offset_table(const nl_model *m, int dim, size_t side, double h)
{
    size_t w = 2 * side - 1, cnt = dim == 1 ? w : dim == 2 ? w * w : w * w * w;
    double *T = malloc(cnt * sizeof *T);
    if (!T)
        return NULL;
    for (size_t i = 0; i < cnt; i++) {
        size_t p[3] = {i % w, (i / w) % w, i / (w * w)};
        double lag[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++)
            lag[a] = ((double)p[a] - (double)(side - 1)) * h;
        T[i] = nl_model_acf(m, dim, lag);
    }
    return T;
}

static int eigen_check(const nl_model *m, int dim, nl_check *c)
{
    size_t side = dim == 1 ? 64 : dim == 2 ? 16 : 6, N = dim == 1 ? side : dim == 2 ? side * side : side * side * side;
    size_t w = 2 * side - 1;
    double h = c->scale / 16, r0 = acf_x(m, dim, 0), lmin = INFINITY, *T = offset_table(m, dim, side, h);
    gsl_matrix *A = gsl_matrix_alloc(N, N);
    gsl_vector *ev = gsl_vector_alloc(N);
    gsl_eigen_symm_workspace *ws = gsl_eigen_symm_alloc(N);
    int st = NL_OK;
    c->eig_side = side;
    c->eig_spacing = h;
    if (!A || !ev || !ws || !T)
        st = NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t i = 0; !st && i < N; i++)
        for (size_t j = 0; j < N; j++) {
            size_t pi[3] = {i % side, (i / side) % side, i / (side * side)}, pj[3] = {j % side, (j / side) % side,
                                                                                      j / (side * side)};
            size_t idx = 0, stride = 1;
            for (int a = 0; a < dim; a++, stride *= w)
                idx += (pi[a] + side - 1 - pj[a]) * stride;
            gsl_matrix_set(A, i, j, T[idx]);
        }
    if (!st && (st = gsl_eigen_symm(A, ev, ws)))
        st = NL_ERROR(NL_EFAIL, "check: the eigenvalues did not converge: %s", nl_gsl_reason(st));
    for (size_t i = 0; !st && i < N; i++)
        lmin = fmin(lmin, gsl_vector_get(ev, i));
    c->min_eigenvalue = lmin / r0;
    gsl_matrix_free(A), gsl_vector_free(ev), gsl_eigen_symm_free(ws), free(T);
    return st;
}

/* Subdivision singularity, N = 2 along x (4 points on the x axis of the
 * model in dim dimensions): the largest spacing L / 2^k, k <= 24, whose
 * matrix is flagged singular (0: none). */
double nl_check_singular_spacing(const nl_model *m, int dim, double L)
{
    nl_subdiv_class cl;
    double a[4], pts[12] = {0}, tgt[3] = {0};
    cl.a = a;
    for (int k = 0; k <= 24; k++) {
        double s = ldexp(L, -k);
        for (int i = 0; i < 4; i++)
            pts[i * dim] = (i - 1) * s;
        tgt[0] = 0.5 * s;
        if (nl_subdiv_solve(m, dim, 4, pts, tgt, NULL, &cl))
            break;
        if (cl.flags & NL_SUBDIV_SINGULAR)
            return s;
    }
    return 0;
}

int nl_check_order(double b)
{
    int m;
    if (isinf(b))
        return -1;
    m = (int)ceil((b - 1) / 2 - 0.05) - 1;
    return m < 0 ? 0 : m;
}

void nl_check_verdict(nl_check *c)
{
    c->why = NL_CHECK_VALID;
    if (c->min_spectrum < -1e-6)
        c->why = c->min_spectrum_k == 0 ? NL_CHECK_NEG_INTEGRAL : NL_CHECK_NEG_SPECTRUM;
    else if (!c->isotropic_bound_ok)
        c->why = NL_CHECK_BOUND;
    else if (c->min_eigenvalue < -1e-9)
        c->why = NL_CHECK_NEG_EIGENVALUE;
    else if (!c->monotone_3d)
        c->why = NL_CHECK_LINE_RISES;
    c->positive_definite = c->why == NL_CHECK_VALID;
}

/* R(0) within the range the checks handle, and L. */
static int scale_of(const nl_model *m, int dim, nl_check *c, double *L0)
{
    double zero[3] = {0, 0, 0}, r0 = nl_model_acf(m, dim, zero);
    if (!isfinite(r0))
        return NL_ERROR(NL_EINVAL, "%s: R(0) is not a finite number; expected a positive variance", nl_model_spec(m));
    if (!(r0 > 0))
        return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a positive variance", nl_model_spec(m), r0);
    /* the checks reach 1e-13 R(0) and square covariances: far from 1
     * they run through subnormal numbers (minutes) or overflow */
    if (r0 < 1e-200 || r0 > 1e200)
        return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a variance between 1e-200 and 1e200 (the checks "
                        "are relative to R(0): rescale the model)", nl_model_spec(m), r0);
    c->variance = r0;
    /* the lag beyond which |R| < 1e-8 R(0): the last such crossing below 2^20 */
    c->scale = 1e-3;
    for (double t = 1e-3; t < 1048576; t *= 1.25)
        if (fabs(acf_x(m, dim, t)) >= 1e-8 * r0)
            c->scale = t * 1.25;
    if (!((*L0 = nl_taper_scale(m, dim)) > 0))
        return NL_ERROR(NL_EINVAL, "%s: R stays within 1%% of R(0) at every lag up to 2^20; expected a covariance "
                        "that varies within 2^20 lags (its spectrum has nothing to measure)", nl_model_spec(m));
    return NL_OK;
}

/* Was the model made separable ("sep" among the keys of its spec; of a
 * sum or product, of every structure's)? */
static int is_separable(const nl_model *m)
{
    const char *s = nl_model_spec(m), *p = s;
    if (nl_model_structures(m) > 1) {
        for (size_t i = 0; i < nl_model_structures(m); i++)
            if (!is_separable(nl_model_structure(m, i)))
                return 0;
        return 1;
    }
    while ((p = strstr(p, "sep")) != NULL) {
        if (p > s && strchr(":;,", p[-1]) && (p[3] == ',' || p[3] == '\0'))
            return 1;
        p += 3;
    }
    return 0;
}

/* The exponent of the d-dimensional density from the line spectrum's: an
 * isotropic or ellipsoidal S(k) ~ k^-B has S1 ~ f^-(B - d + 1); along an
 * axis of a separable product S ~ S1.  NAN where neither holds (exemplars,
 * expressions in x, y, z). */
static double density_decay(const nl_model *m, int dim, double b)
{
    const nl_family *k = nl_model_family(m);
    if (dim == 1 || isinf(b))
        return b;
    if (is_separable(m))
        return b;
    if (k == &nl_family_image || (k == &nl_family_expr && !nl_model_is_isotropic(m)))
        return NAN;
    return b + dim - 1;
}

static void smoothness(const nl_model *m, int dim, nl_check *c)
{
    double r0 = c->variance;
    c->density_decay = density_decay(m, dim, c->spectral_decay);
    /* a 1D spectrum ~ f^-b has finite moments of order 2m < b - 1; the
     * order is a property of R near 0, the same along any line */
    c->differentiable_order = nl_check_order(c->spectral_decay);
    /* a kink at the origin (R(0) - R(d) ~ d^a with a < 1.9) rules out any
     * derivative whatever the spectral fit says */
    {
        double d = c->scale * 1e-5, a = log((r0 - acf_x(m, dim, 2 * d)) / (r0 - acf_x(m, dim, d))) / M_LN2;
        if (isfinite(a) && a < 1.9)
            c->differentiable_order = 0;
    }
    {
        /* the symbolic derivative is d/dt (t, r): not for expressions in x, y, z */
        double d = c->scale * 1e-4, sym = nl_model_is_isotropic(m) ? nl_model_acf_d2(m, 1e-9 * c->scale) : NAN;
        c->r2 = isfinite(sym) ? sym : 2 * (acf_x(m, dim, d) - r0) / (d * d);
        if (c->differentiable_order == 0)
            c->r2 = -INFINITY;
    }
}

/* Schoenberg (1938): an isotropic covariance in d dimensions is a mixture
 * of Omega_d(s r) = Gamma(d/2) (2 / (s r))^((d-2)/2) J_((d-2)/2)(s r),
 * so R >= R(0) inf Omega_d: min J0 = -0.40276 (2D), min sin(x)/x =
 * -0.21723 (3D), the values at the first minima, rounded down. */
double nl_check_isotropic_bound(int dim)
{
    return dim == 2 ? -0.4027593957025532 : dim == 3 ? -0.2172336282112217 : -1;
}

/* The smallest R / R(0) over lags 0..L along x and the bound. */
static void bound_check(const nl_model *m, int dim, nl_check *c)
{
    c->min_r = 1;
    for (double t = c->scale / 4096; t <= c->scale; t += c->scale / 4096) {
        double r = acf_x(m, dim, t) / c->variance;
        if (r < c->min_r)
            c->min_r = r, c->min_r_lag = t;
    }
    c->isotropic_bound_ok = !c->isotropic || c->min_r >= nl_check_isotropic_bound(dim) - 1e-12;
}

static int check_model(const nl_model *m, int dim, nl_check *c)
{
    int st, slow, edge, tapered = 0;
    double L0 = 1, L8;
    memset(c, 0, sizeof *c);
    c->dim = dim;
    c->monotone_3d = 1;
    c->isotropic_bound_ok = 1;
    if ((st = nl_model_check_dim(m, dim)) == NL_ENOTPD) {
        /* known from the literature (the family's descriptor): a verdict */
        c->why = NL_CHECK_KNOWN;
        c->scale = c->variance = c->min_spectrum = c->min_spectrum_k = c->min_eigenvalue = NAN;
        c->min_r = c->spectral_decay = c->density_decay = c->r2 = NAN;
        return NL_OK;
    }
    if (st)
        return st;
    c->isotropic = dim > 1 && nl_model_is_isotropic(m);
    if (nl_model_is_spectral(m))
        return nl_check_spectral(m, dim, c);
    if ((st = scale_of(m, dim, c, &L0)))
        return st;
    /* R still above 1e-8 R(0) at 64 times the lag where it halved: the
     * scales near the origin and of the tail are judged apart, on the
     * tapered spectrum and the asymptotics of the tail */
    L8 = c->scale;
    slow = (dim == 1 || c->isotropic) && L8 > 64 * L0;
    if (slow)
        c->scale = 16 * L0;
    if ((st = spectrum_checks(m, dim, slow, L0, L8, c, &tapered)) ||
        (st = profile_decay(m, dim, slow ? c->scale * 8 / 12 : INFINITY, c)) || (st = eigen_check(m, dim, c)))
        return st;
    if (slow && nl_model_negative_tail(m, dim, L0))
        c->min_spectrum = -1, c->min_spectrum_k = 0, tapered = 0;
    /* exemplars interpolate a table: no asymptotics to read */
    edge = !slow && (dim == 1 || c->isotropic) && nl_model_family(m) != &nl_family_image &&
           nl_model_edge_invalid(m, dim, c->scale);
    bound_check(m, dim, c);
    smoothness(m, dim, c);
    c->singular_checked = 1;
    c->singular_below = nl_check_singular_spacing(m, dim, c->scale);
    nl_check_verdict(c);
    if (tapered && (c->why == NL_CHECK_NEG_INTEGRAL || c->why == NL_CHECK_NEG_SPECTRUM))
        c->why = NL_CHECK_NEG_TAPERED;
    if (edge && c->positive_definite)
        c->why = NL_CHECK_EDGE, c->positive_definite = 0;
    return NL_OK;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_check_model(const nl_model *m, int dim, nl_check *c)
{
    int st;
    if ((st = nl_model_check_stationary(m, "check's positive-definiteness path (nl_check_model)")))
        return st;
    nl_gsl_enter();
    st = check_model(m, dim, c);
    nl_gsl_leave();
    return st;
}
