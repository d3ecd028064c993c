/* Gradient noise and its octave sum. */
#include "lattice.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../core/wk.h"
#include "method.h"

#include <complex.h>
#include <stdio.h>
#include <fftw3.h>
#include <gsl/gsl_multifit.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double fade(double t) { return t * t * t * (t * (6 * t - 15) + 10); }

static uint64_t lat_index(int dim, long i, long j)
{
    return dim == 1 ? (uint64_t)i : ((uint64_t)(uint32_t)j << 32) | (uint32_t)i;
}

/* Gradient noise of cell c at sample (x, y); period (px, py) lattice cells
 * when > 0. */
static double gradient_noise(uint64_t seed, uint32_t stream, int dim, double c, double x, double y, long px, long py)
{
    double fx = x / c, fy = y / c, s = 0;
    long i0 = (long)floor(fx), j0 = (long)floor(fy);
    double tx = fx - (double)i0, ty = fy - (double)j0;
    for (int dj = 0; dj <= (dim == 2); dj++)
        for (int di = 0; di <= 1; di++) {
            long i = i0 + di, j = j0 + dj;
            if (px > 0)
                i = ((i % px) + px) % px;
            if (py > 0)
                j = ((j % py) + py) % py;
            double u = nl_rng_uniform(seed, stream, lat_index(dim, i, dim == 2 ? j : 0)), g;
            double wx = di ? fade(tx) : 1 - fade(tx), rx = tx - di;
            if (dim == 1) {
                g = (2 * u - 1) * rx;
                s += wx * g;
            } else {
                double a = 2 * M_PI * u, wy = dj ? fade(ty) : 1 - fade(ty), ry = ty - dj;
                s += wx * wy * (cos(a) * rx + sin(a) * ry);
            }
        }
    return s;
}

/* The basis spectrum at cell 16, measured once (8 periodic realizations). */
static double basis16[2][2049];
static int basis_ready[2];

/* Periodogram of x (n samples per axis, dim axes, unit spacing, mean 0),
 * P_k = |sum_j x_j exp(-2 pi i j.k / n)|^2 / N at the wrapped frequencies
 * (the two-sided density of analysis/psd.h), accumulated into acc[k] / 8
 * for k < n/2 + 1: in 1D P_k itself, in 2D its mean over the ring of
 * radius k / n (bins as analysis/radial.h).  P is scratch of N doubles, c
 * of N complex values. */
static int accumulate_periodogram(int dim, size_t n, const double *x, double *P, fftw_complex *c, double *acc)
{
    size_t count = dim == 2 ? n * n : n, h0 = n / 2 + 1, rows = count / n, nb = n / 2 + 1, cnt[2049];
    int dims[2] = {(int)n, (int)n};
    double v[2049], unit = 1.0 / (double)n, step = 1.0 / (double)n;
    fftw_plan p = fftw_plan_dft_r2c(dim, dims, P, c, nl_fftw_flags(count));
    if (!p)
        return NL_ERROR(NL_ENOMEM, "cannot plan the basis periodogram FFT");
    for (size_t i = 0; i < count; i++)
        P[i] = x[i] - 0.0;
    fftw_execute(p);
    fftw_destroy_plan(p);
    for (size_t r = 0; r < rows; r++) {
        size_t rneg = (rows - r) % rows;
        for (size_t i = 0; i < h0; i++) {
            double w = 1.0 / (double)count * (creal(c[r * h0 + i]) * creal(c[r * h0 + i]) +
                                              cimag(c[r * h0 + i]) * cimag(c[r * h0 + i]));
            P[r * n + i] = w;
            P[rneg * n + (n - i) % n] = w;
        }
    }
    if (dim == 1) {
        for (size_t k = 0; k < nb; k++)
            acc[k] += P[k] / 8;
        return NL_OK;
    }
    for (size_t b = 0; b < nb; b++)
        v[b] = 0, cnt[b] = 0;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++) {
            double ci = nl_wrap(i, n) * unit, cj = nl_wrap(j, n) * unit, d = sqrt(ci * ci + cj * cj);
            size_t b = (size_t)floor(d / step + 0.5);
            if (b < nb)
                v[b] += P[j * n + i], cnt[b]++;
        }
    for (size_t k = 0; k < nb; k++)
        acc[k] += (cnt[k] ? v[k] / (double)cnt[k] : 0) / 8;
    return NL_OK;
}

static int measure_basis(int dim)
{
    size_t n = dim == 1 ? 4096 : 256, ny = dim == 2 ? n : 1, count = n * ny, nb = n / 2 + 1;
    double acc[2049] = {0};
    double *x = nl_alloc(count * sizeof *x), *P = nl_alloc(count * sizeof *P);
    fftw_complex *c = nl_alloc(ny * nb * sizeof *c);
    int st = x && P && c ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for the basis spectrum");
    for (uint64_t s = 1; s <= 8 && !st; s++) {
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < n; i++)
                x[j * n + i] = gradient_noise(s, NL_LATTICE_STREAM + 99, dim, 16, (double)i, (double)j, (long)n / 16,
                                              dim == 2 ? (long)n / 16 : 0);
        st = accumulate_periodogram(dim, n, x, P, c, acc);
    }
    nl_free(x), nl_free(P), nl_free(c);
    if (st)
        return st;
    /* store on a grid of 2048 steps in f * 16 from 0 to 8 (f from 0 to 0.5) */
    for (int k = 0; k <= 2048; k++) {
        double ff = 0.5 * k / 2048.0, t = ff * (double)n;
        size_t i = (size_t)t;
        double w = t - (double)i;
        basis16[dim - 1][k] = i + 1 < nb ? (1 - w) * acc[i] + w * acc[i + 1] : acc[nb - 1];
    }
    basis_ready[dim - 1] = 1;
    return NL_OK;
}

double nl_synth_lattice_basis_spectrum(int dim, double c, double f)
{
    double t, w;
    int k;
    if (!basis_ready[dim - 1])
        measure_basis(dim);
    t = fabs(f) * c / 16 / 0.5 * 2048;
    if (t >= 2048)
        return 0;
    k = (int)t;
    w = t - k;
    return ((1 - w) * basis16[dim - 1][k] + w * basis16[dim - 1][k + 1]) * pow(c / 16, dim);
}

/* Power of spectrum s over the frequencies lo..hi (radial shells in 2D). */
static double band_power(int dim, double (*s)(const void *, double), const void *ctx, double lo, double hi)
{
    double p = 0, df = (hi - lo) / 400;
    for (int i = 0; i < 400; i++) {
        double f = lo + (i + 0.5) * df;
        p += s(ctx, f) * (dim == 1 ? 2 : 2 * M_PI * f) * df;
    }
    return p;
}

typedef struct {
    int dim;
    double c;
    const nl_model *m;
} sctx;

static double s_basis(const void *ctx, double f)
{
    const sctx *x = ctx;
    return nl_synth_lattice_basis_spectrum(x->dim, x->c, f);
}

/* Non-negative weights v_o (= w_o^2) minimising the relative error
 * sum_f ((sum_o v_o S_o(f) - S_t(f)) / S_t(f))^2 on log-spaced frequencies:
 * weighted least squares (GSL), dropping octaves whose weight comes out
 * negative and refitting the rest (an active-set iteration). */
static int fit_weights(int dim, const nl_model *m, nl_synth_lattice_plan *p, double flo)
{
    enum { NF = 96 };
    int O = p->octaves, active[NL_LATTICE_MAX_OCTAVES], st = NL_OK;
    for (int o = 0; o < O; o++)
        active[o] = 1;
    nl_gsl_enter();
    for (int iter = 0; iter < O; iter++) {
        int k = 0, map[NL_LATTICE_MAX_OCTAVES], neg = 0;
        for (int o = 0; o < O; o++)
            if (active[o])
                map[k++] = o;
        if (k == 0)
            break;
        gsl_matrix *X = gsl_matrix_alloc(NF, (size_t)k), *cov = gsl_matrix_alloc((size_t)k, (size_t)k);
        gsl_vector *y = gsl_vector_alloc(NF), *w = gsl_vector_alloc(NF), *c = gsl_vector_alloc((size_t)k);
        gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc(NF, (size_t)k);
        double chi2;
        if (!X || !cov || !y || !w || !c || !ws) {
            st = NL_ERROR(NL_ENOMEM, "out of memory");
        } else {
            for (int i = 0; i < NF; i++) {
                double f = flo * pow(0.5 / flo, (i + 0.5) / NF), fv[2] = {f, 0};
                double t = nl_model_spectrum(m, dim, fv);
                for (int j = 0; j < k; j++)
                    gsl_matrix_set(X, (size_t)i, (size_t)j, nl_synth_lattice_basis_spectrum(dim, p->cell[map[j]], f));
                gsl_vector_set(y, (size_t)i, t);
                gsl_vector_set(w, (size_t)i, t > 0 ? 1 / (t * t) : 0);
            }
            int gst = gsl_multifit_wlinear(X, w, y, c, cov, &chi2, ws);
            if (gst)
                st = NL_ERROR(NL_EFAIL, "lattice: the weight fit failed: %s", nl_gsl_reason(gst));
            for (int j = 0; !st && j < k; j++) {
                double v = gsl_vector_get(c, (size_t)j);
                if (v < 0)
                    active[map[j]] = 0, neg = 1;
                p->weight[map[j]] = v > 0 ? sqrt(v) : 0;
            }
        }
        gsl_matrix_free(X), gsl_matrix_free(cov), gsl_vector_free(y), gsl_vector_free(w), gsl_vector_free(c);
        gsl_multifit_linear_free(ws);
        if (st || !neg)
            break;
    }
    nl_gsl_leave();
    for (int o = 0; o < O; o++)
        if (!active[o])
            p->weight[o] = 0;
    return st;
}

/* The positive-definiteness rule on the target at the fit frequencies (the
 * 96 of fit_weights): finite everywhere; negative values are refused, or
 * under NL_SYNTH_LATTICE_CLAMP left out of the fit (weight 0) with their
 * power relative to the positive power in p (measure f^dim dlog f: the
 * power of the band in 1D, of the radial shell in 2D). */
static int target_sign(int dim, const nl_model *m, double flo, unsigned flags, nl_synth_lattice_plan *p)
{
    enum { NF = 96 };
    double pos = 0, neg = 0, lo = 0, flo_at = 0;
    for (int i = 0; i < NF; i++) {
        double f = flo * pow(0.5 / flo, (i + 0.5) / NF), fv[2] = {f, 0};
        double t = nl_model_spectrum(m, dim, fv), w = pow(f, dim);
        if (!isfinite(t))
            return NL_ERROR(NL_EINVAL, "%s: the spectrum is %g at f = %g cycles per sample; expected finite values",
                            nl_model_spec(m), t, f);
        if (t < 0) {
            neg -= t * w, p->negatives++;
            if (t < lo)
                lo = t, flo_at = f;
        } else
            pos += t * w;
    }
    p->clamp_error = neg > 0 ? (pos > 0 ? neg / pos : INFINITY) : 0;
    if (neg > 0 && (!(flags & NL_SYNTH_LATTICE_CLAMP) || !(pos > 0)))
        return NL_ERROR(NL_ENOTPD, "%s: not positive definite: the spectrum is negative at %zu of the %d fit "
                        "frequencies (min %.3g at f = %.3g); leaving them out changes the fitted power by %.2g of it "
                        "(use --clamp to accept)", nl_model_spec(m), p->negatives, NF, lo, flo_at, p->clamp_error);
    return NL_OK;
}

static double s_target(const void *ctx, double f)
{
    const sctx *x = ctx;
    double fv[2] = {f, 0}, t = nl_model_spectrum(x->m, x->dim, fv);
    return t > 0 ? t : 0;
}

/* The relative-error fit can leave every weight at 0 (a target falling
 * faster than any octave's basis, e.g. a Gaussian spectrum, whose relative
 * error is dominated by frequencies where it is almost 0): a field of
 * zeros.  Refused when the fitted sum carries less than 1e-3 of the
 * target's power over the fit band. */
static int check_power(int dim, const nl_model *m, const nl_synth_lattice_plan *p)
{
    sctx t = {dim, 0, m};
    double want = band_power(dim, s_target, &t, p->peak[0] / 2, 0.5), got = 0;
    for (int o = 0; o < p->octaves; o++) {
        sctx b = {dim, p->cell[o], m};
        got += p->weight[o] * p->weight[o] * band_power(dim, s_basis, &b, 1e-9, 0.5);
    }
    if (!(got >= 1e-3 * want))
        return NL_ERROR(NL_EINVAL, "lattice: %s: the octave fit leaves %.2g of the target's power (every octave "
                        "weight is 0 or nearly so: the spectrum falls faster than the lattice basis); use "
                        "--interpolant wiener, fft or subdiv", nl_model_spec(m), want > 0 ? got / want : 0);
    return NL_OK;
}

/* The families with a closed-form spectrum, for the message: the spectral
 * ones in every dimension ("power:, spectrum:"), then those with a 1D
 * spectrum ("or a 1D markov, gauss"), from the registry. */
static void closed_form_families(char *buf, size_t size)
{
    size_t len = 0;
    int n1 = 0;
    buf[0] = 0;
    for (size_t i = 0; i < nl_family_count() && len < size; i++) {
        const nl_family *f = nl_family_get(i);
        if (f->flags & NL_FAMILY_SPECTRAL)
            len += (size_t)snprintf(buf + len, size - len, "%s:, ", f->name);
    }
    for (size_t i = 0; i < nl_family_count() && len < size; i++) {
        const nl_family *f = nl_family_get(i);
        if (f->spectrum && !(f->flags & NL_FAMILY_SPECTRAL))
            len += (size_t)snprintf(buf + len, size - len, "%s%s", n1++ ? ", " : "or a 1D ", f->name);
    }
}

int nl_synth_lattice_plan_init(const nl_model *m, int dim, double cell0, int octaves, unsigned flags,
                               nl_synth_lattice_plan *p)
{
    double probe[2] = {0.1, 0};
    int st;
    if (dim != 1 && dim != 2)
        return NL_ERROR(NL_EINVAL, "lattice: expected dimension 1 or 2, got %d", dim);
    if (octaves < 1 || octaves > NL_LATTICE_MAX_OCTAVES)
        return NL_ERROR(NL_EINVAL, "octaves: expected 1 to %d, got %d", NL_LATTICE_MAX_OCTAVES, octaves);
    if (!(cell0 >= 2) || cell0 / pow(2, octaves - 1) < 2)
        return NL_ERROR(NL_EINVAL, "octaves: %d octaves from cell %g reach cells below 2 samples", octaves, cell0);
    if (nl_model_nugget(m) != 0) {
        char list[64];
        nl_method_names(NL_METHOD_NUGGET, NULL, ", ", " or ", list, sizeof list);
        return NL_ERROR(NL_EINVAL, "lattice: %s: a nugget is not represented by lattice noise (its closed-form "
                        "spectrum has no white-noise part); use %s", nl_model_spec(m), list);
    }
    if (!isfinite(nl_model_spectrum(m, dim, probe))) {
        char list[512];
        closed_form_families(list, sizeof list);
        return NL_ERROR(NL_EINVAL, "%s: the lattice method needs the model's spectrum in closed form in %dD (%s)",
                        nl_model_spec(m), dim, list);
    }
    if (!basis_ready[dim - 1] && (st = measure_basis(dim)))
        return st;
    memset(p, 0, sizeof *p);
    p->octaves = octaves;
    for (int o = 0; o < octaves; o++) {
        sctx b = {dim, cell0 / pow(2, o), m};
        double fpk = 0, spk = -1;
        /* peak of the basis spectrum at this cell */
        for (int k = 1; k < 2048; k++) {
            double f = 0.5 * k / 2048.0, v = nl_synth_lattice_basis_spectrum(dim, b.c, f);
            if (v > spk)
                spk = v, fpk = f;
        }
        double lo = fpk / M_SQRT2;
        double below = band_power(dim, s_basis, &b, 1e-9, lo), all = band_power(dim, s_basis, &b, 1e-9, 0.5);
        p->cell[o] = b.c;
        p->peak[o] = fpk;
        p->leakage[o] = all > 0 ? below / all : 0;
    }
    if ((st = target_sign(dim, m, p->peak[0] / 2, flags, p)) || (st = fit_weights(dim, m, p, p->peak[0] / 2)))
        return st;
    return check_power(dim, m, p);
}

int nl_synth_lattice_execute(const nl_synth_lattice_plan *p, uint64_t seed, nl_field *out)
{
    int dim = out->dim;
    size_t nx = out->n[0], ny = dim == 2 ? out->n[1] : 1;
    if (dim > 2)
        return NL_ERROR(NL_EINVAL, "lattice: expected a 1D or 2D field, got %dD", dim);
    memset(out->data, 0, out->count * sizeof *out->data);
    for (int o = 0; o < p->octaves; o++) {
        double c = p->cell[o];
        long px = fmod((double)nx, c) == 0 ? (long)((double)nx / c) : 0;
        long py = dim == 2 && fmod((double)ny, c) == 0 ? (long)((double)ny / c) : 0;
#pragma omp parallel for schedule(static) if (out->count > 65536)
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < nx; i++)
                out->data[j * nx + i] += p->weight[o] * gradient_noise(seed, NL_LATTICE_STREAM + (uint32_t)o, dim, c,
                                                                       (double)i, (double)j, px, py);
    }
    return NL_OK;
}
