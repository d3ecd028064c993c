/* Validity, smoothness and singularity of a model. */
#include "check.h"
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

static int spectrum_checks(const nl_model *m, int dim, nl_check *c)
{
    size_t n = dim == 1 ? 4096 : dim == 2 ? 256 : 64, nn[3] = {n, n, n};
    double h = 8 * c->scale / (double)n, hh[3] = {h, h, h}, smax = 0, smin = INFINITY;
    nl_field *S = nl_field_alloc(dim, nn, hh, NULL);
    int st;
    if (!S)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((st = nl_wk_sample_spectrum(m, S))) {
        nl_field_free(S);
        return st;
    }
    for (size_t i = 0; i < S->count; i++)
        smax = fmax(smax, S->data[i]), smin = fmin(smin, S->data[i]);
    c->min_spectrum = smax > 0 ? smin / smax : -INFINITY;
    /* 3D isotropic: non-increasing along the x axis of the spectrum */
    c->monotone_3d = 1;
    if (dim == 3 && c->isotropic)
        for (size_t k = 1; k < n / 2; k++)
            if (S->data[k] > S->data[k - 1] + 1e-6 * smax)
                c->monotone_3d = 0;
    nl_field_free(S);
    return NL_OK;
}

/* Decay exponent b of the spectrum of the 1D profile R(t): 65536 samples
 * over 8 L, the log-log slope over 16/L .. 128/L (above the correlation
 * scale, a factor 32 below the Nyquist rate 4096/L, so that aliased copies
 * add well under 1%); INFINITY when the spectrum at 128/L is below 1e-13 of
 * its peak (the rounding floor) and its decay steepens across the band
 * (faster than any power). */
static int profile_decay(const nl_model *m, int dim, double L, double *b)
{
    size_t n = 65536, n1[1] = {n};
    double h = 8 * L / (double)n, *f = malloc(n / 2 * sizeof *f), peak = 0;
    nl_field *R = nl_field_alloc(1, n1, &h, NULL), *S = nl_field_alloc(1, n1, &h, NULL);
    nl_slope sl;
    int st = NL_OK;
    if (!R || !S || !f) {
        nl_field_free(R), nl_field_free(S), free(f);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (size_t i = 0; i < n; i++)
        R->data[i] = acf_x(m, dim, (double)nl_wrap(i, n) * h);
    if ((st = nl_wk_acf_to_spectrum(R, S)))
        goto done;
    for (size_t k = 0; k < n / 2; k++)
        f[k] = (double)k / (8 * L), peak = fmax(peak, fabs(S->data[k]));
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

static int eigen_check(const nl_model *m, int dim, nl_check *c)
{
    size_t side = dim == 1 ? 64 : dim == 2 ? 16 : 6, N = dim == 1 ? side : dim == 2 ? side * side : side * side * side;
    double h = c->scale / 16, r0 = acf_x(m, dim, 0), lmin = INFINITY;
    gsl_matrix *A = gsl_matrix_alloc(N, N);
    gsl_vector *ev = gsl_vector_alloc(N);
    gsl_eigen_symm_workspace *w = gsl_eigen_symm_alloc(N);
    int st = NL_OK;
    if (!A || !ev || !w)
        st = NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t i = 0; !st && i < N; i++)
        for (size_t j = 0; j < N; j++) {
            size_t pi[3] = {i % side, (i / side) % side, i / (side * side)}, pj[3] = {j % side, (j / side) % side,
                                                                                      j / (side * side)};
            double lag[3] = {0, 0, 0};
            for (int a = 0; a < dim; a++)
                lag[a] = ((double)pi[a] - (double)pj[a]) * h;
            gsl_matrix_set(A, i, j, nl_model_acf(m, dim, lag));
        }
    if (!st && (st = gsl_eigen_symm(A, ev, w)))
        st = NL_ERROR(NL_EFAIL, "check: the eigenvalues did not converge: %s", nl_gsl_reason(st));
    for (size_t i = 0; !st && i < N; i++)
        lmin = fmin(lmin, gsl_vector_get(ev, i));
    c->min_eigenvalue = lmin / r0;
    gsl_matrix_free(A), gsl_vector_free(ev), gsl_eigen_symm_free(w);
    return st;
}

/* Subdivision singularity, 1D N = 2 along x: the largest spacing L / 2^k,
 * k <= 24, whose matrix is flagged singular (0: none). */
static double singular_spacing(const nl_model *m, double L)
{
    nl_subdiv_class cl;
    double a[4], pts[4], tgt[1];
    cl.a = a;
    for (int k = 0; k <= 24; k++) {
        double s = ldexp(L, -k);
        for (int i = 0; i < 4; i++)
            pts[i] = (i - 1) * s;
        tgt[0] = 0.5 * s;
        if (nl_subdiv_solve(m, 1, 4, pts, tgt, NULL, &cl))
            break;
        if (cl.flags & NL_SUBDIV_SINGULAR)
            return s;
    }
    return 0;
}

static int check_model(const nl_model *m, int dim, nl_check *c)
{
    double r0, zero[3] = {0, 0, 0};
    int st;
    memset(c, 0, sizeof *c);
    c->dim = dim;
    if ((st = nl_model_check_dim(m, dim)))
        return st;
    r0 = nl_model_acf(m, dim, zero);
    if (nl_model_get_kind(m) == NL_MODEL_SPECTRUM) {
        /* R from the spectrum on a grid: a scale cannot be searched; use 1 */
        c->scale = 64;
        r0 = NAN;
    } else {
        if (!(r0 > 0) || !isfinite(r0))
            return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a positive variance", nl_model_spec(m), r0);
        /* the checks reach 1e-13 R(0) and square covariances: far from 1
         * they run through subnormal numbers (minutes) or overflow */
        if (r0 < 1e-200 || r0 > 1e200)
            return NL_ERROR(NL_EINVAL, "%s: R(0) = %g; expected a variance between 1e-200 and 1e200 (the checks "
                            "are relative to R(0): rescale the model)", nl_model_spec(m), r0);
        /* the lag beyond which |R| < 1e-8 R(0): the last such crossing below 2^20 */
        c->scale = 1e-3;
        for (double t = 1e-3; t < 1048576; t *= 1.25)
            if (fabs(acf_x(m, dim, t)) >= 1e-8 * r0)
                c->scale = t * 1.25;
    }
    c->isotropic = dim > 1 && nl_model_is_isotropic(m);
    if ((st = spectrum_checks(m, dim, c)))
        return st;
    c->spectral_decay = INFINITY;
    if (!isnan(r0) && (st = profile_decay(m, dim, c->scale, &c->spectral_decay)))
        return st;
    if (!isnan(r0) && (st = eigen_check(m, dim, c)))
        return st;
    if (isnan(r0))
        c->min_eigenvalue = NAN;
    c->positive_definite = c->min_spectrum >= -1e-6 && !(c->min_eigenvalue < -1e-9);
    /* the -1/n bound */
    c->min_r = 1;
    if (!isnan(r0))
        for (double t = c->scale / 4096; t <= c->scale; t += c->scale / 4096)
            c->min_r = fmin(c->min_r, acf_x(m, dim, t) / r0);
    c->isotropic_bound_ok = !c->isotropic || c->min_r >= -1.0 / dim - 1e-12;
    if (!c->isotropic_bound_ok || !c->monotone_3d)
        c->positive_definite = 0;
    /* smoothness */
    /* a 1D spectrum ~ f^-b has finite moments of order 2m < b - 1; the
     * order is a property of R near 0, the same along any line */
    c->differentiable_order = isinf(c->spectral_decay) ? -1 : (int)ceil((c->spectral_decay - 1) / 2 - 0.05) - 1;
    if (c->differentiable_order < -1)
        c->differentiable_order = 0;
    /* a kink at the origin (R(0) - R(d) ~ d^a with a < 1.9) rules out any
     * derivative whatever the spectral fit says */
    if (!isnan(r0)) {
        double d = c->scale * 1e-5, a = log((r0 - acf_x(m, dim, 2 * d)) / (r0 - acf_x(m, dim, d))) / M_LN2;
        if (isfinite(a) && a < 1.9)
            c->differentiable_order = 0;
    }
    c->r2 = NAN;
    if (!isnan(r0)) {
        double d = c->scale * 1e-4, sym = nl_model_acf_d2(m, 1e-9 * c->scale);
        c->r2 = isfinite(sym) ? sym : 2 * (acf_x(m, dim, d) - r0) / (d * d);
        if (c->differentiable_order == 0)
            c->r2 = -INFINITY;
    }
    if (!isnan(r0) && dim == 1)
        c->singular_below = singular_spacing(m, c->scale);
    return NL_OK;
}

/* Bracketed for GSL (core/gsl_guard_internal.h): its errors come back as statuses. */
int nl_check_model(const nl_model *m, int dim, nl_check *c)
{
    int st;
    nl_gsl_enter();
    st = check_model(m, dim, c);
    nl_gsl_leave();
    return st;
}
