/* The planning policy of core/fftw_plan.h: FFTW_ESTIMATE by default, which
 * takes a measured plan from wisdom when there is one. */
#include "../core/fftw_plan.h"
#include "../core/field.h"
#include "../core/model.h"
#include "../synth/fft.h"
#include "util.h"

#include <criterion/criterion.h>
#include <fftw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static nl_field *synth(const char *fftw, const size_t *n)
{
    nl_model *m;
    nl_synth_fft_plan *p = NULL;
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    if (fftw)
        setenv("NOISELAB_FFTW", fftw, 1);
    else
        unsetenv("NOISELAB_FFTW");
    cr_assert_eq(nl_model_parse("markov:scale=5.3", &m), 0);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p), 0);
    cr_assert_eq(nl_synth_fft_execute(p, 17, f), 0);
    nl_synth_fft_plan_free(p), nl_model_free(m);
    return f;
}

/* The flags: FFTW_ESTIMATE at every size unless NOISELAB_FFTW=measure. */
Test(fftw_wisdom, estimate_unless_measure_is_asked)
{
    setenv("XDG_CACHE_HOME", scratch_dir(), 1);
    unsetenv("NOISELAB_FFTW");
    cr_expect_eq(nl_fftw_flags(64), FFTW_ESTIMATE);
    cr_expect_eq(nl_fftw_flags((size_t)1 << 24), FFTW_ESTIMATE, "a large transform does not wait for planning");
    setenv("NOISELAB_FFTW", "estimate", 1);
    cr_expect_eq(nl_fftw_flags((size_t)1 << 24), FFTW_ESTIMATE);
    setenv("NOISELAB_FFTW", "measure", 1);
    cr_expect_eq(nl_fftw_flags(64), FFTW_MEASURE);
    unsetenv("NOISELAB_FFTW");
}

/* A field planned by default before any wisdom (a first run), one planned
 * with FFTW_MEASURE, and one planned by default once measured wisdom exists
 * (a later run): the first equals the measured one to rounding (1e-12 of
 * the largest value: the plans differ only in the order of their sums), the
 * last equals it bit for bit (the default planner took the measured plan
 * from wisdom).  Then the cache written by nl_fftw_save holds that wisdom. */
Test(fftw_wisdom, default_plan_takes_measured_wisdom)
{
    size_t n[2] = {240, 256};
    char path[4200];
    double dmax = 0, vmax = 0;
    FILE *fp;
    setenv("XDG_CACHE_HOME", scratch_dir(), 1); /* empty: no wisdom yet */
    unsetenv("NOISELAB_WISDOM");
    nl_field *first = synth(NULL, n), *measured = synth("measure", n), *later = synth(NULL, n);
    for (size_t i = 0; i < first->count; i++) {
        dmax = fmax(dmax, fabs(first->data[i] - measured->data[i]));
        vmax = fmax(vmax, fabs(measured->data[i]));
    }
    cr_expect(vmax > 1, "the field is not empty");
    cr_expect(dmax <= 1e-12 * vmax, "first run differs from the measured plan by %g (largest value %g)", dmax, vmax);
    cr_expect_eq(memcmp(later->data, measured->data, later->count * sizeof(double)), 0,
                 "with measured wisdom the default plan is the measured one");
    nl_fftw_save();
    snprintf(path, sizeof path, "%s/noiselab/fftw-wisdom", scratch_dir());
    fp = fopen(path, "r");
    cr_expect_not_null(fp, "the measured plans were kept in %s", path);
    if (fp)
        fclose(fp);
    nl_field_free(first), nl_field_free(measured), nl_field_free(later);
}
