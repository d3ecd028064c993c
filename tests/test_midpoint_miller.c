/* Miller's square-square subdivision (synth/midpoint.h).
 *
 * Properties, all exact up to rounding (tolerance 1e-12, a few ulps of the
 * values involved): the mask is the one Miller prints (9/16, 3/16, 3/16,
 * 1/16 from the nearest corner to the opposite one), sums to 1 and is the
 * tensor product of Chaikin's 3/4, 1/4; the noise-free refinement
 * reproduces a plane at the new points (a quarter of the cell from each
 * corner), which an interpolant of this order must; the displacement
 * variance is the interpolant's error variance for fBm, which in 1D is
 * sigma2 s^(2H) (3/4 4^(-2H) + 1/4 (3/4)^(2H) - 3/16) by hand, and falls
 * by 2^(-2H) per level. */
#include "../core/nl_error.h"
#include "../synth/midpoint.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

Test(midpoint_miller, mask_is_millers_kernel)
{
    double w1[2], w2[4], sum = 0;
    nl_synth_midpoint_miller_mask(1, w1);
    nl_synth_midpoint_miller_mask(2, w2);
    cr_expect_float_eq(w2[0], 9.0 / 16, 1e-15);
    cr_expect_float_eq(w2[1], 3.0 / 16, 1e-15);
    cr_expect_float_eq(w2[2], 3.0 / 16, 1e-15);
    cr_expect_float_eq(w2[3], 1.0 / 16, 1e-15);
    for (int q = 0; q < 4; q++) {
        sum += w2[q];
        cr_expect_float_eq(w2[q], w1[q % 2] * w1[q / 2], 1e-15, "corner %d is not the tensor product", q);
    }
    cr_expect_float_eq(sum, 1.0, 1e-15);
    cr_expect_float_eq(w1[0] + w1[1], 1.0, 1e-15);
}

Test(midpoint_miller, refinement_reproduces_a_plane)
{
    enum { NX = 8, NY = 6 };
    size_t n[2] = {NX, NY};
    double in[NX * NY], out[4 * NX * NY], a = 0.7319, b = -1.2283, c = 2.385;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++)
            in[j * NX + i] = c + a * i + b * j;
    nl_synth_midpoint_miller_refine(2, n, in, 0, 1, 0, out);
    /* new point (2i + p, 2j + q) lies at (i + 1/4 + p/2, j + 1/4 + q/2); away from the periodic seam */
    for (int J = 0; J < 2 * (NY - 1); J++)
        for (int I = 0; I < 2 * (NX - 1); I++) {
            double x = 0.25 + 0.5 * I, y = 0.25 + 0.5 * J;
            cr_expect_float_eq(out[J * 2 * NX + I], c + a * x + b * y, 1e-12, "point (%d, %d): %.15g, plane %.15g", I,
                               J, out[J * 2 * NX + I], c + a * x + b * y);
        }
    /* 1D likewise */
    double l[NX], lo[2 * NX];
    size_t n1[1] = {NX};
    for (int i = 0; i < NX; i++)
        l[i] = c + a * i;
    nl_synth_midpoint_miller_refine(1, n1, l, 0, 1, 0, lo);
    for (int I = 0; I < 2 * (NX - 1); I++)
        cr_expect_float_eq(lo[I], c + a * (0.25 + 0.5 * I), 1e-12, "1D point %d", I);
}

Test(midpoint_miller, variances_are_the_interpolants_error)
{
    double r0, v[6], H = 0.385, s0 = 64, sigma2 = 2.385;
    cr_assert_eq(nl_synth_midpoint_miller_variances(1, 6, s0, H, sigma2, 1, &r0, v), NL_OK);
    cr_expect_float_eq(r0, 0.5 * sigma2 * pow(s0, 2 * H), 1e-12 * r0);
    for (int k = 0; k < 6; k++) {
        double s = s0 / pow(2, k);
        double hand = sigma2 * pow(s, 2 * H) * (0.75 * pow(0.25, 2 * H) + 0.25 * pow(0.75, 2 * H) - 3.0 / 16);
        cr_expect_float_eq(v[k], hand, 1e-12 * hand, "level %d: %.15g, by hand %.15g", k, v[k], hand);
        if (k)
            cr_expect_float_eq(v[k] / v[k - 1], pow(2, -2 * H), 1e-12);
    }
    /* 2D: the same decay, and the variance-scale's extra factor per level */
    double w[6];
    cr_assert_eq(nl_synth_midpoint_miller_variances(2, 6, s0, H, sigma2, 1, &r0, v), NL_OK);
    cr_assert_eq(nl_synth_midpoint_miller_variances(2, 6, s0, H, sigma2, 0.5, &r0, w), NL_OK);
    for (int k = 1; k < 6; k++) {
        cr_expect_float_eq(v[k] / v[k - 1], pow(2, -2 * H), 1e-12);
        cr_expect_float_eq(w[k] / v[k], pow(0.5, k), 1e-12);
    }
}

Test(midpoint_miller, synthesis_sizes_and_errors)
{
    size_t n[2] = {64, 48};
    int st;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    cr_assert_eq(st, NL_OK);
    cr_expect_eq(nl_synth_midpoint_miller_default_levels(2, n), 4); /* 48 = 3 * 2^4: coarse 4 x 3 */
    cr_expect_eq(nl_synth_midpoint_miller(0, 0.7, 1, 1, 3, f), NL_OK);
    for (size_t i = 0; i < f->count; i++)
        cr_assert(isfinite(f->data[i]));
    cr_expect_eq(nl_synth_midpoint_miller(5, 0.7, 1, 1, 3, f), NL_EINVAL); /* 48 / 32 is not whole */
    cr_expect_eq(nl_synth_midpoint_miller(0, 1.0, 1, 1, 3, f), NL_EINVAL);
    cr_expect_eq(nl_synth_midpoint_miller(0, 0.7, 1, 0, 3, f), NL_EINVAL);
    nl_field_free(f);
}
