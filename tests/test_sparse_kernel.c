/* Sparse convolution at arbitrary points, and the band-limited kernels of
 * depth anti-aliasing (Lewis GI '86, sec. 3.1).  Deterministic properties:
 * points on the lattice equal the lattice synthesis bit for bit; a band's
 * field equals the level-0 field blurred by the band's Gaussian (linearity,
 * to rounding); a band's variance follows the Gaussian's gain on a
 * narrow-band kernel; levels blend linearly between footprints 2^l. */
#include "../core/field.h"
#include "../core/nl_error.h"
#include "../synth/sparse.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

static nl_synth_sparse_plan *plan(const char *k, int radius, const char *angle)
{
    nl_synth_sparse_plan *p;
    cr_assert_eq(nl_synth_sparse_plan_expr(k, 2, SPARSE_OPTS(radius, 16, 6.5), &p), NL_OK, "%s", nl_errmsg());
    if (angle)
        cr_assert_eq(nl_synth_sparse_set_angle(p, angle), NL_OK, "%s", nl_errmsg());
    return p;
}

/* points at integer positions, footprint NULL: the samples of execute, bit
 * for bit (same impulses, same summation order, bilinear weights 1 and 0) */
static void lattice_equal(const char *angle)
{
    size_t n[2] = {37, 29};
    long origin[2] = {-11, 23};
    double xy[2 * 37 * 29], out[37 * 29];
    nl_synth_sparse_plan *p = plan("cos(0.45*x+0.2*y)*exp(-r/5)", 20, angle);
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_synth_sparse_execute(p, 7, 0, origin, f), NL_OK, "%s", nl_errmsg());
    for (size_t j = 0; j < n[1]; j++)
        for (size_t i = 0; i < n[0]; i++)
            xy[2 * (j * n[0] + i)] = (double)(origin[0] + (long)i),
            xy[2 * (j * n[0] + i) + 1] = (double)(origin[1] + (long)j);
    cr_assert_eq(nl_synth_sparse_execute_points(p, 7, f->count, xy, NULL, out), NL_OK, "%s", nl_errmsg());
    for (size_t i = 0; i < f->count; i++)
        cr_assert_eq(out[i], f->data[i], "sample %zu: %.17g against %.17g", i, out[i], f->data[i]);
    nl_field_free(f), nl_synth_sparse_plan_free(p);
}

Test(sparse_kernel, points_equal_lattice) { lattice_equal(NULL); }
Test(sparse_kernel, points_equal_lattice_rotated) { lattice_equal("0.02*x-0.01*y+0.3"); }

/* x_l(p) = sum_q g_l(q) x_0(p - q) exactly (the band table is h * g_l, and
 * the sum over impulses is linear), with g_l as the header states; the two
 * sides sum in different orders, so they agree to rounding: 1e-12 of the
 * field's standard deviation (sums of some 10^4 terms of size sd) */
Test(sparse_kernel, band_is_blurred_field)
{
    const int l = 2, G = 4 << (l - 1), m = 9;
    const double sigma = 2;
    size_t n[2] = {2 * 24 + 1 + 2 * 8, 2 * 24 + 1 + 2 * 8};
    long origin[2] = {100 - 24 - 8, -40 - 24 - 8};
    double g[2 * 8 + 1], sum = 0, xy[2 * 9], fp[9], out[9], sd;
    nl_synth_sparse_plan *p = plan("cos(0.5*x)*exp(-r/4)", 24, NULL);
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_synth_sparse_set_bands(p, 3), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_sparse_execute(p, 3, 0, origin, f), NL_OK);
    sd = sqrt(nl_synth_sparse_band_variance(p, 0));
    for (int q = -G; q <= G; q++)
        sum += g[q + G] = exp(-0.5 * q * q / (sigma * sigma));
    for (int k = 0; k < m; k++) {
        long X = 100 + (k % 3) * 12 - 12, Y = -40 + (k / 3) * 12 - 12;
        xy[2 * k] = (double)X, xy[2 * k + 1] = (double)Y, fp[k] = 4; /* footprint 2^l */
    }
    cr_assert_eq(nl_synth_sparse_execute_points(p, 3, (size_t)m, xy, fp, out), NL_OK, "%s", nl_errmsg());
    for (int k = 0; k < m; k++) {
        double s = 0;
        for (int b = -G; b <= G; b++)
            for (int a = -G; a <= G; a++) {
                long i = (long)xy[2 * k] - a - origin[0], j = (long)xy[2 * k + 1] - b - origin[1];
                s += g[a + G] / sum * g[b + G] / sum * f->data[(size_t)j * n[0] + (size_t)i];
            }
        cr_assert_leq(fabs(out[k] - s), 1e-12 * sd, "point %d: band %.15g, blurred field %.15g", k, out[k], s);
    }
    nl_field_free(f), nl_synth_sparse_plan_free(p);
}

/* h = cos(k0 x) exp(-(r/s)^2) has |H|^2 ~ exp(-a |w - w0|^2), a = s^2 / 2
 * (two blobs that do not overlap: exp(-a k0^2 ... ) < 1e-10); blurring by a
 * Gaussian of sd sigma multiplies it by exp(-b |w|^2), b = sigma^2, so the
 * energy ratio is a / (a + b) exp(-a b k0^2 / (a + b)).  The discrete
 * Gaussian truncated at 4 sigma differs from the continuous one by its
 * tail, 6.3e-5 of its mass per axis, and the lattice aliases the blobs by
 * exp(-a (2 pi - k0)^2) < 1e-300: a relative tolerance of 1e-3. */
Test(sparse_kernel, band_variance_gain)
{
    const double k0 = 0.6, s = 12, a = s * s / 2;
    nl_synth_sparse_plan *p = plan("cos(0.6*x)*exp(-(r/12)^2)", 48, NULL);
    cr_assert_eq(nl_synth_sparse_set_bands(p, 4), NL_OK, "%s", nl_errmsg());
    for (int l = 1; l <= 4; l++) {
        double b = ldexp(1, 2 * (l - 1)), want = a / (a + b) * exp(-a * b * k0 * k0 / (a + b));
        double got = nl_synth_sparse_band_variance(p, l) / nl_synth_sparse_band_variance(p, 0);
        cr_log_info("band %d: variance ratio %.6g, predicted %.6g", l, got, want);
        cr_assert_leq(fabs(got - want), 1e-3 * want, "band %d: ratio %.6g, predicted %.6g", l, got, want);
    }
    cr_assert(isnan(nl_synth_sparse_band_variance(p, 5)));
    nl_synth_sparse_plan_free(p);
}

/* a footprint between 2^l and 2^(l+1) blends the two levels linearly in
 * log2(footprint): footprint 2^1.25 = 0.75 x_1 + 0.25 x_2 (to rounding) */
Test(sparse_kernel, levels_blend)
{
    double xy[2] = {3.25, -7.5}, fp[3] = {2, 4, pow(2, 1.25)}, xy3[6], out[3];
    nl_synth_sparse_plan *p = plan("cos(0.5*x+0.3*y)*exp(-r/4)", 24, "0.01*x");
    cr_assert_eq(nl_synth_sparse_set_bands(p, 3), NL_OK);
    for (int k = 0; k < 3; k++)
        xy3[2 * k] = xy[0], xy3[2 * k + 1] = xy[1];
    cr_assert_eq(nl_synth_sparse_execute_points(p, 9, 3, xy3, fp, out), NL_OK, "%s", nl_errmsg());
    cr_assert_leq(fabs(out[2] - (0.75 * out[0] + 0.25 * out[1])), 1e-13 * (fabs(out[0]) + fabs(out[1]) + 1));
    nl_synth_sparse_plan_free(p);
}

Test(sparse_kernel, refusals)
{
    double xy[2] = {0, NAN}, ok[2] = {1, 2}, fp = -1, out[1];
    nl_synth_sparse_plan *p = plan("exp(-r)", 4, NULL), *q;
    cr_assert_eq(nl_synth_sparse_set_bands(p, NL_SPARSE_BANDS_MAX + 1), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_set_bands(p, -1), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_execute_points(p, 1, 1, xy, NULL, out), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "point 0"), "%s", nl_errmsg());
    cr_assert_eq(nl_synth_sparse_execute_points(p, 1, 1, ok, &fp, out), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "footprint"), "%s", nl_errmsg());
    ok[0] = 3e9;
    cr_assert_eq(nl_synth_sparse_execute_points(p, 1, 1, ok, NULL, out), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_execute_points(p, 1, 0, ok, NULL, out), NL_OK);
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-abs(t))", 1, SPARSE_OPTS(4, 0, 1), &q), NL_OK);
    cr_assert_eq(nl_synth_sparse_set_bands(q, 1), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_execute_points(q, 1, 1, ok, NULL, out), NL_EINVAL);
    nl_synth_sparse_plan_free(q), nl_synth_sparse_plan_free(p);
}
