/* Slope fits that keep to the band where the field's model has power
 * (nl_model_band, psd --slope), and the comment lines of the estimators'
 * tables. */
#include "../analysis/slope.h"
#include "../core/model.h"
#include "../core/model_internal.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static char out[1 << 16], err[1 << 12];

static void band_is(const char *spec, int dim, double lo, double hi)
{
    nl_model *m = test_model(spec);
    double a = -1, b = -1;
    cr_assert_eq(nl_model_band(m, dim, &a, &b), NL_OK, "%s: %s", spec, nl_errmsg());
    cr_expect(a == lo && b == hi, "%s in %dD: band [%g, %g], expected [%g, %g]", spec, dim, a, b, lo, hi);
    nl_model_free(m);
}

/* The band is the family's fmin, fmax (defaults included), the whole axis
 * for a family without; exact numbers: they are the parameters as parsed. */
Test(slope_band, family_bands)
{
    double a = 7, b = 7;
    band_is("power:d=1", 1, 1.0 / 1024, 0.5);
    band_is("power:d=2.5,fmin=0.0125,fmax=0.3125", 2, 0.0125, 0.3125);
    band_is("power:d=3.5,fmin=0.03", 3, 0.03, 0.5);
    band_is("markov:scale=3", 1, 0, INFINITY);
    band_is("spectrum:exp(-f^2)", 1, 0, INFINITY);
    band_is("markov:scale=3 + gauss:scale=2.5,var=0.3 + nugget:var=0.1", 2, 0, INFINITY);
    band_is("markov:scale=3 * gauss:scale=2.5", 1, 0, INFINITY);
    nl_model *m = test_model("power:d=1");
    cr_expect_eq(nl_model_band(m, 4, &a, &b), NL_EINVAL);
    cr_expect_eq(nl_model_band(m, 0, &a, &b), NL_EINVAL);
    cr_expect(a == 7 && b == 7, "the results are untouched on failure");
    nl_model_free(m);
}

/* Replace the structures of a parsed two-term sum or product by two power
 * models: the parser refuses spectral structures in sums (core/model.h),
 * so this is the only way to reach the composite rule of nl_model_band. */
static nl_model *composite_of_powers(const char *joined, const char *s1, const char *s2)
{
    nl_model *m = test_model(joined);
    cr_assert_eq(m->nterms, 2, "%s: expected 2 terms", joined);
    nl_model_free(m->terms[0]);
    nl_model_free(m->terms[1]);
    m->terms[0] = test_model(s1);
    m->terms[1] = test_model(s2);
    return m;
}

/* A sum's band holds every term's (the union's hull); a product's reaches
 * from 0 to the sum of the factors' upper edges (the convolution of their
 * spectra); a term without a band makes the whole axis. */
Test(slope_band, sum_and_product_bands)
{
    static const struct {
        const char *joined, *s1, *s2;
        double lo, hi;
    } c[] = {
        {"markov:scale=3 + markov:scale=2", "power:d=1,fmin=0.0125,fmax=0.1875", "power:d=2,fmin=0.0625,fmax=0.375",
         0.0125, 0.375},
        {"markov:scale=3 + markov:scale=2", "power:d=2,fmin=0.0625,fmax=0.375", "power:d=1,fmin=0.0125,fmax=0.1875",
         0.0125, 0.375},
        {"markov:scale=3 + markov:scale=2", "power:d=1,fmin=0.0125,fmax=0.1875", "markov:scale=2", 0, INFINITY},
        {"markov:scale=3 * markov:scale=2", "power:d=1,fmin=0.0125,fmax=0.1875", "power:d=2,fmin=0.0625,fmax=0.25",
         0, 0.4375},
    };
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        nl_model *m = composite_of_powers(c[i].joined, c[i].s1, c[i].s2);
        double a = -1, b = -1;
        cr_assert_eq(nl_model_band(m, 1, &a, &b), NL_OK, "%s", nl_errmsg());
        cr_expect(a == c[i].lo && b == c[i].hi, "%s %c %s: band [%g, %g], expected [%g, %g]", c[i].s1,
                  nl_model_operator(m, 0), c[i].s2, a, b, c[i].lo, c[i].hi);
        nl_model_free(m);
    }
}

/* The 1/f field of the trap, fitted inside its band [fmin, 0.4]: the slope
 * is -1.  Tolerance: log-periodogram ordinates are independent with the
 * variance pi^2/6 of the log of an exponential variable, so the fit's own
 * 95% interval (Student's t over ~26000 ordinates) is 1.96 standard
 * errors; it is 0.016 here, and 0.05 is 6 standard errors (a false alarm
 * once in 10^9 draws; the test also checks that 0.05 stays over 5 of
 * them).  Through the band's lower edge the fit measured -0.36. */
Test(slope_band, power_field_slope_is_minus_one)
{
    int rc = run_noiselab("synth fft --spectrum power:d=1 --size 65536 --seed 7 -o p.tsv", out, sizeof out, err,
                          sizeof err);
    cr_assert_eq(rc, 0, "synth: %s", err);
    json_t *j = run_noiselab_json("psd p.tsv --slope 0.0009765625:0.4 --json");
    json_t *s = json_object_get(j, "slope");
    double slope = json_number_value(json_object_get(s, "slope")), ci = json_number_value(json_object_get(s, "ci95"));
    double se = ci / 1.96;
    cr_expect(0.05 >= 5 * se, "0.05 is %.1f standard errors of the fit (se %g); expected 5 or more", 0.05 / se, se);
    cr_expect(fabs(slope + 1) <= 0.05, "slope %g +- %g over [fmin, 0.4], expected -1 within 0.05", slope, ci);
    cr_expect_eq(json_array_size(json_object_get(s, "flags")), 0, "d = 1 is inside eq. 16's range");
    json_decref(j);
    /* a markov field below its corner frequency is white: flagged */
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=3 --size 4096 --seed 2 -o m.tsv", NULL, 0, err, sizeof err),
                 0, "%s", err);
    j = run_noiselab_json("psd m.tsv --slope 0.001:0.02 --json");
    s = json_object_get(json_object_get(j, "slope"), "flags");
    cr_expect(json_array_size(s) == 1 && !strcmp(json_string_value(json_array_get(s, 0)), "flatter-than-eq16"),
              "a white band: expected the flag flatter-than-eq16");
    json_decref(j);
}

/* Eq. (16) of Lewis 1987 holds for a profile exponent 1 < d < 3; outside,
 * by more than the fit's interval, the fit is flagged (d = -slope - (E - 1)). */
Test(slope_band, fractal_range)
{
    static const struct {
        double slope, ci;
        int E, want;
    } c[] = {
        {-0.36, 0.03, 1, -1}, {-1.0, 0.016, 1, 0}, {-0.98, 0.03, 1, 0}, {-0.9, 0.05, 1, -1}, {-2.9, 0.2, 1, 0},
        {-3.3, 0.2, 1, 1}, {-3.6, 0.1, 2, 0}, {-1.5, 0.1, 2, -1}, {-4.5, 0.2, 2, 1}, {-4.0, 0.05, 3, 0},
        {-2.5, 0.2, 3, -1}, {-5.5, 0.2, 3, 1},
    };
    for (size_t i = 0; i < sizeof c / sizeof *c; i++) {
        nl_slope sl = {.slope = c[i].slope, .ci95 = c[i].ci, .points = 100};
        cr_expect_eq(nl_slope_fractal_range(&sl, c[i].E), c[i].want, "slope %g +- %g in %dD", c[i].slope, c[i].ci,
                     c[i].E);
    }
    cr_expect_eq(nl_slope_fractal_range(NULL, 1), 0);
}

static void refused(const char *args, const char *const *needles)
{
    int rc = run_noiselab(args, out, sizeof out, err, sizeof err);
    cr_expect_eq(rc, 2, "%s: exit %d, stderr: %s", args, rc, err);
    cr_expect_eq(count_lines(err), 1, "%s: expected one line on stderr, got: %s", args, err);
    for (; *needles; needles++)
        cr_expect(strstr(err, *needles) != NULL, "%s: stderr \"%s\" should name \"%s\"", args, err, *needles);
}

/* A band reaching outside the recorded model's is refused, naming the
 * option, the band, the edge and what was expected; from a file (TSV, EXR)
 * and from --realizations alike.  Fields without such a model, or shaped
 * since, are fitted as before. */
Test(slope_band_slow, refused_outside_the_model_band)
{
    const char *lo[] = {"psd: --slope 0.0001:0.4", "below", "power:d=1", "fmin = 0.0009765625",
                        "expected F1 >= 0.0009765625", NULL};
    const char *hi[] = {"--slope 0.01:0.4", "above", "fmax = 0.25", "expected F2 <= 0.25", NULL};
    const char *lo2[] = {"--slope 0.001:0.4", "fmin = 0.03125", NULL};
    cr_assert_eq(run_noiselab("synth fft --spectrum power:d=1 --size 4096 -o p.tsv", NULL, 0, err, sizeof err), 0, "%s",
                 err);
    cr_assert_eq(run_noiselab("synth fft --spectrum power:d=1,fmax=0.25 --size 4096 -o q.tsv", NULL, 0, err,
                              sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("synth fft --spectrum power:d=3,fmin=0.03125 --size 64x64 -o p2.exr", NULL, 0, err,
                              sizeof err), 0, "%s", err);
    char path[300];
    snprintf(path, sizeof path, "%s/out.tsv", scratch_dir());
    refused("psd p.tsv --slope 0.0001:0.4 -o out.tsv", lo);
    cr_expect(!file_exists(path), "no output left");
    refused("psd q.tsv --slope 0.01:0.4", hi);
    refused("psd p2.exr --slope 0.001:0.4", lo2);
    refused("psd --realizations 1 --acf power:d=1 --size 4096 --slope 0.0001:0.4", lo);
    /* inside the band, and fields whose spectrum is not the model's band */
    cr_expect_eq(run_noiselab("psd p.tsv --slope 0.0009765625:0.5", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=3 --size 4096 -o m.tsv", NULL, 0, err, sizeof err), 0);
    cr_expect_eq(run_noiselab("psd m.tsv --slope 0.0001:0.4", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("shape --to uniform p.tsv -o u.tsv", NULL, 0, err, sizeof err), 0, "%s", err);
    cr_expect_eq(run_noiselab("psd u.tsv --slope 0.0001:0.4", out, sizeof out, err, sizeof err), 0, "%s", err);
}

/* The first line of a table. */
static const char *first_line(const char *args)
{
    static char line[512];
    int rc = run_noiselab(args, out, sizeof out, err, sizeof err);
    cr_assert_eq(rc, 0, "%s: %s", args, err);
    snprintf(line, sizeof line, "%.*s", (int)strcspn(out, "\n"), out);
    return line;
}

/* psd --welch says it is Welch's average, with its segments; a periodogram
 * says so; acf's lags are lengths, index times spacing (spacing 2.5: the
 * third row is lag 5). */
Test(slope_band, comment_lines)
{
    const char *c;
    double lag[3];
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=8 --size 1024 --spacing 2.5 -o s.tsv", NULL, 0, err,
                              sizeof err), 0, "%s", err);
    c = first_line("psd s.tsv --welch 64");
    cr_expect(strstr(c, "two-sided Welch density") && strstr(c, "31 Hann-windowed") &&
              strstr(c, "segments of 64 samples") && !strstr(c, "periodogram density"), "psd --welch: %s", c);
    c = first_line("psd s.tsv");
    cr_expect_str_eq(c, "# noiselab psd: two-sided periodogram density, freq in cycles per unit");
    c = first_line("acf s.tsv --max-lag 5");
    cr_expect(strstr(c, "lags in length units (index times spacing)") && !strstr(c, "spacing units"), "acf: %s", c);
    cr_assert_eq(sscanf(strchr(out, '\n') + 1, "lag\tacf\n%lf\t%*f\n%lf\t%*f\n%lf", &lag[0], &lag[1], &lag[2]), 3,
                 "%s", out);
    cr_expect(lag[0] == 0 && lag[1] == 2.5 && lag[2] == 5, "lags %g %g %g, expected 0 2.5 5", lag[0], lag[1], lag[2]);
}
