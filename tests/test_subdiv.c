/* Generalized stochastic subdivision: the paper's tables, the structural
 * properties of the coefficients, the flags (both ways), and the
 * consistency properties of the synthesis. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"

#include <criterion/criterion.h>
#include <math.h>
#include <omp.h>
#include <string.h>

static nl_subdiv_coeffs *coeffs(const char *spec, int dim, int levels, double s0, int N)
{
    nl_model *m;
    nl_subdiv_coeffs *c;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, dim, levels, s0, N, 1e-4, 16, &c), 0, "%s: %s", spec, nl_errmsg());
    nl_model_free(m);
    return c;
}

/* Lewis 1987, Table 1: R = 100 cos(10 t) exp(-|t|), N = 2, 10 levels, as
 * printed (a_1, a_2, variance).  The level-0 observation spacing that
 * reproduces it is 15 (halved at every level); the printed digits then
 * agree to |delta a| <= 1e-6 and relative delta variance <= 1e-5. */
Test(subdiv, lewis_table_1)
{
    static const double table[10][3] = {
        {0.000510, 0.000000, 99.999947}, {0.023041, -0.000001, 99.893768}, {0.149159, -0.000068, 95.447868},
        {-0.339373, 0.000223, 73.455498}, {-0.019945, 0.014377, 99.885315}, {-0.495669, 0.158384, 33.747765},
        {0.343860, -0.337269, 32.062786}, {0.566771, -0.112145, 7.430885},  {0.543814, -0.036580, 3.152761},
        {0.514256, -0.010190, 1.494914}};
    nl_subdiv_coeffs *c = coeffs("expr:100*cos(10*t)*exp(-abs(t))", 1, 10, 15.0, 2);
    for (int k = 0; k < 10; k++) {
        const nl_subdiv_class *cl = &c->level[k].cls[0];
        /* order k = -1, 0, 1, 2: a_1 is index 2, a_2 index 3; symmetric */
        cr_expect_leq(fabs(cl->a[2] - table[k][0]), 1e-6, "level %d a_1 %.7f", k, cl->a[2]);
        cr_expect_leq(fabs(cl->a[3] - table[k][1]), 1e-6, "level %d a_2 %.7f", k, cl->a[3]);
        cr_expect_float_eq(cl->a[1], cl->a[2], 1e-12, "a_0 = a_1");
        cr_expect_float_eq(cl->a[0], cl->a[3], 1e-12, "a_-1 = a_2");
        cr_expect_leq(fabs(cl->variance - table[k][2]) / table[k][2], 1e-5, "level %d variance %.6f", k,
                      cl->variance);
        cr_expect_eq(cl->flags, 0);
    }
    nl_subdiv_coeffs_free(c);
}

/* Lewis 1987, Table 2: mid-face coefficients of exp(-sqrt(x^2 + y^2)) over
 * a 4x4 neighbourhood; spacing 1 reproduces the printed digits. */
Test(subdiv, lewis_table_2)
{
    static const double t[16] = {-0.006170, -0.003781, -0.003781, -0.006170, -0.003781, 0.254035,
                                 0.254035,  -0.003781, -0.003781, 0.254035,  0.254035,  -0.003781,
                                 -0.006170, -0.003781, -0.003781, -0.006170};
    nl_subdiv_coeffs *c = coeffs("markov", 2, 1, 1.0, 2);
    cr_assert_eq(c->level[0].cls[0].cls, NL_SUBDIV_FACE);
    for (int i = 0; i < 16; i++)
        cr_expect_leq(fabs(c->level[0].cls[0].a[i] - t[i]), 5e-6, "coefficient %d: %.7f", i,
                      c->level[0].cls[0].a[i]);
    nl_subdiv_coeffs_free(c);
}

/* exp(-|t|) is Markovian: only the two immediate neighbours count, at every
 * level and neighbourhood size (Lewis: "a simple test of correctness"). */
Test(subdiv, markov_uses_immediate_neighbours_only)
{
    for (int N = 2; N <= 4; N++) {
        nl_subdiv_coeffs *c = coeffs("markov:scale=1.3", 1, 8, 10.0, N);
        for (int k = 0; k < 8; k++)
            for (int i = 0; i < 2 * N; i++) {
                double a = c->level[k].cls[0].a[i];
                if (i == N - 1 || i == N)
                    cr_expect_gt(fabs(a), 1e-6, "N=%d level %d: neighbour coefficient %g", N, k, a);
                else
                    cr_expect_lt(fabs(a), 1e-12, "N=%d level %d: a[%d] = %g", N, k, i, a);
            }
        nl_subdiv_coeffs_free(c);
    }
}

/* Separable exp(-|x|) exp(-|y|): the face uses its four corners, an edge
 * its two ends; every other coefficient vanishes. */
Test(subdiv, separable_markov_uses_face_corners_and_edge_ends)
{
    nl_subdiv_coeffs *c = coeffs("markov:scale=1.7,sep", 2, 6, 8.0, 2);
    for (int k = 0; k < 6; k++)
        for (int j = 0; j < 3; j++) {
            const nl_subdiv_class *cl = &c->level[k].cls[j];
            for (int r = 0; r < 4; r++)
                for (int q = 0; q < 4; q++) {
                    int rr = r - 1, cc = q - 1; /* offsets -1..2 */
                    int used = cl->cls == NL_SUBDIV_FACE   ? (rr == 0 || rr == 1) && (cc == 0 || cc == 1)
                               : cl->cls == NL_SUBDIV_EDGE_X ? rr == 0 && (cc == 0 || cc == 1)
                                                          : cc == 0 && (rr == 0 || rr == 1);
                    double a = cl->a[r * 4 + q];
                    if (used)
                        cr_expect_gt(fabs(a), 1e-6, "level %d %s (%d,%d)", k, nl_subdiv_class_name(cl->cls), rr, cc);
                    else
                        cr_expect_lt(fabs(a), 1e-12, "level %d %s (%d,%d) = %g", k, nl_subdiv_class_name(cl->cls),
                                     rr, cc, a);
                }
            cr_expect_eq(cl->flags & NL_SUBDIV_DIAG_BIAS, 0);
        }
    nl_subdiv_coeffs_free(c);
}

/* Singular: exp(-t^2) at fine levels needs the pseudo-inverse, whose uniform
 * solution is reset to (0, 1/2, 1/2, 0); no variance is ever negative.
 * Not singular: exp(-|t|) at the same spacings. */
Test(subdiv, gauss_is_singular_at_fine_levels_markov_is_not)
{
    nl_subdiv_coeffs *g = coeffs("gauss", 1, 14, 4.0, 2), *m = coeffs("markov", 1, 14, 4.0, 2);
    int singular = 0, reset = 0;
    for (int k = 0; k < 14; k++) {
        const nl_subdiv_class *cl = &g->level[k].cls[0];
        cr_expect_geq(cl->variance, 0.0);
        if (cl->flags & NL_SUBDIV_SINGULAR) {
            singular++;
            cr_expect(cl->flags & NL_SUBDIV_PINV, "level %d: singular but not solved by the pseudo-inverse", k);
        }
        if (cl->flags & NL_SUBDIV_NN_RESET) {
            reset++;
            cr_expect_eq(cl->a[0], 0.0);
            cr_expect_eq(cl->a[1], 0.5);
            cr_expect_eq(cl->a[2], 0.5);
            cr_expect_eq(cl->a[3], 0.0);
        }
        cr_expect_eq(m->level[k].cls[0].flags, 0, "markov level %d flagged", k);
    }
    cr_expect(!(g->level[0].cls[0].flags & NL_SUBDIV_SINGULAR), "the coarsest gauss level is regular");
    cr_expect_geq(singular, 3);
    cr_expect_geq(reset, 1);
    nl_subdiv_coeffs_free(g);
    nl_subdiv_coeffs_free(m);
}

/* cos(10 r) exp(-r) in 2D breaks the -1/n bound: some levels have negative
 * eigenvalues (Lewis: "negative determinants at some subdivision levels").
 * The isotropic Markovian exp(-r) never does. */
Test(subdiv, isotropic_cosine_is_not_positive_definite)
{
    nl_subdiv_coeffs *c = coeffs("expr:cos(10*r)*exp(-r)", 2, 8, 8.0, 2), *m = coeffs("markov", 2, 8, 8.0, 2);
    cr_expect(c->flags & NL_SUBDIV_NOT_PD);
    cr_expect(!(m->flags & NL_SUBDIV_NOT_PD));
    for (int k = 0; k < 8; k++)
        for (int j = 0; j < 3; j++)
            cr_expect_geq(c->level[k].cls[j].variance, 0.0);
    nl_subdiv_coeffs_free(c);
    nl_subdiv_coeffs_free(m);
}

/* Diagonal bias: the isotropic Markovian 4x4 neighbourhood has corner
 * coefficients of 2.4% of the largest (Table 2); the separable one none. */
Test(subdiv, diagonal_bias_flag_both_ways)
{
    nl_subdiv_coeffs *i = coeffs("markov", 2, 1, 1.0, 2), *s = coeffs("markov:sep", 2, 1, 1.0, 2);
    cr_expect(i->level[0].cls[0].flags & NL_SUBDIV_DIAG_BIAS);
    cr_expect(!(s->flags & NL_SUBDIV_DIAG_BIAS));
    nl_subdiv_coeffs_free(i);
    nl_subdiv_coeffs_free(s);
}

/* auto: the error variance (7) decreases with N (a larger subspace), and N
 * stops growing once the improvement is below tol R(0). */
Test(subdiv, auto_neighbourhood)
{
    nl_model *m;
    nl_subdiv_coeffs *a, *n2;
    cr_assert_eq(nl_model_parse("expr:100*cos(10*t)*exp(-abs(t))", &m), 0);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 10, 15.0, 0, 1e-4, 16, &a), 0);
    n2 = coeffs("expr:100*cos(10*t)*exp(-abs(t))", 1, 10, 15.0, 2);
    for (int k = 0; k < 10; k++) {
        int N = a->level[k].N;
        nl_subdiv_coeffs *more;
        /* auto stops at the first N whose successor improves by < tol R(0) */
        if (N >= 2)
            cr_expect_leq(a->level[k].cls[0].variance, n2->level[k].cls[0].variance + 1e-9, "level %d", k);
        else
            cr_expect_lt(a->level[k].cls[0].variance - n2->level[k].cls[0].variance, 1e-4 * 100, "level %d", k);
        if (N == 16)
            continue;
        cr_assert_eq(nl_subdiv_coeffs_alloc(m, 1, 10, 15.0, N + 1, 1e-4, 16, &more), 0);
        cr_expect_lt(a->level[k].cls[0].variance - more->level[k].cls[0].variance, 1e-4 * 100,
                     "level %d: N = %d stopped although N + 1 improves by more than tol", k, N);
        nl_subdiv_coeffs_free(more);
    }
    cr_expect_gt(a->level[5].N, 1, "the oscillatory levels need more than the nearest neighbours");
    nl_subdiv_coeffs_free(a);
    nl_subdiv_coeffs_free(n2);
    nl_model_free(m);
}

static nl_field *window(const nl_subdiv_coeffs *c, int dim, long ox, long oy, size_t nx, size_t ny)
{
    size_t n[2] = {nx, ny};
    long o[2] = {ox, oy};
    nl_field *f = nl_field_alloc(dim, n, NULL, NULL);
    cr_assert_eq(nl_subdiv_synth_window(c, 77, o, f), 0, "%s", nl_errmsg());
    return f;
}

/* Internal consistency: overlapping windows agree bit for bit, and a window
 * equals the same part of a larger one; in 1D and 2D, at negative origins. */
Test(subdiv, windows_agree_on_overlaps)
{
    nl_subdiv_coeffs *c1 = coeffs("markaussian:alpha=1.4,scale=6", 1, 6, 64.0, 2);
    nl_subdiv_coeffs *c2 = coeffs("markov:scale=6", 2, 5, 32.0, 2);
    nl_field *a = window(c1, 1, -37, 0, 200, 1), *b = window(c1, 1, 50, 0, 300, 1);
    for (long i = 50; i < 163; i++)
        cr_assert_eq(a->data[i + 37], b->data[i - 50], "1D sample %ld", i);
    nl_field_free(a), nl_field_free(b);
    a = window(c2, 2, -20, 7, 64, 48);
    b = window(c2, 2, 10, -5, 90, 70);
    for (long y = 7; y < 55; y++)
        for (long x = 10; x < 44; x++)
            cr_assert_eq(a->data[(y - 7) * 64 + (x + 20)], b->data[(y + 5) * 90 + (x - 10)], "2D (%ld, %ld)", x, y);
    nl_field_free(a), nl_field_free(b);
    nl_subdiv_coeffs_free(c1);
    nl_subdiv_coeffs_free(c2);
}

/* Any order, non-causal: one more level (same s_0 and seed) keeps every
 * existing sample; the new field at even indices is the old one. */
Test(subdiv, refining_keeps_existing_samples)
{
    nl_subdiv_coeffs *c5 = coeffs("markov:scale=6", 2, 5, 32.0, 2), *c6 = coeffs("markov:scale=6", 2, 6, 32.0, 2);
    nl_field *a = window(c5, 2, -8, 3, 40, 30), *b = window(c6, 2, -16, 6, 80, 60);
    for (size_t y = 0; y < 30; y++)
        for (size_t x = 0; x < 40; x++)
            cr_assert_eq(a->data[y * 40 + x], b->data[(2 * y) * 80 + 2 * x], "(%zu, %zu)", x, y);
    nl_field_free(a), nl_field_free(b);
    nl_subdiv_coeffs_free(c5);
    nl_subdiv_coeffs_free(c6);
}

/* 512 x 256: the finest levels exceed the 65536 samples from which the
 * refinement runs on several threads, so the two runs really differ in
 * their thread count. */
Test(subdiv, periodic_is_bit_reproducible_across_threads)
{
    nl_model *m;
    nl_subdiv_coeffs *c = coeffs("markov:scale=5", 2, 4, 16.0, 2);
    size_t n[2] = {512, 256};
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_model_parse("markov:scale=5", &m), 0);
    omp_set_num_threads(1);
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 5, 0, a), 0, "%s", nl_errmsg());
    omp_set_num_threads(2);
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 5, 0, b), 0);
    cr_assert_eq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    cr_assert_eq(a->h[0], 1.0);
    nl_field_free(a), nl_field_free(b), nl_model_free(m), nl_subdiv_coeffs_free(c);
}

/* External consistency: a given coarse level is kept exactly. */
Test(subdiv, seed_level_is_kept)
{
    nl_model *m;
    nl_subdiv_coeffs *c = coeffs("markaussian:alpha=1.4,scale=3", 2, 3, 8.0, 2);
    size_t nc[2] = {8, 6}, n[2] = {64, 48};
    nl_field *coarse = nl_field_alloc(2, nc, NULL, NULL), *f = nl_field_alloc(2, n, NULL, NULL);
    for (size_t i = 0; i < coarse->count; i++)
        coarse->data[i] = sin(2.385 * (double)i);
    cr_assert_eq(nl_model_parse("markaussian:alpha=1.4,scale=3", &m), 0);
    cr_assert_eq(nl_subdiv_refine_periodic(c, coarse, 9, 0, f), 0, "%s", nl_errmsg());
    for (size_t y = 0; y < 6; y++)
        for (size_t x = 0; x < 8; x++)
            cr_assert_eq(f->data[8 * y * 64 + 8 * x], coarse->data[y * 8 + x]);
    nl_field_free(coarse), nl_field_free(f), nl_model_free(m), nl_subdiv_coeffs_free(c);
}

/* Not positive definite models are refused by synthesis unless allowed. */
Test(subdiv, synthesis_refuses_not_positive_definite)
{
    nl_model *m;
    nl_subdiv_coeffs *c = coeffs("expr:cos(10*r)*exp(-r)", 2, 6, 8.0, 2);
    size_t n[2] = {128, 128};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_model_parse("expr:cos(10*r)*exp(-r)", &m), 0);
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 1, 0, f), NL_ENOTPD);
    cr_assert(strstr(nl_errmsg(), "not positive definite") != NULL, "%s", nl_errmsg());
    nl_field_free(f), nl_model_free(m), nl_subdiv_coeffs_free(c);
}

/* Random quadrilateral neighbourhoods: each alternative is solved exactly
 * (a face's variance is never above that of its four corners, the N = 1
 * block, which every alternative contains), reaches beyond the block are
 * honoured, and windows stay consistent. */
Test(subdiv, random_neighbourhoods)
{
    nl_model *m;
    nl_subdiv_coeffs *c = coeffs("markov:scale=6", 2, 4, 32.0, 2), *nn = coeffs("markov:scale=6", 2, 4, 32.0, 1);
    cr_assert_eq(nl_model_parse("markov:scale=6", &m), 0);
    cr_assert_eq(nl_subdiv_coeffs_randomize(c, m, 8, 1), 0, "%s", nl_errmsg());
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 3; j++) {
            const nl_subdiv_class *cl = &c->level[k].cls[j];
            cr_assert_eq(cl->nalt, 8);
            for (int a = 0; a < 8 && cl->cls == NL_SUBDIV_FACE; a++)
                cr_expect_leq(cl->alt_var[a], nn->level[k].cls[j].variance + 1e-12, "level %d class %d alt %d", k,
                              j, a);
        }
    cr_expect_geq(c->level[0].reach, 2);
    nl_field *a = window(c, 2, -9, 4, 40, 40), *b = window(c, 2, 1, 10, 40, 40);
    for (long y = 10; y < 44; y++)
        for (long x = 1; x < 31; x++)
            cr_assert_eq(a->data[(y - 4) * 40 + (x + 9)], b->data[(y - 10) * 40 + (x - 1)], "(%ld, %ld)", x, y);
    nl_field_free(a), nl_field_free(b);
    nl_model_free(m), nl_subdiv_coeffs_free(c), nl_subdiv_coeffs_free(nn);
}

/* Levinson's recursion equals the direct solve of eq. (4) for every N
 * where the system is well conditioned (both are backward stable there;
 * 1e-10 leaves room for condition numbers up to about 1e5), stops where
 * the direct solve would call the system singular (the Gaussian at a fine
 * spacing), and the paper's stopping rule stops at the first N whose error
 * variance (7) is below tol R(0). */
Test(subdiv, levinson_equals_direct)
{
    static const struct {
        const char *spec;
        double s;
    } c[] = {{"markov:scale=8", 1}, {"markaussian:alpha=1.4,scale=8", 1},
             {"expr:100*cos(10*t)*exp(-abs(t))", 0.05}, {"matern:nu=1.5,scale=4", 1}};
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        nl_model *m;
        double a[32], var[16];
        int nout;
        cr_assert_eq(nl_model_parse(c[i].spec, &m), 0);
        for (int N = 1; N <= 16; N++) {
            double pts[32], tgt = 0.5 * c[i].s, ad[32];
            nl_subdiv_class cl;
            cl.a = ad;
            cr_assert_eq(nl_subdiv_levinson(m, c[i].s, N, NL_SUBDIV_STOP_NONE, 0, a, var, &nout), NL_OK);
            cr_assert_eq(nout, N, "%s: stopped at %d of %d", c[i].spec, nout, N);
            for (int k = 0; k < 2 * N; k++)
                pts[k] = (k + 1 - N) * c[i].s;
            cr_assert_eq(nl_subdiv_solve(m, 1, (size_t)(2 * N), pts, &tgt, NULL, &cl), NL_OK);
            for (int k = 0; k < 2 * N; k++)
                cr_expect(fabs(a[k] - ad[k]) <= 1e-10, "%s N=%d a[%d]: %.15g vs %.15g", c[i].spec, N, k, a[k], ad[k]);
            cr_expect(fabs(var[N - 1] - cl.raw_variance) <= 1e-10 * cl.raw_variance + 1e-14, "%s N=%d variance",
                      c[i].spec, N);
        }
        {
            double zero = 0, r0 = nl_model_acf(m, 1, &zero), t = 1.0001 * var[3] / r0;  /* reached at N <= 4 */
            cr_assert_eq(nl_subdiv_levinson(m, c[i].s, 16, NL_SUBDIV_STOP_VARIANCE, t, a, var, &nout), NL_OK);
            cr_expect(var[nout - 1] < t * r0 && (nout == 1 || var[nout - 2] >= t * r0), "%s: stopped at N=%d",
                      c[i].spec, nout);
        }
        nl_model_free(m);
    }
}

Test(subdiv, levinson_stops_where_singular)
{
    nl_model *m;
    double a[32], var[16];
    int nout;
    cr_assert_eq(nl_model_parse("gauss:scale=3", &m), 0);
    cr_assert_eq(nl_subdiv_levinson(m, 0.25, 16, NL_SUBDIV_STOP_NONE, 0, a, var, &nout), NL_OK);
    cr_expect(nout >= 1 && nout < 16, "the Gaussian at spacing 0.25 is singular before N = 16, reached %d", nout);
    nl_model_free(m);
}
