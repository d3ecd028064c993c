/* Estimators: the FFT autocorrelation agrees with the direct sum (eq. 15 of
 * Lewis 1987) to rounding, Parseval holds for the periodogram, a cosine
 * lands in its bin, moments and histogram match their definitions. */
#include "../analysis/acf.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <math.h>

static nl_field *noise(int dim, const size_t *n, double h)
{
    double hh[3] = {h, h * 1.5, h};
    nl_field *f = nl_field_alloc(dim, n, hh, NULL);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = 2.385 + nl_rng_gauss(99, 5, i) + 0.3 * sin(0.1 * (double)i);
    return f;
}

/* Direct O(N^2) lag sums, written from the definition. */
static double direct(const nl_field *x, double mean, long lx, long ly)
{
    double s = 0;
    for (long j = 0; j < (long)x->n[1]; j++)
        for (long i = 0; i < (long)x->n[0]; i++) {
            long i2 = i + lx, j2 = j + ly;
            if (i2 < 0 || j2 < 0 || i2 >= (long)x->n[0] || j2 >= (long)x->n[1])
                continue;
            s += (x->data[j * x->n[0] + i] - mean) * (x->data[j2 * x->n[0] + i2] - mean);
        }
    return s;
}

static void compare(int dim, const size_t *n, int unbiased)
{
    nl_field *x = noise(dim, n, 0.5), *full;
    double mean = 0, scale = 0;
    for (size_t i = 0; i < x->count; i++)
        mean += x->data[i] / (double)x->count;
    cr_assert_eq(nl_acf_full(x, NAN, unbiased, &full), 0);
    for (long ly = dim == 2 ? -(long)n[1] + 1 : 0; ly < (dim == 2 ? (long)n[1] : 1); ly++)
        for (long lx = -(long)n[0] + 1; lx < (long)n[0]; lx++) {
            size_t i = (size_t)(lx < 0 ? lx + (long)full->n[0] : lx);
            size_t j = (size_t)(ly < 0 ? ly + (long)full->n[1] : ly);
            double pairs = unbiased ? (double)(n[0] - labs(lx)) * (dim == 2 ? (double)(n[1] - labs(ly)) : 1.0)
                                    : (double)x->count;
            double want = direct(x, mean, lx, ly) / pairs;
            if (lx == 0 && ly == 0)
                scale = want;
            /* rounding of an FFT of size M is ~ eps log2(M) relative to the
             * largest value, the lag-0 sum */
            cr_assert_float_eq(full->data[j * full->n[0] + i], want, 1e-12 * (scale > 0 ? scale : 1),
                               "lag (%ld, %ld)", lx, ly);
        }
    nl_field_free(full);
    nl_field_free(x);
}

Test(acf, fft_equals_direct_sum_1d)
{
    size_t n[1] = {301};
    compare(1, n, 0);
    compare(1, n, 1);
}

Test(acf, fft_equals_direct_sum_2d)
{
    size_t n[2] = {23, 17};
    compare(2, n, 0);
    compare(2, n, 1);
}

Test(acf, axis_profile_units)
{
    size_t n[2] = {40, 30};
    nl_field *x = noise(2, n, 0.5), *full;
    double lag[10], val[10];
    cr_assert_eq(nl_acf_full(x, NAN, 0, &full), 0);
    cr_assert_eq(nl_acf_axis(full, 1, 9, lag, val), 0);
    cr_assert_eq(lag[3], 3 * 0.75);
    cr_assert_eq(val[3], full->data[3 * full->n[0]]);
    cr_assert_neq(nl_acf_axis(full, 1, 30, lag, val), 0);
    nl_field_free(full);
    nl_field_free(x);
}

/* Parseval: sum_k P_k / prod(n h) equals the mean square about the mean. */
Test(psd, parseval)
{
    size_t n1[1] = {1000}, n2[2] = {48, 36};
    for (int dim = 1; dim <= 2; dim++) {
        nl_field *x = noise(dim, dim == 1 ? n1 : n2, 0.37), *P;
        double mean = 0, ms = 0, sum = 0, cellf = 1;
        for (size_t i = 0; i < x->count; i++)
            mean += x->data[i] / (double)x->count;
        for (size_t i = 0; i < x->count; i++)
            ms += (x->data[i] - mean) * (x->data[i] - mean) / (double)x->count;
        cr_assert_eq(nl_psd_periodogram(x, NAN, &P), 0);
        for (int a = 0; a < dim; a++)
            cellf /= (double)x->n[a] * x->h[a];
        for (size_t k = 0; k < P->count; k++)
            sum += P->data[k] * cellf;
        cr_assert_float_eq(sum, ms, 1e-12 * ms, "dim %d", dim);
        nl_field_free(P);
        nl_field_free(x);
    }
}

/* x_j = A cos(2 pi k0 j / N): |X_k0|^2 = (A N / 2)^2, so P_k0 = h A^2 N / 4
 * at f = k0 / (N h), and the other bins are zero up to rounding. */
Test(psd, cosine_lands_in_its_bin)
{
    size_t n[1] = {256}, k0 = 19;
    double h = 0.5, A = 1.7;
    nl_field *x = nl_field_alloc(1, n, &h, NULL), *P;
    for (size_t j = 0; j < n[0]; j++)
        x->data[j] = A * cos(2 * M_PI * (double)(k0 * j) / (double)n[0]);
    cr_assert_eq(nl_psd_periodogram(x, 0.0, &P), 0);
    cr_assert_float_eq(P->data[k0], h * A * A * 256 / 4, 1e-9);
    cr_assert_float_eq(P->data[256 - k0], P->data[k0], 1e-9);
    cr_assert_lt(P->data[k0 + 1], 1e-20);
    nl_field_free(P);
    nl_field_free(x);
}

/* Moments of {1, 2, 3, 4, 10} from their definitions: mean 4, unbiased
 * variance 50/4 = 12.5, skewness (1/n) sum ((x - m)/sd)^3 and excess
 * kurtosis (1/n) sum ((x - m)/sd)^4 - 3 with the same sd. */
Test(hist, moments_and_counts)
{
    size_t n[1] = {5};
    double v[5] = {1, 2, 3, 4, 10}, sd = sqrt(12.5), s3 = 0, s4 = 0, edges[5], counts[4];
    nl_field *x = nl_field_alloc(1, n, NULL, NULL);
    nl_moments m;
    for (int i = 0; i < 5; i++) {
        x->data[i] = v[i];
        s3 += pow((v[i] - 4) / sd, 3) / 5;
        s4 += pow((v[i] - 4) / sd, 4) / 5;
    }
    cr_assert_eq(nl_moments_compute(x, &m), 0);
    cr_assert_float_eq(m.mean, 4, 1e-15);
    cr_assert_float_eq(m.variance, 12.5, 1e-14);
    cr_assert_float_eq(m.skewness, s3, 1e-14);
    cr_assert_float_eq(m.kurtosis, s4 - 3, 1e-14);
    cr_assert_eq(nl_hist(x, 4, edges, counts), 0);
    cr_assert_float_eq(edges[0], 1, 1e-15);
    cr_assert_float_eq(edges[4], 10, 1e-12);
    /* bins of width 2.25: [1, 3.25) holds 1, 2, 3; [3.25, 5.5) holds 4; the
     * maximum 10 falls in the last bin */
    cr_assert_eq(counts[0], 3);
    cr_assert_eq(counts[1], 1);
    cr_assert_eq(counts[2], 0);
    cr_assert_eq(counts[3], 1);
    nl_field_free(x);
}

/* Radial average of the distance itself returns the bin's mean distance,
 * and bin b holds the samples with round(d / step) = b. */
Test(radial, bins_by_distance)
{
    size_t n[2] = {16, 16};
    double h[2] = {1, 1}, r[6], v[6];
    size_t cnt[6];
    nl_field *g = nl_field_alloc(2, n, h, NULL);
    for (size_t j = 0; j < 16; j++)
        for (size_t i = 0; i < 16; i++) {
            double x = (double)(i <= 8 ? (long)i : (long)i - 16), y = (double)(j <= 8 ? (long)j : (long)j - 16);
            g->data[j * 16 + i] = hypot(x, y);
        }
    cr_assert_eq(nl_radial(g, NL_GRID_LAG, 1.0, 6, r, v, cnt), 0);
    cr_assert_eq(cnt[0], 1);
    cr_assert_eq(cnt[1], 8);  /* 4 at distance 1 and 4 at sqrt(2) */
    for (int b = 0; b < 6; b++)
        cr_assert_float_eq(r[b], v[b], 1e-12);
    nl_field_free(g);
}
