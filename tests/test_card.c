/* noiselab card: the ensemble card and the model's bands reach the picture,
 * every plot of the script names its axes, and bad ensembles are refused. */
#include "../analysis/acf.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static char out[8192], err[8192];

static void refused(const char *args, const char *needle)
{
    int rc = run_noiselab(args, out, sizeof out, err, sizeof err);
    cr_expect_eq(rc, 2, "%s: exit %d, stderr: %s", args, rc, err);
    cr_expect_eq(count_lines(err), 1, "%s: expected one line on stderr, got: %s", args, err);
    cr_expect(strstr(err, needle) != NULL, "%s: stderr \"%s\" should name \"%s\"", args, err, needle);
}

/* The card run with its data kept in DIR (NOISELAB_CARD_KEEP); returns the
 * script, read into buf. */
static const char *card_script(const char *dir, const char *args, char *buf, size_t size)
{
    char path[600];
    FILE *fp;
    size_t n;
    snprintf(path, sizeof path, "%s/%s", scratch_dir(), dir);
    mkdir(path, 0755);
    setenv("NOISELAB_CARD_KEEP", path, 1);
    cr_assert_eq(run_noiselab(args, out, sizeof out, err, sizeof err), 0, "%s: %s", args, err);
    unsetenv("NOISELAB_CARD_KEEP");
    snprintf(path, sizeof path, "%s/%s/card.gp", scratch_dir(), dir);
    cr_assert((fp = fopen(path, "r")), "no script kept in %s", path);
    n = fread(buf, 1, size - 1, fp);
    buf[n] = 0;
    fclose(fp);
    return buf;
}

/* Every plot command has a non-empty xlabel and ylabel set since the one
 * before it; returns the number of plots. */
static int labelled_plots(const char *s)
{
    int plots = 0, x = 0, y = 0;
    for (const char *line = s; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
        if (!strncmp(line, "set xlabel '", 12) && line[12] != '\'')
            x = 1;
        if (!strncmp(line, "set ylabel '", 12) && line[12] != '\'')
            y = 1;
        if (!strncmp(line, "plot ", 5)) {
            cr_expect(x && y, "plot %d has no %s label", plots + 1, x ? "y" : "x");
            plots++, x = y = 0;
        }
    }
    return plots;
}

static int count(const char *s, const char *what)
{
    int n = 0;
    for (const char *p = strstr(s, what); p; p = strstr(p + 1, what))
        n++;
    return n;
}

/* 1D: 4 panels, the ACF, spectrum and histogram with the model's bands
 * over sqrt(K) and the ensemble's error bars; the PNG is written. */
Test(card, ensemble_1d)
{
    static char s[65536];
    char png[600];
    card_script("k1", "card --realizations 4 --acf markov:scale=4 --size 256 -o e1.png", s, sizeof s);
    snprintf(png, sizeof png, "%s/e1.png", scratch_dir());
    cr_expect(file_exists(png));
    cr_expect_eq(labelled_plots(s), 4);
    cr_expect_eq(count(s, "with filledcurves"), 3, "one model band per estimate panel:\n%s", s);
    cr_expect_eq(count(s, "with yerrorbars"), 3, "the ensemble's error bars on ACF, spectrum, histogram");
    cr_expect(strstr(s, "mean of 4 biased estimates") != NULL);
    /* the data: lag, mean, lo, hi, R, E, se; the band the model's for one
     * field over sqrt(4) around E (the library's numbers, printed to 8
     * digits: 1e-6 relative) */
    char path[600], line[512];
    double v[7], E[33], lo[33], hi[33];
    size_t n = 256;
    nl_model *m = test_model("markov:scale=4");
    cr_assert_eq(nl_acf_model_band(m, 1, &n, NULL, 0, 32, E, lo, hi), 0);
    snprintf(path, sizeof path, "%s/k1/acf.tsv", scratch_dir());
    FILE *fp = fopen(path, "r");
    cr_assert(fp);
    for (int k = 0; k <= 32 && fgets(line, sizeof line, fp); k++) {
        cr_assert_eq(sscanf(line, "%lf %lf %lf %lf %lf %lf %lf", v, v + 1, v + 2, v + 3, v + 4, v + 5, v + 6), 7);
        cr_expect_float_eq(v[5], E[k], 1e-6 * (fabs(E[k]) + 1e-3), "lag %d: E %g, expected %g", k, v[5], E[k]);
        cr_expect_float_eq(v[3] - v[5], (hi[k] - E[k]) / 2, 1e-6 * hi[k], "lag %d: half-width %g, expected %g", k,
                           v[3] - v[5], (hi[k] - E[k]) / 2);
        cr_expect(v[6] > 0, "lag %d: no standard error", k);
    }
    fclose(fp);
    nl_model_free(m);
}

/* 2D from files: 6 panels, bands on the ACF along x and y and the radial
 * spectrum; the key below every plot with a key. */
Test(card, ensemble_2d_files)
{
    static char s[65536];
    for (int k = 1; k <= 3; k++) {
        char a[160];
        snprintf(a, sizeof a, "synth fft --acf markov:scale=4 --size 64x48 --seed %d -o e%d.exr", k, k);
        cr_assert_eq(run_noiselab(a, out, sizeof out, err, sizeof err), 0, "%s", err);
    }
    card_script("k2", "card e1.exr e2.exr e3.exr --acf markov:scale=4 -o e2.png", s, sizeof s);
    cr_expect_eq(labelled_plots(s), 6);
    cr_expect_eq(count(s, "with filledcurves"), 4, "x, y, histogram and radial bands");
    cr_expect(strstr(s, "set key top") == NULL && strstr(s, "set key bottom") == NULL, "a key inside a plot");
    cr_expect(strstr(s, "model.bin") != NULL, "the model's spectrum map");
}

/* One field with a model: the ACF band is the model's, not the plug-in. */
Test(card, single_field_model_band)
{
    static char s[65536];
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 256 -o one.tsv", out, sizeof out, err, sizeof err),
                 0);
    card_script("k3", "card one.tsv --acf markov:scale=4 -o one.png", s, sizeof s);
    cr_expect_eq(labelled_plots(s), 4);
    cr_expect(strstr(s, "model 95% band") != NULL && strstr(s, "plug-in") == NULL, "%s", s);
    cr_expect(strstr(s, "Welch 95% band") != NULL);
}

Test(card, refuses_bad_ensembles)
{
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x64 -o a.exr", out, sizeof out, err, sizeof err),
                 0);
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x48 -o b.exr", out, sizeof out, err, sizeof err),
                 0);
    refused("card --realizations 0 --acf markov --size 64 -o z.png", "--realizations");
    refused("card a.exr b.exr -o m.png", "expected a field of the size and spacing of a.exr");
    refused("card --realizations 3 --size 64x64 -o n.png", "--acf");
    refused("card --realizations 3 --acf markov --size 64x64 a.exr -o n.png", "got both");
    refused("card --size 64x64 a.exr -o n.png", "--realizations");
}

/* The README's ACF map: acf --max-lag 8 keeps lags -8..8 (17 x 17 around
 * lag 0, whose value is the field's biased variance, the largest), and
 * render --axes lags draws it by gnuplot. */
Test(card, cropped_acf_map_with_axes)
{
    char path[600];
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=4 --size 64x64 -o f.exr", out, sizeof out, err, sizeof err),
                 0);
    cr_assert_eq(run_noiselab("acf f.exr --max-lag 8 -o acf.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_assert_eq(run_noiselab("hist acf.exr", out, sizeof out, err, sizeof err), 0, "%s", err);
    cr_expect(strstr(out, "# n 289\n") != NULL, "expected 17 x 17 lags: %s", out);
    cr_assert_eq(run_noiselab("render acf.exr --range -0.1:1 --axes lags -o acf.png", out, sizeof out, err, sizeof err),
                 0, "%s", err);
    snprintf(path, sizeof path, "%s/acf.png", scratch_dir());
    cr_expect(file_exists(path));
    refused("render acf.exr --axes lags --shade 30,40 -o s.png", "--axes");
}
