/* noiselab hist: histogram and moments of a field. */
#include "cli.h"
#include "../analysis/hist.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab hist IN [--bins B] [--json] [-o OUT.tsv]\n\n"
    "Histogram of the samples of IN (EXR, PNG or 1D TSV) in B equal bins over\n"
    "[min, max] (default 50), with the mean, the unbiased variance, the skewness\n"
    "and the excess kurtosis (0 for a Gaussian).\n";

int cmd_hist(int argc, char **argv)
{
    static const struct option opts[] = {{"bins", required_argument, 0, 'b'}, {"json", no_argument, 0, 'j'},
                                         {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
                                         {0}};
    const char *out = NULL, *tmp = NULL;
    size_t bins = 50;
    int c, json = 0, st;
    double *edges, *counts;
    an_moments mo;
    nl_field *x;

    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'b': bins = cli_parse_count("--bins", optarg, 1); break;
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
    x = cli_read_field(argv[optind], NULL);
    if (out)
        tmp = cli_out_begin(out);
    edges = malloc((bins + 1) * sizeof *edges);
    counts = malloc(bins * sizeof *counts);
    if (!edges || !counts)
        cli_die(1, "out of memory");
    if ((st = an_moments_compute(x, &mo)) || (st = an_hist(x, bins, edges, counts)))
        cli_die_status(st);
    if (json) {
        cli_json_print(json_pack("{s:I,s:f,s:f,s:f,s:f,s:f,s:f,s:o,s:o}", "n", (json_int_t)mo.n, "mean", mo.mean,
                                 "variance", mo.variance, "skewness", mo.skewness, "kurtosis", mo.kurtosis, "min",
                                 mo.min, "max", mo.max, "edges", cli_json_array(edges, bins + 1), "counts",
                                 cli_json_array(counts, bins)));
    } else if (!out) {
        printf("# n %zu\n# mean %.10g\n# variance %.10g\n# skewness %.10g\n# kurtosis %.10g (excess)\n", mo.n,
               mo.mean, mo.variance, mo.skewness, mo.kurtosis);
    }
    if (out || !json) {
        static const char *const names[] = {"lo", "hi", "count"};
        const double *cols[] = {edges, edges + 1, counts};
        if ((st = write_table(out ? tmp : NULL, NULL, 3, names, bins, cols)))
            cli_die_status(st);
    }
    if (out)
        cli_out_commit(out);
    free(edges);
    free(counts);
    nl_field_free(x);
    return 0;
}
