/* noiselab shape: memoryless distribution shaping of a field. */
#include "cli.h"
#include "opt.h"
#include "../core/dist.h"
#include "../synth/shape.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab shape --to DIST IN -o OUT [--format NAME] [--range LO:HI] [--empirical]\n\n"
    "Applies the memoryless nonlinearity y = F_y^-1(F_x(x)) (Lewis GI '86, section 4)\n"
    "so that the field's histogram becomes DIST; F_x is the Gaussian CDF with the\n"
    "field's mean and standard deviation (by a 65536-entry table), or with\n"
    "--empirical the field's own ranks (exact for any input distribution).\n\n"
    "DIST: gauss[:mean=,sd=], uniform[:a=,b=], laplace[:a=], hyperbolic (sech density),\n"
    "      lognormal[:zeta=,sigma=], chi2-1 (squared Gaussian), power:p=P (U^P, the\n"
    "      paper's y^2.5 terrains on the uniform rank), table:FILE (TSV columns u y),\n"
    "      or any nonlinearity expr:G, y = G(z) of the standardised field z (e.g.\n"
    "      expr:x^2, expr:exp(x), expr:2*step(x)-1; variable x; with --empirical z is\n"
    "      the Gaussian score of the rank)\n"
    "OUT: a field file by its extension or --format NAME (noiselab formats).\n";

/* The command's options. */
typedef struct {
    const char *to, *out; /* --to DIST, -o */
    int empirical;        /* --empirical */
} opts_t;

static const cli_opt rows[] = {
    CLI_STRING("to", opts_t, to, .need = "a distribution (e.g. --to laplace)"),
    CLI_FLAG("empirical", opts_t, empirical), CLI_OPT_OUTPUT(opts_t, out, .need = "an output file (noiselab formats)"),
    CLI_OPT_FORMAT, {0}};

int cli_cmd_shape(int argc, char **argv)
{
    opts_t a = {0};
    const char *tmp;
    nl_dist *d;
    nl_field *x;
    nl_meta meta;
    if (cli_opt_parse("shape", help, rows, &a, argc, argv))
        return 0;
    const char *in = cli_one_operand("shape", "input file", argc, argv);
    cli_opt_need("shape", rows, &a);
    cli_field_out_check("-o", a.out, 0);
    cli_check(nl_dist_parse(a.to, &d));
    x = cli_read_field(in, &meta);
    cli_field_out_check("-o", a.out, x->dim);
    tmp = cli_out_begin(a.out);
    cli_check(nl_synth_shape(x, d, a.empirical));
    for (size_t i = 0; i < x->count; i++)
        if (!isfinite(x->data[i]) || (cli_field_is_float32(a.out) && !(fabs(x->data[i]) <= FLT_MAX)))
            cli_die(2, "--to: %s gives the value %g at sample %zu, beyond %s; expected a distribution whose "
                    "values fit the output", a.to, x->data[i], i, cli_field_is_float32(a.out) ? "the float32 range of "
                    "the output" : "the finite numbers");
    size_t len = strlen(meta.method);
    snprintf(meta.method + len, sizeof meta.method - len, "%s shape:%s%s", len ? " +" : "", a.to,
             a.empirical ? ",empirical" : "");
    cli_write_field(a.out, tmp, x, &meta);
    cli_out_commit(a.out);
    nl_field_free(x);
    nl_dist_free(d);
    return 0;
}
