/* noiselab models: the model catalogue. */
#include "cli.h"
#include "opt.h"
#include "../core/model.h"

#include <stdio.h>

static const char help[] =
    "usage: noiselab models [--json]\n\n"
    "Lists every model a --acf or --spectrum SPEC may name, with its parameters\n"
    "and formula.  A spec is NAME[:key=value,...], e.g. markov:scale=8.\n"
    "In 2D and 3D every R model is isotropic, R(|lag|), unless given\n"
    "  sep          separable: R(x) R(y) R(z) / var^(dim-1)\n"
    "  angle=DEG    rotate the correlation ellipse about z\n"
    "  ratio=Q      length along the rotated y axis / length along x\n"
    "  zratio=Q     length along z / length along x\n"
    "(for %s after a final ';', e.g. \"expr:exp(-r);ratio=0.5\").\n"
    "Lags are in spacing units; frequencies in cycles per unit length; spectra\n"
    "are two-sided densities whose integral is the variance R(0).\n"
    "Structures join with + and * ('*' first, no parentheses), each with its own\n"
    "keys: \"spherical:var=0.59,scale=897,nugget=0.05 + markov:var=0.2,scale=300\"\n"
    "(R: the sum, or the product, of the structures'; an expr: structure last or\n"
    "ended by ';'; parameters of a sum named NAME.I, e.g. var.2; docs/models.md).\n";

int cli_cmd_models(int argc, char **argv)
{
    static const cli_opt rows[] = {
    {.name = "json", .type = CLI_OPT_FLAG}, {0}};
    int json = 0;
    size_t n;
    const nl_model_info *cat = nl_model_catalogue(&n);
    if (cli_opt_parse("models", NULL, rows, &json, argc, argv)) {
        char list[256];
        nl_family_names(NL_FAMILY_ARGUMENT, 0, " and ", list, sizeof list);
        printf(help, list);
        return 0;
    }
    cli_no_operands("models", argc, argv);
    if (json) {
        json_t *arr = json_array();
        for (size_t i = 0; i < n; i++)
            json_array_append_new(arr, json_pack("{s:s,s:s,s:s}", "name", cat[i].name, "params", cat[i].params,
                                                 "formula", cat[i].formula));
        cli_json_print(json_pack("{s:o}", "models", arr));
        return 0;
    }
    for (size_t i = 0; i < n; i++)
        printf("%-14s %s\n%14s %s\n", cat[i].name, cat[i].params, "", cat[i].formula);
    return 0;
}
