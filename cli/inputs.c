/* Fields for the analysis commands: files, or FFT realizations. */
#include "inputs.h"
#include "../core/nl_error.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const cli_opt cli_inputs_rows[] = {
    CLI_COUNT("realizations", cli_inputs, K, .lo = 1, .hi = 100000, .what = "at most 100000"),
    CLI_STRING("acf", cli_inputs, spec),
    {.name = "size", .type = CLI_OPT_SIZE, CLI_AT(cli_inputs, n), CLI_AUX(cli_inputs, dim), .lo = 2},
    CLI_OPT_SEED(cli_inputs, seed, seed_set), {0}};

void cli_inputs_operands(cli_inputs *in, const char *cmd, int argc, char **argv)
{
    int st;
    if (!in->K) {
        if (in->spec || in->dim || in->seed_set)
            cli_die(2, "%s: --acf, --size and --seed go with --realizations K, got no --realizations", cmd);
        if (optind >= argc)
            cli_die(2, "%s: expected one input file or more, got none", cmd);
        in->files = argv + optind, in->count = (size_t)(argc - optind);
        return;
    }
    if (optind < argc)
        cli_die(2, "%s: expected input files or --realizations, got both (\"%s\")", cmd, argv[optind]);
    if (!in->spec)
        cli_die(2, "--realizations: expected --acf SPEC, the model to synthesise");
    if (!in->dim)
        cli_die(2, "--realizations: expected --size N, NxM or NxMxL");
    if (!in->seed_set)
        in->seed = 1;
    if (in->seed > UINT64_MAX - in->K)
        cli_die(2, "--seed: expected a seed below %llu for %zu realizations, got %llu",
                (unsigned long long)(UINT64_MAX - in->K), in->K, (unsigned long long)in->seed);
    if ((st = nl_model_parse(in->spec, &in->m)))
        cli_die_status(st);
    in->count = in->K;
}

const char *cli_inputs_name(cli_inputs *in, size_t k)
{
    if (!in->K)
        return in->files[k];
    snprintf(in->name, sizeof in->name, "realization %zu (seed %llu)", k + 1,
             (unsigned long long)(in->seed + k));
    return in->name;
}

static nl_field *realization(cli_inputs *in, size_t k)
{
    int st;
    nl_field *f;
    if (!in->plan && (st = nl_synth_fft_plan_alloc(in->m, in->dim, in->n, NULL, 0, &in->plan)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf %s: %s", in->spec, nl_errmsg());
    if (!(f = nl_field_alloc(in->dim, in->n, NULL, &st)) || (st = nl_synth_fft_execute(in->plan, in->seed + k, f)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--realizations: %s", nl_errmsg());
    return f;
}

nl_field *cli_inputs_read(cli_inputs *in, size_t k, const nl_field *like)
{
    nl_field *x = in->K ? realization(in, k) : cli_read_field(in->files[k], &in->meta);
    int same = !like || x->dim == like->dim;
    for (int a = 0; like && a < 3 && same; a++)
        same = x->n[a] == like->n[a] && (a >= x->dim || x->h[a] == like->h[a]);
    if (!same) /* files only: realizations share one grid */
        cli_die(2, "%s: expected a field of the size and spacing of %s (an ensemble), got %dD of %zu samples",
                in->files[k], in->files[0], x->dim, x->count);
    return x;
}

const char *cli_meta_model(const nl_meta *meta)
{
    /* cmd_shape.c appends " + shape:DIST" (or "shape:DIST") to the method */
    return strstr(meta->method, "shape:") ? "" : meta->model;
}

const char *cli_inputs_model(const cli_inputs *in)
{
    return in->K ? in->spec : cli_meta_model(&in->meta);
}

void cli_inputs_free(cli_inputs *in)
{
    nl_synth_fft_plan_free(in->plan);
    nl_model_free(in->m);
    in->plan = NULL, in->m = NULL;
}

static int source_get(void *ctx, size_t k, const nl_field **out)
{
    cli_ensemble *e = ctx;
    *out = k ? cli_inputs_read(e->in, k, e->first) : e->first;
    return NL_OK;
}

static void source_put(void *ctx, size_t k, const nl_field *f)
{
    (void)ctx;
    if (k)
        nl_field_free((nl_field *)f);
}

nl_ensemble_source cli_inputs_source(cli_ensemble *e)
{
    return (nl_ensemble_source){.K = e->in->count, .get = source_get, .put = source_put, .ctx = e};
}
