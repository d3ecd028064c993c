/* The histogram's band under a Gaussian model: each bin's probability and
 * the spread of its count in a correlated field (analysis/bands.h). */
#include "bands.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

enum { TERMS = 400 };

/* T[m] = sum over lag vectors v != 0 (|v_a| < n_a) of n(v) rho(v)^m,
 * m = 1..TERMS, from R on the wrapped grid of 2 n_a per axis. */
static void lag_powers(const nl_field *R, const size_t *n, int dim, double *T)
{
    double r0 = R->data[0];
    size_t G[3] = {1, 1, 1};
    for (int a = 0; a < dim; a++)
        G[a] = 2 * n[a];
    for (size_t k = 0; k < G[2]; k++)
        for (size_t j = 0; j < G[1]; j++)
            for (size_t i = 0; i < G[0]; i++) {
                size_t idx[3] = {i, j, k};
                double w = 1, p, r;
                int skip = i == 0 && j == 0 && k == 0;
                for (int a = 0; a < dim && !skip; a++) {
                    long v = nl_wrap(idx[a], G[a]);
                    skip = labs(v) >= (long)n[a];  /* lag n_a: no pair */
                    w *= (double)((long)n[a] - labs(v));
                }
                if (skip || (r = R->data[(k * G[1] + j) * G[0] + i] / r0) == 0)
                    continue;
                p = w;
                for (int m = 1; m <= TERMS && fabs(p) > 1e-18 * w; m++)
                    p *= r, T[m] += p;
            }
}

/* eta_k(t) = He_k(t) phi(t) / sqrt(k!) for k = 0..TERMS - 1 (0 at an
 * infinite t), by the recurrence of He (stable in this normalisation). */
static void hermite_functions(double t, double *eta)
{
    if (!isfinite(t)) {
        for (int k = 0; k < TERMS; k++)
            eta[k] = 0;
        return;
    }
    eta[0] = exp(-0.5 * t * t) / sqrt(2 * M_PI);
    eta[1] = t * eta[0];
    for (int k = 1; k + 1 < TERMS; k++)
        eta[k + 1] = (t * eta[k] - sqrt((double)k) * eta[k - 1]) / sqrt((double)k + 1);
}

static int check(const nl_model *m, int dim, const double *edges, size_t bins)
{
    int st;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "dim: expected 1 to 3, got %d", dim);
    if (!bins)
        return NL_ERROR(NL_EINVAL, "bins: expected at least 1, got 0");
    for (size_t b = 0; b < bins; b++)
        if (!(edges[b] < edges[b + 1]))
            return NL_ERROR(NL_EINVAL, "edges: expected increasing edges, got %g then %g", edges[b], edges[b + 1]);
    if ((st = nl_model_check_dim(m, dim)) || (st = nl_model_check_stationary(m, "a histogram band")))
        return st;
    return NL_OK;
}

int nl_hist_model_band(const nl_model *m, int dim, const size_t *n, const double *h, const double *edges,
                       size_t bins, double *density, double *sd)
{
    size_t G[3];
    double N = 1, *T, *ea, *eb, sigma;
    nl_field *R;
    int st;
    if ((st = check(m, dim, edges, bins)))
        return st;
    for (int a = 0; a < dim; a++)
        G[a] = 2 * n[a], N *= (double)n[a];
    if (!(R = nl_field_alloc(dim, G, h, &st)))
        return st;
    if ((st = nl_wk_sample_acf(m, R)) || !(R->data[0] > 0)) {
        double r0 = R->data[0];
        nl_field_free(R);
        return st ? st : NL_ERROR(NL_EINVAL, "model: expected a positive variance R(0), got %g", r0);
    }
    sigma = sqrt(R->data[0]);
    if (!(T = calloc(3 * TERMS + 1, sizeof *T))) {
        nl_field_free(R);
        return NL_ERROR(NL_ENOMEM, "out of memory for the histogram band");
    }
    ea = T + TERMS + 1, eb = ea + TERMS;
    lag_powers(R, n, dim, T);
    nl_field_free(R);
    for (size_t b = 0; b < bins; b++) {
        double a = edges[b] / sigma, z = edges[b + 1] / sigma, w = edges[b + 1] - edges[b];
        double p = gsl_cdf_ugaussian_P(z) - gsl_cdf_ugaussian_P(a), var = N * p * (1 - p);
        hermite_functions(a, ea), hermite_functions(z, eb);
        for (int k = 1; k <= TERMS; k++) {
            double c = (ea[k - 1] - eb[k - 1]) / sqrt((double)k);
            var += c * c * T[k];
        }
        density[b] = p / w;
        sd[b] = sqrt(var > 0 ? var : 0) / (N * w);
    }
    free(T);
    return NL_OK;
}
