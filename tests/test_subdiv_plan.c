/* Subdivision plans: plan once, execute many seeds.  Executing is a pure
 * function of (plan, seed): bit-identical fields for one seed, different
 * fields for two, and the plan path equals the one-shot path bit for bit
 * (the same coefficients, coarse FFT plan and random numbers, so not even
 * rounding may differ).  Then every NL_E* code of subdiv.h's plan API. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

static nl_field *field(int dim, size_t nx, size_t ny)
{
    size_t n[2] = {nx, ny};
    nl_field *f = nl_field_alloc(dim, n, NULL, NULL);
    cr_assert_not_null(f);
    return f;
}

static int same(const nl_field *a, const nl_field *b)
{
    return a->count == b->count && memcmp(a->data, b->data, a->count * sizeof *a->data) == 0;
}

Test(subdiv_plan, execute_is_pure_and_equals_one_shot)
{
    nl_model *m = test_model("markaussian:alpha=1.4,scale=5.3");
    size_t n[2] = {128, 96};
    nl_subdiv_options o;
    nl_subdiv_plan *p;
    nl_subdiv_coeffs *c;
    nl_field *a = field(2, 128, 96), *b = field(2, 128, 96), *d = field(2, 128, 96), *e = field(2, 128, 96);
    nl_subdiv_info info;
    nl_subdiv_options_default(&o);
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), 0, "%s", nl_errmsg());
    nl_subdiv_plan_info(p, &info);
    cr_assert_eq(info.levels, 3, "default policy: coarse grid of >= 8: 96 / 2^3 = 12, 96 / 2^4 = 6");
    cr_assert_eq(nl_subdiv_plan_execute(p, 7, a), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_plan_execute(p, 7, b), 0);
    cr_assert_eq(nl_subdiv_plan_execute(p, 8, d), 0);
    cr_assert(same(a, b), "one seed, two executions");
    cr_assert(!same(a, d), "two seeds");
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, info.levels, info.spacing0, 2, 1e-4, 6, &c), 0);
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 7, 0, e), 0, "%s", nl_errmsg());
    cr_assert(same(a, e), "plan path = one-shot path");
    cr_assert_eq(a->h[0], 1.0);
    nl_subdiv_coeffs_free(c), nl_subdiv_plan_free(p), nl_model_free(m);
    nl_field_free(a), nl_field_free(b), nl_field_free(d), nl_field_free(e);
}

Test(subdiv_plan, window_and_midpoint_equal_one_shot)
{
    nl_model *m = test_model("markov:scale=6.1");
    size_t n[1] = {200};
    long origin[2] = {-37, 0};
    nl_subdiv_options o;
    nl_subdiv_plan *p;
    nl_subdiv_coeffs *c;
    nl_subdiv_info info;
    nl_field *a = field(1, 200, 1), *b = field(1, 200, 1);
    nl_subdiv_options_default(&o);
    o.nonperiodic = 1;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 1, n, 1.0, &o, &p), 0, "%s", nl_errmsg());
    nl_subdiv_plan_info(p, &info);
    cr_assert_eq(info.levels, 6);
    cr_assert_float_eq(info.coarse_correlation, exp(-64 / 6.1), 1e-15, "R(s_0)/R(0) for markov");
    cr_assert_eq(nl_subdiv_plan_execute_window(p, 3, origin, a), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 6, 64.0, 2, 1e-4, 16, &c), 0);
    cr_assert_eq(nl_subdiv_synth_window(c, 3, origin, b), 0);
    cr_assert(same(a, b));
    /* origin NULL is the window at 0 */
    origin[0] = 0;
    cr_assert_eq(nl_subdiv_plan_execute_window(p, 3, NULL, a), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_plan_execute_window(p, 3, origin, b), 0, "%s", nl_errmsg());
    cr_assert(same(a, b));
    nl_subdiv_coeffs_free(c), nl_subdiv_plan_free(p);

    cr_assert_eq(nl_subdiv_plan_alloc_midpoint(1, n, 1.0, 3, 0.7, 1.0, 1.0, &p), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_plan_execute(p, 5, a), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_coeffs_midpoint(1, 3, 8.0, 0.7, 1.0, 1.0, &c), 0);
    cr_assert_eq(nl_subdiv_synth_periodic(c, NULL, 5, 0, b), 0);
    cr_assert(same(a, b));
    nl_subdiv_coeffs_free(c), nl_subdiv_plan_free(p), nl_model_free(m);
    nl_field_free(a), nl_field_free(b);
}

/* The seed image: its samples come back bit for bit (tiny values beside an
 * outlier, so (v - mean) + mean would not give them back), the rest is the
 * refinement of the zero-mean image plus its mean. */
Test(subdiv_plan, seed_image_kept_and_mean_restored)
{
    nl_model *m = test_model("markov:scale=4");
    size_t n[2] = {64, 32}, ni[2] = {16, 8};
    nl_subdiv_options o;
    nl_subdiv_plan *p;
    nl_field *img = field(2, 16, 8), *zero = field(2, 16, 8), *f = field(2, 64, 32), *g = field(2, 64, 32);
    int L;
    double mean = 0;
    for (size_t i = 0; i < img->count; i++)
        mean += (img->data[i] = 1e-9 * sin(2.385 * (double)i) + (i == 5 ? 1e3 : 0));
    mean /= (double)img->count;
    cr_assert_eq(nl_subdiv_image_levels(2, ni, n, 0, &L), 0);
    cr_assert_eq(L, 2);
    nl_subdiv_options_default(&o);
    o.levels = L, o.image = 1;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_plan_execute(p, 1, f), NL_EINVAL, "an image plan needs its image");
    cr_assert_eq(nl_subdiv_plan_execute_image(p, img, 4, f), 0, "%s", nl_errmsg());
    for (size_t j = 0; j < 8; j++)
        for (size_t i = 0; i < 16; i++)
            cr_assert_eq(f->data[4 * j * 64 + 4 * i], img->data[j * 16 + i]);
    for (size_t i = 0; i < zero->count; i++)
        zero->data[i] = img->data[i] - mean;
    cr_assert_eq(nl_subdiv_refine_periodic(nl_subdiv_plan_coeffs(p), zero, 4, 0, g), 0);
    for (size_t i = 0; i < g->count; i++)
        if (i % 4 || (i / 64) % 4)
            cr_assert_eq(f->data[i], g->data[i] + mean, "sample %zu", i);
    nl_subdiv_plan_free(p), nl_model_free(m);
    nl_field_free(img), nl_field_free(zero), nl_field_free(f), nl_field_free(g);
}

Test(subdiv_plan, default_levels_policy)
{
    size_t a[2] = {128, 96}, b[1] = {100}, c[1] = {15}, d[1] = {4096};
    cr_assert_eq(nl_subdiv_default_levels(2, a, 8), 3);
    cr_assert_eq(nl_subdiv_default_levels(1, b, 8), 2, "100 / 4 = 25: 100 / 8 is not whole");
    cr_assert_eq(nl_subdiv_default_levels(1, b, 2), 2);
    cr_assert_eq(nl_subdiv_default_levels(1, c, 2), 0);
    cr_assert_eq(nl_subdiv_default_levels(1, d, 8), 9);
}

/* Every NL_E* code the plan API lists. */
Test(subdiv_plan, error_paths)
{
    nl_model *m = test_model("markov:scale=4"), *spec = test_model("spectrum:1/(1+k^2)"),
             *bad = test_model("expr:cos(10*r)*exp(-r)"), *pw = test_model("power:d=3.6");
    size_t n[2] = {64, 64}, n3[2] = {100, 100}, ni[2] = {16, 16}, nj[2] = {24, 16}, tiny[1] = {1};
    nl_subdiv_options o;
    nl_subdiv_plan *p = (nl_subdiv_plan *)1;
    nl_field *f2 = field(2, 64, 64), *f1 = field(1, 64, 1), *g = field(2, 32, 64);
    long origin[2] = {0, 0};
    int L = -1;
    double H = -1;
    nl_subdiv_options_default(&o);
    cr_assert_eq(nl_subdiv_plan_alloc(m, 3, n, 1.0, &o, &p), NL_EINVAL);
    cr_assert_null(p, "*out is NULL on failure");
    cr_assert_eq(nl_subdiv_plan_alloc(m, 1, tiny, 1.0, &o, &p), NL_EINVAL, "no level fits");
    o.levels = 3;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n3, 1.0, &o, &p), NL_EINVAL, "100 is not a multiple of 8");
    cr_assert_eq(nl_subdiv_plan_alloc(spec, 2, n, 1.0, &o, &p), NL_EINVAL, "subdivision needs R");
    o.random_nb = 2;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 1, n, 1.0, &o, &p), NL_EINVAL, "random neighbourhoods in 1D");
    nl_subdiv_options_default(&o);
    size_t nb[2] = {128, 128};
    cr_assert_eq(nl_subdiv_plan_alloc(bad, 2, nb, 0.25, &o, &p), NL_ENOTPD);
    cr_assert(strstr(nl_errmsg(), "not positive definite"), "%s", nl_errmsg());
    o.allow_not_pd = 1;
    cr_assert_eq(nl_subdiv_plan_alloc(bad, 2, nb, 0.25, &o, &p), 0, "%s", nl_errmsg());
    nl_subdiv_plan_free(p);
    o.allow_not_pd = 0, o.nonperiodic = 1;
    cr_assert_eq(nl_subdiv_plan_alloc(bad, 2, nb, 0.25, &o, &p), NL_ENOTPD, "windows never clamp");

    nl_subdiv_options_default(&o);
    o.levels = 1;
    size_t huge[2] = {(size_t)1 << 33, (size_t)1 << 33};
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, huge, 1.0, &o, &p), NL_ETOOBIG, "a 2^32 x 2^32 coarse FFT");
    o.levels = 0;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), 0);
    cr_assert_eq(nl_subdiv_plan_execute(p, 1, f1), NL_EINVAL, "1D field, 2D plan");
    cr_assert_eq(nl_subdiv_plan_execute(p, 1, g), NL_EINVAL, "size differs from the plan");
    cr_assert_eq(nl_subdiv_plan_execute_window(p, 1, origin, f2), NL_EINVAL, "a periodic plan has no window");
    nl_subdiv_plan_free(p);
    o.nonperiodic = 1;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), 0);
    cr_assert_eq(nl_subdiv_plan_execute_image(p, g, 1, f2), NL_EINVAL, "a window refines no image");
    nl_subdiv_plan_free(p);

    cr_assert_eq(nl_subdiv_image_levels(2, nj, n, 0, &L), NL_EINVAL, "24 does not double to 64");
    cr_assert_eq(nl_subdiv_image_levels(2, ni, n, 3, &L), NL_EINVAL, "16 -> 64 is 2 levels, not 3");
    cr_assert_eq(nl_subdiv_image_levels(2, n, n, 0, &L), NL_EINVAL, "nothing to refine");
    cr_assert_eq(L, -1);

    cr_assert_eq(nl_subdiv_midpoint_hurst(m, 1, &H), NL_EINVAL, "not a power model");
    cr_assert_eq(nl_subdiv_midpoint_hurst(pw, 1, &H), NL_EINVAL, "d = 3.6 in 1D: H = 1.3");
    cr_assert_eq(nl_subdiv_midpoint_hurst(pw, 2, &H), 0);
    cr_assert_float_eq(H, 0.8, 1e-15);
    cr_assert_eq(nl_subdiv_plan_alloc_midpoint(3, n, 1.0, 2, 0.5, 1, 1, &p), NL_EINVAL);
    cr_assert_eq(nl_subdiv_plan_alloc_midpoint(2, n, 1.0, 2, 1.5, 1, 1, &p), NL_EINVAL);
    cr_assert_eq(nl_subdiv_plan_alloc_midpoint(2, n3, 1.0, 3, 0.5, 1, 1, &p), NL_EINVAL, "100 / 8");
    cr_assert_null(p);
    nl_model_free(m), nl_model_free(spec), nl_model_free(bad), nl_model_free(pw);
    nl_field_free(f1), nl_field_free(f2), nl_field_free(g);
}

Test(subdiv_plan, model_param)
{
    nl_model *pw = test_model("power:d=3.6,fmin=0.01"), *m = test_model("markov:scale=4");
    double v = -1;
    cr_assert_eq(nl_model_param(pw, "d", &v), 0);
    cr_assert_eq(v, 3.6);
    cr_assert_eq(nl_model_param(pw, "fmin", &v), 0);
    cr_assert_eq(v, 0.01);
    cr_assert_eq(nl_model_param(m, "var", &v), 0);
    cr_assert_eq(v, 1.0, "defaults are reported");
    v = -1;
    cr_assert_eq(nl_model_param(m, "d", &v), NL_EINVAL, "markov has no d");
    cr_assert_eq(nl_model_param(pw, "nosuch", &v), NL_EINVAL);
    cr_assert_eq(v, -1, "untouched on failure");
    nl_model_free(pw), nl_model_free(m);
}

/* Every NL_E* code of the coefficient and one-shot functions (NL_EFAIL and
 * NL_ENOMEM need a failing solver or allocator: not triggered). */
Test(subdiv_plan, one_shot_error_paths)
{
    nl_model *m = test_model("markov:scale=4"), *flat = test_model("expr:0*t"), *bad = test_model("expr:cos(10*r)*exp(-r)");
    nl_subdiv_coeffs *c = (nl_subdiv_coeffs *)1, *c1, *c2;
    nl_field *f2 = field(2, 64, 64), *f1 = field(1, 64, 1), *coarse = field(2, 16, 16), *small = field(2, 8, 8),
             *odd = field(2, 18, 16);
    long origin[2] = {0, 0};
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 3, 2, 4.0, 2, 1e-4, 6, &c), NL_EINVAL, "dim");
    cr_assert_null(c);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 0, 4.0, 2, 1e-4, 6, &c), NL_EINVAL, "levels 0");
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 41, 4.0, 2, 1e-4, 6, &c), NL_EINVAL, "levels 41");
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 2, 0.0, 2, 1e-4, 6, &c), NL_EINVAL, "spacing0");
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 2, 4.0, 9, 1e-4, 6, &c), NL_EINVAL, "N = 9 in 2D");
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 2, 4.0, 0, 0.0, 6, &c), NL_EINVAL, "tol");
    cr_assert_eq(nl_subdiv_coeffs_alloc(flat, 1, 2, 4.0, 2, 1e-4, 16, &c), NL_EINVAL, "R(0) = 0: %s", nl_errmsg());

    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 2, 4.0, 2, 1e-4, 16, &c1), 0);
    cr_assert_eq(nl_subdiv_coeffs_randomize(c1, m, 4, 1), NL_EINVAL, "1D");
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 2, 16.0, 2, 1e-4, 6, &c2), 0);
    cr_assert_eq(nl_subdiv_coeffs_randomize(c2, m, 0, 1), NL_EINVAL, "k = 0");
    cr_assert_eq(nl_subdiv_coeffs_randomize(c2, m, 257, 1), NL_EINVAL, "k = 257");

    cr_assert_eq(nl_subdiv_synth_periodic(c2, m, 1, 0, f1), NL_EINVAL, "1D field, 2D coefficients");
    cr_assert_eq(nl_subdiv_synth_periodic(c2, m, 1, 0, odd), NL_EINVAL, "18 is not a multiple of 4");
    cr_assert_eq(nl_subdiv_refine_periodic(c2, small, 1, 0, f2), NL_EINVAL, "8 x 8 refined twice is 32 x 32");
    cr_assert_eq(nl_subdiv_refine_periodic(c2, coarse, 1, 0, f1), NL_EINVAL, "dims");
    cr_assert_eq(nl_subdiv_synth_window(c2, 1, origin, f1), NL_EINVAL, "dims");
    nl_subdiv_coeffs_free(c2);
    /* a 4 x 4 coarse grid cannot hold a 6 x 6 neighbourhood */
    nl_field *c4 = field(2, 4, 4), *f16 = field(2, 16, 16);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 2, 2, 16.0, 3, 1e-4, 6, &c2), 0);
    cr_assert_eq(nl_subdiv_refine_periodic(c2, c4, 1, 0, f16), NL_EINVAL, "%s", nl_errmsg());
    cr_assert(strstr(nl_errmsg(), "neighbourhood"), "%s", nl_errmsg());
    nl_subdiv_coeffs_free(c2);
    cr_assert_eq(nl_subdiv_coeffs_alloc(bad, 2, 6, 8.0, 2, 1e-4, 6, &c2), 0);
    cr_assert_eq(nl_subdiv_synth_window(c2, 1, origin, f2), NL_ENOTPD);
    cr_assert_eq(nl_subdiv_refine_periodic(c2, coarse, 1, 0, f2), NL_EINVAL, "16 x 64 = 1024, not 64");
    nl_subdiv_coeffs_free(c2);
    cr_assert_eq(nl_subdiv_coeffs_alloc(bad, 2, 2, 2.0, 2, 1e-4, 6, &c2), 0);
    cr_assert_eq(nl_subdiv_refine_periodic(c2, coarse, 1, 0, f2), NL_ENOTPD, "%s", nl_errmsg());
    nl_subdiv_coeffs_free(c2);
    nl_subdiv_coeffs_free(c1);
    nl_model_free(m), nl_model_free(flat), nl_model_free(bad);
    nl_field_free(f1), nl_field_free(f2), nl_field_free(coarse), nl_field_free(small), nl_field_free(odd);
    nl_field_free(c4), nl_field_free(f16);
}
