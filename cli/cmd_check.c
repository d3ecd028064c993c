/* noiselab check: is a model a valid autocorrelation, how smooth, how singular. */
#include "cli.h"
#include "../analysis/check.h"
#include "../core/model.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>

static const char help[] =
    "usage: noiselab check --acf SPEC --dim D [--json]\n\n"
    "Positive definiteness (the sampled spectrum, the smallest eigenvalue of a\n"
    "covariance matrix, the -1/n bound and the 3D monotone spectrum for isotropic\n"
    "models), smoothness (R''(0), the order of mean-square differentiability) and\n"
    "the spacing below which subdivision's matrix is numerically singular.\n"
    "JSON keys: positive_definite, min_spectrum, min_eigenvalue, isotropic_bound_ok,\n"
    "differentiable_order (null: infinitely), r2, singular_below_spacing (null:\n"
    "never), scale, spectral_decay, flags.  Exit status 0 whatever the verdict.\n";

/* A JSON number, or null where it is undefined or unbounded. */
static json_t *num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

static void print_json(const char *spec, int dim, const nl_check *k)
{
    json_t *fl = json_array();
    if (!k->positive_definite)
        json_array_append_new(fl, json_string("not-positive-definite"));
    if (k->singular_below > 0)
        json_array_append_new(fl, json_string("singular"));
    if (!k->isotropic_bound_ok)
        json_array_append_new(fl, json_string("isotropic-bound"));
    if (!k->monotone_3d)
        json_array_append_new(fl, json_string("not-monotone-3d"));
    json_t *o = json_pack("{s:s,s:i,s:b,s:o,s:o,s:b,s:b,s:o,s:o,s:o,s:o,s:o,s:o,s:o}", "model", spec, "dim", dim,
                          "positive_definite", k->positive_definite, "min_spectrum", num(k->min_spectrum),
                          "min_eigenvalue", isfinite(k->min_eigenvalue) ? json_real(k->min_eigenvalue) : json_null(),
                          "isotropic_bound_ok", k->isotropic_bound_ok, "isotropic", k->isotropic, "min_r", num(k->min_r),
                          "differentiable_order",
                          k->differentiable_order < 0 ? json_null() : json_integer(k->differentiable_order), "r2",
                          isfinite(k->r2) ? json_real(k->r2) : json_null(), "singular_below_spacing",
                          k->singular_below > 0 ? json_real(k->singular_below) : json_null(), "scale", num(k->scale),
                          "spectral_decay", isfinite(k->spectral_decay) ? json_real(k->spectral_decay) : json_null(),
                          "flags", fl);
    cli_json_print(o);
}

static void print_text(const char *spec, int dim, const nl_check *k)
{
    printf("%s in %dD: %s\n", spec, dim, k->positive_definite ? "positive definite" : "NOT positive definite");
    printf("  min spectrum / max     %.3g\n", k->min_spectrum);
    if (isfinite(k->min_eigenvalue))
        printf("  min eigenvalue / R(0)  %.3g\n", k->min_eigenvalue);
    else
        printf("  min eigenvalue / R(0)  not computed (a spectrum: model has no R(0) here)\n");
    if (k->isotropic)
        printf("  min R / R(0)           %.4f (isotropic bound -1/%d: %s)\n", k->min_r, dim,
               k->isotropic_bound_ok ? "ok" : "violated");
    if (dim == 3 && k->isotropic)
        printf("  3D spectrum monotone   %s\n", k->monotone_3d ? "yes" : "no");
    if (k->differentiable_order < 0)
        printf("  differentiable         infinitely (spectrum decays faster than any power)\n");
    else if (isfinite(k->spectral_decay))
        printf("  differentiable         %d times (spectrum ~ f^-%.2f)\n", k->differentiable_order,
               k->spectral_decay);
    else /* the spectral fit saw no power law, but R has a kink at lag 0 */
        printf("  differentiable         %d times (R has a kink at lag 0)\n", k->differentiable_order);
    if (isfinite(k->r2))
        printf("  R''(0)                 %.6g\n", k->r2);
    else if (k->r2 < 0)
        printf("  R''(0)                 unbounded below (a kink at lag 0)\n");
    else
        printf("  R''(0)                 not computed (a spectrum: model)\n");
    if (k->singular_below > 0)
        printf("  numerically singular below spacing %.3g (subdivision, N = 2)\n", k->singular_below);
    else
        printf("  never numerically singular (down to spacing %.3g)\n", ldexp(k->scale, -24));
}

int cli_cmd_check(int argc, char **argv)
{
    static const struct option opts[] = {{"acf", required_argument, 0, 'a'}, {"spectrum", required_argument, 0, 'a'},
                                         {"dim", required_argument, 0, 'd'}, {"json", no_argument, 0, 'j'},
                                         {"help", no_argument, 0, 'h'},      {0}};
    const char *spec = NULL;
    int c, dim = 0, json = 0, st;
    nl_model *m;
    nl_check k;
    while ((c = cli_getopt(argc, argv, ":h", opts, "check")) != -1) {
        switch (c) {
        case 'a': spec = optarg; break;
        case 'd': dim = cli_parse_dim(optarg, 3); break;
        case 'j': json = 1; break;
        case 'h': fputs(help, stdout); return 0;
        }
    }
    cli_no_operands("check", argc, argv);
    if (!spec)
        cli_die(2, "check: --acf: expected a model (see noiselab models)");
    if (!dim)
        cli_die(2, "check: --dim: expected 1, 2 or 3");
    if ((st = nl_model_parse(spec, &m)) || (st = nl_check_model(m, dim, &k)))
        cli_die_status(st);
    if (json)
        print_json(spec, dim, &k);
    else
        print_text(spec, dim, &k);
    nl_model_free(m);
    return 0;
}
