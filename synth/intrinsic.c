/* Exact simulation of the power-variogram field: fractional Gaussian noise
 * summed in 1D, Stein's cut-off embedding plus a random plane in 2D
 * (synth/intrinsic.h).  The FFT synthesis is synth/fft.h's, planned from
 * the embedding's sampled spectrum. */
#include "intrinsic.h"
#include "fft.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../core/wk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct nl_synth_intrinsic_plan {
    int dim;                      /* 1 or 2 */
    size_t n[3];                  /* grid (unused axes 1) */
    double h[3];                  /* spacing */
    double alpha, c, nugget;      /* the model's */
    double amp;                   /* factor on the embedded field: sqrt(c) D^(alpha/2) (2D), 1 (1D) */
    nl_synth_fft_plan *fft;       /* the embedding's synthesis; NULL when its covariance is 0 (2D, alpha = 2) */
    nl_synth_intrinsic_info info; /* what the plan reports */
};

/* The smallest even 2,3,5-smooth number >= x (>= 2). */
static size_t smooth_even(double x)
{
    size_t v = x > 2 ? (size_t)ceil(x) : 2;
    for (v += v & 1;; v += 2) {
        size_t r = v;
        while (r % 2 == 0)
            r /= 2;
        while (r % 3 == 0)
            r /= 3;
        while (r % 5 == 0)
            r /= 5;
        if (r == 1)
            return v;
    }
}

/* Stein's cut-off covariance at the scaled lag s (Stein 2002; synth/intrinsic.h). */
static double phi(const nl_synth_intrinsic_plan *p, double beta, double c0, double s)
{
    double R = p->info.cutoff;
    if (s <= 1)
        return c0 - pow(s, p->alpha) + p->info.c2 * s * s;
    return s < R ? beta * (R - s) * (R - s) * (R - s) / s : 0.0;
}

/* The embedding's covariance, wrapped: 2D, phi periodized over the images
 * k in {-1, 0, 1} per axis (the support R D is at most the period); 1D, the
 * fractional Gaussian noise autocovariance of lag min(j, M - j) (Davies and
 * Harte 1987), c h^alpha (|k+1|^a - 2|k|^a + |k-1|^a). */
static void sample_embedding(const nl_synth_intrinsic_plan *p, nl_field *R)
{
    const double a = p->alpha;
    if (p->dim == 1) {
        for (size_t j = 0; j < R->n[0]; j++) {
            double k = fabs((double)nl_wrap(j, R->n[0]));
            R->data[j] = p->c * pow(p->h[0], a) * (pow(k + 1, a) - 2 * pow(k, a) + pow(fabs(k - 1), a));
        }
        return;
    }
    double Rc = p->info.cutoff, D = p->info.diameter;
    double beta = Rc > 1 ? a * (2 - a) / (3 * Rc * (Rc * Rc - 1)) : 0;
    double c0 = beta * (Rc - 1) * (Rc - 1) * (Rc - 1) + 1 - p->info.c2;
    const size_t m0 = R->n[0], m1 = R->n[1];
#pragma omp parallel for schedule(static) if (m0 * m1 > 65536)
    for (size_t j = 0; j < m1; j++)
        for (size_t i = 0; i < m0; i++) {
            double v = 0, w0 = (double)nl_wrap(i, m0), w1 = (double)nl_wrap(j, m1);
            for (int k1 = -1; k1 <= 1; k1++) {
                double y = (w1 + k1 * (double)m1) * p->h[1];
                if (fabs(y) >= Rc * D)
                    continue;
                for (int k0 = -1; k0 <= 1; k0++) {
                    double x = (w0 + k0 * (double)m0) * p->h[0], s = sqrt(x * x + y * y) / D;
                    if (s < Rc)
                        v += phi(p, beta, c0, s);
                }
            }
            R->data[j * m0 + i] = v;
        }
}

/* The eigenvalues of the embedding (its sampled spectrum over the cell
 * volume): checked for sign, rounding negatives zeroed, then planned. */
static int plan_embedding(nl_synth_intrinsic_plan *p)
{
    int st;
    double cell = p->h[0] * p->h[1], lo = INFINITY, hi = -INFINITY;
    nl_field *R, *S = NULL;
    /* alive at once: R, S, the transform's complex buffer (2), the plan's
     * half spectrum and amplitudes (1) */
    if ((st = nl_size_check(p->dim, p->info.m, sizeof(double), 5, NULL))) {
        char why[256];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        return NL_ERROR(st, "synth intrinsic: the embedding of %zux%zu samples (5 arrays of its size) does not "
                        "fit: %s", p->info.m[0], p->info.m[1], why);
    }
    R = nl_field_alloc(p->dim, p->info.m, p->h, &st);
    if (R && !(S = nl_field_alloc(p->dim, p->info.m, p->h, &st)))
        nl_field_free(R), R = NULL;
    if (!R)
        return st;
    sample_embedding(p, R);
    if (!(st = nl_wk_acf_to_spectrum(R, S))) {
        for (size_t k = 0; k < S->count; k++)
            lo = fmin(lo, S->data[k] / cell), hi = fmax(hi, S->data[k] / cell);
        p->info.min_eigenvalue = lo, p->info.max_eigenvalue = hi;
        if (!(hi > 0) || lo < -NL_SYNTH_INTRINSIC_EIG_TOL * hi)
            st = NL_ERROR(NL_ENOTPD, "synth intrinsic: alpha=%g: the embedding %zux%zu has eigenvalues from %.3g "
                          "to %.3g; expected none below -%g of the largest", p->alpha, p->info.m[0], p->info.m[1],
                          lo, hi, NL_SYNTH_INTRINSIC_EIG_TOL);
    }
    for (size_t k = 0; !st && k < S->count; k++)
        S->data[k] = fmax(S->data[k], 0.0);
    if (!st)
        st = nl_synth_fft_plan_spectrum(S, 0, &p->fft);
    nl_field_free(R), nl_field_free(S);
    return st;
}

static int check_args(const nl_model *m, int dim, const size_t *n, const double *h)
{
    if (!nl_model_is_intrinsic(m))
        return NL_ERROR(NL_EINVAL, "synth intrinsic: %s has a covariance; expected an intrinsic model (powvar: "
                        "use circulant or fft for this one)", nl_model_spec(m));
    if (!nl_model_intrinsic_structure(m))
        return NL_ERROR(NL_EINVAL, "synth intrinsic: %s: expected powvar, or powvar plus nugget: structures (its "
                        "other structures have covariances)", nl_model_spec(m));
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "synth intrinsic: expected a 1D or 2D grid, got %dD", dim);
    if (dim == 2 && !nl_model_is_isotropic(m))
        return NL_ERROR(NL_EINVAL, "synth intrinsic: %s: expected an isotropic model in 2D (no angle or ratio)",
                        nl_model_spec(m));
    for (int a = 0; a < dim; a++) {
        if (n[a] < 2)
            return NL_ERROR(NL_EINVAL, "synth intrinsic: expected at least 2 samples per axis, got %zu", n[a]);
        if (h && !(h[a] > 0 && isfinite(h[a])))
            return NL_ERROR(NL_EINVAL, "synth intrinsic: spacing: expected a positive number, got %g", h[a]);
    }
    return NL_OK;
}

int nl_synth_intrinsic_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                                  nl_synth_intrinsic_plan **out)
{
    nl_synth_intrinsic_plan *p;
    int st;
    *out = NULL;
    if ((st = check_args(m, dim, n, h)))
        return st;
    if (!(p = calloc(1, sizeof *p)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->dim = dim;
    for (int a = 0; a < 3; a++)
        p->n[a] = a < dim ? n[a] : 1, p->h[a] = a < dim && h ? h[a] : 1;
    nl_model_param(nl_model_intrinsic_structure(m), "alpha", &p->alpha);
    nl_model_param(nl_model_intrinsic_structure(m), "c", &p->c);
    p->nugget = nl_model_nugget(m);
    p->info.m[1] = 1, p->amp = 1;
    if (dim == 1) {
        p->info.m[0] = smooth_even(2.0 * ((double)n[0] - 2));
    } else {
        double dx = (double)(n[0] - 1) * p->h[0], dy = (double)(n[1] - 1) * p->h[1];
        p->info.diameter = sqrt(dx * dx + dy * dy);
        p->info.cutoff = p->alpha <= 1.5 ? 1 : 2;
        double Rc = p->info.cutoff, beta = Rc > 1 ? p->alpha * (2 - p->alpha) / (3 * Rc * (Rc * Rc - 1)) : 0;
        p->info.c2 = (p->alpha - beta * (Rc - 1) * (Rc - 1) * (Rc + 2)) / 2;
        for (int a = 0; a < 2; a++)
            p->info.m[a] = smooth_even((double)(n[a] - 1) + Rc * p->info.diameter / p->h[a]);
        p->amp = sqrt(p->c) * pow(p->info.diameter, p->alpha / 2);
    }
    /* alpha = 2 in 2D: phi = 0, the field is the plane alone */
    if (!(dim == 2 && p->alpha == 2) && (st = plan_embedding(p))) {
        nl_synth_intrinsic_plan_free(p);
        return st;
    }
    *out = p;
    return NL_OK;
}

void nl_synth_intrinsic_plan_info(const nl_synth_intrinsic_plan *p, nl_synth_intrinsic_info *info)
{
    *info = p->info;
}

/* 1D: Z_0 = 0, Z_i = X_1 + ... + X_i. */
static void sum_increments(const nl_field *w, nl_field *out)
{
    double z = 0;
    out->data[0] = 0;
    for (size_t i = 1; i < out->n[0]; i++)
        out->data[i] = z += w->data[i - 1];
}

/* 2D: the embedded field's window times amp, plus the plane, less its
 * value at the origin. */
static void add_plane(const nl_synth_intrinsic_plan *p, const nl_field *w, uint64_t seed, nl_field *out)
{
    const size_t n0 = p->n[0], n1 = p->n[1];
    double g[2], D = p->info.diameter, b = sqrt(2 * p->info.c2) * p->amp / D;
    double y0 = w ? w->data[0] : 0;
    nl_rng_gauss_pair(seed, NL_SYNTH_INTRINSIC_STREAM, 0, g);
#pragma omp parallel for schedule(static) if (n0 * n1 > 65536)
    for (size_t j = 0; j < n1; j++)
        for (size_t i = 0; i < n0; i++) {
            double y = w ? w->data[j * w->n[0] + i] - y0 : 0;
            out->data[j * n0 + i] = p->amp * y + b * (g[0] * (double)i * p->h[0] + g[1] * (double)j * p->h[1]);
        }
}

int nl_synth_intrinsic_execute(const nl_synth_intrinsic_plan *p, uint64_t seed, nl_field *out)
{
    nl_field *w = NULL;
    int st = NL_OK;
    if (out->dim != p->dim || out->n[0] != p->n[0] || out->n[1] != p->n[1] || out->n[2] != 1)
        return NL_ERROR(NL_EINVAL, "synth intrinsic: the output field does not match the plan's grid");
    if (p->fft) {
        if (!(w = nl_field_alloc(p->dim, p->info.m, p->h, &st)))
            return st;
        if ((st = nl_synth_fft_execute(p->fft, seed, w))) {
            nl_field_free(w);
            return st;
        }
    }
    if (p->dim == 1)
        sum_increments(w, out);
    else
        add_plane(p, w, seed, out);
    nl_field_free(w);
    if (p->nugget > 0) {
        double sd = sqrt(p->nugget);
        for (size_t k = 0; k < out->count; k++)
            out->data[k] += sd * nl_rng_gauss(seed, NL_SYNTH_INTRINSIC_STREAM, 1 + k);
    }
    return NL_OK;
}

void nl_synth_intrinsic_plan_free(nl_synth_intrinsic_plan *p)
{
    if (!p)
        return;
    nl_synth_fft_plan_free(p->fft);
    free(p);
}
