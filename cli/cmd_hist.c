/* noiselab hist: histogram and moments of a field. */
#include "cli.h"
#include "../core/field.h"
#include "../analysis/gof.h"
#include "../analysis/hist.h"
#include "../core/dist.h"
#include "../core/nl_error.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab hist IN [--bins B] [--against DIST] [--json] [-o OUT.tsv]\n\n"
    "Histogram of the samples of IN (EXR, PNG or 1D TSV) in B equal bins over\n"
    "[min, max] (default 50), with the mean, the unbiased variance, the skewness\n"
    "and the excess kurtosis (0 for a Gaussian).  --against DIST adds the density\n"
    "of DIST per bin (column pdf) and the Kolmogorov-Smirnov and chi-square tests\n"
    "(equal-probability bins) against it; DIST as in noiselab shape.  The tests\n"
    "assume independent samples: use them on white fields or sparse decimations.\n";

/* Options of noiselab hist. */
typedef struct {
    const char *in, *out, *tmp, *against; /* input, output (and its temporary), distribution spec */
    size_t bins;                          /* equal bins over [min, max] */
    int json;
} hist_opts;

static void parse(int argc, char **argv, hist_opts *o)
{
    static const struct option opts[] = {{"bins", required_argument, 0, 'b'}, {"json", no_argument, 0, 'j'},
                                         {"against", required_argument, 0, 'a'},
                                         {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
                                         {0}};
    int c;
    o->bins = 50;
    while ((c = cli_getopt(argc, argv, ":ho:", opts, "hist")) != -1) {
        switch (c) {
        case 'b': o->bins = cli_parse_count("--bins", optarg, 1); break;
        case 'a': o->against = optarg; break;
        case 'j': o->json = 1; break;
        case 'o': o->out = optarg; break;
        case 'h': fputs(help, stdout); exit(0);
        }
    }
    o->in = cli_one_operand("hist", "input file", argc, argv);
    if (o->out && !cli_has_ext(o->out, ".tsv"))
        cli_die(2, "-o: expected a .tsv file (the histogram is a table), got \"%s\"", o->out);
    if (o->bins > 10000000)
        cli_die(2, "--bins: expected at most 10000000, got %zu", o->bins);
    if (nl_size_check(1, &o->bins, sizeof(double), 4, NULL))
        cli_die(2, "--bins %zu: the edges, counts and densities do not fit in the memory available", o->bins);
}

/* A JSON number, or null where it is undefined (a constant field). */
static json_t *num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

/* "%.10g", or "undefined (constant field)". */
static void print_moment(const char *name, double v, const char *tail)
{
    if (isfinite(v))
        printf("# %s %.10g%s\n", name, v, tail);
    else
        printf("# %s undefined (constant field: variance 0)\n", name);
}

static void output(const hist_opts *o, const nl_moments *mo, const double *edges, const double *counts,
                   const nl_gof *gof, const double *pdf)
{
    size_t bins = o->bins;
    if (o->json) {
        json_t *j = json_pack("{s:I,s:f,s:f,s:o,s:o,s:f,s:f,s:o,s:o}", "n", (json_int_t)mo->n, "mean", mo->mean,
                              "variance", mo->variance, "skewness", num(mo->skewness), "kurtosis",
                              num(mo->kurtosis), "min", mo->min, "max", mo->max, "edges",
                              cli_json_array(edges, bins + 1), "counts", cli_json_array(counts, bins));
        if (pdf)
            json_object_set_new(j, "against", json_pack("{s:s,s:f,s:f,s:f,s:I,s:f,s:o}", "distribution", o->against,
                                                        "ks_statistic", gof->D, "ks_p", gof->p_ks, "chi2", gof->chi2,
                                                        "chi2_bins", (json_int_t)gof->bins, "chi2_p", gof->p_chi2,
                                                        "pdf", cli_json_array(pdf, bins)));
        cli_json_print(j);
    } else if (!o->out) {
        printf("# n %zu\n# mean %.10g\n# variance %.10g\n", mo->n, mo->mean, mo->variance);
        print_moment("skewness", mo->skewness, "");
        print_moment("kurtosis", mo->kurtosis, " (excess)");
        if (pdf)
            printf("# against %s: KS D %.6g p %.4g; chi-square %.6g on %zu equal-probability bins, p %.4g\n",
                   o->against, gof->D, gof->p_ks, gof->chi2, gof->bins - 1, gof->p_chi2);
    }
    if (o->out || !o->json) {
        static const char *const names[] = {"lo", "hi", "count", "pdf"};
        const double *cols[] = {edges, edges + 1, counts, pdf};
        cli_check(cli_write_table(o->out ? o->tmp : NULL, NULL, pdf ? 4 : 3, names, bins, cols));
    }
    cli_out_commit(o->out);
}

int cli_cmd_hist(int argc, char **argv)
{
    hist_opts o = {0};
    nl_dist *dist = NULL;
    nl_gof gof;
    double *edges, *counts, *pdf = NULL;
    nl_moments mo;
    nl_field *x;
    int st;

    parse(argc, argv, &o);
    if (o.against && (st = nl_dist_parse(o.against, &dist)))
        cli_die_status(st);
    x = cli_read_field(o.in, NULL);
    o.tmp = cli_out_begin(o.out);
    edges = cli_malloc((o.bins + 1) * sizeof *edges);
    counts = cli_malloc(o.bins * sizeof *counts);
    if ((st = nl_moments_compute(x, &mo)) || (st = nl_hist(x, o.bins, edges, counts)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", o.in, nl_errmsg());
    if (dist) {
        cli_check(nl_gof_test(x->data, x->count, dist, o.bins < 2 ? 2 : o.bins, &gof));
        pdf = cli_malloc(o.bins * sizeof *pdf);
        cli_check(nl_gof_bin_density(dist, edges, o.bins, pdf));
    }
    output(&o, &mo, edges, counts, dist ? &gof : NULL, pdf);
    free(edges), free(counts), free(pdf);
    nl_dist_free(dist);
    nl_field_free(x);
    return 0;
}
