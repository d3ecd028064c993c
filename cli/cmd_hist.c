/* noiselab hist: histogram and moments of a field, or of an ensemble of fields. */
#include "cli.h"
#include "dist_inputs.h"
#include "inputs.h"
#include "../core/field.h"
#include "../analysis/ensemble.h"
#include "../analysis/gof.h"
#include "../analysis/gof_boot.h"
#include "../analysis/hist.h"
#include "../core/dist.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab hist IN...|--realizations K --acf SPEC --size N [--seed S]\n"
    "                     [--bins B] [--against DIST [--draws D] [--draw-seed S] | --independent]\n"
    "                     [--json] [-o OUT.tsv]\n\n"
    "Histogram of the samples of IN (EXR, PNG or 1D TSV) in B equal bins over\n"
    "[min, max] (default 50), with the mean, the unbiased variance, the skewness\n"
    "and the excess kurtosis (0 for a Gaussian).\n\n"
    "  --against DIST  add the density of DIST per bin (column pdf) and test the\n"
    "                samples against it; DIST as in noiselab shape.  Neighbours of a\n"
    "                correlated field are nearly copies of each other, so the tests'\n"
    "                null is drawn, not assumed: D fields with the law DIST and the\n"
    "                correlation of the field's own normal scores Phi^-1(F(x))\n"
    "                (a Gaussian copula, analysis/gof_boot.h), every sample kept.\n"
    "                Each statistic is tested against its draws: Kolmogorov-Smirnov\n"
    "                D, chi-square on min(bins, n/5) equal-probability bins, and the\n"
    "                mean, variance, skewness and kurtosis where DIST has them; p\n"
    "                from a law fitted to the draws (Kolmogorov, moved and scaled;\n"
    "                scaled chi-square; t, on the log scale for the variance and\n"
    "                kurtosis) and the rank p.  The verdict is the smallest p times\n"
    "                the number of tests (Bonferroni).  Also printed: the variance\n"
    "                ratio and KS distance this field would reveal 80% of the time\n"
    "                at 5%.  At 5%, of 640 fields of 128x128 (markov, gauss,\n"
    "                gencauchy and band-limited power models mapped exactly to gauss,\n"
    "                laplace, uniform and lognormal), the verdict rejected 4.8%; the\n"
    "                single tests 3.1% (KS) to 8.9% (kurtosis).  Fields with the\n"
    "                detectable variance ratio were rejected 80% and 81% of the time\n"
    "                (experiments/gof_boot_rates.c, fig-gof-boot.sh).  199 draws take\n"
    "                about 0.3 s on 128x128 and 7 s on 512x512 (one core).\n"
    "  --draws D     null draws (default 199, at least 2)\n"
    "  --draw-seed S the seed of the null draws (default 1)\n"
    "  --independent test every sample as if independent (white fields only)\n"
    "  --json        every number on stdout as JSON\n"
    "  -o OUT.tsv    the table: lo, hi, count[, se][, pdf]\n\n"
    "Several inputs make an ensemble: the histogram on common bins over the\n"
    "range of all of them, with the mean count per field and its standard\n"
    "error (column se), and each moment's mean over the fields +- its standard\n"
    "error; --against pools every field's samples, each field's null drawn\n"
    "with its own correlation.\n"
    "--realizations K --acf SPEC --size N [--seed S] analyses, in place of files,\n"
    "the K fields of noiselab synth fft --acf SPEC --size N with seeds S\n"
    "(default 1) to S + K - 1.\n\n"
    "Under mpirun with one .h5 input, each process reads its slab of the field\n"
    "and the moments and counts are summed over the processes (rank 0 prints\n"
    "the same results); --against is refused there.\n";

/* Options of noiselab hist. */
typedef struct {
    cli_inputs src;                       /* files or realizations */
    size_t nin;                           /* their number */
    const char *out, *tmp, *against;      /* output (and its temporary), distribution spec */
    size_t bins;                          /* equal bins over [min, max] */
    size_t draws;                         /* null draws of the test */
    uint64_t draw_seed;                   /* their seed */
    int json, independent;
    int draws_given;                      /* --draws or --draw-seed given */
} hist_opts;

/* Moments over the fields: their means, and standard errors (ensembles). */
typedef struct {
    nl_moments m;      /* means of each moment (n: samples in all, min/max: overall) */
    nl_moments se;     /* standard errors (ensembles only) */
} hist_moments;

/* What the test against DIST found. */
typedef struct {
    nl_gof g;                  /* --independent: statistics and p-values */
    size_t n;                  /* samples */
    nl_gof_boot b;             /* the bootstrap test */
} hist_test;

static const cli_opt rows[] = {
    CLI_COUNT("bins", hist_opts, bins, .lo = 1), CLI_OPT_JSON(hist_opts, json),
    CLI_STRING("against", hist_opts, against), CLI_FLAG("independent", hist_opts, independent),
    CLI_COUNT("draws", hist_opts, draws, CLI_GIVEN(hist_opts, draws_given), .lo = 2, .hi = 100000),
    CLI_U64("draw-seed", hist_opts, draw_seed, CLI_GIVEN(hist_opts, draws_given)),
    CLI_OPT_OUTPUT(hist_opts, out), CLI_GROUP(cli_inputs_rows, hist_opts, src), {0}};

static void parse(int argc, char **argv, hist_opts *o)
{
    o->bins = 50, o->draws = NL_GOF_BOOT_DRAWS, o->draw_seed = NL_GOF_BOOT_SEED;
    if (cli_opt_parse("hist", help, rows, o, argc, argv))
        exit(0);
    cli_inputs_operands(&o->src, "hist", argc, argv);
    o->nin = o->src.count;
    if (o->out && !cli_has_ext(o->out, ".tsv"))
        cli_die(2, "-o: expected a .tsv file (the histogram is a table), got \"%s\"", o->out);
    if (o->bins > 10000000)
        cli_die(2, "--bins: expected at most 10000000, got %zu", o->bins);
    if (o->independent && !o->against)
        cli_die(2, "--independent: expected --against DIST (it says how to test), got no --against");
    if (o->draws_given && (!o->against || o->independent))
        cli_die(2, "--draws, --draw-seed: expected --against DIST without --independent (they set the null draws of "
                "its test), got %s", o->against ? "--independent" : "no --against");
    if (nl_size_check(1, &o->bins, sizeof(double), 4 + (o->nin > 1 ? o->nin : 0), NULL))
        cli_die(2, "--bins %zu: the edges, counts and densities do not fit in the memory available", o->bins);
}

/* A JSON number, or null where it is undefined (a constant field). */
static json_t *num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

/* "%.10g", "%.10g +- %.3g" (ensembles), or "undefined (constant field)". */
static void print_moment(const char *name, double v, double se, int ens, const char *tail)
{
    if (!isfinite(v))
        printf("# %s undefined (constant field: variance 0)\n", name);
    else if (ens && isfinite(se))
        printf("# %s %.10g +- %.3g (standard error)%s\n", name, v, se, tail);
    else
        printf("# %s %.10g%s\n", name, v, tail);
}

/* One statistic of the bootstrap test as JSON. */
static json_t *stat_json(const nl_gof_boot_stat *t)
{
    return json_pack("{s:o,s:o,s:o,s:o,s:o,s:o}", "statistic", num(t->value), "expected", num(t->expected),
                     "null_mean", num(t->null_mean), "null_sd", num(t->null_sd), "p", num(t->p), "p_rank",
                     num(t->p_rank));
}

static json_t *boot_json(const hist_opts *o, const nl_gof_boot *b)
{
    json_t *j = json_object(), *tests = json_object();
    for (int s = 0; s < NL_GOF_NSTATS; s++)
        if (b->stat[s].tested)
            json_object_set_new(tests, nl_gof_boot_name(s), stat_json(&b->stat[s]));
    json_object_set_new(j, "draws", json_integer((json_int_t)b->draws));
    json_object_set_new(j, "draw_seed", json_integer((json_int_t)o->draw_seed));
    json_object_set_new(j, "tests", tests);
    json_object_set_new(j, "ks_effective_n", num(b->ks_n_eff));
    json_object_set_new(j, "ks_shift", num(b->ks_shift));
    json_object_set_new(j, "moment_dof", num(b->moment_dof));
    json_object_set_new(j, "chi2_scale", num(b->chi2_scale));
    json_object_set_new(j, "chi2_dof", num(b->chi2_dof));
    json_object_set_new(j, "verdict_p", num(b->p));
    json_object_set_new(j, "verdict_from", json_string(nl_gof_boot_name(b->p_from)));
    json_object_set_new(j, "detectable", json_pack("{s:[o,o],s:o,s:o}", "variance_ratio", num(b->var_ratio_lo),
                                                   num(b->var_ratio_hi), "ks_distance", num(b->ks_detectable),
                                                   "ks_q95", num(b->ks_q95)));
    json_object_set_new(j, "window_radius", json_pack("[o,o]", num(b->radius_min), num(b->radius_max)));
    return j;
}

static json_t *test_json(const hist_opts *o, const hist_test *t, const double *pdf)
{
    const nl_gof_boot *b = &t->b;
    int boot = !o->independent;
    json_t *j = json_pack("{s:s,s:o,s:o,s:o,s:I,s:o,s:o}", "distribution", o->against, "ks_statistic",
                          num(boot ? b->stat[NL_GOF_KS].value : t->g.D), "ks_p",
                          num(boot ? b->stat[NL_GOF_KS].p : t->g.p_ks), "chi2",
                          num(boot ? b->stat[NL_GOF_CHI2].value : t->g.chi2), "chi2_bins",
                          (json_int_t)(boot ? b->bins : t->g.bins), "chi2_p",
                          num(boot ? b->stat[NL_GOF_CHI2].p : t->g.p_chi2), "pdf", cli_json_array(pdf, o->bins));
    json_object_set_new(j, "n", json_integer((json_int_t)t->n));
    json_object_set_new(j, "method", json_string(boot ? "bootstrap" : "independent"));
    if (boot)
        json_object_set_new(j, "bootstrap", boot_json(o, b));
    return j;
}

static void print_json(const hist_opts *o, const hist_moments *mo, const double *edges, const double *counts,
                       const double *se, const hist_test *t, const double *pdf)
{
    const nl_moments *m = &mo->m;
    json_t *j = json_pack("{s:I,s:f,s:f,s:o,s:o,s:f,s:f,s:o,s:o}", "n", (json_int_t)m->n, "mean", m->mean,
                          "variance", m->variance, "skewness", num(m->skewness), "kurtosis", num(m->kurtosis), "min",
                          m->min, "max", m->max, "edges", cli_json_array(edges, o->bins + 1), "counts",
                          cli_json_array(counts, o->bins));
    if (o->nin > 1) {
        json_object_set_new(j, "fields", json_integer((json_int_t)o->nin));
        json_object_set_new(j, "counts_se", cli_json_array(se, o->bins));
        json_object_set_new(j, "se", json_pack("{s:o,s:o,s:o,s:o}", "mean", num(mo->se.mean), "variance",
                                               num(mo->se.variance), "skewness", num(mo->se.skewness), "kurtosis",
                                               num(mo->se.kurtosis)));
    }
    if (pdf)
        json_object_set_new(j, "against", test_json(o, t, pdf));
    cli_json_print(j);
}

/* The bootstrap test: one line per statistic, the verdict, the power. */
static void print_boot(const hist_opts *o, const nl_gof_boot *b)
{
    const nl_gof_boot_stat *ks = &b->stat[NL_GOF_KS], *c = &b->stat[NL_GOF_CHI2];
    const char *a = o->against;
    printf("# against %s: n = %zu, %zu null draws with the field's own correlation (window radius %g", a, b->n,
           b->draws, b->radius_max);
    if (b->radius_min < b->radius_max)
        printf(" at most, %g at least", b->radius_min);
    printf(" samples)\n");
    printf("# against %s: KS D %.6g p %.4g (rank p %.3g; Kolmogorov law fitted to the draws, effective n %.1f)\n", a,
           ks->value, ks->p, ks->p_rank, b->ks_n_eff);
    printf("# against %s: chi-square %.6g on %zu equal-probability bins p %.4g (rank p %.3g; %.3g chi-square on "
           "%.1f degrees of freedom)\n", a, c->value, b->bins, c->p, c->p_rank, b->chi2_scale, b->chi2_dof);
    for (int s = NL_GOF_MEAN; s < NL_GOF_NSTATS; s++) {
        const nl_gof_boot_stat *m = &b->stat[s];
        if (m->tested)
            printf("# against %s: %s %.6g (law %.6g, null %.6g +- %.3g) p %.4g (rank p %.3g; t law, %.0f degrees of "
                   "freedom)\n", a, nl_gof_boot_name(s), m->value, m->expected, m->null_mean, m->null_sd, m->p,
                   m->p_rank, b->moment_dof);
    }
    printf("# against %s: verdict p %.4g (%s, times %zu tests): %s at 5%%\n", a, b->p, nl_gof_boot_name(b->p_from),
           b->tests, b->p < 0.05 ? "rejected" : "not rejected");
    printf("# against %s: detectable 80%% of the time at 5%%: KS distance %.3g", a, b->ks_detectable);
    if (b->stat[NL_GOF_VARIANCE].tested) {
        printf(", variance ratio below %.3g", b->var_ratio_lo);
        if (isfinite(b->var_ratio_hi))
            printf(" or above %.3g", b->var_ratio_hi);
    }
    printf("\n");
}

static void print_text(const hist_opts *o, const hist_moments *mo, const hist_test *t, int tested)
{
    const nl_moments *m = &mo->m, *s = &mo->se;
    int ens = o->nin > 1;
    if (ens)
        printf("# fields %zu (means over the fields +- their standard errors; counts per field)\n", o->nin);
    printf("# n %zu\n", m->n);
    print_moment("mean", m->mean, s->mean, ens, "");
    print_moment("variance", m->variance, s->variance, ens, "");
    print_moment("skewness", m->skewness, s->skewness, ens, "");
    print_moment("kurtosis", m->kurtosis, s->kurtosis, ens, " (excess)");
    if (!tested)
        return;
    if (o->independent) {
        printf("# against %s: n = %zu, every sample taken as independent\n", o->against, t->n);
        printf("# against %s: KS D %.6g p %.4g; chi-square %.6g on %zu equal-probability bins (%zu degrees of "
               "freedom), p %.4g\n", o->against, t->g.D, t->g.p_ks, t->g.chi2, t->g.bins, t->g.bins - 1, t->g.p_chi2);
        return;
    }
    print_boot(o, &t->b);
}

static void output(const hist_opts *o, const hist_moments *mo, const double *edges, const double *counts,
                   const double *se, const hist_test *t, const double *pdf)
{
    if (o->json)
        print_json(o, mo, edges, counts, se, t, pdf);
    else if (!o->out)
        print_text(o, mo, t, pdf != NULL);
    if (o->out || !o->json) {
        const char *names[5] = {"lo", "hi", "count"};
        const double *cols[5] = {edges, edges + 1, counts};
        int nc = 3;
        if (se)
            names[nc] = "se", cols[nc++] = se;
        if (pdf)
            names[nc] = "pdf", cols[nc++] = pdf;
        cli_check(cli_write_table(o->out ? o->tmp : NULL, NULL, nc, names, o->bins, cols));
    }
    cli_out_commit(o->out);
}

/* Read every input; an ensemble's fields are held together, checked
 * against the memory available as a whole. */
static nl_field **read_all(hist_opts *o)
{
    nl_field **x = cli_malloc(o->nin * sizeof *x);
    size_t total = 0;
    for (size_t k = 0; k < o->nin; k++) {
        x[k] = cli_inputs_read(&o->src, k, NULL);
        total += x[k]->count;
        if (nl_size_check(1, &total, sizeof(double), 1, NULL))
            cli_die(2, "hist: %zu fields of %zu samples in all do not fit in the memory available; expected fewer "
                    "or smaller inputs", k + 1, total);
    }
    return x;
}

/* The inputs, all read, as an ensemble's source. */
static nl_ensemble_source source(const hist_opts *o, nl_field **x)
{
    return (nl_ensemble_source){.K = o->nin, .fields = (const nl_field *const *)x};
}

/* The moments of each field; their means and standard errors over an ensemble. */
static void moments(hist_opts *o, nl_field **x, hist_moments *mo)
{
    nl_ensemble_source src = source(o, x);
    size_t bad;
    int st = nl_ensemble_moments(&src, &mo->m, &mo->se, &bad);
    if (st && bad < o->nin)
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", cli_inputs_name(&o->src, bad), nl_errmsg());
    cli_check(st);
}

/* The histogram; an ensemble's on the bins of the overall range, as mean counts per field with their se. */
static void histogram(hist_opts *o, nl_field **x, const hist_moments *mo, double *edges, double *counts,
                      double *se)
{
    nl_ensemble_source src = source(o, x);
    size_t bad;
    int st;
    if (o->nin == 1) {
        if ((st = nl_hist(x[0], o->bins, edges, counts)))
            cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", cli_inputs_name(&o->src, 0), nl_errmsg());
        return;
    }
    st = nl_ensemble_hist(&src, o->bins, mo->m.min, mo->m.max, edges, counts, se, &bad);
    if (st && bad == o->nin && st != NL_ENOMEM && st != NL_ETOOBIG)
        cli_die(nl_error_is_input(st) ? 2 : 1, "hist: the fields together: %s", nl_errmsg());
    cli_check(st);
}

/* The test against dist: the bootstrap (analysis/gof_boot.h), or every sample as independent. */
static void test(const hist_opts *o, nl_field **x, const nl_dist *dist, hist_test *t)
{
    size_t bins;
    double *pool;
    int st;
    t->n = 0;
    for (size_t k = 0; k < o->nin; k++)
        t->n += x[k]->count;
    if (!o->independent) {
        bins = t->n / 5 < o->bins ? t->n / 5 : o->bins;
        bins = bins < 2 ? 2 : bins;
        if ((st = nl_gof_boot_test((const nl_field *const *)x, o->nin, dist, o->draws, o->draw_seed, bins, &t->b)))
            cli_die(nl_error_is_input(st) ? 2 : 1, "--against %s: %s", o->against, nl_errmsg());
        return;
    }
    pool = cli_malloc(t->n * sizeof *pool);
    for (size_t k = 0, m = 0; k < o->nin; m += x[k++]->count)
        memcpy(pool + m, x[k]->data, x[k]->count * sizeof *pool);
    if ((st = nl_gof_test(pool, t->n, dist, o->bins < 2 ? 2 : o->bins, &t->g)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--against %s: %s", o->against, nl_errmsg());
    free(pool);
}

/* Under an MPI launcher with one .h5 input: the moments and histogram
 * reduced over every process's slab (cli/dist_inputs.h); rank 0 writes
 * them.  The test against a distribution thins the field on one process:
 * refused. */
static int distributed(hist_opts *o)
{
    cli_slab s;
    nl_field hdr;
    hist_moments mo = {0};
    hist_test t = {0};
    double *edges, *counts;
    if (o->against)
        cli_dist_refuse("hist", "--against");
    cli_dist_read(&o->src, &s, &hdr);
    edges = cli_malloc((o->bins + 1) * sizeof *edges), counts = cli_malloc(o->bins * sizeof *counts);
    cli_dist_check(&o->src, cli_h5->hist(&s, o->bins, &mo.m, edges, counts));
    cli_dist_free(&s);
    if (cli_dist_leader()) {
        o->tmp = cli_out_begin(o->out);
        output(o, &mo, edges, counts, NULL, &t, NULL);
    }
    free(edges), free(counts);
    return 0;
}

int cli_cmd_hist(int argc, char **argv)
{
    hist_opts o = {0};
    nl_dist *dist = NULL;
    hist_test t = {0};
    hist_moments mo = {0};
    double *edges, *counts, *se = NULL, *pdf = NULL;
    nl_field **x;
    int st;

    parse(argc, argv, &o);
    if (cli_dist_wanted(&o.src, "hist"))
        return distributed(&o);
    if (o.against && (st = nl_dist_parse(o.against, &dist)))
        cli_die_status(st);
    if (dist && nl_dist_is_function(dist))
        cli_die(2, "--against %s: expected a distribution (an expr: nonlinearity has no CDF to test against)",
                o.against);
    x = read_all(&o);
    o.tmp = cli_out_begin(o.out);
    edges = cli_malloc((o.bins + 1) * sizeof *edges);
    counts = cli_malloc(o.bins * sizeof *counts);
    if (o.nin > 1)
        se = cli_malloc(o.bins * sizeof *se);
    moments(&o, x, &mo);
    histogram(&o, x, &mo, edges, counts, se);
    if (dist) {
        test(&o, x, dist, &t);
        pdf = cli_malloc(o.bins * sizeof *pdf);
        cli_check(nl_gof_bin_density(dist, edges, o.bins, pdf));
    }
    output(&o, &mo, edges, counts, se, &t, pdf);
    free(edges), free(counts), free(se), free(pdf);
    nl_dist_free(dist);
    for (size_t k = 0; k < o.nin; k++)
        nl_field_free(x[k]);
    free(x);
    cli_inputs_free(&o.src);
    return 0;
}
