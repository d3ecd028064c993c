/* The crease and aliasing detectors, each tested both ways on fixed seeds.
 * The reference values of the crease index are stated in
 * analysis/creases.h; each case here is more than 0.25 away from the
 * threshold, beyond the index's sampling error at these sizes. */
#include "../analysis/aliasing.h"
#include "../analysis/creases.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"

#include <criterion/criterion.h>
#include <math.h>

static nl_field *gss(const char *spec, int dim, size_t n, int L, double h)
{
    nl_model *m;
    nl_subdiv_coeffs *c;
    size_t nn[2] = {n, n};
    double hh[2] = {h, h};
    nl_field *f = nl_field_alloc(dim, nn, hh, NULL);
    cr_assert_eq(nl_model_parse(spec, &m), 0);
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, dim, L, ldexp(h, L), 2, 1e-4, 16, &c), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 11, 0, f), 0, "%s", nl_errmsg());
    nl_subdiv_coeffs_free(c);
    nl_model_free(m);
    return f;
}

static nl_field *mpd(int dim, size_t n, int L, double H)
{
    nl_subdiv_coeffs *c;
    size_t nn[2] = {n, n};
    nl_field *f = nl_field_alloc(dim, nn, NULL, NULL);
    cr_assert_eq(nl_subdiv_coeffs_midpoint(dim, L, ldexp(1, L), H, 1, 1, &c), 0);
    cr_assert_eq(nl_subdiv_synth_periodic(c, NULL, 11, 0, f), 0);
    nl_subdiv_coeffs_free(c);
    return f;
}

/* Must raise: midpoint displacement of f^-2.6 noise (H = 0.8), Lewis's
 * example of a non-Markovian fractal made by a Markovian construction. */
Test(creases, midpoint_displacement_of_fractal_noise_is_flagged)
{
    nl_creases r;
    nl_field *f = mpd(1, 65536, 12, 0.8);
    cr_assert_eq(nl_creases_measure(f, 12, &r), 0);
    cr_log_info("midpoint H=0.8 1D: crease index %.3f", r.index);
    cr_expect(r.flagged, "crease index %.3f", r.index);
    nl_field_free(f);
    f = mpd(2, 512, 8, 0.8);
    cr_assert_eq(nl_creases_measure(f, 8, &r), 0);
    cr_log_info("midpoint H=0.8 2D: crease index %.3f", r.index);
    cr_expect(r.flagged, "2D crease index %.3f", r.index);
    nl_field_free(f);
}

/* Must not raise: generalized subdivision to the same target, and midpoint
 * displacement of Brownian motion (H = 1/2, where it is exact). */
Test(creases, generalized_subdivision_is_not_flagged)
{
    nl_creases r;
    nl_field *f = gss("power:d=2.6,fmin=0.0001", 1, 65536, 12, 1.0);
    cr_assert_eq(nl_creases_measure(f, 12, &r), 0);
    cr_log_info("subdiv power:d=2.6 1D: crease index %.3f", r.index);
    cr_expect_not(r.flagged, "crease index %.3f", r.index);
    nl_field_free(f);
    f = mpd(1, 65536, 12, 0.5);
    cr_assert_eq(nl_creases_measure(f, 12, &r), 0);
    cr_expect_not(r.flagged, "Brownian midpoint displacement: crease index %.3f", r.index);
    nl_field_free(f);
    f = gss("markaussian:alpha=1.4,scale=40", 2, 512, 7, 1.0);
    cr_assert_eq(nl_creases_measure(f, 7, &r), 0);
    cr_log_info("subdiv markaussian 2D: crease index %.3f", r.index);
    cr_expect_not(r.flagged, "2D crease index %.3f", r.index);
    nl_field_free(f);
}

/* Must raise: cos(10 t) exp(-t^2) at spacing 1/4, where its spectral peak
 * (1.59 cycles per unit) lies between half Nyquist (1) and Nyquist (2): the
 * level below shows a different noise (Lewis's Fig. 2, levels 3 to 4).
 * Must not: exp(-|t|/4) at spacing 1/4, a monotone spectrum at a fine level.
 * The measurement and the prediction from the spectrum fall on the same
 * side of the threshold. */
Test(aliasing, both_ways)
{
    nl_model *osc, *mk;
    double A, P;
    nl_field *f = gss("gauss-osc:omega=10", 1, 8192, 6, 0.25);
    cr_assert_eq(nl_model_parse("gauss-osc:omega=10", &osc), 0);
    cr_assert_eq(nl_aliasing_measure(f, &A), 0);
    cr_assert_eq(nl_aliasing_predict(osc, f, &P), 0);
    cr_log_info("gauss-osc h=1/4: aliasing %.3f, predicted %.3f", A, P);
    cr_expect_gt(A, NL_ALIAS_MAX);
    cr_expect_gt(P, NL_ALIAS_MAX);
    nl_field_free(f);
    f = gss("markov:scale=4", 1, 8192, 6, 0.25);
    cr_assert_eq(nl_model_parse("markov:scale=4", &mk), 0);
    cr_assert_eq(nl_aliasing_measure(f, &A), 0);
    cr_assert_eq(nl_aliasing_predict(mk, f, &P), 0);
    cr_log_info("markov h=1/4: aliasing %.4f, predicted %.4f", A, P);
    cr_expect_lt(A, NL_ALIAS_MAX);
    cr_expect_lt(P, NL_ALIAS_MAX);
    nl_field_free(f);
    nl_model_free(osc);
    nl_model_free(mk);
}

/* The measurement itself: a pure cosine above half Nyquist is all aliasing,
 * one below is none. */
Test(aliasing, cosines)
{
    size_t n[1] = {256};
    nl_field *f = nl_field_alloc(1, n, NULL, NULL);
    double A;
    for (size_t i = 0; i < 256; i++)
        f->data[i] = cos(2 * M_PI * 80 * (double)i / 256);
    cr_assert_eq(nl_aliasing_measure(f, &A), 0);
    cr_expect_float_eq(A, 1.0, 1e-9);
    for (size_t i = 0; i < 256; i++)
        f->data[i] = cos(2 * M_PI * 20 * (double)i / 256);
    cr_assert_eq(nl_aliasing_measure(f, &A), 0);
    cr_expect_float_eq(A, 0.0, 1e-9);
    nl_field_free(f);
}
