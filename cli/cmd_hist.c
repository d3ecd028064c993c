/* noiselab hist: histogram and moments of a field. */
#include "cli.h"
#include "../analysis/gof.h"
#include "../analysis/hist.h"
#include "../core/dist.h"

#include <getopt.h>
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

int cli_cmd_hist(int argc, char **argv)
{
    static const struct option opts[] = {{"bins", required_argument, 0, 'b'}, {"json", no_argument, 0, 'j'},
                                         {"against", required_argument, 0, 'a'},
                                         {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
                                         {0}};
    const char *out = NULL, *tmp = NULL, *against = NULL;
    nl_dist *dist = NULL;
    nl_gof gof;
    double *pdf = NULL;
    size_t bins = 50;
    int c, json = 0, st;
    double *edges, *counts;
    nl_moments mo;
    nl_field *x;

    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'b': bins = cli_parse_count("--bins", optarg, 1); break;
        case 'a': against = optarg; break;
        case 'j': json = 1; break;
        case 'o': out = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("hist", c, argv);
        }
    }
    if (optind + 1 != argc)
        cli_die(2, "hist: expected one input file, got %d", argc - optind);
    if (bins > 10000000)
        cli_die(2, "--bins: expected at most 10000000, got %zu", bins);
    if (against && (st = nl_dist_parse(against, &dist)))
        cli_die_status(st);
    x = cli_read_field(argv[optind], NULL);
    if (out)
        tmp = cli_out_begin(out);
    edges = malloc((bins + 1) * sizeof *edges);
    counts = malloc(bins * sizeof *counts);
    if (!edges || !counts)
        cli_die(1, "out of memory");
    if ((st = nl_moments_compute(x, &mo)) || (st = nl_hist(x, bins, edges, counts)))
        cli_die_status(st);
    if (dist) {
        if ((st = nl_gof_test(x->data, x->count, dist, bins < 2 ? 2 : bins, &gof)))
            cli_die_status(st);
        pdf = malloc(bins * sizeof *pdf);
        if (!pdf)
            cli_die(1, "out of memory");
        /* expected density per bin: probability mass over the bin width */
        for (size_t b = 0; b < bins; b++)
            pdf[b] = (nl_dist_cdf(dist, edges[b + 1]) - nl_dist_cdf(dist, edges[b])) / (edges[b + 1] - edges[b]);
    }
    if (json) {
        json_t *o = json_pack("{s:I,s:f,s:f,s:f,s:f,s:f,s:f,s:o,s:o}", "n", (json_int_t)mo.n, "mean", mo.mean,
                              "variance", mo.variance, "skewness", mo.skewness, "kurtosis", mo.kurtosis, "min",
                              mo.min, "max", mo.max, "edges", cli_json_array(edges, bins + 1), "counts",
                              cli_json_array(counts, bins));
        if (dist)
            json_object_set_new(o, "against", json_pack("{s:s,s:f,s:f,s:f,s:I,s:f,s:o}", "distribution", against,
                                                        "ks_statistic", gof.D, "ks_p", gof.p_ks, "chi2", gof.chi2,
                                                        "chi2_bins", (json_int_t)gof.bins, "chi2_p", gof.p_chi2,
                                                        "pdf", cli_json_array(pdf, bins)));
        cli_json_print(o);
    } else if (!out) {
        printf("# n %zu\n# mean %.10g\n# variance %.10g\n# skewness %.10g\n# kurtosis %.10g (excess)\n", mo.n,
               mo.mean, mo.variance, mo.skewness, mo.kurtosis);
        if (dist)
            printf("# against %s: KS D %.6g p %.4g; chi-square %.6g on %zu equal-probability bins, p %.4g\n",
                   against, gof.D, gof.p_ks, gof.chi2, gof.bins - 1, gof.p_chi2);
    }
    if (out || !json) {
        static const char *const names[] = {"lo", "hi", "count", "pdf"};
        const double *cols[] = {edges, edges + 1, counts, pdf};
        if ((st = cli_write_table(out ? tmp : NULL, NULL, pdf ? 4 : 3, names, bins, cols)))
            cli_die_status(st);
    }
    if (out)
        cli_out_commit(out);
    free(edges);
    free(counts);
    free(pdf);
    nl_dist_free(dist);
    nl_field_free(x);
    return 0;
}
