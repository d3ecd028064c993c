/* Mean, population variance and rms of a field's samples
 * (core/field_stats.h) against closed forms. */
#include "../core/field_stats.h"

#include <criterion/criterion.h>
#include <math.h>

/* x_i = a + b i for i = 0..N-1: mean a + b (N-1)/2, population variance
 * b^2 (N^2 - 1)/12, mean square var + mean^2.  The sums carry N roundings
 * of relative size 2^-53 each, so 1e-12 relative is ample for N = 1000. */
Test(field_stats, arithmetic_sequence)
{
    size_t n[2] = {40, 25}, N = 1000;
    int st;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    double a = 2.385, b = -0.0173, mean, var;
    cr_assert_not_null(f);
    for (size_t i = 0; i < N; i++)
        f->data[i] = a + b * (double)i;
    nl_field_mean_var(f, &mean, &var);
    double m = a + b * (double)(N - 1) / 2, v = b * b * ((double)N * (double)N - 1) / 12;
    cr_expect(fabs(mean - m) <= 1e-12 * fabs(m), "mean %.17g, expected %.17g", mean, m);
    cr_expect(fabs(var - v) <= 1e-12 * v, "variance %.17g, expected %.17g", var, v);
    double r = sqrt(v + m * m);
    cr_expect(fabs(nl_field_rms(f) - r) <= 1e-12 * r, "rms %.17g, expected %.17g", nl_field_rms(f), r);
    nl_field_free(f);
}

/* A constant field has variance exactly 0 (every deviation is 0 once the
 * mean of N equal terms x/N is x, true for N a power of two); +-c has rms
 * exactly c and mean exactly 0. */
Test(field_stats, exact_cases)
{
    size_t n = 64;
    int st;
    nl_field *f = nl_field_alloc(1, &n, NULL, &st);
    double mean, var;
    cr_assert_not_null(f);
    for (size_t i = 0; i < n; i++)
        f->data[i] = 3.25;
    nl_field_mean_var(f, &mean, &var);
    cr_expect_eq(mean, 3.25);
    cr_expect_eq(var, 0);
    for (size_t i = 0; i < n; i++)
        f->data[i] = i % 2 ? -1.5 : 1.5;
    nl_field_mean_var(f, &mean, &var);
    cr_expect_eq(mean, 0);
    cr_expect_eq(var, 2.25);
    cr_expect_eq(nl_field_rms(f), 1.5);
    nl_field_free(f);
}
