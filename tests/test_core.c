/* Unit tests of core/: fields, size checks, the counter-based RNG. */
#include "../core/field.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

Test(field, alloc_sets_layout_and_zeroes)
{
    size_t n[3] = {5, 3, 2};
    double h[3] = {0.5, 2.25, 1.5};
    int st;
    nl_field *f = nl_field_alloc(3, n, h, &st);
    cr_assert_not_null(f);
    cr_assert_eq(st, NL_OK);
    cr_assert_eq(f->count, 30);
    cr_assert_eq(f->h[1], 2.25);
    for (size_t i = 0; i < f->count; i++)
        cr_assert_eq(f->data[i], 0.0);
    nl_field_free(f);
    f = nl_field_alloc(1, n, NULL, &st);
    cr_assert_eq(f->n[1], 1);
    cr_assert_eq(f->h[0], 1.0);
    nl_field_free(f);
}

Test(field, rejects_zero_size_and_bad_spacing)
{
    size_t n[2] = {0, 5};
    double h[2] = {1, -1};
    int st;
    cr_assert_null(nl_field_alloc(2, n, NULL, &st));
    cr_assert_eq(st, NL_EINVAL);
    n[0] = 4;
    cr_assert_null(nl_field_alloc(2, n, h, &st));
    cr_assert_eq(st, NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "-1") != NULL, "message names the value: %s", nl_errmsg());
    cr_assert_null(nl_field_alloc(4, n, NULL, &st));
    cr_assert_eq(st, NL_EINVAL);
}

Test(field, refuses_overflow_and_more_than_memory)
{
    size_t big[3] = {SIZE_MAX / 2, 3, 1}, huge[3] = {1u << 20, 1u << 20, 1u << 10};
    cr_assert_eq(nl_size_check(2, big, 8, 1, NULL), NL_ETOOBIG);
    cr_assert(strstr(nl_errmsg(), "overflow") != NULL, "%s", nl_errmsg());
    /* 2^50 doubles: no overflow in size_t, but far beyond any memory */
    cr_assert_eq(nl_size_check(3, huge, 8, 1, NULL), NL_ETOOBIG);
    cr_assert(strstr(nl_errmsg(), "available") != NULL, "%s", nl_errmsg());
    cr_assert_gt(nl_mem_available(), 0);
}

Test(rng, is_a_pure_function_of_seed_stream_index)
{
    double a = nl_rng_gauss(7, 0, 123456789012ULL);
    double b;
    for (int i = 0; i < 10; i++)
        (void)nl_rng_gauss(7, 0, (uint64_t)i);
    b = nl_rng_gauss(7, 0, 123456789012ULL);
    cr_assert_eq(a, b);
    cr_assert_neq(a, nl_rng_gauss(8, 0, 123456789012ULL));
    cr_assert_neq(a, nl_rng_gauss(7, 1, 123456789012ULL));
    /* the high half of the index matters */
    cr_assert_neq(nl_rng_gauss(7, 0, 5), nl_rng_gauss(7, 0, 5 + (1ULL << 32)));
}

/* Moments of n = 10^6 draws: the sample mean has sd 1/sqrt(n) = 1e-3, the
 * sample variance sd sqrt(2/n) = 1.41e-3, the fourth moment (E = 3) sd
 * sqrt((105 - 9)/n) = 9.8e-3, and the lag-1 product (E = 0) sd 1e-3.  Five
 * standard deviations on each. */
Test(rng, gaussian_moments_and_independence)
{
    const size_t n = 1000000;
    double s1 = 0, s2 = 0, s4 = 0, lag = 0, prev = 0, umin = 1, umax = 0;
    for (size_t i = 0; i < n; i++) {
        double g = nl_rng_gauss(2.385e6, 3, i), u = nl_rng_uniform(11, 0, i);
        s1 += g;
        s2 += g * g;
        s4 += g * g * g * g;
        if (i)
            lag += g * prev;
        prev = g;
        umin = fmin(umin, u);
        umax = fmax(umax, u);
    }
    cr_expect_leq(fabs(s1 / n), 5e-3);
    cr_expect_leq(fabs(s2 / n - 1), 5 * 1.414e-3);
    cr_expect_leq(fabs(s4 / n - 3), 5 * 9.8e-3);
    cr_expect_leq(fabs(lag / n), 5e-3);
    cr_expect_gt(umin, 0.0);
    cr_expect_lt(umax, 1.0);
}

/* The pair's first half is nl_rng_gauss of the same arguments, exactly; its
 * second (sine) half is N(0, 1) and independent of the first.  n = 10^6
 * pairs: mean and cross product (E = 0) have sd 1/sqrt(n) = 1e-3, the
 * variance sd sqrt(2/n) = 1.41e-3, E[g0^2 g1^2] = 1 with sd
 * sqrt((E g^4)^2 - 1)/sqrt(n) = sqrt(8/n) = 2.83e-3 (zero for independent
 * halves, not for merely uncorrelated ones).  Five sd on each. */
Test(rng, gaussian_pair_halves_are_independent_normals)
{
    const size_t n = 1000000;
    double s1 = 0, s2 = 0, cross = 0, sq = 0;
    for (size_t i = 0; i < n; i++) {
        double g[2];
        nl_rng_gauss_pair(99, 4, i, g);
        if (i % 1000 == 0)
            cr_assert_eq(g[0], nl_rng_gauss(99, 4, i), "i=%zu", i);
        s1 += g[1];
        s2 += g[1] * g[1];
        cross += g[0] * g[1];
        sq += g[0] * g[0] * g[1] * g[1];
    }
    cr_expect_leq(fabs(s1 / n), 5e-3);
    cr_expect_leq(fabs(s2 / n - 1), 5 * 1.414e-3);
    cr_expect_leq(fabs(cross / n), 5e-3);
    cr_expect_leq(fabs(sq / n - 1), 5 * 2.83e-3);
}
