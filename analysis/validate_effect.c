/* Validation: effect sizes with their intervals, detectable error, the
 * spectrum by octave bands, the verdict (analysis/validate.h). */
#include "validate_internal.h"
#include "verdict.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void nl_validate_effect_of(size_t L, const double *mean, const double *se, const double *target, double r0,
                           double c, double k, nl_validate_effect *e, size_t *worst)
{
    double dmax = -1, lo = 0, hi = 0, semax = 0, zmax = 0;
    size_t w = 0;
    for (size_t i = 0; i < L; i++) {
        double d = fabs(mean[i] - target[i]), z = d / fmax(se[i], 1e-300);
        if (d > dmax)
            dmax = d, w = i;
        lo = fmax(lo, d - c * se[i]);
        hi = fmax(hi, d + c * se[i]);
        semax = fmax(semax, se[i]);
        zmax = fmax(zmax, z);
    }
    e->effect = (nl_validate_interval){dmax / r0, lo / r0, hi / r0};
    e->zmax = zmax;
    e->detectable = k * semax / r0;
    if (worst)
        *worst = w;
}

void nl_validate_bands_of(const nl_validate_result *v, int *band)
{
    size_t j = 0;
    for (size_t z = 0; z < v->n[2]; z++)
        for (size_t y = 0; y < v->n[1]; y++)
            for (size_t x = 0; x < v->n[0]; x++, j++) {
                double fx = (double)nl_wrap(x, v->n[0]) / (double)v->n[0];
                double fy = (double)nl_wrap(y, v->n[1]) / (double)v->n[1];
                double fz = (double)nl_wrap(z, v->n[2]) / (double)v->n[2];
                double f = sqrt(fx * fx + fy * fy + fz * fz);
                int b = 0;
                while ((size_t)b + 1 < v->nbands && f <= v->band_lo[b])
                    b++;
                band[j] = f > 0 ? b : -1;
            }
}

/* Band means of S at the n-grid frequencies; S has `stride` times the
 * grid's samples per axis (its frequency k stands at index stride k).  With
 * them the shape (sum S)^2 / (2 sum S^2) of each band: a periodogram
 * ordinate of a Gaussian field is S_k times an exponential variable (chi^2_2
 * / 2), P(-k) = P(k), so the band mean of one realization is close to a
 * Gamma variable of that shape (the number of independent ordinates,
 * weighted by S). */
static void band_means(const nl_validate_result *v, const int *band, const nl_field *S, size_t stride, double *out,
                       double *shape)
{
    double cnt[NL_VALIDATE_BANDS] = {0}, sq[NL_VALIDATE_BANDS] = {0};
    size_t j = 0;
    memset(out, 0, NL_VALIDATE_BANDS * sizeof *out);
    for (size_t z = 0; z < v->n[2]; z++)
        for (size_t y = 0; y < v->n[1]; y++)
            for (size_t x = 0; x < v->n[0]; x++, j++) {
                size_t ix = x, iy = y, iz = z;
                if (band[j] < 0)
                    continue;
                if (stride > 1) {  /* frequency w/n is index 2w (wrapped) on the 2n grid */
                    ix = (size_t)(nl_wrap(x, v->n[0]) * 2 + (long)S->n[0]) % S->n[0];
                    iy = (size_t)(nl_wrap(y, v->n[1]) * 2 + (long)S->n[1]) % S->n[1];
                    iz = (size_t)(nl_wrap(z, v->n[2]) * 2 + (long)S->n[2]) % S->n[2];
                }
                double s = S->data[(iz * S->n[1] + iy) * S->n[0] + ix];
                out[band[j]] += s, sq[band[j]] += s * s;
                cnt[band[j]]++;
            }
    for (size_t b = 0; b < v->nbands; b++)
        shape[b] = sq[b] > 0 ? out[b] * out[b] / (2 * sq[b]) : NAN, out[b] = cnt[b] > 0 ? out[b] / cnt[b] : NAN;
}

/* R on the 2n grid times the Bartlett window prod_a (1 - |l_a| / n_a), the
 * expected periodogram of a non-periodic field (analysis/psd.h: E P is S
 * smoothed by the Fejer kernel), read at the n-grid frequencies. */
static int fejer_targets(const nl_model *m, nl_validate_result *v, const int *band)
{
    size_t n2[3] = {2 * v->n[0], v->dim > 1 ? 2 * v->n[1] : 1, v->dim > 2 ? 2 * v->n[2] : 1};
    int st = NL_OK;
    nl_field *R = nl_field_alloc(v->dim, n2, NULL, &st), *S = R ? nl_field_alloc(v->dim, n2, NULL, &st) : NULL;
    if (S && !(st = nl_wk_sample_acf(m, R))) {
        size_t j = 0;
        for (size_t z = 0; z < n2[2]; z++)
            for (size_t y = 0; y < n2[1]; y++)
                for (size_t x = 0; x < n2[0]; x++, j++) {
                    double w = 1;
                    long l[3] = {nl_wrap(x, n2[0]), nl_wrap(y, n2[1]), nl_wrap(z, n2[2])};
                    for (int a = 0; a < v->dim; a++)
                        w *= fmax(0, 1 - fabs((double)l[a]) / (double)v->n[a]);
                    R->data[j] *= w;
                }
        if (!(st = nl_wk_acf_to_spectrum(R, S)))
            band_means(v, band, S, 2, v->band_fejer, v->band_shape_fejer);
    }
    nl_field_free(R), nl_field_free(S);
    return st;
}

int nl_validate_spectrum_targets(const nl_model *m, nl_validate_result *v)
{
    int st = NL_OK, *band = NULL;
    nl_field *S = nl_field_alloc(v->dim, v->n, NULL, &st);
    if (S && !(st = nl_size_check(v->dim, v->n, sizeof *band, 1, NULL)) && !(band = malloc(S->count * sizeof *band)))
        st = NL_ERROR(NL_ENOMEM, "out of memory for %zu frequencies", S->count);
    if (band) {
        nl_validate_bands_of(v, band);
        if (!(st = nl_wk_sample_spectrum(m, S))) {
            band_means(v, band, S, 1, v->band_periodic, v->band_shape_periodic);
            st = fejer_targets(m, v, band);
        }
    }
    for (size_t b = 0; b < v->nbands && !st; b++)
        if (!isfinite(v->band_periodic[b]) || !isfinite(v->band_fejer[b]) || !(v->band_shape_periodic[b] > 0) ||
            !(v->band_shape_fejer[b] > 0))
            st = NL_ERROR(NL_EINVAL, "validate: the model's spectrum is not finite in band %zu", b);
    free(band);
    nl_field_free(S);
    return st;
}

/* The interval of a band's expectation mu from its ensemble mean b: under
 * a Gaussian field with the expected spectrum b / mu follows Gamma(K, 1/K)
 * with K = M times the band's shape (band_means), so mu lies in
 * [b / q(1 - a/2), b / q(a/2)] with a = 0.05 / bands (Bonferroni); the
 * band values are skewed (a band of few frequencies is close to an
 * exponential's mean), which an interval b +- t se would ignore. */
static void band_interval(double b, double K, size_t nbands, double *lo, double *hi)
{
    double a = 0.05 / (double)nbands, qlo, qhi;
    nl_gsl_enter();
    if (K > 1000) { /* Wilson-Hilferty: GSL's inverse does not converge for large shapes */
        double z = gsl_cdf_ugaussian_Qinv(a / 2), c = 1 - 1 / (9 * K), w = 1 / (3 * sqrt(K));
        qhi = pow(c + z * w, 3), qlo = pow(c - z * w, 3);
    } else
        qhi = gsl_cdf_gamma_Qinv(a / 2, K, 1 / K), qlo = gsl_cdf_gamma_Pinv(a / 2, K, 1 / K);
    nl_gsl_leave();
    *lo = b / qhi, *hi = b / qlo;
}

/* The periodogram's bands against their expectation. */
static void spectrum_summary(const nl_validate_result *v, const double *b1, const double *b2, const double *expected,
                             const double *shape, nl_validate_method_result *r)
{
    double M = (double)v->realizations, top = 0;
    r->spectrum_error = (nl_validate_interval){0, 0, 0};
    for (size_t b = 0; b < v->nbands; b++)
        top = fmax(top, expected[b]);
    for (size_t b = 0; b < NL_VALIDATE_BANDS; b++) {
        double mu = b < v->nbands ? b1[b] / M : NAN, se = b < v->nbands ? sqrt(fmax(0, (b2[b] - M * mu * mu) / (M - 1)) / M) : NAN;
        double d, lo, hi, e = expected[b];
        r->band_mean[b] = mu, r->band_se[b] = se;
        r->band_error[b] = (nl_validate_interval){NAN, NAN, NAN};
        if (b >= v->nbands || !(e > 1e-6 * top))
            continue;
        band_interval(mu, fmin(M * shape[b], se > 0 ? (mu / se) * (mu / se) : INFINITY), v->nbands, &lo, &hi);
        d = (mu - e) / e;
        r->band_error[b] = (nl_validate_interval){d, (lo - e) / e, (hi - e) / e};
        r->spectrum_error.est = fmax(r->spectrum_error.est, fabs(d));
        /* the interval of |error|: 0 when the band's interval holds 0 */
        r->spectrum_error.lo = fmax(r->spectrum_error.lo, lo > e ? (lo - e) / e : hi < e ? (e - hi) / e : 0);
        r->spectrum_error.hi = fmax(r->spectrum_error.hi, fmax(fabs(lo - e), fabs(hi - e)) / e);
    }
}

/* The lag of flat index i. */
static void lag_of(const nl_validate_result *v, size_t i, long *lag)
{
    for (int d = 0; d < NL_VALIDATE_DIRS; d++) {
        if (i < v->nlag[d]) {
            nl_validate_dir_lag(v->dim, d, (long)i, lag);
            return;
        }
        i -= v->nlag[d];
    }
    memcpy(lag, v->map[i], 3 * sizeof *lag);
}

void nl_validate_exact_effect(nl_validate_result *v, const double *exact)
{
    double target[NL_VALIDATE_DIRS * (NL_VALIDATE_MAXLAG + 1) + NL_VALIDATE_MAPLAGS], dmax = 0;
    size_t w = 0;
    nl_validate_flatten(v, v->target, v->map_target, target);
    for (size_t i = 0; i < v->ntests; i++)
        if (fabs(exact[i] - target[i]) > dmax)
            dmax = fabs(exact[i] - target[i]), w = i;
    v->exact_effect = dmax / v->target[NL_VALIDATE_X][0];
    lag_of(v, w, v->exact_worst);
}

void nl_validate_summarise(const nl_validate_result *v, const double *mean, const double *se, const double *b1,
                           const double *b2, const double *expected, const double *exact, nl_validate_method_result *r)
{
    double target[NL_VALIDATE_DIRS * (NL_VALIDATE_MAXLAG + 1) + NL_VALIDATE_MAPLAGS];
    double r0 = v->target[NL_VALIDATE_X][0], c = v->ci_factor;
    double k = v->threshold + nl_verdict_threshold(0.4, 1, v->realizations - 1);
    size_t off = 0, w;
    nl_validate_flatten(v, v->target, v->map_target, target);
    memset(r->dir, 0, sizeof r->dir);
    for (int d = 0; d < NL_VALIDATE_DIRS; d++) {
        if (v->nlag[d]) {
            nl_validate_effect_of(v->nlag[d], mean + off, se + off, target + off, r0, c, k, &r->dir[d], &w);
            lag_of(v, off + w, r->dir[d].worst);
        }
        for (size_t l = 0; l < v->nlag[d]; l++)
            r->mean[d][l] = mean[off + l], r->se[d][l] = se[off + l];
        off += v->nlag[d];
    }
    memset(&r->map, 0, sizeof r->map);
    for (size_t i = 0; i < v->nmap; i++)
        r->map_mean[i] = mean[off + i], r->map_se[i] = se[off + i];
    if (v->nmap) {
        nl_validate_effect_of(v->nmap, mean + off, se + off, target + off, r0, c, k, &r->map, &w);
        lag_of(v, off + w, r->map.worst);
    }
    nl_validate_effect_of(v->ntests, mean, se, target, r0, c, k, &r->all, &w);
    lag_of(v, w, r->all.worst);
    r->have_exact = exact != NULL;
    if (exact) {
        nl_validate_effect_of(v->ntests, mean, se, exact, r0, c, k, &r->vs_exact, &w);
        lag_of(v, w, r->vs_exact.worst);
    }
    {
        double t = nl_verdict_threshold(0.05, 1, v->realizations - 1);
        r->variance = (nl_validate_interval){mean[0] / r0, (mean[0] - t * se[0]) / r0, (mean[0] + t * se[0]) / r0};
    }
    spectrum_summary(v, b1, b2, expected, expected == v->band_fejer ? v->band_shape_fejer : v->band_shape_periodic, r);
    r->pass = r->all.zmax <= v->threshold;
    r->verdict = r->all.effect.hi <= v->tolerance  ? NL_VALIDATE_WITHIN
                 : r->all.effect.lo > v->tolerance ? NL_VALIDATE_OFF
                                                   : NL_VALIDATE_UNRESOLVED;
}
