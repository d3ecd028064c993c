/* The method registry (synth/method.h): every method is found by its name,
 * plans, executes and describes through its descriptor; its fields are bit
 * for bit those of the per-method functions it calls (the descriptors only
 * forward), and its option table checks values by type and range with
 * messages naming the option. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/faulting.h"
#include "../synth/fft.h"
#include "../synth/method.h"
#include "../synth/subdiv.h"

#include <criterion/criterion.h>
#include <jansson.h>
#include <string.h>

Test(method, every_method_is_found_by_its_name_once)
{
    int n = nl_method_count();
    cr_assert_geq(n, 8);
    for (int i = 0; i < n; i++) {
        const nl_method_type *t = nl_method_at(i);
        cr_assert_not_null(t->name);
        cr_expect_eq(nl_method_find(t->name), t, "%s", t->name);
        cr_expect(t->noptions <= NL_METHOD_MAX_OPTIONS, "%s", t->name);
        cr_expect(t->dims >= 1 && t->dims <= 7, "%s", t->name);
        cr_expect(t->plan && t->execute && t->describe && t->free, "%s", t->name);
        cr_expect(!(t->caps & NL_METHOD_MODEL) != !(t->caps & NL_METHOD_NO_MODEL), "%s", t->name);
    }
    cr_expect_null(nl_method_at(n));
    cr_expect_null(nl_method_find("nosuch"));
    cr_expect(nl_method_planned("rank1"));
}

Test(method, names_are_listed_by_capability_and_option)
{
    char buf[256];
    cr_expect_eq(nl_method_names(0, "levels", " ", " ", buf, sizeof buf), 2);
    cr_expect_str_eq(buf, "subdiv midpoint");
    cr_expect_eq(nl_method_names(NL_METHOD_WINDOW, NULL, ", ", " or ", buf, sizeof buf), 2);
    cr_expect_str_eq(buf, "subdiv or sparse");
    nl_method_names(0, NULL, ", ", " or ", buf, 12); /* truncated, still terminated */
    cr_expect_lt(strlen(buf), 12u);
}

/* Exact methods first, each group in the registry's order: the order of
 * validate's methods and of the capability messages. */
Test(method, ranked_lists_the_exact_methods_first)
{
    char buf[256];
    int n = nl_method_count(), seen_approx = 0;
    for (int i = 0; i < n; i++) {
        const nl_method_type *t = nl_method_ranked(i);
        cr_assert_not_null(t);
        cr_expect(!(seen_approx && (t->caps & NL_METHOD_EXACT)), "%s after an approximate method", t->name);
        seen_approx |= !(t->caps & NL_METHOD_EXACT);
    }
    cr_expect_null(nl_method_ranked(n));
    nl_method_names(NL_METHOD_DISTRIBUTED | NL_METHOD_EXACT_FIRST, NULL, ", ", " and ", buf, sizeof buf);
    cr_expect_str_eq(buf, "fft, circulant, subdiv and sparse");
    nl_method_names(NL_METHOD_CONDITIONABLE | NL_METHOD_EXACT_FIRST, NULL, ", ", " and ", buf, sizeof buf);
    cr_expect_str_eq(buf, "fft, circulant and subdiv");
}

/* NL_METHOD_NUGGET is what the methods do: each model method with it
 * plans a model with a nugget, each without it refuses one with a message
 * naming the methods that have it. */
Test(method, the_nugget_capability_is_what_planning_does)
{
    char list[128];
    nl_model *m;
    nl_method_grid g = {2, {32, 32, 1}, {1, 1, 1}, {0, 0}};
    cr_assert_eq(nl_model_parse("markov:scale=4,nugget=0.1", &m), NL_OK);
    cr_assert_eq(nl_method_names(NL_METHOD_NUGGET, NULL, ", ", " or ", list, sizeof list), 3);
    cr_expect_str_eq(list, "fft, circulant or cholesky");
    for (int i = 0; i < nl_method_count(); i++) {
        const nl_method_type *t = nl_method_at(i);
        nl_method_options o;
        nl_method_plan *p = NULL;
        if (!(t->caps & NL_METHOD_MODEL) || !(t->dims & 2u) || nl_method_option_index(t, "H") >= 0 ||
            (t->caps & NL_METHOD_INTRINSIC))
            continue;
        nl_method_options_default(t, &o);
        int st = nl_method_plan_alloc(t, m, &g, &o, &p);
        if (t->caps & NL_METHOD_NUGGET)
            cr_expect_eq(st, NL_OK, "%s: %s", t->name, nl_errmsg());
        else
            cr_expect(st == NL_EINVAL && strstr(nl_errmsg(), "nugget") && strstr(nl_errmsg(), list),
                      "%s: %d %s", t->name, st, nl_errmsg());
        nl_method_plan_free(p);
    }
    nl_model_free(m);
}

/* Every method's report is one JSON object (or none), with a positive
 * preview scale, for a field and for the plan alone.  Each method gets the
 * first model it plans (midpoint needs a power law, intrinsic powvar). */
Test(method, every_report_is_a_json_object)
{
    static nl_method_report r;
    nl_model *m[3];
    cr_assert_eq(nl_model_parse("markov:scale=4.385", &m[0]), 0);
    cr_assert_eq(nl_model_parse("power:d=2.385", &m[1]), 0);
    cr_assert_eq(nl_model_parse("powvar:alpha=1.385", &m[2]), 0);
    for (int i = 0; i < nl_method_count(); i++) {
        const nl_method_type *t = nl_method_at(i);
        nl_method_grid g = {2, {16, 16, 1}, {1, 1, 1}, {0, 0}};
        nl_method_options o;
        nl_method_plan *p = NULL;
        int st = NL_OK, k = 0;
        nl_field *f = nl_field_alloc(2, g.n, NULL, &st);
        cr_assert_not_null(f);
        nl_method_options_default(t, &o);
        for (k = 0; k < 3 && !p; k++)
            st = nl_method_plan_alloc(t, t->caps & NL_METHOD_NO_MODEL ? NULL : m[k], &g, &o, &p);
        cr_assert_eq(st, NL_OK, "%s: %s", t->name, nl_errmsg());
        cr_assert_eq(nl_method_execute(p, 7, f), NL_OK, "%s", t->name);
        for (int with = 0; with < 2; with++) {
            cr_assert_eq(nl_method_report_of(p, m[k - 1], 7, with ? f : NULL, &r), NL_OK, "%s", t->name);
            cr_expect_eq(strncmp(r.method, t->name, strlen(t->name)), 0, "%s", r.method);
            cr_expect_gt(r.sd, 0, "%s", t->name);
            json_t *j = r.json[0] ? json_loads(r.json, 0, NULL) : json_object();
            cr_expect(json_is_object(j), "%s: %s", t->name, r.json);
            json_decref(j);
        }
        nl_method_plan_free(p);
        nl_field_free(f);
    }
    nl_model_free(m[0]), nl_model_free(m[1]), nl_model_free(m[2]);
}

/* The same bits as the per-method plan for one seed. */
static void expect_same(const nl_field *a, const nl_field *b)
{
    cr_assert_eq(a->count, b->count);
    cr_expect_eq(memcmp(a->data, b->data, a->count * sizeof *a->data), 0);
}

Test(method, fft_through_the_registry_is_the_fft_plan)
{
    const nl_method_type *t = nl_method_find("fft");
    nl_method_grid g = {2, {48, 40, 1}, {1, 1, 1}, {0, 0}};
    nl_method_options o;
    nl_method_plan *p;
    nl_synth_fft_plan *q;
    nl_model *m;
    char s[64];
    cr_assert_eq(nl_model_parse("markov:scale=4.385", &m), 0);
    nl_field *a = nl_field_alloc(2, g.n, NULL, NULL), *b = nl_field_alloc(2, g.n, NULL, NULL);
    nl_method_options_default(t, &o);
    cr_assert_eq(nl_method_plan_alloc(t, m, &g, &o, &p), 0);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, g.n, g.h, 0, &q), 0);
    cr_assert_eq(nl_method_execute(p, 7, a), 0);
    cr_assert_eq(nl_synth_fft_execute(q, 7, b), 0);
    expect_same(a, b);
    cr_assert_eq(nl_method_describe(p, s, sizeof s), 0);
    cr_expect_str_eq(s, "fft");
    cr_expect_eq(nl_method_describe(p, s, 2), NL_EINVAL); /* does not fit */
    nl_method_plan_free(p), nl_synth_fft_plan_free(q), nl_model_free(m);
    nl_field_free(a), nl_field_free(b);
}

Test(method, subdiv_options_shape_the_plan_and_its_method_string)
{
    const nl_method_type *t = nl_method_find("subdiv");
    nl_method_grid g = {1, {256, 1, 1}, {1, 1, 1}, {0, 0}};
    nl_method_options o;
    nl_subdiv_options so;
    nl_method_plan *p;
    nl_subdiv_plan *q;
    nl_model *m;
    char s[256];
    cr_assert_eq(nl_model_parse("gauss:scale=6.25", &m), 0);
    nl_field *a = nl_field_alloc(1, g.n, NULL, NULL), *b = nl_field_alloc(1, g.n, NULL, NULL);
    nl_method_options_default(t, &o);
    cr_assert_eq(nl_method_options_set(&o, "neighborhood", "3", "--neighborhood"), 0);
    cr_assert_eq(nl_method_options_set(&o, "tol", "variance:1e-3", "--tol"), 0);
    cr_assert_eq(nl_method_options_set(&o, "levels", "4", "--levels"), 0);
    cr_assert_eq(nl_method_plan_alloc(t, m, &g, &o, &p), 0);
    nl_subdiv_options_default(&so);
    so.N = 3, so.tol = 1e-3, so.stop = NL_SUBDIV_STOP_VARIANCE, so.levels = 4;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 1, g.n, 1.0, &so, &q), 0);
    cr_assert_eq(nl_method_execute(p, 11, a), 0);
    cr_assert_eq(nl_subdiv_plan_execute(q, 11, b), 0);
    expect_same(a, b);
    cr_assert_eq(nl_method_describe(p, s, sizeof s), 0);
    cr_expect_str_eq(s, "subdiv:levels=4,neighborhood=3,tol=variance:0.001,periodic");
    cr_expect(nl_method_options_given(&o, "levels"));
    cr_expect(!nl_method_options_given(&o, "taps"));
    nl_method_plan_free(p), nl_subdiv_plan_free(q), nl_model_free(m);
    nl_field_free(a), nl_field_free(b);
}

Test(method, faulting_takes_no_model)
{
    const nl_method_type *t = nl_method_find("faulting");
    nl_method_grid g = {2, {40, 36, 1}, {1, 1, 1}, {0, 0}};
    nl_method_options o;
    nl_method_plan *p;
    size_t K;
    char s[64];
    nl_field *a = nl_field_alloc(2, g.n, NULL, NULL), *b = nl_field_alloc(2, g.n, NULL, NULL);
    nl_method_options_default(t, &o);
    cr_assert_eq(nl_method_options_set(&o, "density", "2.385", NULL), 0);
    cr_assert_eq(nl_method_plan_alloc(t, NULL, &g, &o, &p), 0);
    cr_assert_eq(nl_method_execute(p, 3, a), 0);
    cr_assert_eq(nl_synth_faulting(3, 2.385, b, &K), 0);
    expect_same(a, b);
    cr_expect_eq(nl_synth_faulting_count(3, 2.385, b), K);
    cr_assert_eq(nl_method_describe(p, s, sizeof s), 0);
    cr_expect_str_eq(s, "faulting:density=2.3849999999999998");
    nl_method_plan_free(p), nl_field_free(a), nl_field_free(b);
}

Test(method, option_values_are_checked_by_the_table)
{
    nl_method_options o;
    nl_method_options_default(nl_method_find("subdiv"), &o);
    cr_expect_eq(nl_method_options_set(&o, "levels", "31", "--levels"), NL_EINVAL);
    cr_expect_str_eq(nl_errmsg(), "--levels: expected 1 to 30, got \"31\"");
    cr_expect_eq(nl_method_options_set(&o, "levels", "x", "--levels"), NL_EINVAL);
    cr_expect_str_eq(nl_errmsg(), "--levels: expected an integer >= 1, got \"x\"");
    cr_expect_eq(nl_method_options_set(&o, "tol", "variance:-1", "--tol"), NL_EINVAL);
    cr_expect_eq(nl_method_options_set(&o, "displacements", "both", "--displacements"), NL_EINVAL);
    cr_expect_str_eq(nl_errmsg(), "--displacements: expected independent or correlated, got \"both\"");
    cr_expect_eq(nl_method_options_set(&o, "radius", "3", "--radius"), NL_EINVAL); /* sparse's, not subdiv's */
    cr_expect_eq(nl_method_options_set(&o, "neighborhood", "auto", NULL), 0);
    cr_expect_eq(nl_method_options_get(&o, "neighborhood")->i, 0);
    nl_method_options_default(nl_method_find("midpoint"), &o);
    cr_expect_eq(nl_method_options_set(&o, "H", "1", "--H"), NL_EINVAL); /* open interval */
    cr_expect_str_eq(nl_errmsg(), "--H: expected a Hurst exponent between 0 and 1, got \"1\"");
}

Test(method, a_grid_outside_the_methods_dimensions_is_refused)
{
    const nl_method_type *t = nl_method_find("lattice");
    nl_method_grid g = {3, {8, 8, 8}, {1, 1, 1}, {0, 0}};
    nl_method_options o;
    nl_method_plan *p;
    nl_model *m;
    cr_assert_eq(nl_model_parse("gauss:scale=2", &m), 0);
    nl_method_options_default(t, &o);
    cr_expect_eq(nl_method_plan_alloc(t, m, &g, &o, &p), NL_EINVAL);
    cr_expect_null(p);
    cr_expect_str_eq(nl_errmsg(), "synth lattice: expected a 1D or 2D --size, got 3D");
    nl_model_free(m);
}
