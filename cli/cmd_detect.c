/* noiselab detect: creases and aliasing in a subdivision field. */
#include "cli.h"
#include "opt.h"
#include "../core/nl_error.h"
#include "../analysis/aliasing.h"
#include "../analysis/creases.h"
#include "../core/model.h"

#include <math.h>
#include <stdio.h>

static const char help[] =
    "usage: noiselab detect IN --levels L [--acf SPEC | --spectrum SPEC] [--json]\n\n"
    "Looks for the artefacts of subdivision in a 1D or 2D field made with L levels:\n"
    "  creases   mean squared second difference across the vertices (1D) or grid lines\n"
    "            (2D) made at each level, relative to the finest level's (1 for a\n"
    "            stationary process); the crease index is\n"
    "            the median over levels 1..L-1 with at least 64 samples; flagged above 1.5\n"
    "  aliasing  the energy by which every other sample differs from the low-passed,\n"
    "            decimated field, over the variance (zooming out one level); flagged\n"
    "            above 0.1; with a model, also the value its spectrum predicts\n"
    "Exit status 0 whatever is found; the flags are in the output.\n";

/* The command's options. */
typedef struct {
    const char *spec;  /* --acf or --spectrum */
    int levels, json;  /* --levels, --json */
} opts_t;

static const cli_opt rows[] = {
    CLI_INT("levels", opts_t, levels, .lo = 1, .need = "the number of subdivision levels of the field"),
    CLI_OPT_MODEL(opts_t, spec), CLI_OPT_JSON(opts_t, json), {0}};

int cli_cmd_detect(int argc, char **argv)
{
    opts_t a = {0};
    int st;
    double A, P = NAN;
    nl_creases cr;
    nl_field *x;
    if (cli_opt_parse("detect", help, rows, &a, argc, argv))
        return 0;
    const char *in = cli_one_operand("detect", "input file", argc, argv);
    cli_opt_need("detect", rows, &a);
    if (a.levels > 40)
        cli_die(2, "--levels: expected at most 40, got %d", a.levels);
    x = cli_read_field(in, NULL);
    if ((st = nl_creases_measure(x, a.levels, &cr)) || (st = nl_aliasing_measure(x, &A)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--levels %d on %s: %s", a.levels, in, nl_errmsg());
    if (!isfinite(A) || !isfinite(cr.index))
        cli_die(2, "detect: %s gives an undefined measure (crease index %g, aliasing %g); expected a random field",
                in, cr.index, A);
    if (a.spec) {
        nl_model *m;
        if ((st = nl_model_parse(a.spec, &m)) || (st = nl_aliasing_predict(m, x, &P)))
            cli_die_status(st);
        nl_model_free(m);
    }
    if (a.json) {
        json_t *fl = json_array();
        if (cr.flagged)
            json_array_append_new(fl, json_string("crease"));
        if (A > NL_ALIAS_MAX)
            json_array_append_new(fl, json_string("aliasing"));
        cli_json_print(json_pack("{s:f,s:o,s:f,s:o,s:o}", "crease_index", cr.index, "crease_ratios",
                                 cli_json_array(cr.ratio, (size_t)a.levels + 1), "aliasing", A, "aliasing_predicted",
                                 isnan(P) ? json_null() : json_real(P), "flags", fl));
    } else {
        printf("crease index %.3f (threshold %.1f)%s\n", cr.index, NL_CREASE_MAX, cr.flagged ? "  crease" : "");
        printf("  curvature ratio by level:");
        for (int k = 0; k <= a.levels; k++)
            if (!isnan(cr.ratio[k]))
                printf(" %d:%.2f", k, cr.ratio[k]);
        printf("\naliasing %.4f (threshold %.1f)%s", A, NL_ALIAS_MAX, A > NL_ALIAS_MAX ? "  aliasing" : "");
        if (!isnan(P))
            printf(", predicted %.4f", P);
        printf("\n");
    }
    nl_field_free(x);
    return 0;
}
