/* noiselab validate: every applicable method on one model, measured. */
#include "opt.h"
#include "validate_report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help_usage[] =
    "usage: noiselab validate (--acf SPEC | --spectrum SPEC) --dim 1|2|3 (-o DIR [--force] | --json)\n"
    "                         [--size N] [--realizations M] [--seed S] [--tolerance E]\n"
    "                         [method options]\n\n"
    ;
/* then the paragraph naming the methods validate runs, then: */
static const char help[] =
    "  effect size      the largest |mean ACF - R| / R(0) over the lags tested, with a\n"
    "                   conservative 95% interval (simultaneous over the lags); lags along\n"
    "                   x (and y and the diagonal in 2D; x, y, z and the diagonal in 3D) up\n"
    "                   to where R falls below 5% of R(0) or a quarter of the grid, and the\n"
    "                   lag map (every lag of the half box up to that lag, at most 32 in 2D\n"
    "                   and 10 in 3D)\n"
    "  detectable error the error at any tested lag that the z test below finds with 80%\n"
    "                   power: what this ensemble can resolve\n"
    "  max |z|          |mean - R| / se against the Bonferroni threshold of Student's\n"
    "                   t(M-1) at a family-wise rate of 1e-3 over the lags\n"
    "  variance ratio   mean r(0) / R(0), 95% interval\n"
    "  spectrum         the periodogram's relative error per octave band against its\n"
    "                   expectation for the method (reported, not part of the verdict)\n"
    "Subdivision is also compared with its own exact expected ACF on grids up to 64x64\n"
    "(2D) or 2048 (1D); its verdict, like every method's, is against the model's R.\n\n"
    "  --size N          samples per axis, a power of two (default 2048 in 1D, 128 in 2D,\n"
    "                    32 in 3D); N^dim M at most 2^24\n"
    "  --realizations M  ensemble size, 4..1000 (default 64)\n"
    "  --seed S          the first seed (default 1): another S gives an independent ensemble\n"
    "  --tolerance E     largest effect size accepted (default 0.1): a method is \"within\"\n"
    "                    when the whole interval is at most E, \"off\" when all of it is\n"
    "                    above E, \"unresolved\" otherwise (more realizations or a larger\n"
    "                    grid narrow the interval)\n"
    "  --json            print every number of the report as JSON on stdout\n"
    "  -o DIR            DIR/index.md (the report, led by a table of the methods),\n"
    "                    verdict.json (as --json), acf.tsv, spectrum.tsv, map.tsv (2D\n"
    "                    and 3D), and with gnuplot acf.png, error.png, spectrum.png and\n"
    "                    map.png; DIR is made when missing, and an existing DIR must be\n"
    "                    empty (not /).  The files appear together when the run succeeds;\n"
    "                    a failure or an interrupt removes only what this run made\n"
    "  --force           write into an existing DIR that holds files, replacing those\n"
    "                    of the report's names\n"
    "method options, as for noiselab synth:\n";
/* then a line per method taking them, then: */
static const char help_exit[] =
    "\n"
    "Each method is judged against what it claims: an exact method (fft, circulant,\n"
    "cholesky) against the model's R; subdivision, which misses R by construction,\n"
    "against its own exact expected ACF where that is computed (it then reports its\n"
    "error against R); an approximate method with nothing to compare at this size\n"
    "is reported, not judged.\n"
    "exit status: 0 the model is positive definite and every judged method is within\n"
    "the tolerance of its claim; 3 a method is off its claim (or none could be\n"
    "judged); 4 the model is not positive definite in this dimension (no method\n"
    "runs); 5 none is off but one is unresolved (more --realizations decide); 2 bad\n"
    "input; 1 an output cannot be written.\n";

/* validate's method options as its help shows them (rows below). */
static const struct {
    const char *name, *arg;
} method_opts[] = {{"levels", "L"},       {"neighborhood", "N|auto"}, {"tol", "E"}, {"random-neighborhoods", "K"},
                   {"density", "D (default 32)"}, {"radius", "R"},      {"cell", "C"}};

/* The methods validate runs, grouped by the dimensions they take:
 * "fft and circulant; subdiv, subdiv-correlated and sparse in 1D and 2D". */
static void run_list(char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = '\0';
    for (unsigned dims = 7; dims; dims >>= 1) {
        int n = 0, count = 0, k;
        for (k = 0; k < nl_validate_method_count(); k++)
            count += nl_validate_method_type(k)->dims == dims;
        for (k = 0; k < nl_validate_method_count() && len < size; k++)
            if (nl_validate_method_type(k)->dims == dims)
                len += (size_t)snprintf(buf + len, size - len, "%s%s", n++ ? n == count ? " and " : ", " : len ? "; " : "",
                                        nl_validate_method_name(k));
        if (n && dims != 7 && len < size)
            len += (size_t)snprintf(buf + len, size - len, dims == 3 ? " in 1D and 2D" : " in 1D");
    }
}

/* The help: the paragraph and the method options from the registry. */
static const char *help_text(void)
{
    static char *text;
    size_t size, width = 0;
    char list[256], par[512], line[256];
    FILE *f = open_memstream(&text, &size);
    if (!f)
        return help;
    run_list(list, sizeof list);
    snprintf(par, sizeof par, "Checks the model (noiselab check), synthesises M realizations (seeds S..S+M-1) with "
             "every applicable method (%s) on an N^dim grid, and measures how far each ensemble is from the model:",
             list);
    fputs(help_usage, f);
    cli_fill(f, par, 88);
    fputs(help, f);
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < nl_validate_method_count(); k++) {
            const nl_method_type *t = nl_validate_method_type(k);
            size_t len = 0;
            if (k && nl_validate_method_type(k - 1) == t)
                continue;
            for (size_t j = 0; j < sizeof method_opts / sizeof *method_opts && len < sizeof line; j++)
                if (nl_method_option_index(t, method_opts[j].name) >= 0)
                    len += (size_t)snprintf(line + len, sizeof line - len, "%s--%s %s", len ? ", " : "",
                                            method_opts[j].name, method_opts[j].arg);
            if (!len)
                continue;
            if (!pass && len > width)
                width = len;
            if (pass)
                fprintf(f, "  %-*s   %s\n", (int)width, line, t->name);
        }
    fputs(help_exit, f);
    fclose(f);
    return text;
}

static const cli_opt rows[] = {
    CLI_STRING("acf", cli_validate, spec), CLI_STRING("spectrum", cli_validate, spectrum),
    CLI_OPT_DIMS(cli_validate, dim, 3, .need = "1, 2 or 3"), CLI_OPT_OUTPUT(cli_validate, dir),
    CLI_COUNT("size", cli_validate, N, .lo = 16), CLI_COUNT("realizations", cli_validate, M, .lo = 4),
    CLI_POSITIVE("tolerance", cli_validate, o.tolerance, .what = "relative error"), CLI_OPT_JSON(cli_validate, json),
    CLI_U64("seed", cli_validate, o.seed), CLI_FLAG("force", cli_validate, force),
    /* the methods' options, as for synth */
    CLI_INT("levels", cli_validate, o.subdiv_levels, CLI_FROM_TO(1, 30)),
    CLI_INT("neighborhood", cli_validate, o.subdiv_N, CLI_FROM_TO(1, 2147483647), .flags = CLI_AUTO,
            CLI_GIVEN(cli_validate, N_given)),
    CLI_POSITIVE("tol", cli_validate, o.subdiv_tol, .what = "number", CLI_GIVEN(cli_validate, tol_given)),
    CLI_INT("random-neighborhoods", cli_validate, o.subdiv_random, CLI_FROM_TO(1, 256)),
    CLI_POSITIVE("density", cli_validate, o.sparse_density, .what = "number"),
    CLI_INT("radius", cli_validate, o.sparse_radius, CLI_FROM_TO(1, 4096)),
    CLI_INT("cell", cli_validate, o.sparse_cell, CLI_FROM_TO(1, 1048576)), {0}};

/* The size, within the work limit: every method synthesises and estimates
 * M fields, about 2e5 samples a second, so 2^24 samples keep each method
 * near a minute. */
static void check_size(cli_validate *v)
{
    if (v->M > 1000)
        cli_die(2, "--realizations: expected at most 1000, got %zu", v->M);
    if (!v->N)
        v->N = v->dim == 1 ? 2048 : v->dim == 2 ? 128 : 32;
    if (v->N & (v->N - 1))
        cli_die(2, "--size: expected a power of two, got %zu", v->N);
    if ((double)v->M * pow((double)v->N, v->dim) > 16777216.0)
        cli_die(2, "--size %zu with --realizations %zu in %dD: %.3g samples per method; expected at most 2^24 "
                "(about a minute per method)", v->N, v->M, v->dim, (double)v->M * pow((double)v->N, v->dim));
}

static void parse(int argc, char **argv, cli_validate *v)
{
    static char sbuf[1200];
    nl_validate_options_default(&v->o);
    v->M = 64;
    if (cli_opt_parse("validate", help_text(), rows, v, argc, argv))
        exit(0);
    cli_no_operands("validate", argc, argv);
    const char *acf = v->spec, *spec = v->spectrum;
    if (!acf == !spec)
        cli_die(2, "validate: expected exactly one of --acf SPEC or --spectrum SPEC");
    cli_opt_need("validate", rows, v);
    if (!v->dir && !v->json)
        cli_die(2, "validate: expected -o DIR, --json or both");
    if (v->force && !v->dir)
        cli_die(2, "--force: expected -o DIR (it lets the report replace files in an existing folder)");
    if (v->tol_given && v->o.subdiv_N)
        cli_die(2, "--tol %g: expected --neighborhood auto (the tolerance stops its growth), got --neighborhood %d%s",
                v->o.subdiv_tol, v->o.subdiv_N, v->N_given ? "" : " (the default)");
    check_size(v);
    v->spec = acf ? acf : spec;
    v->spectral = spec != NULL;
    cli_check(nl_model_parse(acf ? acf : cli_spectrum_spec(spec, sbuf, sizeof sbuf), &v->m));
    if (spec && !nl_model_is_spectral(v->m))
        cli_die(2, "--spectrum: \"%s\" is an autocorrelation model; pass it with --acf", spec);
}

/* R finite at every lag of the validation grid (a model singular at one
 * lag would be refused by some methods with a message naming a NaN and
 * pass others unnoticed); models given by their spectrum are sampled in
 * frequency by every method, and their R is checked at the tested lags. */
static void check_grid_lags(const cli_validate *v)
{
    size_t n2 = v->dim > 1 ? v->N : 1, n3 = v->dim > 2 ? v->N : 1;
    if (nl_model_is_spectral(v->m))
        return;
    for (size_t k = 0; k < n3; k++)
        for (size_t j = 0; j < n2; j++)
            for (size_t i = 0; i < v->N; i++) {
                double lag[3] = {(double)i, (double)j, (double)k};
                if (!isfinite(nl_model_acf(v->m, v->dim, lag)))
                    cli_die(2, "--acf: %s is not finite at lag (%zu, %zu%s) of the %zu-sample grid; expected a "
                            "model finite at every lag", v->spec, i, j, v->dim > 2 ? ", ..." : "", v->N);
            }
}

/* Progress of the whole run: every method of M realizations. */
static void progress(void *ctx, int meth, size_t done, size_t total)
{
    (void)ctx;
    cli_progress("validate", (meth + (double)done / (double)total) / nl_validate_method_count());
}

/* A family known not to be positive definite in the dimension: the
 * verdict, nothing to run (exit status 4, as for any model check finds not
 * positive definite), no report. */
static int known_not_pd(cli_validate *v)
{
    char why[4096];
    snprintf(why, sizeof why, "%s", nl_errmsg());
    if (v->json)
        cli_json_print(json_pack("{s:s,s:i,s:b,s:s,s:s,s:i}", "model", nl_model_spec(v->m), "dim", v->dim,
                                 "positive_definite", 0, "why", "known-not-positive-definite", "reason", why,
                                 "exit_status", 4));
    else
        printf("%s %dD: NOT positive definite (%s); no method runs%s\n", nl_model_spec(v->m), v->dim, why,
               v->dir ? ", no report written" : "");
    nl_model_free(v->m);
    if (fflush(stdout) || ferror(stdout))
        cli_die(1, "standard output: write failed");
    return 4;
}

int cli_cmd_validate(int argc, char **argv)
{
    static cli_validate v;
    size_t n[3];
    int st;
    memset(&v, 0, sizeof v);
    parse(argc, argv, &v);
    if ((st = nl_model_check_stationary(v.m, "validate (an ensemble ACF against R)")) ||
        (st = nl_check_model(v.m, v.dim, &v.k)))
        cli_die_status(st);
    if (v.k.why == NL_CHECK_KNOWN)
        return known_not_pd(&v);
    check_grid_lags(&v);
    n[0] = n[1] = n[2] = v.N;
    v.o.realizations = v.M, v.o.progress = progress;
    /* the folder is made once every check has passed; a failure from here
     * on removes it when this run made it (cli_out_dir) */
    if (v.dir)
        cli_out_dir("-o", v.dir, v.force);
    if ((st = nl_validate_model(v.m, v.dim, n, v.k.positive_definite, &v.o, &v.r)))
        cli_die_status(st);
    cli_progress_done();
    if (v.dir)
        cli_validate_write(&v);
    if (v.json)
        cli_json_print(cli_validate_json(&v));
    else {
        printf("%s %dD: %s;", v.spec, v.dim, v.k.positive_definite ? "positive definite" : "NOT positive definite");
        for (int meth = 0; meth < NL_VALIDATE_METHODS; meth++) {
            const nl_validate_method_result *r = &v.r.method[meth];
            int verdict, claim = nl_validate_claim(&v.r, meth, &verdict);
            if (r->ran && claim == NL_VALIDATE_CLAIM_OWN)
                printf(" %s %s its own exact ACF (against R %s %.3g [%.3g, %.3g])", r->name,
                       nl_validate_verdict_name(verdict), nl_validate_verdict_name(r->verdict), r->all.effect.est,
                       r->all.effect.lo, r->all.effect.hi);
            else if (r->ran)
                printf(" %s %s%s (%.3g [%.3g, %.3g])", r->name, nl_validate_verdict_name(r->verdict),
                       claim == NL_VALIDATE_CLAIM_NONE ? " R, not judged" : "", r->all.effect.est,
                       r->all.effect.lo, r->all.effect.hi);
            else
                printf(" %s refused", r->name);
        }
        printf("%s%s%s\n", v.dir ? " (report in " : "", v.dir ? v.dir : "", v.dir ? "/index.md)" : "");
    }
    st = cli_validate_status(&v);
    nl_model_free(v.m);
    if (st) {
        /* a method off the model is a finding, not a failure: the report stays */
        if (fflush(stdout) || ferror(stdout))
            cli_die(1, "standard output: write failed");
        cli_out_finish(1);
    }
    return st;
}
